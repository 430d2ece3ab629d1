// SPDX-License-Identifier: MIT
// Damaged HDF5 caches (issue 10): a cache written by the project's own writer, then truncated, with
// bytes flipped in its headers, data and attributes, or with shapes that lie. Every variant must
// read correctly or fail with an InputError naming the file; no crash, no other exception, no
// allocation beyond what the file can hold. The damaged files are made here, none is committed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "datasets/io/hdf5_preflight.h"
#include "datasets/io/inflate_budget.h"
#include "datasets/readers/hdf5_cache.h"
#include "tests/datasets/io_test_util.h"
#include "tests/datasets/readers_generic_test_util.h"

namespace rpt {
namespace {

using test::ByteVec;
using ::testing::AllOf;
using ::testing::HasSubstr;

ByteVec ReadBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return ByteVec(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A small cache holding both groups, as `rpt convert` writes it.
ByteVec ValidCache(const test::TempDir& dir) {
  const auto path = dir.path() / "valid.h5";
  WriteSequencesHdf5(path, {test::MakeLabelSequence("s", 3, "f_")});
  WriteDetectionsHdf5(path, test::MakeDetections(3, {"cam_a", "cam_b"}, CocoBodyJoints(), "f_"), {.add_to_existing = true});
  return ReadBytes(path);
}

// Sets io::SetHdf5Preflight for a scope; back on (rpt's default) after it.
struct PreflightSetting {
  explicit PreflightSetting(bool enabled) { io::SetHdf5Preflight(enabled); }
  ~PreflightSetting() { io::SetHdf5Preflight(true); }
};

// Reads `bytes` as a cache every way the CLI does. Returns "" when every read succeeded or failed
// with an InputError naming the file; otherwise what went wrong. `preflight`: walk the file in a
// child process first (io::PreflightHdf5, as rpt does); off, the readers' own checks are tested
// alone, as a crash then ends this test's process.
std::string ReadEveryWay(const test::TempDir& dir, const ByteVec& bytes, const std::string& variant,
                         bool preflight = false) {
  const auto path = dir.Write("damaged.h5", bytes);
  const PreflightSetting setting(preflight);
  const std::vector<std::function<void()>> reads = {[&] { ProbeHdf5Cache(path); }, [&] { ReadDetectionsHdf5(path); },
                                                    [&] { MaterializeAll(OpenSequencesHdf5(path)); }};
  for (const auto& read : reads) {
    try {
      read();
    } catch (const InputError& e) {
      if (std::string(e.what()).find(path.string()) == std::string::npos) return variant + ": " + e.what();
    } catch (const std::exception& e) {
      return variant + ": not an InputError: " + e.what();
    }
    // Every error path closed what it opened: no file, group, dataset, type or attribute is left.
    const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
    if (open != 0) return variant + ": " + std::to_string(open) + " HDF5 objects left open";
  }
  return {};
}

// Positions of `needle` in `bytes`.
std::vector<std::size_t> Find(const ByteVec& bytes, const ByteVec& needle) {
  std::vector<std::size_t> at;
  for (auto it = bytes.begin(); (it = std::search(it, bytes.end(), needle.begin(), needle.end())) != bytes.end(); ++it) {
    at.push_back(static_cast<std::size_t>(it - bytes.begin()));
  }
  return at;
}

ByteVec U64(std::uint64_t value) {
  ByteVec out;
  test::AppendLE(out, value, 8);
  return out;
}

TEST(Hdf5CacheCorruption, TruncatedFilesAreInputErrors) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  ASSERT_EQ(ReadEveryWay(dir, valid, "valid"), "");
  const std::size_t step = std::max<std::size_t>(1, valid.size() / 200);
  for (std::size_t cut = 0; cut < valid.size(); cut += step) {
    EXPECT_EQ(ReadEveryWay(dir, ByteVec(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(cut)),
                           "cut at " + std::to_string(cut)),
              "");
  }
}

// Bytes all over the file (superblock, object headers, B-trees, heaps, attributes, data) flipped
// one at a time: about 2000 evenly spaced positions, each with one of three masks. Before the
// reader checked stored sizes, ends of allocation and variable-length strings this crashed
// (SIGSEGV inside H5Dread: H5D__contig_read -> H5VM_memcpyvv).
TEST(Hdf5CacheCorruption, FlippedBytesAreInputErrors) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  const std::size_t step = valid.size() / 2000 + 1;
  const std::uint8_t masks[3] = {0xff, 0x80, 0x01};
  for (std::size_t at = 0; at < valid.size(); at += step) {
    ByteVec bytes = valid;
    bytes[at] ^= masks[at % 3];
    const std::string problem = ReadEveryWay(dir, bytes, "byte " + std::to_string(at) + " ^ " + std::to_string(masks[at % 3]));
    EXPECT_EQ(problem, "");
    if (!problem.empty()) return;  // one report is enough
  }
}

// Each dataset's values carry a CRC-32 (attribute "crc32"): one byte changed inside the stored
// values of any dataset (keypoints, offsets, camera matrices, frame ids, ...) is refused naming
// the dataset, where before 26 of 126 damaged caches were read with different numbers.
TEST(Hdf5CacheChecksum, ChangedValuesOfEveryDatasetAreRefused) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  const auto path = dir.Write("valid.h5", valid);
  std::vector<std::pair<std::string, haddr_t>> datasets;  // name, offset of its contiguous data
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<std::string> names;
    const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->emplace_back(name);
      return 0;
    };
    ASSERT_GE(H5Lvisit(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect, &names), 0);
    for (const std::string& name : names) {
      const hid_t object = H5Oopen(file, name.c_str(), H5P_DEFAULT);
      if (H5Iget_type(object) == H5I_DATASET) datasets.emplace_back(name, H5Dget_offset(object));
      H5Oclose(object);
    }
    H5Fclose(file);
  }
  ASSERT_GE(datasets.size(), 10u);
  int checked = 0;
  for (const auto& dataset : datasets) {
    const std::string& name = dataset.first;  // not a structured binding: clang before 16 cannot capture one
    const auto offset = dataset.second;
    if (offset == HADDR_UNDEF) continue;  // empty dataset: no data to damage
    ByteVec bytes = valid;
    bytes[offset] ^= 0x01;  // the first stored value
    const auto damaged = dir.Write("damaged.h5", bytes);
    const std::string message = test::InputErrorOf([&] {
      if (name.rfind("detections", 0) == 0) {
        ReadDetectionsHdf5(damaged);
      } else {
        MaterializeAll(OpenSequencesHdf5(damaged));
      }
    });
    EXPECT_THAT(message, AllOf(HasSubstr("damaged.h5"), HasSubstr(name))) << name;
    EXPECT_THAT(message, HasSubstr("checksum mismatch")) << name;
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

// The attribute region: the bytes around each attribute name and value, set to 0x00 and 0xff.
TEST(Hdf5CacheCorruption, DamagedAttributesAreInputErrors) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  for (const std::string text : {"format", "version", "count", "rpt-detections", "rpt-sequences", "fps", "name"}) {
    const std::vector<std::size_t> places = Find(valid, ByteVec(text.begin(), text.end()));
    ASSERT_FALSE(places.empty()) << text;
    for (const std::size_t place : places) {
      for (std::size_t at = place >= 48 ? place - 48 : 0; at < std::min(valid.size(), place + text.size() + 48); ++at) {
        for (const std::uint8_t value : {std::uint8_t{0x00}, std::uint8_t{0xff}}) {
          ByteVec bytes = valid;
          bytes[at] = value;
          EXPECT_EQ(ReadEveryWay(dir, bytes, text + ": byte " + std::to_string(at) + " = " + std::to_string(value)), "");
        }
      }
    }
  }
}

// Replaces attribute `name` of `object` in the cache at `path` by `value` (a float64, or a fixed
// string when `text` is set), as a damaged byte or another tool's edit would leave it. Deleted and
// created again: HDF5 1.10 cannot write an attribute opened by name.
void ReplaceAttribute(const std::filesystem::path& path, const char* object, const char* name, double value,
                      const std::string* text = nullptr) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Adelete_by_name(file, object, name, H5P_DEFAULT), 0) << object << " " << name;
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t type = text ? H5Tcopy(H5T_C_S1) : H5Tcopy(H5T_IEEE_F64LE);
  if (text) H5Tset_size(type, text->size());
  const hid_t attribute = H5Acreate_by_name(file, object, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(text ? H5Awrite(attribute, type, text->data()) : H5Awrite(attribute, H5T_NATIVE_DOUBLE, &value), 0);
  H5Aclose(attribute);
  H5Tclose(type);
  H5Sclose(space);
  H5Fclose(file);
}

// The length of an attribute's name, damaged in every attribute message of the file (message
// version 1: version, reserved byte, name size, datatype size, dataspace size, then the name): listing the attributes with
// H5Aiterate2 made HDF5 1.10 free an uninitialised table and crash (the group checksum of
// /sequences, in the walk of Hdf5CacheCorruption.FlippedBytesAreInputErrors); the reader looks
// attributes up by name instead.
TEST(Hdf5CacheCorruption, DamagedAttributeNameLengthsAreInputErrors) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  int variants = 0;
  for (const std::string name : {"format", "version", "count", "fps", "name", "crc32"}) {
    const ByteVec needle(name.c_str(), name.c_str() + name.size() + 1);  // with its NUL
    for (const std::size_t at : Find(valid, needle)) {
      if (at < 8 || valid[at - 8] != 1 || valid[at - 6] != name.size() + 1) continue;  // not an attribute message
      for (const std::uint8_t mask : {std::uint8_t{0x80}, std::uint8_t{0x01}, std::uint8_t{0xff}}) {
        ByteVec bytes = valid;
        bytes[at - 5] ^= mask;  // the name size's high byte
        EXPECT_EQ(ReadEveryWay(dir, bytes, name + " at byte " + std::to_string(at) + ": name size ^ " + std::to_string(mask)), "");
        ++variants;
      }
    }
  }
  EXPECT_GE(variants, 3 * 20);
}

// The attributes of the labels (the number of sequences, a sequence's name and frame rate) carry a
// CRC-32 on their group (format version 3): a changed value is refused naming the group, where a
// flipped byte in fps (30 -> 3) or count (2 -> 1: a sequence left out) was read without a word.
TEST(Hdf5CacheChecksum, ChangedAttributesOfTheLabelsAreRefused) {
  test::TempDir dir;
  const auto path = dir.path() / "valid.h5";
  WriteSequencesHdf5(path, {test::MakeLabelSequence("first", 2, "f_"), test::MakeLabelSequence("second", 2, "g_")});
  ASSERT_EQ(MaterializeAll(OpenSequencesHdf5(path)).size(), 2u);
  const ByteVec valid = ReadBytes(path);
  const std::string other_name = "frost";  // as long as "first": only the value differs
  const struct {
    const char* object;
    const char* name;
    double value;
    const std::string* text;
  } edits[] = {{"/sequences/0", "fps", 3.0, nullptr},
               {"/sequences/1", "fps", 30.000001, nullptr},
               {"/sequences/0", "name", 0, &other_name},
               {"/sequences", "count", 1, nullptr}};
  for (const auto& edit : edits) {
    const auto damaged = dir.Write("damaged.h5", valid);
    ReplaceAttribute(damaged, edit.object, edit.name, edit.value, edit.text);
    const std::string message = test::InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(damaged)); });
    EXPECT_THAT(message, HasSubstr(std::string("damaged.h5: ") + edit.object + ": checksum mismatch: the attributes differ"))
        << edit.object << " " << edit.name;
  }
  // Caches rpt wrote before (version 2: no checksum on the attributes) are read as they are.
  const auto version2 = dir.Write("version2.h5", valid);
  ReplaceAttribute(version2, "/sequences", "version", 2);
  ReplaceAttribute(version2, "/sequences/1", "fps", 3.0);
  for (const char* group : {"/sequences", "/sequences/0", "/sequences/1"}) {
    const hid_t file = H5Fopen(version2.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Adelete_by_name(file, group, "crc32", H5P_DEFAULT), 0) << group;
    H5Fclose(file);
  }
  const std::vector<Sequence> read = MaterializeAll(OpenSequencesHdf5(version2));
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].fps, 30);
  EXPECT_EQ(read[1].fps, 3);
}

// A format tag with a line break in it (a damaged file can hold any bytes there; a damaged string
// can even come back as heap memory): the message quotes it escaped, on one line.
TEST(Hdf5CacheCorruption, AFormatTagIsQuotedOnOneLine) {
  test::TempDir dir;
  ByteVec bytes = ValidCache(dir);
  const std::string tag = "rpt-sequences";
  const std::vector<std::size_t> places = Find(bytes, ByteVec(tag.begin(), tag.end()));
  ASSERT_FALSE(places.empty());
  for (const std::size_t place : places) bytes[place + 4] = '\n';  // "rpt-\nequences"
  const auto damaged = dir.Write("damaged.h5", bytes);
  const std::string message = test::InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(damaged)); });
  EXPECT_THAT(message, HasSubstr("attribute format is 'rpt-\\x0aequences'")) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Dataspace dimensions rewritten in the file's bytes: the dataset claims far more elements than the
// file stores. The reader must refuse before allocating for the claim.
TEST(Hdf5CacheCorruption, DimensionsThatLieAreInputErrors) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  // Three frames: the frame-count dimensions are 3 (and 4 for offsets); 17 joints; 3 cameras.
  for (const std::uint64_t honest : {3u, 4u, 17u, 21u}) {
    for (const std::size_t at : Find(valid, U64(honest))) {
      for (const std::uint64_t lie : {std::uint64_t{1} << 40, std::uint64_t{1} << 62, std::uint64_t{0xffffffffffffffff},
                                      honest + 1, std::uint64_t{0}}) {
        ByteVec bytes = valid;
        const ByteVec value = U64(lie);
        std::copy(value.begin(), value.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
        EXPECT_EQ(ReadEveryWay(dir, bytes, std::to_string(honest) + " at byte " + std::to_string(at) + " -> " +
                                               std::to_string(lie)),
                  "");
      }
    }
  }
}

// A compressed (or never written) dataset expands far beyond the file: 2 MB of gzip holding
// gigabytes of zero-score persons took 7.8 GB to inspect. Here a chunked keypoints dataset of
// 400,000 persons (78 MB as float32) that was never written (all fill values) in a file of a few
// kilobytes: above the 64 MB floor of the budget.
TEST(Hdf5CacheCorruption, DatasetsExpandingBeyondTheBudgetAreRefusedBeforeReading) {
  test::TempDir dir;
  const auto path = dir.path() / "bomb.h5";
  Detections detections;
  detections.joints = CocoBodyJoints();
  detections.frames.resize(1);
  detections.frames[0].frame_id = "f";
  detections.frames[0].cameras = {"c"};
  detections.frames[0].views.resize(1);
  detections.frames[0].views[0].Clear(17);
  WriteDetectionsHdf5(path, detections);
  const hsize_t persons = 400'000;
  {
    H5E_auto2_t func = nullptr;
    void* data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    // Version 1: the datasets replaced below carry no checksums, as another tool's would.
    H5Adelete_by_name(file, "/detections", "version", H5P_DEFAULT);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t version =
        H5Acreate_by_name(file, "/detections", "version", H5T_STD_I32LE, scalar, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const int one = 1;
    ASSERT_GE(H5Awrite(version, H5T_NATIVE_INT, &one), 0);
    H5Aclose(version);
    H5Sclose(scalar);
    H5Ldelete(file, "/detections/keypoints", H5P_DEFAULT);
    H5Ldelete(file, "/detections/person_offsets", H5P_DEFAULT);
    const hsize_t dims[3] = {persons, 17, 3}, chunk[3] = {65536, 17, 3};
    const hid_t space = H5Screate_simple(3, dims, nullptr);
    const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(create, 3, chunk);
    H5Pset_deflate(create, 9);
    const hid_t keypoints = H5Dcreate2(file, "/detections/keypoints", H5T_IEEE_F32LE, space, H5P_DEFAULT, create, H5P_DEFAULT);
    ASSERT_GE(keypoints, 0);
    const std::int64_t offsets[2] = {0, static_cast<std::int64_t>(persons)};
    const hsize_t two = 2;
    const hid_t offsets_space = H5Screate_simple(1, &two, nullptr);
    const hid_t person_offsets = H5Dcreate2(file, "/detections/person_offsets", H5T_STD_I64LE, offsets_space,
                                            H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(person_offsets, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, offsets);
    H5Dclose(person_offsets);
    H5Sclose(offsets_space);
    H5Dclose(keypoints);
    H5Pclose(create);
    H5Sclose(space);
    H5Fclose(file);
    H5Eset_auto2(H5E_DEFAULT, func, data);
  }
  ASSERT_LT(std::filesystem::file_size(path), 100'000u);
  EXPECT_THAT(test::InputErrorOf([&] { ReadDetectionsHdf5(path); }),
              HasSubstr(path.string() + ": /detections/keypoints: decompressing 77.8 MB would take the data "
                                      "decompressed from " + path.string() + " to "));
  // A larger limit (`rpt --max-inflate-mb 200`) lets it through: 400,000 persons of score 0.
  io::SetInflateLimitMb(200);
  const Detections read = ReadDetectionsHdf5(path);
  io::SetInflateLimitMb(0);
  ASSERT_EQ(read.frames.size(), 1u);
  EXPECT_EQ(read.frames[0].views[0].num_persons(), static_cast<int>(persons));
}

// The cache with its root group's local heap address (in the symbol table message of the root
// group's object header, HDF5 format version 0 as HDF5 1.10 writes it) replaced by `address`. The
// root object header's address is in the superblock's root symbol table entry (byte 64); a
// version 1 object header has 16 bytes before its messages, each message 8 bytes before its data;
// the symbol table message (type 0x11) holds the B-tree address, then the local heap address.
ByteVec WithRootLocalHeapAt(ByteVec bytes, std::uint64_t address) {
  const auto u64 = [&](std::size_t at) {
    std::uint64_t value = 0;
    for (int i = 7; i >= 0; --i) value = value << 8 | bytes.at(at + static_cast<std::size_t>(i));
    return value;
  };
  EXPECT_EQ(bytes.at(8), 0) << "superblock version 0 expected";
  EXPECT_EQ(bytes.at(13), 8) << "8-byte addresses expected";
  const std::size_t header = static_cast<std::size_t>(u64(64));
  EXPECT_EQ(bytes.at(header), 1) << "object header version 1 expected";
  const int messages = bytes.at(header + 2) | bytes.at(header + 3) << 8;
  std::size_t at = header + 16;
  for (int m = 0; m < messages; ++m) {
    const int type = bytes.at(at) | bytes.at(at + 1) << 8;
    const std::size_t size = bytes.at(at + 2) | bytes.at(at + 3) << 8;
    if (type == 0x11) {
      const ByteVec value = U64(address);
      std::copy(value.begin(), value.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at + 8 + 8));
      return bytes;
    }
    at += 8 + size;
  }
  ADD_FAILURE() << "no symbol table message in the root group's object header";
  return bytes;
}

// Found by fuzzing (issue 10): HDF5 1.10.8 follows a root group local heap address of all ones
// (HDF5's "undefined address") and crashes (SIGSEGV, memcpy from address 0 in H5F__accum_read
// below H5G__stab_lookup) on the first lookup, before any check of rpt's could run. The file is
// walked in a child process first (io::PreflightHdf5): the crash stays there and the reader
// reports the file as damaged. Before, this test's process died.
TEST(Hdf5CacheCorruption, UndefinedRootLocalHeapIsAnInputErrorNotACrash) {
  test::TempDir dir;
  const ByteVec valid = ValidCache(dir);
  const ByteVec damaged = WithRootLocalHeapAt(valid, 0xffffffffffffffff);
  ASSERT_NE(damaged, valid);
  EXPECT_EQ(ReadEveryWay(dir, damaged, "root local heap at the undefined address", /*preflight=*/true), "");
  const auto path = dir.Write("undefined_heap.h5", damaged);
  EXPECT_THAT(
      test::InputErrorOf([&] { ProbeHdf5Cache(path); }),
      AllOf(HasSubstr(path.string() + ": the HDF5 library"), HasSubstr("the file is damaged; rpt did not read it")));
  // Other addresses past the end of the file are errors HDF5 reports itself.
  EXPECT_EQ(ReadEveryWay(dir, WithRootLocalHeapAt(valid, std::uint64_t{1} << 40), "root local heap past the end"), "");
  EXPECT_EQ(ReadEveryWay(dir, WithRootLocalHeapAt(valid, std::uint64_t{1} << 40), "root local heap past the end", true),
            "");
}

// The walk is bounded in time: a child that does not finish is killed, reaped, and the file
// refused (here with a limit of 0 ms, which no walk meets). A valid file's walk finishes.
TEST(Hdf5Preflight, AChildThatDoesNotFinishInTimeIsKilledAndTheFileRefused) {
  test::TempDir dir;
  const auto path = dir.Write("valid.h5", ValidCache(dir));
  EXPECT_TRUE(io::WalkHdf5Metadata(path, io::InflateLimitFor(std::filesystem::file_size(path))));
  EXPECT_THAT(
      test::InputErrorOf([&] { io::PreflightHdf5(path.string(), path, 1 << 20, std::chrono::milliseconds(0)); }),
      HasSubstr(path.string() + ": the HDF5 library did not finish walking the file's metadata within 0 ms"));
  io::PreflightHdf5(path.string(), path, 1 << 20);  // finishes: no exception
  // No child is left behind: every one was reaped.
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);
}

// A small file that passed is remembered by its bytes: opened again, it is not walked (a limit of
// 0 ms passes); the same name and size with other bytes, written within the same clock tick, is
// walked again (and the 0 ms limit refuses it).
TEST(Hdf5Preflight, SmallFilesThatPassedAreRememberedByTheirBytes) {
  test::TempDir dir;
  ByteVec bytes = ValidCache(dir);
  const auto path = dir.Write("remembered.h5", bytes);
  io::PreflightHdf5(path.string(), path, 1 << 21);
  EXPECT_NO_THROW(io::PreflightHdf5(path.string(), path, 1 << 21, std::chrono::milliseconds(0)));
  bytes.back() ^= 0xff;
  dir.Write("remembered.h5", bytes);
  EXPECT_THAT(
      test::InputErrorOf([&] { io::PreflightHdf5(path.string(), path, 1 << 21, std::chrono::milliseconds(0)); }),
      HasSubstr("did not finish"));
  io::ForgetPassedHdf5Files();
}

}  // namespace
}  // namespace rpt

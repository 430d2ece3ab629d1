// SPDX-License-Identifier: MIT
#include "datasets/io/npy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/errors.h"
#include "datasets/io/inflate_budget.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt::io {
namespace {

using ::testing::HasSubstr;
using test::ByteVec;
using test::NpyBytes;
using test::PickleWriter;


ByteVec F8(const std::vector<double>& v) { return test::RawOf(v); }

// The pickle np.save writes for an object array: the array itself.
ByteVec ObjectArrayPickle(const std::vector<std::int64_t>& shape, const std::function<void(PickleWriter&)>& items) {
  PickleWriter w;
  w.Proto(3).ArrayBegin().ShapeTuple(shape).DType("O8", "|", -1, -1, 63).Bool(false).EmptyList().Mark();
  items(w);
  w.Appends().ArrayEnd().Stop();
  return w.bytes;
}

// ---------------------------------------------------------------------------------------
// NPY

TEST(Npy, Version1Float64) {
  const auto bytes = NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }", F8({1, 2, 3, 4, 5, 6}));
  const PyView v = ParseNpy(bytes, "a.npy");
  EXPECT_EQ(v.AsArray().dtype.Str(), "<f8");
  EXPECT_EQ(v.ToDoubles({2, 3}), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(Npy, Version2And3FortranOrder) {
  for (int major : {2, 3}) {
    const auto bytes = NpyBytes("{'descr': '<i4', 'fortran_order': True, 'shape': (2, 2), }",
                                test::RawOf(std::vector<std::int32_t>{1, 3, 2, 4}), major);
    const PyView v = ParseNpy(bytes, "f.npy");
    EXPECT_EQ(v.ToDoubles({2, 2}), (std::vector<double>{1, 2, 3, 4})) << major;
  }
}

TEST(Npy, SmallTypesAndByteOrder) {
  EXPECT_EQ(ParseNpy(NpyBytes("{'descr': '|u1', 'fortran_order': False, 'shape': (3,), }", ByteVec{0, 128, 255}), "u.npy").ToDoubles(),
            (std::vector<double>{0, 128, 255}));
  EXPECT_EQ(ParseNpy(NpyBytes("{'descr': '|b1', 'fortran_order': False, 'shape': (2,), }", ByteVec{1, 0}), "b.npy").ToDoubles(),
            (std::vector<double>{1, 0}));
  // float16: 1.0 = 0x3c00, -2.0 = 0xc000, 0.5 = 0x3800.
  EXPECT_EQ(ParseNpy(NpyBytes("{'descr': '<f2', 'fortran_order': False, 'shape': (3,), }", ByteVec{0x00, 0x3c, 0x00, 0xc0, 0x00, 0x38}), "h.npy")
                .ToDoubles(),
            (std::vector<double>{1.0, -2.0, 0.5}));
  EXPECT_EQ(ParseNpy(NpyBytes("{'descr': '>i2', 'fortran_order': False, 'shape': (2,), }", ByteVec{0x01, 0x00, 0xff, 0xfe}), "be.npy")
                .ToDoubles(),
            (std::vector<double>{256, -2}));
  const PyView scalar = ParseNpy(NpyBytes("{'descr': '<f4', 'fortran_order': False, 'shape': (), }", test::RawOf(std::vector<float>{2.5f})), "s.npy");
  EXPECT_DOUBLE_EQ(scalar.AsDouble(), 2.5);
}

TEST(Npy, UnicodeStrings) {
  const auto data = test::RawOf(std::vector<std::uint32_t>{'S', '9', 0, 'S', '1', '1'});
  const PyView v = ParseNpy(NpyBytes("{'descr': '<U3', 'fortran_order': False, 'shape': (2,), }", data), "u.npy");
  EXPECT_EQ(v.AsArray().ElementAsString(0), "S9");
  EXPECT_EQ(v.AsArray().ElementAsString(1), "S11");
}

TEST(Npy, StructuredDescrWithPaddingAndSubarrays) {
  // Like learnable-triangulation's table: int8, int16 with a padding byte, a float32 3x2.
  const std::string header =
      "{'descr': [('subject_idx', '|i1'), ('', '|V1'), ('frame_idx', '<i2'), ('keypoints', '<f4', (3, 2))], "
      "'fortran_order': False, 'shape': (2,), }";
  ByteVec data;
  for (int r = 0; r < 2; ++r) {
    data.push_back(static_cast<std::uint8_t>(5 + r));
    data.push_back(0xAA);  // padding
    test::AppendLE(data, 1000 + r, 2);
    std::vector<float> k(6);
    for (int i = 0; i < 6; ++i) k[i] = static_cast<float>(10 * r + i);
    test::Append(data, test::RawOf(k));
  }
  const PyView v = ParseNpy(NpyBytes(header, data), "labels.npy");
  const NdArray& a = v.AsArray();
  EXPECT_EQ(a.dtype.item_size, 28u);
  ASSERT_EQ(a.dtype.fields.size(), 3u);
  EXPECT_EQ(a.dtype.fields[1].offset, 2u);
  EXPECT_EQ(v.Field("subject_idx").ToDoubles({2}), (std::vector<double>{5, 6}));
  EXPECT_EQ(v.Field("frame_idx").ToDoubles({2}), (std::vector<double>{1000, 1001}));
  const auto kp = v.Field("keypoints").ToDoubles({2, 3, 2});
  EXPECT_EQ(kp[0], 0);
  EXPECT_EQ(kp[11], 15);
  EXPECT_THAT(test::InputErrorOf([&] { v.Field("bbox"); }), HasSubstr("labels.npy: top level: structured array has no field 'bbox'"));
}

TEST(Npy, ObjectArrayDictPayload) {
  // np.save({'aria01': array}) gives a 0-d object array whose payload pickles the array.
  const ByteVec payload = ObjectArrayPickle({}, [](PickleWriter& w) {
    w.EmptyDict().Str("aria01").Array({2, 4}, "f8", "<", false, F8({1, 2, 3, 1, 0, 0, 0, 0})).SetItem();
  });
  const auto bytes = NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (), }", payload);
  test::TempDir dir;
  const PyView v = ReadNpy(dir.Write("00001.npy", bytes));
  ASSERT_TRUE(v.IsDict());
  EXPECT_EQ(v.Key("aria01").ToDoubles({2, 4})[3], 1.0);
  EXPECT_THAT(test::InputErrorOf([&] { v.Key("aria02"); }), HasSubstr("00001.npy: top level: missing key 'aria02'"));
}

TEST(Npy, ObjectArrayListPayload) {
  const ByteVec payload = ObjectArrayPickle({2}, [](PickleWriter& w) {
    w.EmptyDict().Str("human_name").Str("aria01").SetItem();
    w.EmptyDict().Str("human_name").Str("aria02").SetItem();
  });
  const PyView v = ParseNpy(NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (2,), }", payload), "list.npy");
  ASSERT_EQ(v.Size(), 2u);
  EXPECT_EQ(v.At(1).Key("human_name").AsStr(), "aria02");
  // A hostile payload is refused by the pickle VM with the file offset.
  PickleWriter evil;
  evil.Proto(2).Global("os", "system").Stop();
  const std::string msg = test::InputErrorOf([&] { ParseNpy(NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (), }", evil.bytes), "evil.npy"); });
  EXPECT_THAT(msg, HasSubstr("evil.npy"));
  EXPECT_THAT(msg, HasSubstr("'os.system' is not allowed"));
  EXPECT_THAT(msg, HasSubstr("at byte 130"));
}

TEST(Npy, TruncatedAtEveryCut) {
  const auto bytes = NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }", F8({1, 2, 3}));
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    EXPECT_THAT(test::InputErrorOf([&] { ParseNpy(std::span(bytes).first(cut), "cut.npy"); }), HasSubstr("cut.npy")) << cut;
  }
  const ByteVec payload = ObjectArrayPickle({}, [](PickleWriter& w) { w.Str("x"); });
  const auto obj = NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (), }", payload);
  for (std::size_t cut = 0; cut < obj.size(); ++cut) {
    EXPECT_THAT(test::InputErrorOf([&] { ParseNpy(std::span(obj).first(cut), "cutobj.npy"); }), HasSubstr("cutobj.npy")) << cut;
  }
}

TEST(Npy, MalformedHeaders) {
  auto error = [](const std::string& header) { return test::InputErrorOf([&] { ParseNpy(NpyBytes(header, ByteVec(64, 0)), "h.npy"); }); };
  EXPECT_THAT(error("{'descr': '<f8', 'fortran_order': False, 'shape': (4611686018427387904, 4), }"), HasSubstr("overflow"));
  EXPECT_THAT(error("{'descr': '<f8', 'fortran_order': False, 'shape': (-1,), }"), HasSubstr("negative dimension"));
  EXPECT_THAT(error("{'descr': '<M8[ns]', 'fortran_order': False, 'shape': (1,), }"), HasSubstr("unsupported dtype descr '<M8[ns]'"));
  EXPECT_THAT(error("{'descr': '<f8', 'fortran_order': False, }"), HasSubstr("missing key 'shape'"));
  EXPECT_THAT(error("{'descr': '<f8', 'fortran_order': False, 'shape': (1,"), HasSubstr("h.npy: NPY header"));
  EXPECT_THAT(error("{'descr': 'unterminated"), HasSubstr("unterminated string"));
  EXPECT_THAT(error(std::string(500, '[')), HasSubstr("nests too deeply"));
  EXPECT_THAT(error("{'descr': __import__('os')}"), HasSubstr("unknown name"));
  EXPECT_THAT(error("{'descr': '<f8', 'fortran_order': 'yes', 'shape': (1,), }"), HasSubstr("'fortran_order': expected bool"));
  ByteVec bad = NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", F8({1}));
  bad[0] = 'X';
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpy(bad, "m.npy"); }), HasSubstr("m.npy: not an NPY file"));
  ByteVec v9 = NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", F8({1}));
  v9[6] = 9;
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpy(v9, "v.npy"); }), HasSubstr("unsupported NPY version 9.0"));
}

TEST(Npy, MissingFileNamesPath) {
  EXPECT_THAT(test::InputErrorOf([] { ReadNpy("/nonexistent/poses3d/00001.npy"); }), HasSubstr("/nonexistent/poses3d/00001.npy: file not found"));
}

// ---------------------------------------------------------------------------------------
// NPZ

ByteVec SampleNpz() {
  std::vector<test::ZipMember> members;
  members.push_back({"positions.npy", NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", F8({1, 2, 3, 4})), false, true});
  ByteVec big(4000 * 8);
  std::vector<double> ramp(4000);
  for (int i = 0; i < 4000; ++i) ramp[i] = i % 7;
  members.push_back({"ramp.npy", NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (4000,), }", F8(ramp)), true, false});
  members.push_back({"README.txt", ByteVec{'h', 'i'}, true, false});
  return test::ZipBytes(members);
}

TEST(Npz, StoredAndDeflatedMembers) {
  test::TempDir dir;
  const auto npz = ReadNpz(dir.Write("data.npz", SampleNpz()));
  ASSERT_EQ(npz.size(), 3u);
  EXPECT_EQ(npz.at("positions").ToDoubles({2, 2}), (std::vector<double>{1, 2, 3, 4}));
  const auto ramp = npz.at("ramp").ToDoubles({4000});
  EXPECT_EQ(ramp[13], 6.0);
  EXPECT_EQ(npz.at("README.txt").AsBytes(), "hi");
  EXPECT_THAT(test::InputErrorOf([&] { npz.at("ramp").ToDoubles({3}); }), HasSubstr("data.npz[ramp.npy]: top level: expected shape (3,)"));
}

TEST(Npz, ObjectMembers) {
  const ByteVec payload = ObjectArrayPickle({}, [](PickleWriter& w) {
    w.EmptyDict().Str("S1").EmptyDict().Str("Directions").Array({1, 3}, "f4", "<", false, test::RawOf(std::vector<float>{1, 2, 3})).SetItem().SetItem();
  });
  const ByteVec npz = test::ZipBytes({{"positions_3d.npy", NpyBytes("{'descr': '|O', 'fortran_order': False, 'shape': (), }", payload), true, false}});
  const auto m = ParseNpz(npz, "data_3d.npz");
  EXPECT_EQ(m.at("positions_3d").Key("S1").Key("Directions").ToDoubles({1, 3}), (std::vector<double>{1, 2, 3}));
}

TEST(Npz, TruncatedAtManyCuts) {
  const ByteVec npz = SampleNpz();
  for (std::size_t cut = 0; cut < npz.size(); cut += 7) {
    EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(std::span(npz).first(cut), "cut.npz"); }), HasSubstr("cut.npz")) << cut;
  }
}

TEST(Npz, CorruptAndUnsupportedArchives) {
  ByteVec npz = SampleNpz();
  // Flip a byte inside the stored member's NPY data: the CRC catches it.
  ByteVec flipped = npz;
  flipped[30 + 13 + 20 + 128 + 3] ^= 0x55;
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(flipped, "crc.npz"); }), HasSubstr("crc.npz: member 'positions.npy': CRC-32 mismatch"));
  // zip64 markers in the end record.
  ByteVec z64 = npz;
  const std::size_t eocd = z64.size() - 22;
  z64[eocd + 16] = z64[eocd + 17] = z64[eocd + 18] = z64[eocd + 19] = 0xff;
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(z64, "big.npz"); }), HasSubstr("big.npz: zip64 archives are not supported"));
  // An unsupported compression method (bzip2 = 12) in the central directory.
  ByteVec bz = test::ZipBytes({{"a.npy", ByteVec{1, 2, 3}, false, false}});
  const std::size_t central = 30 + 5 + 3;
  bz[central + 10] = 12;
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(bz, "bz.npz"); }), HasSubstr("compression method 12 is not supported"));
  // A deflated member claiming an impossible expansion (decompression bomb guard).
  ByteVec bomb = test::ZipBytes({{"a.npy", ByteVec(100, 0), true, false}});
  const std::size_t bomb_central = bomb.size() - 22 - 46 - 5;
  test::ByteVec huge;
  test::AppendLE(huge, 0x7fffffff, 4);
  std::copy(huge.begin(), huge.end(), bomb.begin() + static_cast<std::ptrdiff_t>(bomb_central + 24));
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(bomb, "bomb.npz"); }), HasSubstr("implausible uncompressed size"));
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(ByteVec{'P', 'K'}, "tiny.npz"); }), HasSubstr("tiny.npz: too short for a ZIP archive"));
  EXPECT_THAT(test::InputErrorOf([] { ReadNpz("/nonexistent/data.npz"); }), HasSubstr("/nonexistent/data.npz: file not found"));
}

// A 1 MB NPZ inflated to 2 GB before the "missing member" error (issue 10). Required members are
// looked up in the directory first, and the sizes the directory declares must fit the file's
// decompression budget before any member is inflated.
TEST(Npz, RequiredMembersAndTheBudgetAreCheckedBeforeInflating) {
  // A member whose deflate data is garbage: inflating it would fail with "corrupt compressed data".
  ByteVec broken = test::ZipBytes({{"train_data.npy", ByteVec(4096, 7), true, false}});
  broken[30 + 14 + 2] ^= 0xff;
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(broken, "h3wb.npz", {"train_data", "metadata"}); }),
              HasSubstr("h3wb.npz: no member 'metadata.npy' (members: train_data.npy)"));
  // Two members of 40 MB each (under the budget alone, 80 MB together) in a file of 80 kB.
  const ByteVec zeros(40 << 20, 0);
  const ByteVec two = test::ZipBytes({{"a.bin", zeros, true, false}, {"b.bin", zeros, true, false}});
  ASSERT_LT(two.size(), 200'000u);
  EXPECT_THAT(test::InputErrorOf([&] { ParseNpz(two, "two.npz"); }),
              HasSubstr("two.npz: deflated members: decompressing 80.0 MB would take the data decompressed from "
                        "two.npz to 80.0 MB, above the limit of 64.0 MB"));
  SetInflateLimitMb(100);
  const auto members = ParseNpz(two, "two.npz", {"a.bin", "b.bin"});
  SetInflateLimitMb(0);
  EXPECT_EQ(members.size(), 2u);
}

}  // namespace
}  // namespace rpt::io

// SPDX-License-Identifier: MIT
// predictions.npz and predictions.h5 (engine/outputs/{array_frames,npz_export,h5_export}.h) from
// hand-made frames: read back by our NPY reader and by the HDF5 C API, every value exactly as
// given: padding rows, missing and filled joints, unknown times, two sequences fed interleaved,
// a non-ASCII frame id, blocks of frames smaller than the run.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "core/errors.h"
#include "datasets/io/npy.h"
#include "engine/outputs/array_frames.h"
#include "engine/outputs/h5_export.h"
#include "engine/outputs/npz_export.h"
#include "tests/hdf5_test_file.h"

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rpt_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A person of the test frames: track id, per joint x, y, z, score and provenance.
struct Person {
  int track_id;
  std::vector<std::array<double, 4>> joints;
  std::vector<JointProvenance> provenance;
};
struct TestFrame {
  int sequence;
  std::string id;
  double time_s;
  std::vector<Person> persons;
};

const JointNames kJoints = {"nose", "wrist"};
constexpr auto kT = JointProvenance::kTriangulated;
constexpr auto kF = JointProvenance::kFilled;

// Sequence 0 ("walk", 25 fps): two frames; sequence 1 ("run/2", unknown rate): three frames, one
// of them with three persons (the run's largest count), one without anybody.
std::vector<TestFrame> Frames() {
  return {
      {0,
       "w_0",
       0.0,
       {{3, {{1, 2, 3, 0.9}, {4, 5, 6, 0.05}}, {kT, kF}},
        {-1, {{7, 8, 9, 0.8}, {0, 0, 0, 0}}, {JointProvenance::kLifted, kT}}}},
      {1,
       "r\xc3\xbcn_0",
       kNaN,
       {{0, {{10, 11, 12, 1}, {13, 14, 15, 0.5}}, {kT, JointProvenance::kSmoothed}},
        {1, {{16, 17, 18, 0.25}, {19, 20, 21, 0.75}}, {JointProvenance::kPredicted, kT}},
        {2, {{-1, -2, -3, 0.5}, {-4, -5, -6, kNaN}}, {kT, kT}}}},
      {0, "w_1", 0.04, {{3, {{1.5, 2.5, 3.5, 0.7}, {4.5, 5.5, 6.5, 0.6}}, {kT, kT}}}},
      {1, "r\xc3\xbcn_1", 0.5, {}},
      {1, "r\xc3\xbcn_2", 1.0, {{4, {{0.125, 0.25, 0.375, 0.5}, {1, 1, 1, 0.05}}, {kT, kF}}}},
  };
}

void Feed(ArrayFrames* frames) {
  SequenceHeader walk, run;
  walk.name = "walk";
  walk.fps = 25;
  run.name = "run/2";
  frames->BeginSequence(1, run, kJoints);  // interleaved, as parallel sequences come
  frames->BeginSequence(0, walk, kJoints);
  FrameStats stats;
  for (const TestFrame& f : Frames()) {
    SequenceFrame input;
    input.id = f.id;
    input.timestamp_s = f.time_s;
    Poses3D persons;
    persons.Clear(static_cast<int>(kJoints.size()));
    for (const Person& p : f.persons) {
      auto person = persons.AddPerson(p.track_id);
      for (size_t j = 0; j < kJoints.size(); ++j) {
        for (int r = 0; r < 4; ++r) person(r, static_cast<int>(j)) = p.joints[j][r];
        persons.PersonProvenance(persons.num_persons() - 1)[j] = static_cast<uint8_t>(p.provenance[j]);
      }
    }
    frames->Frame(FrameOutput{f.sequence, &input, &persons, &stats});
  }
  frames->EndSequence(0);
  frames->EndSequence(1);
}

// What the arrays must hold: frames in sequence order (w_0, w_1, rün_0, rün_1, rün_2).
struct Expected {
  std::vector<double> poses;  // 5 x 3 x 2 x 4
  std::vector<int> track_ids, num_persons, provenance;
  std::vector<double> times_s;
  std::vector<std::string> ids;
};
Expected ExpectedArrays(bool filled_joints) {
  std::vector<TestFrame> frames = Frames();
  std::stable_sort(frames.begin(), frames.end(),
                   [](const TestFrame& a, const TestFrame& b) { return a.sequence < b.sequence; });
  Expected e;
  for (const TestFrame& f : frames) {
    e.ids.push_back(f.id);
    e.times_s.push_back(f.time_s);
    e.num_persons.push_back(static_cast<int>(f.persons.size()));
    for (size_t p = 0; p < 3; ++p) {
      const bool real = p < f.persons.size();
      e.track_ids.push_back(real ? f.persons[p].track_id : -1);
      for (size_t j = 0; j < 2; ++j) {
        e.provenance.push_back(real ? static_cast<int>(f.persons[p].provenance[j]) : 255);
        if (!real) {
          e.poses.insert(e.poses.end(), 4, kNaN);
          continue;
        }
        const auto& v = f.persons[p].joints[j];
        const bool written = v[3] > 0 && (filled_joints || f.persons[p].provenance[j] != kF);
        if (written) {
          e.poses.insert(e.poses.end(), v.begin(), v.end());
        } else {
          e.poses.insert(e.poses.end(), {kNaN, kNaN, kNaN, 0.0});
        }
      }
    }
  }
  return e;
}

// Equal, NaN equal to NaN.
void ExpectSameNumbers(const std::vector<double>& actual, const std::vector<double>& expected,
                       const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (size_t i = 0; i < actual.size(); ++i) {
    if (std::isnan(expected[i])) {
      EXPECT_TRUE(std::isnan(actual[i])) << what << "[" << i << "] = " << actual[i];
    } else {
      EXPECT_EQ(actual[i], expected[i]) << what << "[" << i << "]";
    }
  }
}

std::vector<double> AsDoubles(const std::vector<int>& values) { return {values.begin(), values.end()}; }

void ExpectNpz(const fs::path& path, const Expected& e) {
  const auto npz = io::ReadNpz(path);
  const auto array = [&](const std::string& name) -> const io::NdArray& { return npz.at(name).AsArray(); };
  const auto strings = [&](const std::string& name) {
    std::vector<std::string> out;
    for (size_t i = 0; i < array(name).Size(); ++i) out.push_back(array(name).ElementAsString(i));
    return out;
  };
  EXPECT_EQ(array("poses").shape, (std::vector<std::int64_t>{5, 3, 2, 4}));
  EXPECT_EQ(array("poses").dtype.Str(), "<f8");
  ExpectSameNumbers(array("poses").ToDoubles(), e.poses, "npz poses");
  EXPECT_EQ(array("track_ids").shape, (std::vector<std::int64_t>{5, 3}));
  EXPECT_EQ(array("track_ids").dtype.Str(), "<i4");
  ExpectSameNumbers(array("track_ids").ToDoubles(), AsDoubles(e.track_ids), "npz track_ids");
  ExpectSameNumbers(array("num_persons").ToDoubles(), AsDoubles(e.num_persons), "npz num_persons");
  EXPECT_EQ(array("provenance").shape, (std::vector<std::int64_t>{5, 3, 2}));
  EXPECT_EQ(array("provenance").dtype.Str(), "|u1");
  ExpectSameNumbers(array("provenance").ToDoubles(), AsDoubles(e.provenance), "npz provenance");
  ExpectSameNumbers(array("times_s").ToDoubles(), e.times_s, "npz times_s");
  EXPECT_EQ(strings("frame_ids"), e.ids);
  EXPECT_EQ(array("frame_ids").dtype.Str(), "<U5");
  EXPECT_EQ(strings("joint_names"), kJoints);
  EXPECT_EQ(strings("provenance_names"), ProvenanceNames());
  EXPECT_EQ(strings("sequence_names"), (std::vector<std::string>{"walk", "run/2"}));
  ExpectSameNumbers(array("sequence_frame_offsets").ToDoubles(), {0, 2, 5}, "npz sequence_frame_offsets");
  ExpectSameNumbers(array("sequence_fps").ToDoubles(), {25, kNaN}, "npz sequence_fps");
  EXPECT_TRUE(array("run_id").shape.empty()) << "0-d";
  EXPECT_EQ(strings("run_id"), std::vector<std::string>{"run-7"});
  EXPECT_EQ(strings("position_unit"), std::vector<std::string>{"m"});
  EXPECT_EQ(strings("time_unit"), std::vector<std::string>{"s"});
  EXPECT_EQ(npz.size(), 14u);
}


void ExpectH5(const fs::path& path, const Expected& e) {
  const test::Hdf5TestFile h5(path);
  ASSERT_TRUE(h5.ok()) << path;
  EXPECT_EQ(h5.Shape("/poses"), (std::vector<std::int64_t>{5, 3, 2, 4}));
  ExpectSameNumbers(h5.Doubles("/poses"), e.poses, "h5 poses");
  EXPECT_EQ(h5.Shape("/track_ids"), (std::vector<std::int64_t>{5, 3}));
  ExpectSameNumbers(h5.Doubles("/track_ids"), AsDoubles(e.track_ids), "h5 track_ids");
  ExpectSameNumbers(h5.Doubles("/num_persons"), AsDoubles(e.num_persons), "h5 num_persons");
  EXPECT_EQ(h5.Shape("/provenance"), (std::vector<std::int64_t>{5, 3, 2}));
  ExpectSameNumbers(h5.Doubles("/provenance"), AsDoubles(e.provenance), "h5 provenance");
  ExpectSameNumbers(h5.Doubles("/times_s"), e.times_s, "h5 times_s");
  EXPECT_EQ(h5.Strings("/frame_ids"), e.ids);
  EXPECT_EQ(h5.Strings("/joint_names"), kJoints);
  EXPECT_EQ(h5.Strings("/provenance_names"), ProvenanceNames());
  EXPECT_EQ(h5.Strings("/sequence_names"), (std::vector<std::string>{"walk", "run/2"}));
  ExpectSameNumbers(h5.Doubles("/sequence_frame_offsets"), {0, 2, 5}, "h5 sequence_frame_offsets");
  ExpectSameNumbers(h5.Doubles("/sequence_fps"), {25, kNaN}, "h5 sequence_fps");
  EXPECT_EQ(h5.Attribute("run_id"), "run-7");
  EXPECT_EQ(h5.Attribute("position_unit"), "m");
  EXPECT_EQ(h5.Attribute("time_unit"), "s");
}

TEST(ArrayExports, NpzAndH5HoldEveryFrameExactlyPaddedToTheLargestFrame) {
  const fs::path dir = TempDir("array_exports");
  for (const bool filled : {true, false}) {
    ExportOptions options;
    options.filled_joints = filled;
    ArrayFrames frames(dir / "predictions.arrays", "run-7", 2, options);
    Feed(&frames);
    EXPECT_EQ(frames.num_frames(), 5);
    EXPECT_EQ(frames.max_persons(), 3);
    EXPECT_EQ(frames.max_id_code_points(), 5u);
    EXPECT_EQ(frames.max_id_bytes(), 6u);
    const std::string tag = filled ? "" : "_nofill";
    // Blocks of 2 frames: 3 blocks, the last one short.
    WriteNpzExport(dir / ("predictions" + tag + ".npz"), frames, 2);
    WriteH5Export(dir / ("predictions" + tag + ".h5"), frames, 2);
    SCOPED_TRACE(filled ? "filled joints written" : "--no-filled-joints");
    const Expected e = ExpectedArrays(filled);
    ExpectNpz(dir / ("predictions" + tag + ".npz"), e);
    ExpectH5(dir / ("predictions" + tag + ".h5"), e);
  }
  // The run's own block size (all 5 frames in one block) gives the same files.
  {
    ArrayFrames frames(dir / "predictions.arrays", "run-7", 2, ExportOptions{});
    Feed(&frames);
    EXPECT_EQ(frames.block_frames(), 4096);
    WriteNpzExport(dir / "one_block.npz", frames);
    WriteH5Export(dir / "one_block.h5", frames);
    ExpectNpz(dir / "one_block.npz", ExpectedArrays(true));
    ExpectH5(dir / "one_block.h5", ExpectedArrays(true));
  }
  // The filled joints (w_0 person 0 and rün_2 person 0, joint 1) differ between the two runs.
  const auto with = io::ReadNpz(dir / "predictions.npz").at("poses").AsArray().ToDoubles();
  const auto without = io::ReadNpz(dir / "predictions_nofill.npz").at("poses").AsArray().ToDoubles();
  EXPECT_EQ(with[4], 4.0);
  EXPECT_TRUE(std::isnan(without[4]));
  EXPECT_EQ(without[7], 0.0) << "a filled joint not written: score 0";
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".part-"), std::string::npos) << "scratch left: " << entry.path();
  }
  fs::remove_all(dir);
}

TEST(ArrayExports, BlocksOfOneFrameReadTheSameFrames) {
  const fs::path dir = TempDir("array_blocks");
  ArrayFrames frames(dir / "predictions.arrays", "run-7", 2, ExportOptions{});
  Feed(&frames);
  const Expected e = ExpectedArrays(true);
  ArrayFrames::Blocks blocks(frames, 1);
  std::vector<double> poses;
  std::vector<std::string> ids;
  while (blocks.Next()) {
    EXPECT_EQ(blocks.frames(), 1);
    EXPECT_EQ(blocks.first_frame(), static_cast<std::int64_t>(ids.size()));
    poses.insert(poses.end(), blocks.poses().begin(), blocks.poses().end());
    ids.push_back(blocks.ids()[0]);
  }
  ExpectSameNumbers(poses, e.poses, "poses by single frames");
  EXPECT_EQ(ids, e.ids);
  fs::remove_all(dir);
}

TEST(ArrayExports, SequencesWithOtherJointsAreRefused) {
  const fs::path dir = TempDir("array_joints");
  ArrayFrames frames(dir / "predictions.arrays", "run", 2, ExportOptions{});
  SequenceHeader a, b;
  a.name = "a";
  b.name = "b";
  frames.BeginSequence(0, a, {"x", "y"});
  frames.BeginSequence(1, b, {"x"});
  frames.EndSequence(0);
  frames.EndSequence(1);
  try {
    WriteNpzExport(dir / "predictions.npz", frames);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sequence 'b' has other output joints than 'a'"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "predictions.npz"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::engine

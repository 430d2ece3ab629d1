// SPDX-License-Identifier: MIT
// The joint-definition adapter end to end (engine/joint_adapter{,_fit}.h): fitted on one half of a
// generated scene whose dataset defines its joints elsewhere than the detector, it recovers the
// shift and removes it on the other half; it is refused on its own fitting frames and on
// predictions of other joints; its file is read back and bad files are refused naming the file
// and the place; on the real Shelf-4DA bundle it lowers the held-out MPJPE.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "core/body_frame.h"
#include "core/errors.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "engine/input.h"
#include "engine/joint_adapter.h"
#include "engine/joint_adapter_fit.h"
#include "engine/run.h"
#include "tests/test_data.h"

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;

// The shift planted per GT joint, in the GT person's body frame: a dataset whose hips sit lower and
// further apart, shoulders further in, and other joints a little forward.
Eigen::Vector3d PlantedShift(const std::string& joint) {
  if (joint == "hip_left") return {-0.04, 0.01, -0.08};
  if (joint == "hip_right") return {0.04, 0.01, -0.08};
  if (joint == "shoulder_left") return {0.02, 0.0, -0.03};
  if (joint == "shoulder_right") return {-0.02, 0.0, -0.03};
  return {0.0, 0.015, 0.005};
}

// A noise-free generated scene (perfect detector) whose GT joints are moved by PlantedShift in
// each GT person's own body frame: the detector keeps its joint definitions, the dataset has others.
Sequence ShiftedScene(int frames) {
  SyntheticParams params;
  params.cameras = 4;
  params.people = 3;
  params.frames = frames;
  params.noise = "perfect";
  params.seed = 5;
  Sequence scene = MakeSyntheticDataset(params)[0];
  const BodyFrameJoints joints = BodyFrameJoints::Find(scene.gt_joints);
  for (SequenceFrame& frame : scene.frames) {
    for (int p = 0; p < frame.gt.num_persons(); ++p) {
      auto person = frame.gt.Person(p);
      const auto body = MakeBodyFrame(person, joints);
      if (!body) continue;
      const Eigen::Matrix4Xd unshifted = person;
      for (size_t j = 0; j < scene.gt_joints.size(); ++j) {
        if (unshifted(3, static_cast<long>(j)) > 0) {
          person.col(static_cast<long>(j)).head<3>() += body->axes * PlantedShift(scene.gt_joints[j]);
        }
      }
    }
  }
  return scene;
}

// Frames [first, last) of `scene` as their own sequence.
Sequence Part(const Sequence& scene, size_t first, size_t last) {
  Sequence part = scene;
  part.frames.assign(scene.frames.begin() + static_cast<long>(first), scene.frames.begin() + static_cast<long>(last));
  return part;
}

RunOptions Options() {
  RunOptions options;
  options.threads = 1;
  return options;
}

TEST(JointAdapterTest, FittedOnOneHalfRecoversThePlantedShiftAndRemovesItOnTheOther) {
  const Sequence scene = ShiftedScene(60);
  const std::vector<Sequence> fit_half = {Part(scene, 0, 30)};
  const std::vector<Sequence> eval_half = {Part(scene, 30, 60)};
  JointAdapter adapter = FitJointAdapter(fit_half, Options(), {OffsetStatistic::kMedian, 20});
  EXPECT_EQ(adapter.fit.frames, 30);
  EXPECT_EQ(adapter.fit.frame_ids.front(), scene.frames[0].id);
  EXPECT_EQ(adapter.fit.frame_ids.back(), scene.frames[29].id);
  EXPECT_EQ(adapter.fit.matched_persons, 90);  // 3 persons in each of 30 frames
  EXPECT_EQ(adapter.fit.persons_without_body_frame, 0);
  int fitted = 0;
  for (size_t j = 0; j < adapter.joints.size(); ++j) {
    if (FindJoint(scene.gt_joints, adapter.joints[j]) < 0) {  // no GT joint of that name: no offset
      EXPECT_EQ(adapter.samples[j], 0) << adapter.joints[j];
      EXPECT_EQ(adapter.offset_m[j], Eigen::Vector3d::Zero()) << adapter.joints[j];
      continue;
    }
    ++fitted;
    EXPECT_EQ(adapter.samples[j], 90) << adapter.joints[j];
    // Perfect detections triangulate to the unshifted GT up to rounding (1e-12 measured).
    EXPECT_LT((adapter.offset_m[j] - PlantedShift(adapter.joints[j])).cwiseAbs().maxCoeff(), 1e-9) << adapter.joints[j];
  }
  EXPECT_EQ(fitted, 17);

  RunOptions without = Options();
  const RunResult before = engine::Run(eval_half, without);
  RunOptions with = Options();
  auto shared = std::make_shared<JointAdapter>(adapter);
  with.adapter = shared;
  const RunResult after = engine::Run(eval_half, with);
  EXPECT_EQ(after.adapted_persons, 90);
  EXPECT_EQ(after.unadapted_persons, 0);
  // The planted shift over the 13 evaluated joints: 9 x |(0, 15, 5)|, 2 x |(20, 0, 30)|, 2 x |(40, 10, 80)| mm.
  EXPECT_NEAR(before.metrics.mpjpe_mm, (9 * std::sqrt(250.0) + 2 * std::sqrt(1300.0) + 2 * 90.0) / 13, 1e-3);
  EXPECT_LT(after.metrics.mpjpe_mm, 1e-6);

  // Never evaluated on its own fitting frames: one fitting frame in the input is enough.
  std::vector<Sequence> overlapping = {Part(scene, 29, 40)};
  try {
    engine::Run(overlapping, with);
    FAIL() << "evaluated on a fitting frame";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("frame '" + scene.frames[29].id + "' is one it was fitted on"),
              std::string::npos)
        << e.what();
  }
}

TEST(JointAdapterTest, RefusesPredictionsOfOtherJointsNamingTheFile) {
  JointAdapter adapter;
  adapter.path = "shelf.json";
  adapter.joints = {"nose", "shoulder_left", "shoulder_right", "hip_left", "hip_right"};
  adapter.offset_m.assign(5, Eigen::Vector3d::Zero());
  EXPECT_NO_THROW(CheckAdapterJoints(adapter, adapter.joints));
  try {
    CheckAdapterJoints(adapter, {"nose", "shoulder_left", "shoulder_right", "hip_left", "knee_left"});
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("shelf.json: fitted for other joints than the predictions': joint 4 "
                                         "(/joints/4/name) is 'hip_right', the predictions' is 'knee_left'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(CheckAdapterJoints(adapter, {"nose"}), ConfigError);
  adapter.joints = {"nose", "hip_left"};
  EXPECT_THROW(CheckAdapterJoints(adapter, adapter.joints), ConfigError);  // no body frame
}

class AdapterFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rpt_adapter_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }
  // The message ReadJointAdapter throws for `text`.
  std::string ErrorOf(const std::string& text) {
    const fs::path path = Write("bad.json", text);
    try {
      ReadJointAdapter(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

JointAdapter SmallAdapter() {
  JointAdapter adapter;
  adapter.joints = {"shoulder_left", "shoulder_right", "hip_left", "hip_right"};
  adapter.offset_m = {{0.01, 0.02, 0.03}, {-0.01, 0.02, 0.03}, {0.0, 0.0, -0.1}, {0.0, 0.0, -0.1}};
  adapter.samples = {40, 41, 42, 0};
  adapter.spread_m = {0.01, 0.02, 0.03, std::nan("")};
  adapter.fit.dataset = "shelf-4da";
  adapter.fit.params = {"frames=0-1"};
  adapter.fit.frame_ids = {"f0", "f1"};
  adapter.fit.frames = 2;
  adapter.fit.matched_persons = 3;
  return adapter;
}

TEST_F(AdapterFileTest, WrittenFileReadsBack) {
  const fs::path path = dir_ / "adapter.json";
  WriteJointAdapter(path, SmallAdapter());
  const JointAdapter read = ReadJointAdapter(path);
  EXPECT_EQ(read.path, path.string());
  EXPECT_EQ(read.joints, SmallAdapter().joints);
  EXPECT_EQ(read.offset_m, SmallAdapter().offset_m);
  EXPECT_EQ(read.samples, SmallAdapter().samples);
  EXPECT_TRUE(std::isnan(read.spread_m[3]));
  EXPECT_EQ(read.fit.frame_ids, SmallAdapter().fit.frame_ids);
  EXPECT_EQ(read.fit.params, SmallAdapter().fit.params);
  EXPECT_TRUE(read.IsFitFrame("f1"));
  EXPECT_FALSE(read.IsFitFrame("f2"));
  EXPECT_EQ(FitDescription(read.fit), "shelf-4da frames=0-1: 2 frames ('f0' to 'f1'), 3 matched persons");
}

TEST_F(AdapterFileTest, BadFilesAreRefusedNamingTheFileAndThePlace) {
  const std::string good = JointAdapterJson(SmallAdapter()).dump();
  const std::string path = (dir_ / "bad.json").string();
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  EXPECT_EQ(ErrorOf("[1]"), path + ": /: expected an object, got array [1]");
  EXPECT_EQ(ErrorOf(replaced("\"format\":\"rpt joint adapter\"", "\"format\":\"x\"")),
            path + ": /format: expected \"rpt joint adapter\" (a file written by `rpt fit-adapter`)");
  EXPECT_EQ(ErrorOf(replaced("\"offset_m\":[0.01,", "\"offset_m\":[\"a\",")),
            path + ": /joints/0/offset_m/0: expected a number, got string \"a\"");
  EXPECT_EQ(ErrorOf(replaced("\"offset_m\":[-0.01,0.02,0.03]", "\"offset_m\":[-0.01,0.02]")),
            path + ": /joints/1/offset_m: expected 3 numbers (x right, y forward, z up; metres), got array "
                   "[-0.01,0.02]");
  EXPECT_EQ(ErrorOf(replaced("\"offset_m\":[0.0,0.0,-0.1]", "\"offset_m\":[0.0,0.0,-1.5]")),
            path + ": /joints/2/offset_m/2: an offset of at most 1.0 m per axis, got number -1.5");
  EXPECT_EQ(ErrorOf(replaced("\"name\":\"hip_right\"", "\"name\":\"hip_left\"")),
            path + ": /joints/3/name: joint 'hip_left' appears twice");
  EXPECT_EQ(ErrorOf(replaced("\"samples\":40", "\"sample\":40")),
            path + ": /joints/0/sample: unknown key 'sample' (did you mean 'samples'?)");
  EXPECT_EQ(ErrorOf(replaced("\"frame_ids\":[\"f0\",\"f1\"]", "\"frame_ids\":[\"f0\"]")),
            path + ": /fit/frame_ids: 1 frame ids, but \"frames\" says 2");
  EXPECT_EQ(ErrorOf(replaced(",\"frame_ids\":[\"f0\",\"f1\"]", "")), path + ": /fit: missing \"frame_ids\"");
  EXPECT_EQ(ErrorOf(replaced("\"frames\":2", "\"frames\":-2")),
            path + ": /fit/frames: expected a non-negative integer, got number -2");
  EXPECT_NE(ErrorOf("{\"format\": ").find(path + ":1:"), std::string::npos);
  EXPECT_NE(ErrorOf("").find(path), std::string::npos);
}

// The real case (skipped without ../shared/data): Shelf-4DA's OpenPose joints are not Shelf's.
// Fitted on frames 0-149, the adapter lowers the MPJPE of frames 150-300, and the other way round.
TEST(JointAdapterRealTest, LowersTheHeldOutShelf4daMpjpe) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association/gt.txt");
  const auto input = [](const std::string& frames) {
    InputSpec spec;
    spec.dataset = "shelf-4da";
    spec.root = test::SharedData("shelf/4d_association").string();
    spec.params = {"frames=" + frames};
    return spec;
  };
  for (const auto& [fit_frames, eval_frames] : {std::pair<std::string, std::string>{"0-149", "150-300"},
                                                std::pair<std::string, std::string>{"150-300", "0-149"}}) {
    Input fit_input = OpenInput(input(fit_frames));
    const auto adapter = std::make_shared<JointAdapter>(FitJointAdapter(fit_input, Options(), {}));
    EXPECT_GT(adapter->fit.matched_persons, 200) << fit_frames;
    Input plain_input = OpenInput(input(eval_frames));
    const RunResult without = engine::Run(plain_input, Options());
    RunOptions with_options = Options();
    with_options.adapter = adapter;
    Input adapted_input = OpenInput(input(eval_frames));
    const RunResult with = engine::Run(adapted_input, with_options);
    EXPECT_LT(with.metrics.mpjpe_mm, without.metrics.mpjpe_mm - 5.0) << "fit " << fit_frames;
    Input own_frames = OpenInput(input(fit_frames));
    EXPECT_THROW(engine::Run(own_frames, with_options), ConfigError);
  }
}

}  // namespace
}  // namespace rpt::engine

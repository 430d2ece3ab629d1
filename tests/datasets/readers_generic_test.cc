// SPDX-License-Identifier: MIT
// Generic labels (skelda schema) and the shared pieces: joint names and path mappings.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>

#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_common.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/datasets/tolerance_test_util.h"

namespace rpt {
using engine::ReadDataset;
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using test::InputErrorOf;
using test::WriteText;

TEST(GenericLabels, RoundTripKeepsCamerasGroundTruthAndTimestamps) {
  test::TempDir dir;
  std::vector<Sequence> sequences = {test::MakeLabelSequence("studio/take1", 4, "take1_"),
                                     test::MakeLabelSequence("studio/take2", 3, "take2_")};
  sequences[1].cameras[0] = test::LookAtCamera("cam_h36m", {3, 3, 1.8}, DistortionModel::kH36M);
  for (auto& frame : sequences[1].frames) {  // untracked sequence: no "bodyids" written
    std::fill(frame.gt.track_ids.begin(), frame.gt.track_ids.end(), -1);
  }
  const auto path = dir.path() / "labels.json";
  WriteLabels(path, sequences);
  const std::vector<Sequence> read = MaterializeAll(OpenLabels(path));
  ASSERT_EQ(read.size(), 2u);
  for (size_t s = 0; s < 2; ++s) test::ExpectSequencesNear(sequences[s], read[s]);
  EXPECT_EQ(read[0].cameras[2].model, DistortionModel::kFisheye);
  EXPECT_EQ(read[0].cameras[1].model, DistortionModel::kOpenCV);
  EXPECT_EQ(read[0].cameras[0].model, DistortionModel::kNone);
  EXPECT_EQ(read[1].cameras[0].model, DistortionModel::kH36M);
  EXPECT_TRUE(read[0].frames[0].views.empty());
  // A camera centre written as T projects the same way after reading.
  Eigen::Vector2d a, b;
  ASSERT_TRUE(sequences[0].cameras[2].Project(Eigen::Vector3d(0.3, 0.2, 1.1), &a));
  ASSERT_TRUE(read[0].cameras[2].Project(Eigen::Vector3d(0.3, 0.2, 1.1), &b));
  EXPECT_LT((a - b).norm(), 1e-9);
}

// A skelda file as the RPT authors' tools write it: T nested 3x1 in metres, no scene, no
// timestamps, DC of zeros, a fisheye camera, splits.
constexpr const char* kSkeldaLabels = R"([
 {"id": "s_000000", "splits": ["test"], "joints": ["nose", "shoulder_left", "shoulder_right"],
  "imgpaths": ["a.jpg", "b.jpg"],
  "cameras": [
    {"name": "00_03", "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "DC": [0, 0, 0, 0, 0],
     "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4], [1.5]], "width": 1920, "height": 1080},
    {"name": "fish", "type": "fisheye", "K": [[600, 0, 640], [0, 600, 480], [0, 0, 1]], "DC": [0.1, -0.02, 0.003, -0.0004],
     "R": [[-1, 0, 0], [0, 0, -1], [0, -1, 0]], "T": [[0], [4], [1.5]], "width": 1280, "height": 960}],
  "bodies3D": [[[0.1, 0.2, 1.7, 1], [0.3, 0.2, 1.5, 0.05], [-0.1, 0.2, 1.5, 1]]],
  "room_size": [[8], [8], [3]], "room_center": [0, 0, 1.5]},
 {"id": "s_000001", "splits": ["train"], "joints": ["nose", "shoulder_left", "shoulder_right"],
  "cameras": [
    {"name": "00_03", "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "DC": [0, 0, 0, 0, 0],
     "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4], [1.5]], "width": 1920, "height": 1080},
    {"name": "fish", "type": "fisheye", "K": [[600, 0, 640], [0, 600, 480], [0, 0, 1]], "DC": [0.1, -0.02, 0.003, -0.0004],
     "R": [[-1, 0, 0], [0, 0, -1], [0, -1, 0]], "T": [[0], [4], [1.5]], "width": 1280, "height": 960}],
  "bodies3D": []},
 {"id": "s_000002", "splits": ["test"], "joints": ["nose", "shoulder_left", "shoulder_right"],
  "cameras": [
    {"name": "00_03", "K": [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]], "DC": [0, 0, 0, 0, 0],
     "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4], [1.5]], "width": 1920, "height": 1080},
    {"name": "fish", "type": "fisheye", "K": [[600, 0, 640], [0, 600, 480], [0, 0, 1]], "DC": [0.1, -0.02, 0.003, -0.0004],
     "R": [[-1, 0, 0], [0, 0, -1], [0, -1, 0]], "T": [[0], [4], [1.5]], "width": 1280, "height": 960}],
  "bodies3D": [[[0.1, 0.2, 1.7, 1], [0.3, 0.2, 1.5, 1], [-0.1, 0.2, 1.5, 1]],
               [[1.1, 0.2, 1.7, 1], [1.3, 0.2, 1.5, 1], [0.9, 0.2, 1.5, 0]]]}
])";

TEST(GenericLabels, ReadsSkeldaLabelsWithSplitsAndFrameTimestamps) {
  test::TempDir dir;
  const auto path = WriteText(dir, "test.json", kSkeldaLabels);
  const std::vector<Sequence> all = MaterializeAll(OpenLabels(path));
  ASSERT_EQ(all.size(), 1u);
  const Sequence& s = all[0];
  EXPECT_EQ(s.name, "test");  // no scene: the file's stem
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(s.gt_joints, (JointNames{"nose", "shoulder_left", "shoulder_right"}));
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].model, DistortionModel::kNone);
  EXPECT_EQ(s.cameras[1].model, DistortionModel::kFisheye);
  EXPECT_DOUBLE_EQ(s.cameras[1].dist[3], -0.0004);
  EXPECT_LT((s.cameras[0].Center() - Eigen::Vector3d(0, -4, 1.5)).norm(), 1e-12);
  EXPECT_LT((s.room.size_m - Eigen::Vector3d(8, 8, 3)).norm(), 1e-12);
  EXPECT_LT((s.room.center_m - Eigen::Vector3d(0, 0, 1.5)).norm(), 1e-12);
  // Neither "timestamp" nor "fps": the times are unknown, which one warning says.
  EXPECT_EQ(s.fps, 0);
  for (const SequenceFrame& frame : s.frames) EXPECT_TRUE(std::isnan(frame.timestamp_s)) << frame.id;
  ASSERT_EQ(s.warnings.items().size(), 1u);
  EXPECT_EQ(s.warnings.items()[0].kind, InputWarningKind::kMissing);
  EXPECT_EQ(s.warnings.items()[0].count, 3);
  EXPECT_THAT(s.warnings.items()[0].Line(),
              HasSubstr(path.string() + ": 3 labels without \"timestamp\" or \"fps\": their times are unknown"));
  EXPECT_EQ(s.frames[2].gt.num_persons(), 2);
  EXPECT_DOUBLE_EQ(s.frames[0].gt.Person(0)(3, 1), 0.05);
  EXPECT_EQ(s.frames[1].gt.num_persons(), 0);

  LabelsOptions options;
  options.fps = 25;  // the frame rate the file does not give: time = index / fps, no warning
  const Sequence timed = MaterializeAll(OpenLabels(path, options))[0];
  EXPECT_DOUBLE_EQ(timed.fps, 25);
  EXPECT_DOUBLE_EQ(timed.frames[2].timestamp_s, 2 / 25.0);
  EXPECT_TRUE(timed.warnings.empty());

  options.split = "test";
  options.fps = 10;
  const std::vector<Sequence> test = MaterializeAll(OpenLabels(path, options));
  ASSERT_EQ(test.size(), 1u);
  ASSERT_EQ(test[0].frames.size(), 2u);
  EXPECT_EQ(test[0].frames[1].id, "s_000002");
  EXPECT_DOUBLE_EQ(test[0].frames[1].timestamp_s, 0.2);  // index in the file, not in the split
  options.split = "val";
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(path, options)); }), HasSubstr("no labels in split 'val'"));
}

std::string Label(const std::string& id, const std::string& scene_key, const std::string& scene, double cx) {
  return R"({"id": ")" + id + R"(", ")" + scene_key + R"(": ")" + scene +
         R"(", "joints": ["nose"], "bodies3D": [[[0, 0, 1, 1]]],
   "cameras": [{"name": "c", "K": [[900, 0, 500], [0, 900, 400], [0, 0, 1]], "DC": [0.1, 0, 0, 0, 0],
                "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "T": [)" +
         std::to_string(cx) + R"(, 0, -3], "width": 1000, "height": 800}]})";
}

TEST(GenericLabels, GroupsLabelsBySceneInFileOrder) {
  test::TempDir dir;
  const auto path = WriteText(dir, "l.json",
                              "[" + Label("b1", "seq", "B", 0) + "," + Label("a1", "seq", "A", 1) + "," +
                                  Label("b2", "seq", "B", 0) + "," + Label("a2", "seq", "A", 1) + "]");
  LabelsOptions options;
  options.fps = 25;
  const std::vector<Sequence> sequences = MaterializeAll(OpenLabels(path, options));
  ASSERT_EQ(sequences.size(), 2u);
  EXPECT_EQ(sequences[0].name, "B");
  EXPECT_EQ(sequences[1].name, "A");
  ASSERT_EQ(sequences[0].frames.size(), 2u);
  EXPECT_EQ(sequences[0].frames[1].id, "b2");
  EXPECT_DOUBLE_EQ(sequences[0].frames[1].timestamp_s, 1 / 25.0);
  EXPECT_EQ(sequences[0].cameras[0].model, DistortionModel::kOpenCV);
  EXPECT_LT((sequences[1].cameras[0].Center() - Eigen::Vector3d(1, 0, -3)).norm(), 1e-12);
}

TEST(GenericLabels, CamerasThatDifferWithinASequenceNameBothLabels) {
  test::TempDir dir;
  const auto path = WriteText(dir, "l.json", "[" + Label("f0", "scene", "S", 0) + "," + Label("f1", "scene", "S", 0) + "," +
                                                 Label("f2", "scene", "S", 0.5) + "]");
  const std::string error = InputErrorOf([&] { MaterializeAll(OpenLabels(path)); });
  EXPECT_THAT(error, HasSubstr("l.json: labels 'f0' and 'f2' (/2) of sequence 'S' have different cameras"));
  EXPECT_THAT(error, HasSubstr("T differs"));
}

// R as JSON rows with `digits` significant digits.
std::string RotationJson(const Eigen::Matrix3d& R, int digits) {
  std::string text = "[";
  for (int r = 0; r < 3; ++r) {
    text += r ? ", [" : "[";
    for (int c = 0; c < 3; ++c) {
      char number[40];
      std::snprintf(number, sizeof(number), "%.*g", digits, R(r, c));
      text += std::string(c ? ", " : "") + number;
    }
    text += "]";
  }
  return text + "]";
}

// Label() with the camera's R replaced by `R_json`.
std::string LabelWithR(const std::string& id, const std::string& scene, const std::string& R_json) {
  std::string label = Label(id, "scene", scene, 0);
  const std::string identity = "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]";
  return label.replace(label.find(identity), identity.size(), R_json);
}

TEST(GenericLabels, RotationsWithSixDigitsAreReorthonormalisedAndCountedOncePerCamera) {
  test::TempDir dir;
  const Eigen::Matrix3d exact =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(0.2, 0.9, -0.4).normalized()).toRotationMatrix();
  const std::string rounded = RotationJson(exact, 6);
  // Two scenes of two labels each: the cameras of a scene are parsed (and counted) once.
  const auto path = WriteText(dir, "l.json", "[" + LabelWithR("a0", "A", rounded) + "," + LabelWithR("a1", "A", rounded) +
                                                 "," + LabelWithR("b0", "B", rounded) + "," +
                                                 LabelWithR("b1", "B", rounded) + "]");
  LabelsOptions timed;  // times known: the warnings are the rotations' only
  timed.fps = 25;
  const std::vector<Sequence> sequences = MaterializeAll(OpenLabels(path, timed));
  ASSERT_EQ(sequences.size(), 2u);
  InputWarnings all;
  for (const Sequence& sequence : sequences) {
    EXPECT_LT(test::OrthonormalityError(sequence.cameras[0].R), 1e-12);
    EXPECT_LT((sequence.cameras[0].R - exact).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_LT((sequence.cameras[0].Center() - Eigen::Vector3d(0, 0, -3)).norm(), 1e-12);
    test::ExpectOneWarning(sequence.warnings, path.string(), test::kRotationsFixed, 1);
    all.Merge(sequence.warnings);
  }
  ASSERT_EQ(all.items().size(), 1u);
  EXPECT_EQ(all.items()[0].Line().rfind(path.string() + ": 2 rotations re-orthonormalised (max |R^T R - I| = ", 0), 0u)
      << all.items()[0].Line();
  // Written with 17 digits: round-off only, nothing to report.
  const auto exact_path = WriteText(dir, "exact.json", "[" + LabelWithR("a0", "A", RotationJson(exact, 17)) + "]");
  EXPECT_TRUE(MaterializeAll(OpenLabels(exact_path, timed))[0].warnings.empty());
}

TEST(GenericLabels, RotationFartherThanTheToleranceNamesFileAndCamera) {
  test::TempDir dir;
  const Eigen::Matrix3d exact =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(0.2, 0.9, -0.4).normalized()).toRotationMatrix();
  const auto path = WriteText(dir, "l.json", "[" + LabelWithR("a0", "A", RotationJson(exact, 17)) + "," +
                                                 LabelWithR("b0", "B", RotationJson(test::WrongRotation(exact), 17)) + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(path)); }),
              HasSubstr(path.string() + ": /1/cameras/0/R: R is not a rotation (max |R^T R - I| = 0.010025"));
}

TEST(GenericLabels, MalformedFilesNameFileAndPlace) {
  test::TempDir dir;
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(dir.path() / "missing.json")); }),
              HasSubstr("missing.json: file not found"));
  const auto truncated = WriteText(dir, "truncated.json", "[\n" + Label("f0", "scene", "S", 0) + ",\n {\"id\": ");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(truncated)); }),
              HasSubstr("truncated.json:5:8: JSON parse error"));

  std::string text = Label("f0", "scene", "S", 0);
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    return WriteText(dir, "bad.json", "[" + t + "]");
  };
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(with(R"(["nose"])", R"(["nose", "left_shoulder"])"))); }),
              HasSubstr("bad.json: /0/joints: unknown joint name 'left_shoulder' (did you mean 'shoulder_left'?)"));
  // Every unknown name at once (a file of another skeleton took one run per name), each with what
  // it may mean in any case or spelling.
  EXPECT_THAT(InputErrorOf([&] {
                MaterializeAll(OpenLabels(
                    with(R"(["nose"])", R"(["LEFT_SHOULDER", "nose", "mid_hip", "r_wrist", "left_eye_inner"])")));
              }),
              HasSubstr(
                  "bad.json: /0/joints: unknown joint names (4): 'LEFT_SHOULDER' (did you mean 'shoulder_left'?), "
                  "'mid_hip' (did you mean 'hip_middle'?), 'r_wrist' (did you mean 'wrist_right'?), "
                  "'left_eye_inner'; rpt's names: nose, eye_left, ..., ankle_right, foot_big_toe_left, ..., "
                  "face_00 .. face_67, hand_root_left, hand_thumb_1_left .. hand_pinky_4_right"));
  // MMPose's COCO-WholeBody names (a whole-body user's file: the face and hands got no hint).
  EXPECT_THAT(InputErrorOf([&] {
                MaterializeAll(OpenLabels(with(R"(["nose"])", R"(["face-0", "nose", "face-67", "left_hand_root",
                    "right_forefinger2", "left_middle_finger3", "left_ring_finger4", "right_pinky_finger1",
                    "left_thumb1", "face-68", "left_forefinger5"])")));
              }),
              HasSubstr("unknown joint names (10): 'face-0' (did you mean 'face_00'?), 'face-67' (did you mean "
                        "'face_67'?), 'left_hand_root' (did you mean 'hand_root_left'?), 'right_forefinger2' (did "
                        "you mean 'hand_index_2_right'?), 'left_middle_finger3' (did you mean 'hand_middle_3_left'?), "
                        "'left_ring_finger4' (did you mean 'hand_ring_4_left'?), 'right_pinky_finger1' (did you mean "
                        "'hand_pinky_1_right'?), 'left_thumb1' (did you mean 'hand_thumb_1_left'?), 'face-68', "
                        "'left_forefinger5';"));
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(with(R"(["nose"])", R"(["nose", "eye_left"])"))); }),
              HasSubstr("bad.json: /0/bodies3D/0: expected 2 joints (as many as \"joints\" names), got 1"));
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(with("[0, 0, 1, 1]", "[0, 0, 1, 1, 5]"))); }),
              HasSubstr("/0/bodies3D/0/0: expected [x, y, z, visibility]"));
  EXPECT_THAT(
      InputErrorOf([&] {
        MaterializeAll(OpenLabels(with(R"("DC": [0.1, 0, 0, 0, 0])", R"("type": "fisheye", "DC": [0.1, 0, 0, 0, 0])")));
      }),
      HasSubstr("/0/cameras/0/DC: a fisheye camera needs 4 coefficients"));
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(with(R"("width": 1000)", R"("width": "wide")"))); }),
              HasSubstr("/0/cameras/0/width: expected an integer"));
  EXPECT_THAT(InputErrorOf([&] {
                MaterializeAll(
                    OpenLabels(with(R"([[1, 0, 0], [0, 1, 0], [0, 0, 1]])", R"([[2, 0, 0], [0, 1, 0], [0, 0, 1]])")));
              }),
              HasSubstr("bad.json: /0/cameras/0/R: R is not a rotation (max |R^T R - I| = 3"));
  const auto duplicate = WriteText(dir, "dup.json", "[" + Label("f0", "scene", "S", 0) + "," + Label("f0", "scene", "T", 0) + "]");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(duplicate)); }),
              HasSubstr("dup.json: /1/id: id 'f0' is also used by label 0"));
  const auto object = WriteText(dir, "object.json", "{\"frames\": []}");
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabels(object)); }),
              HasSubstr("object.json: /: expected a list of labels"));
}

// Honest time: labels with neither "timestamp" nor "fps" have unknown times (NaN), one warning per
// file however many scenes it holds, and the unknown times survive the writers (labels JSON:
// null; HDF5 cache: NaN) and validation.
TEST(GenericLabels, WithoutTimesTheTimesAreUnknownWithOneWarningPerFile) {
  test::TempDir dir;
  const auto path = WriteText(
      dir, "l.json",
      "[" + Label("b1", "seq", "B", 0) + "," + Label("a1", "seq", "A", 1) + "," + Label("b2", "seq", "B", 0) + "]");
  const std::vector<Sequence> sequences = MaterializeAll(OpenLabels(path));
  ASSERT_EQ(sequences.size(), 2u);
  InputWarnings all;
  for (const Sequence& sequence : sequences) {
    EXPECT_EQ(sequence.fps, 0);
    for (const SequenceFrame& frame : sequence.frames) EXPECT_TRUE(std::isnan(frame.timestamp_s)) << frame.id;
    ValidateSequence(sequence, sequence.name);  // an unknown time is valid
    all.Merge(sequence.warnings);
  }
  ASSERT_EQ(all.items().size(), 1u);
  EXPECT_EQ(all.items()[0].kind, InputWarningKind::kMissing);
  EXPECT_EQ(all.items()[0].Line(),
            path.string() +
                ": 3 labels without \"timestamp\" or \"fps\": their times are unknown, so nothing is carried from one "
                "frame to the next (no tracking, no speed limits); give each label a \"timestamp\", each scene an "
                "\"fps\", or the frame rate as --param fps=N");

  // Written back: "timestamp": null, no "fps"; read again: the same unknown times and warning.
  const auto written = dir.path() / "written.json";
  WriteLabels(written, sequences);
  std::ifstream in(written);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("\"timestamp\":null"), std::string::npos) << text;
  EXPECT_EQ(text.find("\"fps\""), std::string::npos);
  const std::vector<Sequence> again = MaterializeAll(OpenLabels(written));
  ASSERT_EQ(again.size(), 2u);
  EXPECT_TRUE(std::isnan(again[0].frames[1].timestamp_s));
  EXPECT_EQ(again[0].warnings.items().size(), 1u);
  // The HDF5 cache (rpt convert) keeps NaN and says so once per file.
  const auto cache = dir.path() / "l.h5";
  WriteSequencesHdf5(cache, sequences);
  const std::vector<Sequence> cached = MaterializeAll(OpenLabelsFile(cache));
  ASSERT_EQ(cached.size(), 2u);
  InputWarnings cached_warnings;
  for (const Sequence& sequence : cached) {
    for (const SequenceFrame& frame : sequence.frames) EXPECT_TRUE(std::isnan(frame.timestamp_s)) << frame.id;
    cached_warnings.Merge(sequence.warnings);
  }
  ASSERT_EQ(cached_warnings.items().size(), 1u);
  EXPECT_EQ(
      cached_warnings.items()[0].Line().rfind(cache.string() + ": 3 frames with unknown times (NaN timestamps", 0), 0u);
  // Infinite times are refused.
  std::vector<Sequence> infinite = sequences;
  infinite[0].frames[0].timestamp_s = std::numeric_limits<double>::infinity();
  WriteSequencesHdf5(cache, infinite);
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenLabelsFile(cache)); }),
              HasSubstr("/sequences/0/timestamps: element 0 is infinite"));
  // A frame rate gives the times (index in the scene / fps) and silences the warning.
  LabelsOptions options;
  options.fps = 4;
  const std::vector<Sequence> timed = MaterializeAll(OpenLabels(path, options));
  EXPECT_DOUBLE_EQ(timed[0].frames[1].timestamp_s, 0.25);
  EXPECT_TRUE(timed[0].warnings.empty());
  EXPECT_TRUE(timed[1].warnings.empty());
}

TEST(GenericLabels, RegistryPairTakesSplitAndFps) {
  test::TempDir dir;
  const auto path = WriteText(dir, "test.json", kSkeldaLabels);
  const DatasetInfo info = GenericInfo();
  EXPECT_EQ(info.name, "generic");
  DatasetRequest request;
  request.dataset = "generic";
  request.root = path;
  request.params = {{"split", "test"}, {"fps", "50"}};
  const std::vector<Sequence> sequences = ReadDataset(request);
  ASSERT_EQ(sequences.size(), 1u);
  EXPECT_EQ(sequences[0].frames.size(), 2u);
  EXPECT_DOUBLE_EQ(sequences[0].frames[1].timestamp_s, 2 / 50.0);
  request.params = {{"fps", "fast"}};
  EXPECT_EQ(test::ConfigErrorOf([&] { ReadDataset(request); }),
            "--param fps=fast: generic.fps: 'fast' is not a number >= 0");
  request.params = {{"fps", "-1"}};
  EXPECT_EQ(test::ConfigErrorOf([&] { ReadDataset(request); }), "--param fps=-1: generic.fps: '-1' is not a number >= 0");
  request.params = {{"frames", "1-2"}};
  EXPECT_EQ(test::ConfigErrorOf([&] { ReadDataset(request); }),
            "--param frames=1-2: unknown parameter 'frames' (generic has: split, fps)");
}

TEST(GenericCommon, JointNamesAreCheckedWithSuggestions) {
  EXPECT_TRUE(IsKnownJointName("hand_pinky_4_right"));
  EXPECT_TRUE(IsKnownJointName("face_07"));
  EXPECT_TRUE(IsKnownJointName("head_top"));
  EXPECT_TRUE(IsKnownJointName("hip_middle"));
  EXPECT_TRUE(IsKnownJointName("extra_tail"));
  EXPECT_FALSE(IsKnownJointName("extra_"));
  EXPECT_FALSE(IsKnownJointName("LShoulder"));
  EXPECT_THAT(InputErrorOf([] { CheckJointNames({"nose", "left_big_toe"}, "f.json: /joints"); }),
              HasSubstr("f.json: /joints: unknown joint name 'left_big_toe' (did you mean 'foot_big_toe_left'?)"));
  EXPECT_THAT(InputErrorOf([] { CheckJointNames({"Nose"}, "x"); }), HasSubstr("(did you mean 'nose'?)"));
  // OpenPose's and Human3.6M's spellings.
  for (const auto& [given, meant] : std::vector<std::pair<std::string, std::string>>{
           {"LShoulder", "shoulder_left"}, {"RWrist", "wrist_right"}, {"RBigToe", "foot_big_toe_right"},
           {"LFoot", "ankle_left"}, {"MidHip", "hip_middle"}, {"Hip", "hip_middle"}}) {
    EXPECT_THAT(InputErrorOf([&] { CheckJointNames({given}, "x"); }), HasSubstr("(did you mean '" + meant + "'?)"))
        << given;
  }
  EXPECT_THAT(InputErrorOf([] { CheckJointNames({"LTail"}, "x"); }), Not(HasSubstr("did you mean")));
  EXPECT_THAT(InputErrorOf([] { CheckJointNames({"nose", "nose"}, "x"); }), HasSubstr("'nose' appears twice"));
  EXPECT_THAT(InputErrorOf([] { CheckJointNames({}, "x"); }), HasSubstr("x: the joint list is empty"));
}

TEST(GenericCommon, PathMappingTemplatesPadOffsetAndCheckGroups) {
  const PathMapper mapper({R"(([^/]+)/(?:.*_)?(\d+)_keypoints\.json)", "shelf_{2:6+300}", "{1}{{x}}"}, "test");
  std::string frame, camera;
  ASSERT_TRUE(mapper.Apply("Camera0/shelf_000000000012_keypoints.json", "src", &frame, &camera));
  EXPECT_EQ(frame, "shelf_000312");
  EXPECT_EQ(camera, "Camera0{x}");
  ASSERT_TRUE(mapper.Apply("c1/7_keypoints.json", "src", &frame, &camera));
  EXPECT_EQ(frame, "shelf_000307");
  EXPECT_FALSE(mapper.Apply("c1/sub/notes.txt", "src", &frame, &camera));

  const PathMapper minus({R"((\d+)\.png)", "f{1:2-10}", "cam"}, "test");
  EXPECT_THAT(InputErrorOf([&] { minus.Apply("5.png", "images.json", &frame, &camera); }), HasSubstr("is negative"));
  ASSERT_TRUE(minus.Apply("1234.png", "images.json", &frame, &camera));
  EXPECT_EQ(frame, "f1224");

  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({"(a", "{1}", "c"}, "openpose"); }), HasSubstr("not a valid regular expression"));
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({"(a)", "{2}", "c"}, "openpose"); }),
              HasSubstr("uses {2} but pattern '(a)' has 1 capture group(s)"));
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({"(a)", "{1:x}", "c"}, "openpose"); }), HasSubstr("width must be"));
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({"(a)", "{1", "c"}, "openpose"); }), HasSubstr("unmatched '{'"));
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({"(a)", "}", "c"}, "openpose"); }), HasSubstr("unmatched '}'"));
  const PathMapper text_group({R"(([a-z]+)(\d+))", "{1:3}", "c"}, "t");
  EXPECT_THAT(InputErrorOf([&] { text_group.Apply("abc1", "src", &frame, &camera); }),
              HasSubstr("capture group 1 is 'abc', not a non-negative integer"));
  // A name far longer than any path is refused, not matched (std::regex overflowed the stack on
  // a 40 000-character COCO file_name); one at the limit is matched.
  const PathMapper names({R"(([a-z]+)/([a-z]+)\.png)", "{2}", "{1}"}, "t");
  const std::string longest = "c/" + std::string(4096 - 6, 'f') + ".png";
  ASSERT_EQ(longest.size(), 4096u);
  ASSERT_TRUE(names.Apply(longest, "src", &frame, &camera));
  EXPECT_EQ(frame.size(), 4090u);
  EXPECT_THAT(InputErrorOf([&] { names.Apply("c/" + std::string(40011, 'f') + ".png", "ann.json: /images/0/file_name", &frame, &camera); }),
              HasSubstr("ann.json: /images/0/file_name: a name of 40017 bytes, longer than any file path (4096)"));
  // A pattern that makes a backtracking engine take exponential time ((a+)+b on 40 a's: hours with
  // std::regex, from a run.json someone else wrote) matches in linear time: this returns at once.
  const PathMapper nested({R"(([^/]+)/(?:(a+)+b|(\d+)_keypoints\.json))", "{3:6}", "{1}"}, "t");
  EXPECT_FALSE(nested.Apply("cam0/" + std::string(4000, 'a'), "src", &frame, &camera));
  ASSERT_TRUE(nested.Apply("cam0/12_keypoints.json", "src", &frame, &camera));
  EXPECT_EQ(frame, "000012");
  // Names need not be UTF-8 (file names are bytes).
  const PathMapper any({R"(([a-z]+)/(.+)\.png)", "{2}", "{1}"}, "t");
  ASSERT_TRUE(any.Apply("c/fr\xff\xfe.png", "src", &frame, &camera));
  EXPECT_EQ(frame, "fr\xff\xfe");
  // What RE2 lacks is refused at once, naming the syntax.
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({R"((a)\1)", "{1}", "c"}, "openpose"); }),
              HasSubstr("is not a valid regular expression ("));
  EXPECT_THAT(test::ConfigErrorOf([] { PathMapper({R"((?=a)(a))", "{1}", "c"}, "openpose"); }),
              HasSubstr("RE2 syntax: no backreferences or lookaround"));
}

}  // namespace
}  // namespace rpt

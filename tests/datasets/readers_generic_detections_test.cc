// SPDX-License-Identifier: MIT
// Generic detections JSON, OpenPose folders, COCO result lists and the ReadDetectionsFile entry point.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "datasets/readers/coco_detections.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/readers/openpose_json.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/datasets/tolerance_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using ::testing::Not;
using test::InputErrorOf;
using test::WriteText;

// ---------------------------------------------------------------------------------------------
// Generic detections

TEST(GenericDetections, RoundTripKeepsEmptyViewsAndMissingJoints) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(6, {"cam_a", "cam_b", "cam_c"}, CocoBodyJoints());
  const auto path = dir.path() / "detections.json";
  WriteGenericDetections(path, detections);
  const Detections read = ReadGenericDetections(path);
  test::ExpectDetectionsNear(detections, read, 0);
  EXPECT_EQ(read.frames[0].views[0].num_persons(), 0);  // an empty view stays an empty view
  EXPECT_EQ(read.frames[0].views[0].num_joints, 17);
  EXPECT_DOUBLE_EQ(read.frames[0].views[1].Person(0)(2, 3), 0.0);  // missing joint
}

TEST(GenericDetections, AcceptsNullJointsAndLeftOutCameras) {
  test::TempDir dir;
  const auto path = WriteText(dir, "d.json", R"({"joints": ["nose", "wrist_left"], "frames": [
    {"id": 12, "views": [{"camera": "c1", "poses": [[[10.5, 20, 0.9], null]]}, {"camera": "c2", "poses": []}]},
    {"id": "f2", "views": []}]})");
  const Detections read = ReadGenericDetections(path);
  ASSERT_EQ(read.frames.size(), 2u);
  EXPECT_EQ(read.frames[0].frame_id, "12");
  EXPECT_EQ(read.frames[0].cameras, (std::vector<std::string>{"c1", "c2"}));
  ASSERT_EQ(read.frames[0].views[0].num_persons(), 1);
  EXPECT_DOUBLE_EQ(read.frames[0].views[0].Person(0)(0, 0), 10.5);
  EXPECT_DOUBLE_EQ(read.frames[0].views[0].Person(0)(2, 1), 0.0);
  EXPECT_TRUE(read.frames[1].views.empty());
}

TEST(GenericDetections, MalformedFilesNameFileAndPointer) {
  test::TempDir dir;
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(dir.path() / "none.json"); }), HasSubstr("none.json: file not found"));
  const auto truncated = WriteText(dir, "cut.json", "{\"joints\": [\"nose\"],\n \"frames\": [{\"id\": \"a\", \"views\": [");
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(truncated); }), ContainsRegex("cut\\.json:2:[0-9]+: JSON parse error"));

  // 16 joints in a pose while 17 are declared.
  nlohmann::json doc = {{"joints", CocoBodyJoints()}, {"frames", nlohmann::json::array()}};
  nlohmann::json pose = nlohmann::json::array();
  for (int j = 0; j < 16; ++j) pose.push_back({1.0 * j, 2.0, 0.5});
  doc["frames"].push_back({{"id", "f0"}, {"views", {{{"camera", "c0"}, {"poses", {pose}}}}}});
  const auto short_pose = WriteText(dir, "short.json", doc.dump());
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(short_pose); }),
              HasSubstr("short.json: /frames/0/views/0/poses/0: expected 17 joints (as many as \"joints\" names), got 16"));

  auto write = [&](const std::string& text) { return WriteText(dir, "bad.json", text); };
  // Another tool's JSON object: what it is not, and what is read (MMPose's output named).
  const std::string mmpose = InputErrorOf([&] {
    ReadGenericDetections(write(R"({"meta_info": {}, "instance_info": [{"frame_id": 0, "instances": []}]})"));
  });
  EXPECT_THAT(mmpose, HasSubstr("bad.json: /joints: missing: not rpt's generic detections {\"joints\", \"frames\"} "
                                "(an MMPose inferencer predictions file?"));
  EXPECT_THAT(mmpose, HasSubstr("; supported:\n  a folder of OpenPose JSON files"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(write(R"({"frames": []})")); }),
              Not(HasSubstr("MMPose")));
  // [null, null, 0] (a NaN position written as JSON null) is a missing joint; with a score it is not.
  const Detections nan_written = ReadGenericDetections(
      write(R"({"joints": ["nose", "neck"], "frames": [{"id": "a", "views": [{"camera": "c", "poses": [[[1, 2, 0.5], [null, null, 0]]]}]}]})"));
  EXPECT_EQ(nan_written.frames[0].views[0].data, (std::vector<double>{1, 2, 0.5, 0, 0, 0}));
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(R"({"joints": ["nose"], "frames": [{"id": "a", "views": [{"camera": "c", "poses": [[[null, null, 0.4]]]}]}]})"));
              }),
              HasSubstr("bad.json: /frames/0/views/0/poses/0/0: expected [x, y, score] or null"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(write(R"({"joints": ["nose", "l_wrist"], "frames": []})")); }),
              HasSubstr("bad.json: /joints: unknown joint name 'l_wrist'"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(R"({"joints": ["nose"], "frames": [{"id": "a", "views": [{"camera": "c", "poses": [[[1, 2, 1.6]]]}]}]})"));
              }),
              HasSubstr("bad.json: /frames/0/views/0/poses/0/0: score 1.6 outside [0, 1] (values up to 1.5 are clamped to 1)"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(R"({"joints": ["nose"], "frames": [{"id": "a", "views": [{"camera": "c", "poses": [[[1, 2]]]}]}]})"));
              }),
              HasSubstr("/frames/0/views/0/poses/0/0: expected [x, y, score] or null"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(R"({"joints": ["nose"], "frames": [{"id": "a", "views": [{"camera": "c", "poses": []}, {"camera": "c", "poses": []}]}]})"));
              }),
              HasSubstr("/frames/0/views/1/camera: camera 'c' appears twice"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(R"({"joints": ["nose"], "frames": [{"id": "a", "views": []}, {"id": "a", "views": []}]})"));
              }),
              HasSubstr("/frames/1/id: frame id 'a' also used by /frames/0"));
  // Names from the file stay on the message's one line: a line break in them is escaped.
  const std::string split_names = InputErrorOf([&] {
    ReadGenericDetections(write(
        R"({"joints": ["nose"], "frames": [{"id": "a\nb", "views": [{"camera": "c\td", "poses": []}, {"camera": "c\td", "poses": []}]}, {"id": "a\nb", "views": []}]})"));
  });
  EXPECT_THAT(split_names, HasSubstr("camera 'c\\x09d' appears twice"));
  EXPECT_EQ(split_names.find_first_of("\n\t"), std::string::npos) << split_names;
  EXPECT_THAT(InputErrorOf([&] {
                ReadGenericDetections(write(
                    R"({"joints": ["nose"], "frames": [{"id": "a\nb", "views": []}, {"id": "a\nb", "views": []}]})"));
              }),
              HasSubstr("frame id 'a\\x0ab' also used by /frames/0"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(write(R"({"version": 1.3, "people": []})")); }),
              HasSubstr("single OpenPose file"));
}

TEST(CocoDetections, OptionsCheckNamesTheKey) {
  CocoDetectionsOptions options;
  EXPECT_EQ(options.Check(), "");
  options.min_score = -1;
  EXPECT_EQ(test::ConfigErrorOf([&] { ReadCocoDetections("unused.json", options); }),
            "coco.min_score: '-1.0' is not a number >= 0");
  options = {};
  options.mapping = CocoImageMapping::kAnnotationImages;
  EXPECT_EQ(options.Check(),
            "coco.annotation_file: the annotation-images mapping needs an annotation file with \"images\"");
}

TEST(GenericDetections, WriterRefusesNaN) {
  test::TempDir dir;
  Detections detections = test::MakeDetections(2, {"a"}, CocoBodyJoints());
  detections.frames[1].views[0].data[4] = std::nan("");
  EXPECT_THAT(InputErrorOf([&] { WriteGenericDetections(dir.path() / "d.json", detections); }),
              HasSubstr("frame 'frame_000001', camera 'a', person 0, joint 'eye_left': NaN or infinity"));
}

// One frame, one view, one person of two joints with the given score texts (JSON numbers).
std::string OnePersonJson(const std::string& nose_score, const std::string& eye_score) {
  return R"({"joints": ["nose", "eye_left"], "frames": [{"id": "f0", "views": [{"camera": "c", "poses": [[[1, 2, )" +
         nose_score + "], [3, 4, " + eye_score + "]]]}]}]}";
}

TEST(GenericDetections, ScoresSlightlyAboveOneAreClampedAndCounted) {
  test::TempDir dir;
  const auto path = WriteText(dir, "d.json", OnePersonJson("1.008", "1.018"));
  const Detections d = ReadGenericDetections(path);
  const auto person = d.frames[0].views[0].Person(0);
  EXPECT_EQ(person(2, 0), 1.0);
  EXPECT_EQ(person(2, 1), 1.0);
  test::ExpectOneWarning(d.warnings, path.string(), test::kScoresClamped, 2);
  EXPECT_EQ(d.warnings.items()[0].Line(), path.string() + ": 2 scores above 1 clamped to 1 (largest = 1.018)");
  EXPECT_TRUE(ReadGenericDetections(WriteText(dir, "ok.json", OnePersonJson("1", "0.5"))).warnings.empty());
}

TEST(GenericDetections, NegativeLargeOrNanScoresNameFileAndPointer) {
  test::TempDir dir;
  const auto large = WriteText(dir, "large.json", OnePersonJson("0.9", "1.6"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(large); }),
              HasSubstr(large.string() + ": /frames/0/views/0/poses/0/1: score 1.6 outside [0, 1]"));
  const auto negative = WriteText(dir, "negative.json", OnePersonJson("-0.1", "0.9"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(negative); }),
              HasSubstr(negative.string() + ": /frames/0/views/0/poses/0/0: score -0.1 outside [0, 1]"));
  // JSON has no NaN: a file that writes one is a parse error naming line and column.
  const auto nan = WriteText(dir, "nan.json", OnePersonJson("NaN", "0.9"));
  EXPECT_THAT(InputErrorOf([&] { ReadGenericDetections(nan); }), ContainsRegex("nan\\.json:1:[0-9]+: JSON parse error"));
}

// ---------------------------------------------------------------------------------------------
// OpenPose folders

// A flat x, y, c list of `points` points; point i at (base + i, 2 * base + i) with score s.
nlohmann::json Flat(int points, double base, double score) {
  nlohmann::json out = nlohmann::json::array();
  for (int i = 0; i < points; ++i) {
    out.push_back(base + i);
    out.push_back(2 * base + i);
    out.push_back(score);
  }
  return out;
}

void WriteOpenPose(const test::TempDir& dir, const std::string& relative, const std::vector<nlohmann::json>& people) {
  nlohmann::json doc = {{"version", 1.3}, {"people", people}};
  WriteText(dir, relative, doc.dump());
}

TEST(OpenPose, Body25FolderMapsToCocoNamesAndFeet) {
  test::TempDir dir;
  nlohmann::json person = {{"person_id", {-1}}, {"pose_keypoints_2d", Flat(25, 100, 0.8)},
                           {"face_keypoints_2d", nlohmann::json::array()}, {"hand_left_keypoints_2d", nlohmann::json::array()}};
  person["pose_keypoints_2d"][3 * 4 + 2] = 0;    // right wrist missing
  person["pose_keypoints_2d"][3 * 19 + 2] = 1.02;  // confidence above 1: clamped and counted
  WriteOpenPose(dir, "Camera0/shelf_000000000000_keypoints.json", {person});
  WriteOpenPose(dir, "Camera0/shelf_000000000001_keypoints.json", {});
  WriteOpenPose(dir, "Camera1/shelf_000000000000_keypoints.json", {person, person});
  WriteText(dir, "Camera1/notes.txt", "ignored");

  OpenPoseFolderOptions options;
  options.mapping.frame_id = "shelf_{2:6+300}";
  const Detections d = ReadOpenPoseFolder(dir.path(), options);
  ASSERT_EQ(d.joints.size(), 23u);  // auto: BODY_25 -> body + feet
  EXPECT_EQ(d.joints[17], "foot_big_toe_left");
  ASSERT_EQ(d.frames.size(), 2u);
  EXPECT_EQ(d.frames[0].frame_id, "shelf_000300");
  EXPECT_EQ(d.frames[0].cameras, (std::vector<std::string>{"Camera0", "Camera1"}));
  EXPECT_EQ(d.frames[1].cameras, (std::vector<std::string>{"Camera0"}));
  EXPECT_EQ(d.frames[1].views[0].num_persons(), 0);
  EXPECT_EQ(d.frames[0].views[1].num_persons(), 2);
  const auto p = d.frames[0].views[0].Person(0);
  const auto at = [&](const std::string& name) { return p.col(FindJoint(d.joints, name)); };
  EXPECT_DOUBLE_EQ(at("nose")(0), 100);                // BODY_25 0
  EXPECT_DOUBLE_EQ(at("eye_right")(0), 115);           // 15
  EXPECT_DOUBLE_EQ(at("eye_left")(0), 116);            // 16
  EXPECT_DOUBLE_EQ(at("ear_right")(1), 217);           // 17
  EXPECT_DOUBLE_EQ(at("ear_left")(1), 218);            // 18
  EXPECT_DOUBLE_EQ(at("shoulder_right")(0), 102);      // 2
  EXPECT_DOUBLE_EQ(at("shoulder_left")(0), 105);       // 5
  EXPECT_DOUBLE_EQ(at("hip_right")(0), 109);           // 9 (8 = mid-hip dropped)
  EXPECT_DOUBLE_EQ(at("ankle_left")(0), 114);          // 14
  EXPECT_DOUBLE_EQ(at("foot_heel_right")(0), 124);     // 24
  EXPECT_DOUBLE_EQ(at("wrist_right")(2), 0.0);
  EXPECT_DOUBLE_EQ(at("foot_big_toe_left")(2), 1.0);
  // notes.txt does not match the pattern: ignored and counted; 3 scores clamped (3 persons in 2 files);
  // Camera1 has no file for frame 1, which Camera0 has (OpenPose writes one for every frame).
  ASSERT_EQ(d.warnings.items().size(), 3u);
  EXPECT_EQ(d.warnings.items()[0].Line(), dir.path().string() + ": 1 files not matching the pattern '" +
                                              OpenPoseFolderOptions{}.mapping.pattern +
                                              "' ignored (e.g. 'Camera1/notes.txt')");
  EXPECT_EQ(d.warnings.items()[1].what, test::kScoresClamped);
  EXPECT_EQ(d.warnings.items()[1].count, 3);
  EXPECT_EQ(d.warnings.items()[2].Line(), dir.path().string() +
                                              ": 1 frames without a file of camera 'Camera1' (other cameras have "
                                              "one; no data from it there: it neither supports nor contradicts a "
                                              "person)");
  EXPECT_EQ(d.warnings.items()[2].kind, InputWarningKind::kMissing);
  EXPECT_TRUE(d.unlisted_cameras_unavailable);

  options.joints = OpenPoseJointSet::kBody;
  EXPECT_EQ(ReadOpenPoseFolder(dir.path(), options).joints, CocoBodyJoints());
}

// A camera folder that is a link (cameras gathered from several disks) is read; a file entry that
// is not a regular file (a FIFO would block the read) is skipped and counted, never opened; a link
// loop ends.
TEST(OpenPose, LinkedCameraFoldersAreReadAndOtherEntriesCounted) {
  test::TempDir dir, elsewhere;
  const nlohmann::json person = {{"pose_keypoints_2d", Flat(18, 10, 0.5)}};
  WriteOpenPose(dir, "c0/vid_000000000001_keypoints.json", {person});
  WriteOpenPose(elsewhere, "c1/vid_000000000001_keypoints.json", {person, person});
  std::filesystem::create_directory_symlink(elsewhere.path() / "c1", dir.path() / "c1");
  std::filesystem::create_directory_symlink(dir.path(), dir.path() / "c0" / "loop");
  ASSERT_EQ(mkfifo((dir.path() / "c0" / "vid_000000000002_keypoints.json").c_str(), 0600), 0);
  const Detections d = ReadOpenPoseFolder(dir.path());
  ASSERT_EQ(d.frames.size(), 1u);
  EXPECT_EQ(d.frames[0].cameras, (std::vector<std::string>{"c0", "c1"}));
  EXPECT_EQ(d.frames[0].views[1].num_persons(), 2);
  const auto said = [&](const std::string& line) {
    return std::any_of(d.warnings.items().begin(), d.warnings.items().end(),
                       [&](const InputWarning& item) { return item.Line() == line; });
  };
  EXPECT_TRUE(said(dir.path().string() +
                   ": 1 entries that are not regular files (FIFOs, devices, dangling links) skipped "
                   "(e.g. 'c0/vid_000000000002_keypoints.json')"))
      << "the FIFO is not said";
  EXPECT_TRUE(said(dir.path().string() +
                   ": 1 folders reached a second time through a link (a loop, or two links to one folder) "
                   "not read again (e.g. 'c0/loop')"))
      << "the link loop is not said";
}

TEST(OpenPose, Coco18FolderGivesCoco17) {
  test::TempDir dir;
  WriteOpenPose(dir, "c0/vid_000000000042_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
  const Detections d = ReadOpenPoseFolder(dir.path());
  EXPECT_EQ(d.joints, CocoBodyJoints());
  ASSERT_EQ(d.frames.size(), 1u);
  EXPECT_EQ(d.frames[0].frame_id, "000042");
  const auto p = d.frames[0].views[0].Person(0);
  EXPECT_DOUBLE_EQ(p(0, FindJoint(d.joints, "hip_right")), 18);   // COCO-18 8
  EXPECT_DOUBLE_EQ(p(0, FindJoint(d.joints, "eye_right")), 24);   // 14
  EXPECT_DOUBLE_EQ(p(0, FindJoint(d.joints, "ear_left")), 27);    // 17
}

TEST(OpenPose, WholeBodyFaceAndHands) {
  test::TempDir dir;
  nlohmann::json person = {{"pose_keypoints_2d", Flat(25, 100, 0.9)},
                           {"face_keypoints_2d", Flat(70, 300, 0.7)},
                           {"hand_left_keypoints_2d", Flat(21, 500, 0.6)},
                           {"hand_right_keypoints_2d", Flat(21, 600, 0.4)}};
  WriteOpenPose(dir, "cam/a_000000000003_keypoints.json", {person});
  // A COCO-18 person in another view: feet stay missing.
  WriteOpenPose(dir, "cam2/a_000000000003_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
  const Detections d = ReadOpenPoseFolder(dir.path());
  EXPECT_EQ(d.joints, CocoWholeBodyJoints());
  const auto p = d.frames[0].views[0].Person(0);
  const auto at = [&](const std::string& name) { return p.col(FindJoint(d.joints, name)); };
  EXPECT_DOUBLE_EQ(at("face_00")(0), 300);
  EXPECT_DOUBLE_EQ(at("face_67")(0), 367);
  EXPECT_DOUBLE_EQ(at("hand_root_left")(0), 500);
  EXPECT_DOUBLE_EQ(at("hand_thumb_4_left")(0), 504);
  EXPECT_DOUBLE_EQ(at("hand_index_1_left")(0), 505);
  EXPECT_DOUBLE_EQ(at("hand_pinky_4_right")(0), 620);
  EXPECT_DOUBLE_EQ(at("hand_pinky_4_right")(2), 0.4);
  const auto q = d.frames[0].views[1].Person(0);
  EXPECT_DOUBLE_EQ(q(2, FindJoint(d.joints, "foot_heel_left")), 0.0);
  EXPECT_DOUBLE_EQ(q(2, FindJoint(d.joints, "face_10")), 0.0);
  EXPECT_DOUBLE_EQ(q(0, FindJoint(d.joints, "ankle_left")), 23);  // COCO-18 13
  // One person of two has face and hands: auto chose whole-body for both, and says so.
  ASSERT_EQ(d.warnings.items().size(), 1u);
  EXPECT_EQ(d.warnings.items()[0].Line(),
            dir.path().string() + ": 1 persons without face or hand points, while 1 others have them: "
            "--openpose-joints auto read every person as 133 COCO-WholeBody joints, theirs missing "
            "(--openpose-joints body-feet reads the body only)");
  OpenPoseFolderOptions whole_body;
  whole_body.joints = OpenPoseJointSet::kWholeBody;
  EXPECT_TRUE(ReadOpenPoseFolder(dir.path(), whole_body).warnings.empty()) << "asked for: nothing to say";
}

TEST(OpenPose, CustomMappingAndErrors) {
  test::TempDir dir;
  // Flat layout: <camera>_<frame>_keypoints.json in one folder.
  WriteOpenPose(dir, "cam1_000000000005_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
  WriteOpenPose(dir, "cam2_000000000005_keypoints.json", {});
  OpenPoseFolderOptions options;
  options.mapping = {R"(([a-z0-9]+)_(\d+)_keypoints\.json)", "seq_{2:4}", "{1}"};
  const Detections d = ReadOpenPoseFolder(dir.path(), options);
  ASSERT_EQ(d.frames.size(), 1u);
  EXPECT_EQ(d.frames[0].frame_id, "seq_0005");
  EXPECT_EQ(d.frames[0].cameras, (std::vector<std::string>{"cam1", "cam2"}));

  options.mapping.camera = "same";
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(dir.path(), options); }), HasSubstr("both map to frame 'seq_0005', camera 'same'"));
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(dir.path()); }), HasSubstr("no file matches the pattern"));
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(dir.path() / "nope"); }), HasSubstr("nope: folder not found"));

  test::TempDir bad;
  WriteOpenPose(bad, "c/x_000000000001_keypoints.json", {{{"pose_keypoints_2d", Flat(15, 1, 1)}}});
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(bad.path()); }),
              HasSubstr("x_000000000001_keypoints.json: /people/0/pose_keypoints_2d: 45 numbers, expected 75 or 54"));
  WriteText(bad, "c/x_000000000001_keypoints.json", "{\"people\": [");
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(bad.path()); }), ContainsRegex("keypoints\\.json:1:[0-9]+: JSON parse error"));
}

TEST(OpenPose, ConfidencesSlightlyAboveOneAreCountedOncePerFolder) {
  test::TempDir dir;
  nlohmann::json person = {{"pose_keypoints_2d", Flat(18, 10, 0.5)}};
  person["pose_keypoints_2d"][3 * 0 + 2] = 1.008;   // nose
  person["pose_keypoints_2d"][3 * 14 + 2] = 1.018;  // right eye
  nlohmann::json hands = {{"pose_keypoints_2d", Flat(18, 10, 0.5)}, {"hand_left_keypoints_2d", Flat(21, 50, 1.008)}};
  WriteOpenPose(dir, "c0/v_000000000001_keypoints.json", {person});
  WriteOpenPose(dir, "c1/v_000000000001_keypoints.json", {person, hands});
  OpenPoseFolderOptions whole_body;  // asked for (auto would also say that two persons have no hands)
  whole_body.joints = OpenPoseJointSet::kWholeBody;
  const Detections d = ReadOpenPoseFolder(dir.path(), whole_body);
  for (const Poses2D& view : d.frames[0].views) {
    for (size_t i = 2; i < view.data.size(); i += 3) EXPECT_LE(view.data[i], 1.0);
    EXPECT_EQ(view.Person(0)(2, FindJoint(d.joints, "nose")), 1.0);
    EXPECT_EQ(view.Person(0)(2, FindJoint(d.joints, "eye_right")), 1.0);
  }
  EXPECT_EQ(d.frames[0].views[1].Person(1)(2, FindJoint(d.joints, "hand_root_left")), 1.0);
  // One line for the folder, not one per file: 2 + 2 + 21 values above 1.
  test::ExpectOneWarning(d.warnings, dir.path().string(), test::kScoresClamped, 25);
}

TEST(OpenPose, NegativeOrLargeConfidencesNameFileAndPointer) {
  for (const double score : {1.6, -0.1}) {
    test::TempDir dir;
    nlohmann::json person = {{"pose_keypoints_2d", Flat(18, 10, 0.5)}};
    person["pose_keypoints_2d"][3 * 5 + 2] = score;
    WriteOpenPose(dir, "c0/v_000000000001_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
    WriteOpenPose(dir, "c1/v_000000000001_keypoints.json", {person});
    EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(dir.path()); }),
                HasSubstr((dir.path() / "c1" / "v_000000000001_keypoints.json").string() +
                          ": /people/0/pose_keypoints_2d/17 (point 5): score " + (score > 0 ? "1.6" : "-0.1") +
                          " outside [0, 1]"));
  }
  test::TempDir dir;
  WriteText(dir, "c0/v_000000000001_keypoints.json", R"({"people": [{"pose_keypoints_2d": [1, 2, NaN]}]})");
  EXPECT_THAT(InputErrorOf([&] { ReadOpenPoseFolder(dir.path()); }), ContainsRegex("keypoints\\.json:1:[0-9]+: JSON parse error"));
}

// ---------------------------------------------------------------------------------------------
// COCO result lists

nlohmann::json CocoResult(std::int64_t image_id, double base, double score = 0.9) {
  return {{"image_id", image_id}, {"category_id", 1}, {"score", score}, {"keypoints", Flat(17, base, 0.75)}};
}

TEST(Coco, AnnotationImagesMapFramesAndCameras) {
  test::TempDir dir;
  const auto annotations = WriteText(dir, "ann.json", nlohmann::json{{"images", {
      {{"id", 1}, {"file_name", "images/cam_left/img_0017.jpg"}},
      {{"id", 2}, {"file_name", "images/cam_right/img_0017.jpg"}},
      {{"id", 3}, {"file_name", "images/cam_left/img_0018.jpg"}},
      {{"id", 4}, {"file_name", "whatever.png"}, {"frame_id", "custom_18"}, {"camera", "cam_top"}}}}}.dump());
  const auto results = WriteText(dir, "results.json",
                                 nlohmann::json::array({CocoResult(2, 10), CocoResult(1, 20), CocoResult(1, 30, 0.1), CocoResult(4, 40)}).dump());
  CocoDetectionsOptions options;
  options.mapping = CocoImageMapping::kAnnotationImages;
  options.annotation_file = annotations;
  options.file_name_mapping.frame_id = "lab_{2:6}";
  const Detections d = ReadCocoDetections(results, options);
  EXPECT_EQ(d.joints, CocoBodyJoints());
  ASSERT_EQ(d.frames.size(), 3u);
  EXPECT_EQ(d.frames[0].frame_id, "custom_18");
  EXPECT_EQ(d.frames[1].frame_id, "lab_000017");
  EXPECT_EQ(d.frames[2].frame_id, "lab_000018");
  EXPECT_EQ(d.frames[1].cameras, (std::vector<std::string>{"cam_left", "cam_right"}));
  EXPECT_EQ(d.frames[1].views[0].num_persons(), 2);
  EXPECT_DOUBLE_EQ(d.frames[1].views[0].Person(0)(0, 0), 20);
  EXPECT_DOUBLE_EQ(d.frames[1].views[0].Person(1)(1, 16), 76);
  EXPECT_EQ(d.frames[2].views[0].num_persons(), 0);  // listed image without detections

  options.min_score = 0.5;
  EXPECT_EQ(ReadCocoDetections(results, options).frames[1].views[0].num_persons(), 1);
}

TEST(Coco, MalformedListsNameFileAndPointer) {
  test::TempDir dir;
  auto results = [&](const nlohmann::json& list) { return WriteText(dir, "r.json", list.dump()); };
  nlohmann::json short_result = CocoResult(10010000001, 1);
  short_result["keypoints"] = Flat(16, 1, 1);
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({CocoResult(10010000001, 1), short_result}))); }),
              HasSubstr("r.json: /1/keypoints: 48 numbers, expected 51"));
  nlohmann::json whole = CocoResult(10010000002, 1);
  whole["keypoints"] = Flat(133, 1, 1);
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({CocoResult(10010000001, 1), whole}))); }),
              HasSubstr("/1/keypoints: 133 joints, but /0/keypoints has 17"));
  EXPECT_EQ(ReadCocoDetections(results(nlohmann::json::array({whole}))).joints, CocoWholeBodyJoints());
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({CocoResult(17, 1)}))); }),
              HasSubstr("/0/image_id: image id 17 is not an MVOR multi-view id"));
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({{{"image_id", "x"}}}))); }),
              HasSubstr("/0/image_id: image id \"x\" is a name, not a number"));
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({{{"image_id", 2.5}}}))); }),
              HasSubstr("/0/image_id: expected an integer image id"));
  const auto annotations = WriteText(dir, "ann.json", R"({"images": [{"id": 1, "file_name": "flat.jpg"}]})");
  CocoDetectionsOptions options;
  options.mapping = CocoImageMapping::kAnnotationImages;
  options.annotation_file = annotations;
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array({CocoResult(1, 1)})), options); }),
              HasSubstr("ann.json: /images/0/file_name: 'flat.jpg' does not match the pattern"));
  options.annotation_file.clear();
  EXPECT_THAT(test::ConfigErrorOf([&] { ReadCocoDetections(results(nlohmann::json::array()), options); }), HasSubstr("needs an annotation file"));
}

TEST(Coco, ScoresSlightlyAboveOneAreClampedAndCounted) {
  test::TempDir dir;
  nlohmann::json first = CocoResult(10010000001, 1), second = CocoResult(10020000001, 5);
  first["keypoints"][2] = 1.008;
  second["keypoints"][3 * 16 + 2] = 1.018;
  const auto path = WriteText(dir, "r.json", nlohmann::json::array({first, second}).dump());
  const Detections d = ReadCocoDetections(path);
  ASSERT_EQ(d.frames.size(), 1u);
  EXPECT_EQ(d.frames[0].views[0].Person(0)(2, 0), 1.0);
  EXPECT_EQ(d.frames[0].views[1].Person(0)(2, 16), 1.0);
  EXPECT_EQ(d.frames[0].views[1].Person(0)(2, 15), 0.75);
  test::ExpectOneWarning(d.warnings, path.string(), test::kScoresClamped, 2);
}

TEST(Coco, NegativeLargeOrNanScoresNameFileAndPointer) {
  test::TempDir dir;
  for (const double score : {1.6, -0.1}) {
    nlohmann::json bad = CocoResult(10010000002, 1);
    bad["keypoints"][3 * 4 + 2] = score;
    const auto path = WriteText(dir, "r.json", nlohmann::json::array({CocoResult(10010000001, 1), bad}).dump());
    EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(path); }),
                HasSubstr(path.string() + ": /1/keypoints/14 (joint 4): score " + (score > 0 ? "1.6" : "-0.1") +
                          " outside [0, 1]"));
  }
  std::string text = nlohmann::json::array({CocoResult(10010000001, 1)}).dump();
  text.replace(text.find("0.75"), 4, "NaN");
  const auto nan = WriteText(dir, "nan.json", text);
  EXPECT_THAT(InputErrorOf([&] { ReadCocoDetections(nan); }), ContainsRegex("nan\\.json:1:[0-9]+: JSON parse error"));
}

TEST(Coco, MvorOpenPoseFixtureClampsAndCountsEveryScoreAboveOne) {
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  const auto path = test::SharedData("mvor/openpose_kps.json");
  // Count the values above 1 independently: the same arrays the reader uses (coco_keypoints when
  // present, else keypoints), every third number.
  const nlohmann::json results = nlohmann::json::parse(std::ifstream(path));
  long above = 0;
  double largest = 0;
  for (const nlohmann::json& item : results) {
    const nlohmann::json& keypoints = item.contains("coco_keypoints") ? item["coco_keypoints"] : item["keypoints"];
    for (size_t k = 2; k < keypoints.size(); k += 3) {
      const double score = keypoints[k].get<double>();
      if (score > 1) ++above, largest = std::max(largest, score);
    }
  }
  ASSERT_GT(above, 0) << "the MVOR OpenPose output has confidences above 1";

  const Detections d = ReadCocoDetections(path);
  for (const FrameDetections& frame : d.frames) {
    for (const Poses2D& view : frame.views) {
      for (size_t i = 2; i < view.data.size(); i += 3) ASSERT_LE(view.data[i], 1.0);
    }
  }
  test::ExpectOneWarning(d.warnings, path.string(), test::kScoresClamped, above);
  EXPECT_DOUBLE_EQ(d.warnings.items()[0].worst, largest);
}

TEST(Coco, MvorOpenPoseFixtureUsesCocoKeypoints) {
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  const auto path = test::SharedData("mvor/openpose_kps.json");
  const Detections d = ReadCocoDetections(path);
  EXPECT_EQ(d.joints, CocoBodyJoints());
  size_t views = 0, persons = 0;
  for (const FrameDetections& frame : d.frames) {
    views += frame.views.size();
    for (const Poses2D& view : frame.views) persons += view.num_persons();
  }
  EXPECT_EQ(persons, 4091u);
  EXPECT_EQ(views, 2005u);
  EXPECT_EQ(d.frames.size(), 726u);
  // Image 10010000001 = day 1, cam 1, frame 1: one detection; COCO joint 0 (nose) comes from
  // coco_keypoints (the 10-joint MVOR "keypoints" has the head there).
  const auto frame = std::find_if(d.frames.begin(), d.frames.end(), [](const FrameDetections& f) { return f.frame_id == "mvor_day1_000001"; });
  ASSERT_NE(frame, d.frames.end());
  const auto cam = std::find(frame->cameras.begin(), frame->cameras.end(), "cam1") - frame->cameras.begin();
  ASSERT_LT(cam, static_cast<long>(frame->cameras.size()));
  const Poses2D& view = frame->views[cam];
  ASSERT_EQ(view.num_persons(), 1);
  EXPECT_DOUBLE_EQ(view.Person(0)(0, 0), 3.72591);
  EXPECT_DOUBLE_EQ(view.Person(0)(1, 0), 338.525);
  EXPECT_DOUBLE_EQ(view.Person(0)(0, 1), 3.72129);  // left eye: only in coco_keypoints
  EXPECT_DOUBLE_EQ(view.Person(0)(2, 2), 0.0);      // right eye missing
}

TEST(Coco, MvorAnnotationImagesGiveTheSameFramesAsTheIdConvention) {
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const auto results = test::SharedData("mvor/openpose_kps.json");
  CocoDetectionsOptions options;
  options.annotation_file = test::SharedData("mvor/camma_mvor_2018.json");
  const Detections by_id = ReadCocoDetections(results, options);  // MVOR ids, all 2196 images listed
  size_t views = 0;
  for (const FrameDetections& frame : by_id.frames) views += frame.views.size();
  EXPECT_EQ(by_id.frames.size(), 732u);
  EXPECT_EQ(views, 2196u);

  options.mapping = CocoImageMapping::kAnnotationImages;
  options.file_name_mapping = {R"(day(\d+)/cam(\d+)/color/(\d+)\.png)", "mvor_day{1}_{3:6}", "cam{2}"};
  const Detections by_name = ReadCocoDetections(results, options);
  test::ExpectDetectionsNear(by_id, by_name, 0);
}

// ---------------------------------------------------------------------------------------------
// ReadDetectionsFile

TEST(Coco, SkippedResultsAreCountedAsUnusedInput) {
  test::TempDir dir;
  nlohmann::json chair = CocoResult(10010000001, 3), text_category = CocoResult(10010000001, 4);
  chair["category_id"] = 62;
  text_category["category_id"] = "62";
  nlohmann::json string_person = CocoResult(10010000002, 5), box_only = CocoResult(10010000002, 6);
  string_person["category_id"] = "1";  // MVOR's openpose_kps.json writes the category as a string
  box_only["keypoints"] = nlohmann::json::array();
  nlohmann::json no_score = CocoResult(10020000001, 7);
  no_score["score"] = "high";
  const auto path = WriteText(
      dir, "r.json",
      nlohmann::json::array({CocoResult(10010000001, 1), chair, text_category, string_person, box_only, no_score})
          .dump());
  // Before: the chairs became persons, the box-only result vanished silently.
  const Detections d = ReadCocoDetections(path);
  // mvor_day1_000001: cam1 (the person, not the chairs), cam2 (score "high": unused without
  // min_score); mvor_day1_000002: cam1 (category "1"; the box-only result skipped).
  ASSERT_EQ(d.frames.size(), 2u);
  ASSERT_EQ(d.frames[0].cameras, (std::vector<std::string>{"cam1", "cam2"}));
  EXPECT_EQ(d.frames[0].views[0].num_persons(), 1);
  EXPECT_EQ(d.frames[0].views[1].num_persons(), 1);
  ASSERT_EQ(d.frames[1].cameras, (std::vector<std::string>{"cam1"}));
  EXPECT_EQ(d.frames[1].views[0].num_persons(), 1);
  std::vector<std::string> lines;
  for (const InputWarning& w : d.warnings.items()) {
    EXPECT_EQ(w.kind, InputWarningKind::kUnused) << w.Line();
    lines.push_back(w.Line());
  }
  EXPECT_EQ(lines, (std::vector<std::string>{
                       path.string() + ": 2 results of another category than person (category_id 1) skipped",
                       path.string() + ": 1 results without keypoints (box only) skipped"}));

  // With min_score a score that is not a number cannot be compared: skipped and counted.
  CocoDetectionsOptions options;
  options.min_score = 0.5;
  const Detections filtered = ReadCocoDetections(path, options);
  EXPECT_EQ(filtered.frames[0].cameras, (std::vector<std::string>{"cam1"}));
  ASSERT_EQ(filtered.warnings.items().size(), 3u);
  EXPECT_EQ(filtered.warnings.items()[2].Line(),
            path.string() + ": 1 results with a non-numeric \"score\" skipped (min_score needs a number)");
}

TEST(OpenPose, FilesNotMatchingThePatternAreCountedOnceForTheFolder) {
  test::TempDir dir;
  WriteOpenPose(dir, "cam0/v_000000000001_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
  // A camera whose files are named differently: before, the whole camera vanished silently.
  WriteOpenPose(dir, "cam1/v_000000000001.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});
  WriteOpenPose(dir, "cam1/v_000000000002.json", {});
  WriteText(dir, "README.txt", "notes");
  const Detections d = ReadOpenPoseFolder(dir.path());
  ASSERT_EQ(d.frames.size(), 1u);
  EXPECT_EQ(d.frames[0].cameras, (std::vector<std::string>{"cam0"}));
  test::ExpectOneWarning(
      d.warnings, dir.path().string(),
      "files not matching the pattern '" + OpenPoseFolderOptions{}.mapping.pattern + "' ignored (e.g. 'README.txt')",
      3);
  EXPECT_EQ(d.warnings.items()[0].kind, InputWarningKind::kUnused);
}

TEST(DetectionsFile, DispatchesOnFolderExtensionAndContent) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(3, {"c0", "c1"}, CocoBodyJoints(), "mvor_day1_");
  WriteGenericDetections(dir.path() / "generic.json", detections);
  WriteDetectionsHdf5(dir.path() / "cache.H5", detections, {.add_to_existing = false, .float64 = true});
  WriteText(dir, "coco.json", "  \n" + nlohmann::json::array({CocoResult(10020000001, 5)}).dump());
  WriteOpenPose(dir, "openpose/c0/v_000000000001_keypoints.json", {{{"pose_keypoints_2d", Flat(18, 10, 0.5)}}});

  test::ExpectDetectionsNear(detections, ReadDetectionsFile(dir.path() / "generic.json"), 0);
  test::ExpectDetectionsNear(detections, ReadDetectionsFile(dir.path() / "cache.H5"), 0);
  const Detections coco = ReadDetectionsFile(dir.path() / "coco.json");
  ASSERT_EQ(coco.frames.size(), 1u);
  EXPECT_EQ(coco.frames[0].frame_id, "mvor_day1_000001");
  EXPECT_EQ(coco.frames[0].cameras[0], "cam2");
  DetectionsFileOptions options;
  options.openpose.mapping.frame_id = "f{2:3}";
  EXPECT_EQ(ReadDetectionsFile(dir.path() / "openpose", options).frames[0].frame_id, "f001");

  // A VoxelPose cache is read as one (readers_voxelpose_test.cc), given its sequence's frame-id prefix.
  WriteText(dir, "voxelpose.pkl", "x");
  EXPECT_THAT(test::ErrorMessage<ConfigError>([&] { ReadDetectionsFile(dir.path() / "voxelpose.pkl"); }),
              HasSubstr("voxelpose.pkl: a VoxelPose cache is keyed"));
  DetectionsFileOptions voxelpose;
  voxelpose.voxelpose.frame_id_prefix = "shelf";
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsFile(dir.path() / "voxelpose.pkl", voxelpose); }),
              HasSubstr("voxelpose.pkl"));
  WriteText(dir, "d.csv", "x");
  const std::string unknown = InputErrorOf([&] { ReadDetectionsFile(dir.path() / "d.csv"); });
  EXPECT_THAT(unknown, HasSubstr("d.csv: unknown detection format '.csv'"));
  EXPECT_THAT(unknown, HasSubstr(".h5 / .hdf5"));
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsFile(dir.path() / "absent.json"); }), HasSubstr("absent.json: file not found"));
  WriteText(dir, "number.json", "42");
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsFile(dir.path() / "number.json"); }), HasSubstr("number.json:1:1: expected a JSON object"));
  WriteText(dir, "fake.h5", "{\"joints\": []}");
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsFile(dir.path() / "fake.h5"); }), HasSubstr("fake.h5: byte 0: not an HDF5 file"));
}

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// The 4D-Association Shelf reader: the real bundle in shared/data/shelf/4d_association (skipped
// when absent; never copied into the project) and small files of the same grammar written by the
// tests (hand-made numbers, nothing derived from the bundle).
// Over 500 lines on purpose: one file for the one reader, its real-data checks beside the
// small-file cases they explain.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/joints.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/fourda_text.h"
#include "datasets/readers/openpose_body25.h"
#include "datasets/readers/shelf_4da.h"
#include "datasets/readers/shelf_campus.h"
#include "datasets/readers/voxelpose_calibration.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt {
using engine::ReadDataset;
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

constexpr const char* kBundle = "shelf/4d_association";

DatasetRequest Request(const fs::path& root, std::map<std::string, std::string> params = {}) {
  DatasetRequest request;
  request.dataset = "shelf-4da";
  request.root = root;
  request.params = std::move(params);
  return request;
}

const InputWarning* FindWarning(const InputWarnings& warnings, const std::string& file, const std::string& what) {
  for (const InputWarning& w : warnings.items()) {
    if (w.what == what && w.source.size() >= file.size() && w.source.ends_with(file)) return &w;
  }
  return nullptr;
}

// ---------------------------------------------------------------------------------------
// Writers for the 4D-Association grammar (fourda_text.h), used for hand-made fixtures.

std::string Rows(const Eigen::MatrixXd& m) {
  std::ostringstream s;
  s.precision(10);
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c) s << (c ? " " : "") << m(r, c);
    if (m.cols() > 0) s << "\n";
  }
  return s.str();
}

std::string DetectionText(const std::vector<PafCandidates>& frames, int skel_type = kFourDaBody25) {
  std::ostringstream s;
  s << skel_type << " " << frames.size() << "\n";
  for (const PafCandidates& frame : frames) {
    for (const Eigen::Matrix3Xd& joint : frame.joints) s << joint.cols() << "\n" << Rows(joint);
    for (const Eigen::MatrixXd& paf : frame.pafs) s << Rows(paf);
  }
  return s.str();
}

struct GtPerson {
  int identity = 0;
  Eigen::Matrix4Xd joints;
};

std::string GtText(const std::vector<std::vector<GtPerson>>& frames, int num_joints = 15) {
  std::ostringstream s;
  s << num_joints << " " << frames.size() << "\n";
  for (const auto& frame : frames) {
    s << frame.size() << "\n";
    for (const GtPerson& p : frame) s << p.identity << "\n" << Rows(p.joints);
  }
  return s.str();
}

// A standing person at (x, y): SHELF15 joints from the ankles (z = 0.05) to the head top
// (z = 1.75), pelvis = mean of the hips, validity 1.
Eigen::Matrix4Xd StandingPerson(double x, double y) {
  const double z[15] = {0.05, 0.5, 0.9, 0.9, 0.5, 0.05, 1.0, 1.2, 1.45, 1.45, 1.2, 1.0, 1.55, 1.75, 0.9};
  const double dx[15] = {-0.1, -0.1, -0.1, 0.1, 0.1, 0.1, -0.3, -0.25, -0.2, 0.2, 0.25, 0.3, 0.0, 0.0, 0.0};
  Eigen::Matrix4Xd m(4, 15);
  for (int j = 0; j < 15; ++j) m.col(j) << x + dx[j], y, z[j], 1.0;
  return m;
}

// One BODY_25 frame with two persons A (candidate 0) and B (candidate 1) on nose, neck,
// shoulder_right, elbow_right, hip_middle and hip_right; the five limbs between them carry PAF
// matrices [[0.9, 0.3], [0.2, 0.8]], so the greedy association can only pair 0-0 and 1-1.
PafCandidates TwoPersonFrame() {
  const PafSkeleton& skeleton = Body25PafSkeleton();
  const std::vector<int> used = {0, 1, 2, 3, 8, 9};
  PafCandidates c;
  for (int j = 0; j < kBody25Joints; ++j) {
    const bool on = std::find(used.begin(), used.end(), j) != used.end();
    Eigen::Matrix3Xd m(3, on ? 2 : 0);
    if (on) {
      m.col(0) << 0.2 + 0.01 * j, 0.1 + 0.02 * j, 0.8;
      m.col(1) << 0.7 + 0.01 * j, 0.15 + 0.02 * j, 0.6;
    }
    c.joints.push_back(m);
  }
  for (const auto& [a, b] : skeleton.limbs) {
    Eigen::MatrixXd paf = Eigen::MatrixXd::Zero(c.joints[a].cols(), c.joints[b].cols());
    if (paf.size() == 4) paf << 0.9, 0.3, 0.2, 0.8;
    c.pafs.push_back(paf);
  }
  return c;
}

// A camera at (0, -5, 1) looking along +y (z up), 1001x801 so that pixels = 1000 x, 800 y.
std::string CalibrationJson(const std::string& extra_extrinsics = "") {
  const std::string extrinsics = extra_extrinsics.empty()
                                     ? R"("RT": [1, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5])"
                                     : extra_extrinsics;
  return R"({"0": {"K": [1000, 0, 500, 0, 1000, 400, 0, 0, 1], )" + extrinsics + R"(, "imgSize": [1001, 801]}})";
}

void WriteText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A complete root: one camera, two GT frames (identities 3 and 0, then nobody), two detection
// frames (the two-person frame, then nothing).
void WriteBundle(const fs::path& root) {
  WriteText(root / "calibration.json", CalibrationJson());
  WriteText(root / "gt.txt", GtText({{{3, StandingPerson(-0.5, 0.0)}, {0, StandingPerson(0.6, 0.2)}}, {}}));
  PafCandidates empty = TwoPersonFrame();
  for (Eigen::Matrix3Xd& j : empty.joints) j.resize(3, 0);
  for (Eigen::MatrixXd& p : empty.pafs) p.resize(0, 0);
  PafCandidates frame = TwoPersonFrame();
  frame.joints[0](2, 1) = 1.2;  // B's nose: slightly above 1, as real OpenPose output has
  WriteText(root / "detection" / "0.txt", DetectionText({frame, empty}));
}

// ---------------------------------------------------------------------------------------
// Written files

TEST(Shelf4daReader, HandMadeBundleAssemblesTheTwoPersons) {
  const test::TempDir dir;
  WriteBundle(dir.path());
  const std::vector<Sequence> sequences = ReadDataset(Request(dir.path()));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& s = sequences[0];
  EXPECT_EQ(s.name, "shelf-4da");
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].name, "0");
  EXPECT_EQ(s.cameras[0].width, 1001);
  EXPECT_TRUE(s.cameras[0].Center().isApprox(Eigen::Vector3d(0, -5, 1), 1e-12));
  EXPECT_EQ(s.gt_joints, Shelf4daJoints());
  EXPECT_EQ(s.detection_joints, CocoBodyJoints());
  EXPECT_DOUBLE_EQ(s.fps, 25.0);

  ASSERT_EQ(s.frames.size(), 2u);
  EXPECT_EQ(s.frames[0].id, "shelf4da_000000");
  EXPECT_EQ(s.frames[1].id, "shelf4da_000001");
  EXPECT_DOUBLE_EQ(s.frames[1].timestamp_s, 1.0 / 25.0);

  const Poses3D& gt = s.frames[0].gt;
  EXPECT_EQ(gt.track_ids, (std::vector<int>{3, 0}));
  const int hip_middle = FindJoint(s.gt_joints, "hip_middle");
  const int nose = FindJoint(s.gt_joints, "nose");
  EXPECT_TRUE(gt.Person(1).col(hip_middle).head<3>().isApprox(Eigen::Vector3d(0.6, 0.2, 0.9), 1e-12));
  EXPECT_NEAR(gt.Person(1)(2, nose), 0.5 * (1.55 + 1.75), 1e-12);
  EXPECT_EQ(s.frames[1].gt.num_persons(), 0);

  const Poses2D& view = s.frames[0].views[0];
  ASSERT_EQ(view.num_persons(), 2);
  // Person A (candidate 0) comes first: its 0.9 link is the strongest.
  const int shoulder = FindJoint(s.detection_joints, "shoulder_right");
  const int elbow = FindJoint(s.detection_joints, "elbow_right");
  const int hip = FindJoint(s.detection_joints, "hip_right");
  const int coco_nose = FindJoint(s.detection_joints, "nose");
  EXPECT_NEAR(view.Person(0)(0, shoulder), 1000 * 0.22, 1e-9);  // x = 0.2 + 0.01 * 2, times (width - 1)
  EXPECT_NEAR(view.Person(0)(1, shoulder), 800 * 0.14, 1e-9);
  EXPECT_NEAR(view.Person(1)(0, elbow), 1000 * 0.73, 1e-9);
  EXPECT_NEAR(view.Person(1)(0, hip), 1000 * 0.79, 1e-9);
  EXPECT_DOUBLE_EQ(view.Person(0)(2, hip), 0.8);
  EXPECT_DOUBLE_EQ(view.Person(1)(2, coco_nose), 1.0) << "1.2 clamped";
  for (int p = 0; p < 2; ++p) EXPECT_EQ((view.Person(p).row(2).array() > 0).count(), 4) << "nose, shoulder, elbow, hip";
  EXPECT_EQ(s.frames[1].views[0].num_persons(), 0);
  // The grouping is timed per frame (the step table's "paf_grouping (reader)").
  for (const SequenceFrame& frame : s.frames) EXPECT_GE(frame.paf_grouping_us, 0.0) << frame.id;

  const InputWarning* clamped = FindWarning(s.warnings, "0.txt", "scores above 1 clamped to 1");
  ASSERT_NE(clamped, nullptr);
  EXPECT_EQ(clamped->count, 1);
  EXPECT_NEAR(clamped->worst, 1.2, 1e-12);
}

TEST(Shelf4daReader, ParamsSelectFramesDetectionsNoseAndAssociation) {
  const test::TempDir dir;
  WriteBundle(dir.path());
  const Sequence one = ReadDataset(Request(dir.path(), {{"frames", "1"}, {"detections", "none"}}))[0];
  ASSERT_EQ(one.frames.size(), 1u);
  EXPECT_EQ(one.frames[0].id, "shelf4da_000001");
  EXPECT_TRUE(one.frames[0].views.empty());
  EXPECT_TRUE(one.detection_joints.empty());
  EXPECT_LT(one.frames[0].paf_grouping_us, 0.0) << "nothing grouped, no grouping time";

  const Sequence top = ReadDataset(Request(dir.path(), {{"nose_proxy", "top"}}))[0];
  EXPECT_NEAR(top.frames[0].gt.Person(0)(2, FindJoint(top.gt_joints, "nose")), 1.75, 1e-12);
  // Both persons have 6 BODY_25 joints.
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"min_joints", "7"}}))[0].frames[0].views[0].num_persons(), 0);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"min_paf_score", "0.95"}}))[0].frames[0].views[0].num_persons(), 0);

  EXPECT_THAT(test::InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"frames", "0-2"}}));
              }),
              HasSubstr("gt.txt: frame 2 requested but the file has 2 frames (0-1)"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"detections", "pkl"}}));
              }),
              HasSubstr("--param detections=pkl: shelf-4da.detections: 'pkl' is not one of openpose, none"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"min_joints", "1"}}));
              }),
              HasSubstr("is not an integer in [2, 25]"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"min_paf_score", "-1"}}));
              }),
              HasSubstr("is not a number >= 0"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"fps", "30"}}));
              }),
              HasSubstr("--param fps=30: unknown parameter 'fps' (shelf-4da has:"));
  // A detection file of a camera the calibration does not have is unused input, named (it was
  // left unread silently: a calibration missing a camera ran on the others).
  const std::string what = "detection files of cameras calibration.json does not have, not read (cameras '4')";
  fs::copy_file(dir.path() / "detection" / "0.txt", dir.path() / "detection" / "4.txt");
  const Sequence extra = ReadDataset(Request(dir.path(), {}))[0];
  EXPECT_EQ(FindWarning(top.warnings, "detection", what), nullptr);
  const InputWarning* unread = FindWarning(extra.warnings, "detection", what);
  ASSERT_NE(unread, nullptr);
  EXPECT_EQ(unread->Line(), (dir.path() / "detection").string() +
                                ": 1 detection files of cameras calibration.json does not have, not read (cameras '4')");
  EXPECT_EQ(unread->kind, InputWarningKind::kUnused);
}

TEST(Shelf4daReader, MalformedDetectionFilesNameFileLineAndToken) {
  const test::TempDir dir;
  const std::string valid = DetectionText({TwoPersonFrame()});
  InputWarnings warnings;
  const auto error = [&](const std::string& text) {
    WriteText(dir.path() / "0.txt", text);
    return test::InputErrorOf([&] { ReadFourDaDetections(dir.path() / "0.txt", &warnings); });
  };
  const auto replace_token = [](const std::string& text, int index, const std::string& with) {
    std::istringstream in(text);
    std::ostringstream out;
    std::string token;
    for (int i = 1; in >> token; ++i) out << (i == index ? with : token) << " ";
    return out.str();
  };
  WriteText(dir.path() / "ok.txt", valid);
  ASSERT_EQ(ReadFourDaDetections(dir.path() / "ok.txt", &warnings).frames.size(), 1u);

  // Line 2 holds joint 0's candidate count (token 3), lines 3-5 its x, y and score rows.
  EXPECT_THAT(error(valid.substr(0, valid.size() / 2)), HasSubstr("unexpected end of file after token"));
  EXPECT_THAT(error(valid.substr(0, valid.size() / 2)), HasSubstr("0.txt:"));
  std::string negative = valid;
  negative.replace(valid.find("\n2\n"), 3, "\n-1\n");
  EXPECT_THAT(error(negative),
              HasSubstr("0.txt:2: token 3: frame 0, joint 0 (nose): candidate count: '-1' is not an integer >= 0"));
  std::string word = valid;
  word.replace(valid.find("0.2 "), 3, "abc");
  EXPECT_THAT(error(word), HasSubstr("0.txt:3: token 4: frame 0, joint 0 (nose), candidate 0: x: 'abc' is not a finite number"));
  EXPECT_THAT(error(replace_token(valid, 4, "nan")), HasSubstr("token 4: frame 0, joint 0 (nose), candidate 0: x: 'nan'"));
  EXPECT_THAT(error(replace_token(valid, 8, "2.5")), HasSubstr("0.txt:1: token 8: score 2.5 outside [0, 1]"));
  EXPECT_THAT(error("2 1\n" + valid.substr(4)), HasSubstr("0.txt:1: token 1: header: skeleton type 2 is not supported"));
  EXPECT_THAT(error("4 x\n"), HasSubstr("0.txt:1: token 2: header: frame count: 'x' is not an integer >= 0"));
  EXPECT_THAT(error(""), HasSubstr("0.txt:1: unexpected end of file after token 0, expected header: skeleton type"));
  EXPECT_THAT(error("4 2\n" + valid.substr(4)), HasSubstr("expected frame 1, joint 0 (nose): candidate count"));
  EXPECT_THAT(error(valid + "0.5\n"), HasSubstr("0.txt:55: token 84: '0.5' after the end of the 1 frames the header announces"));
  // Counts larger than the rest of the file can hold fail at once instead of allocating.
  std::string zeros;
  for (int i = 0; i < 30; ++i) zeros += "0 ";
  EXPECT_THAT(error("4 1\n999999999 " + zeros),
              HasSubstr("0.txt:2: token 3: frame 0, joint 0 (nose): candidate count 999999999: needs 999999999 x 3 more "
                        "numbers, the rest of the file holds at most 31"));
  EXPECT_THAT(error("4 2000000000\n"), HasSubstr("header: frame count 2000000000: needs 2000000000 x 25 more numbers"));
  // Every truncation before the last number is an InputError, never a crash or a hang (a cut inside
  // the last number can leave a valid shorter number).
  const size_t last_number = valid.find_last_of(" \n", valid.find_last_not_of(" \n")) + 1;
  for (size_t length = 0; length <= last_number; ++length) {
    EXPECT_THROW(ParseFourDaDetections(valid.substr(0, length), "cut.txt", &warnings), InputError) << length;
  }
}

TEST(Shelf4daReader, MalformedGroundTruthAndCountMismatches) {
  const test::TempDir dir;
  WriteBundle(dir.path());
  const fs::path gt = dir.path() / "gt.txt";
  const auto error = [&] { return test::InputErrorOf([&] { ReadDataset(Request(dir.path())); }); };

  // A wrong joint count in the header shifts every matrix: caught by the first validity not in [0, 1].
  WriteText(gt, GtText({{{0, StandingPerson(0, 0)}}, {}}, 15).replace(0, 2, "14"));
  EXPECT_THAT(error(), HasSubstr("gt.txt:6: token 47: frame 0, person 0, joint 0: validity 1.550000 outside [0, 1]"));
  WriteText(gt, GtText({{{0, StandingPerson(0, 0).leftCols(14)}}, {}}, 14));
  EXPECT_THAT(error(), HasSubstr("gt.txt:1: header: 14 joints, expected 15 (SHELF15)"));
  WriteText(gt, GtText({{{0, StandingPerson(0, 0)}, {0, StandingPerson(1, 0)}}, {}}));
  EXPECT_THAT(error(), HasSubstr("gt.txt:8: token 65: frame 0, person 1: identity 0 appears twice in this frame"));
  WriteText(gt, GtText({{{-2, StandingPerson(0, 0)}}, {}}));
  EXPECT_THAT(error(), HasSubstr("gt.txt:3: frame 0, person 0: identity -2 is negative"));
  Eigen::Matrix4Xd invalid = StandingPerson(0, 0);
  invalid(3, 4) = 2.0;
  WriteText(gt, GtText({{{0, invalid}}, {}}));
  EXPECT_THAT(error(), HasSubstr("gt.txt:7: token 54: frame 0, person 0, joint 4: validity 2.000000 outside [0, 1]"));
  WriteText(gt, GtText({{{0, StandingPerson(0, 0)}}}));
  EXPECT_THAT(error(), HasSubstr("0.txt:1: header: 2 frames, "));
  EXPECT_THAT(error(), HasSubstr("gt.txt has 1"));
  fs::remove(gt);
  EXPECT_THAT(error(), HasSubstr("gt.txt: file not found"));
  // A FIFO in its place is refused, not read (the read would wait for a writer for ever).
  ASSERT_EQ(mkfifo(gt.c_str(), 0600), 0);
  EXPECT_THAT(error(), HasSubstr("gt.txt: not a regular file"));
  fs::remove(gt);
  WriteText(gt, GtText({{}, {}}));
  fs::remove(dir.path() / "detection" / "0.txt");
  EXPECT_THAT(error(), HasSubstr("0.txt: file not found"));
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"detections", "none"}}))[0].frames.size(), 2u);
}

TEST(Shelf4daReader, CalibrationVariantsAndErrors) {
  const test::TempDir dir;
  const fs::path path = dir.path() / "calibration.json";
  const auto read = [&](const std::string& extrinsics, InputWarnings* warnings = nullptr) {
    WriteText(path, CalibrationJson(extrinsics));
    return ReadFourDaCalibration(path, warnings);
  };
  const Camera reference = read("")[0];
  // R as a Rodrigues vector (+90 degrees about x) and T give the same camera.
  const Camera rodrigues = read(R"("R": [1.5707963267948966, 0, 0], "T": [0, 1, 5])")[0];
  EXPECT_TRUE(rodrigues.R.isApprox(reference.R, 1e-12));
  EXPECT_TRUE(rodrigues.t.isApprox(reference.t, 1e-12));
  const Camera matrix = read(R"("R": [1, 0, 0, 0, 0, -1, 0, 1, 0], "T": [0, 1, 5])")[0];
  EXPECT_TRUE(matrix.R.isApprox(reference.R, 1e-12));
  // RT wins over R, T (4D-Association's order).
  EXPECT_TRUE(read(R"("R": [0, 0, 0], "T": [9, 9, 9], "RT": [1, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5])")[0].t.isApprox(reference.t));
  EXPECT_NO_THROW(read(R"("RT": [1, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5], "distCoeff": [0, 0, 0, 0, 0], "rectifyAlpha": 1)"));

  // A rotation rounded to 6 digits is accepted, made orthonormal and counted.
  InputWarnings warnings;
  const Camera rounded = read(R"("RT": [0.707107, -0.707107, 0, 0,  0, 0, -1, 1,  0.707107, 0.707107, 0, 5])", &warnings)[0];
  EXPECT_LT((rounded.R.transpose() * rounded.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  const InputWarning* w = FindWarning(warnings, "calibration.json", "rotations re-orthonormalised");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->count, 1);

  const auto error = [&](const std::string& extrinsics) { return test::InputErrorOf([&] { read(extrinsics); }); };
  EXPECT_THAT(error(R"("RT": [2, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5])"),
              HasSubstr("calibration.json: /0/RT: R is not a rotation"));
  EXPECT_THAT(error(R"("RT": [1, 0, 0, 0,  0, 0, 1, 1,  0, 1, 0, 5])"), HasSubstr("/0/RT: R is a reflection"));
  EXPECT_THAT(error(R"("Q": 1)"), HasSubstr("/0: no extrinsics (expected \"RT\", or \"R\" and \"T\")"));
  EXPECT_THAT(error(R"("R": [1, 2], "T": [0, 0, 0])"), HasSubstr("/0/R: expected 3 numbers (Rodrigues vector) or 9"));
  EXPECT_THAT(error(R"("R": [0, 0, 0])"), HasSubstr("/0/T"));
  EXPECT_THAT(error(R"("RT": [1, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5], "distCoeff": [0.1, 0, 0, 0, 0])"),
              HasSubstr("/0/distCoeff: non-zero distortion is not supported"));
  WriteText(path, R"({"0": {"K": [1000, 0, 500, 0, 1000, 400, 0, 0, 1], "RT": [1, 0, 0, 0,  0, 0, -1, 1,  0, 1, 0, 5], "imgSize": [0, 801]}})");
  EXPECT_THAT(test::InputErrorOf([&] { ReadFourDaCalibration(path, nullptr); }),
              HasSubstr("/0/imgSize: image size 0.000000 is not a positive integer"));
}

// ---------------------------------------------------------------------------------------
// The real bundle (skipped when shared/data is absent)

TEST(Shelf4daFixture, HeaderFactsAndSequenceShape) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/gt.txt");
  const fs::path root = test::SharedData(kBundle);
  const FourDaSkeletons gt = ReadFourDaSkeletons(root / "gt.txt");
  EXPECT_EQ(gt.num_joints, 15);
  ASSERT_EQ(gt.frames.size(), 301u);
  // SHELF15 joint 14 is the pelvis = mean of the hips (joints 2, 3), to the file's 6 digits.
  double worst = 0;
  for (const auto& frame : gt.frames) {
    for (const FourDaPerson& p : frame) {
      worst = std::max(worst, (p.joints.col(14) - 0.5 * (p.joints.col(2) + p.joints.col(3))).head<3>().cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LT(worst, 1e-5);
  for (int c = 0; c < 5; ++c) {
    InputWarnings warnings;
    const FourDaDetections d = ReadFourDaDetections(root / "detection" / (std::to_string(c) + ".txt"), &warnings);
    EXPECT_EQ(d.skel_type, 4) << "BODY25";
    EXPECT_EQ(d.frames.size(), 301u);
  }

  const Sequence s = ReadDataset(Request(root))[0];
  ASSERT_EQ(s.frames.size(), 301u);
  EXPECT_EQ(s.frames.front().id, "shelf4da_000000");
  EXPECT_EQ(s.frames.back().id, "shelf4da_000300");
  EXPECT_DOUBLE_EQ(s.frames.back().timestamp_s, 300.0 / 25.0);
  ASSERT_EQ(s.cameras.size(), 5u);
  for (size_t c = 0; c < 5; ++c) {
    EXPECT_EQ(s.cameras[c].name, std::to_string(c));
    EXPECT_EQ(s.cameras[c].width, 1032);
    EXPECT_EQ(s.cameras[c].height, 776);
    EXPECT_EQ(s.frames[0].views[c].num_joints, 17);
  }
  for (const SequenceFrame& frame : s.frames) EXPECT_GT(frame.paf_grouping_us, 0.0) << frame.id;
  for (const std::string& joint : EvaluationJoints13()) EXPECT_GE(FindJoint(s.gt_joints, joint), 0) << joint;
  EXPECT_TRUE(s.room.center_m.isApprox(ShelfRoom().center_m));
  EXPECT_TRUE(s.room.size_m.isApprox(ShelfRoom().size_m));
}

TEST(Shelf4daFixture, GroundTruthPersonSetsPerFrame) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/gt.txt");
  const Sequence s = ReadDataset(Request(test::SharedData(kBundle), {{"detections", "none"}}))[0];
  std::map<std::string, int> frames_per_set;
  long persons = 0;
  for (const SequenceFrame& frame : s.frames) {
    std::vector<int> ids = frame.gt.track_ids;
    std::sort(ids.begin(), ids.end());
    std::string key;
    for (int id : ids) {
      if (!key.empty()) key += ',';
      key += std::to_string(id);
    }
    ++frames_per_set["(" + key + ")"];
    persons += frame.gt.num_persons();
  }
  const std::map<std::string, int> expected = {{"(0,2)", 133}, {"(0)", 92},    {"()", 22},   {"(0,1,2)", 18},
                                               {"(0,1,3)", 16}, {"(0,2,3)", 10}, {"(0,3)", 7}, {"(0,1)", 3}};
  EXPECT_EQ(frames_per_set, expected);
  EXPECT_EQ(persons, 510);
}

TEST(Shelf4daFixture, DetectionsAreTimeAlignedWithTheGroundTruth) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/gt.txt");
  const fs::path root = test::SharedData(kBundle);
  InputWarnings warnings;
  const FourDaDetections d = ReadFourDaDetections(root / "detection" / "0.txt", &warnings);
  const Eigen::Matrix3Xd& neck = d.frames[0].joints[1];  // BODY_25 joint 1
  ASSERT_EQ(neck.cols(), 2);
  std::vector<double> neck_x = {neck(0, 0) * 1031, neck(0, 1) * 1031};
  std::sort(neck_x.begin(), neck_x.end());
  EXPECT_NEAR(neck_x[0], 241.0, 1.0);
  EXPECT_NEAR(neck_x[1], 725.5, 1.0);

  const Sequence s = ReadDataset(Request(root, {{"frames", "0"}, {"detections", "none"}}))[0];
  const Poses3D& gt = s.frames[0].gt;
  ASSERT_EQ(gt.track_ids, (std::vector<int>{0, 2}));
  const int head_bottom = FindJoint(s.gt_joints, "head_bottom");
  Eigen::Vector2d uv0, uv2;
  ASSERT_TRUE(s.cameras[0].Project(gt.Person(0).col(head_bottom).head<3>(), &uv0));
  ASSERT_TRUE(s.cameras[0].Project(gt.Person(1).col(head_bottom).head<3>(), &uv2));
  EXPECT_NEAR(uv0.x(), 242.0, 1.0);
  EXPECT_NEAR(uv2.x(), 701.0, 1.0);
}

// The bundle's GT is a variant of actorsGT.mat for the same instants: on the mmpose Shelf subset
// (3 frames, believed to be Shelf images 300-302) actor 0 has joints identical to the bundle's
// frames 0-2 (all six leg joints in frame 0, the left ankle in every frame) while the others
// differ by 1-7 cm (observed maximum 7.2 cm).
TEST(Shelf4daFixture, GroundTruthIsAVariantOfActorsGt) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/gt.txt");
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  DatasetRequest shelf_request;
  shelf_request.dataset = "shelf";
  shelf_request.root = test::SharedData("shelf");
  shelf_request.params = {{"frames", "0-2"}};
  const Sequence shelf = ReadDataset(shelf_request)[0];
  const Sequence fourda =
      ReadDataset(Request(test::SharedData(kBundle), {{"frames", "0-2"}, {"detections", "none"}}))[0];
  for (size_t f = 0; f < 3; ++f) {
    const Poses3D& a = shelf.frames[f].gt;
    const Poses3D& b = fourda.frames[f].gt;
    const int pa = static_cast<int>(std::find(a.track_ids.begin(), a.track_ids.end(), 0) - a.track_ids.begin());
    const int pb = static_cast<int>(std::find(b.track_ids.begin(), b.track_ids.end(), 0) - b.track_ids.begin());
    ASSERT_LT(pa, a.num_persons());
    ASSERT_LT(pb, b.num_persons());
    const Eigen::VectorXd distance = (a.Person(pa).topLeftCorner(3, 14) - b.Person(pb).topLeftCorner(3, 14)).colwise().norm();
    EXPECT_LT(distance(5), 1e-6) << "frame " << f << ": ankle_left";
    EXPECT_LT(distance.maxCoeff(), 0.08) << "frame " << f;
    if (f == 0) {
      EXPECT_LT(distance.head(6).maxCoeff(), 1e-6) << "frame 0: legs";
    }
  }
}

TEST(Shelf4daFixture, CalibrationIsVoxelPoseShelfWithRotationsCounted) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/calibration.json");
  RPT_REQUIRE_SHARED_DATA("shelf/calibration_shelf.json");
  const Sequence s = ReadDataset(Request(test::SharedData(kBundle), {{"frames", "0"}, {"detections", "none"}}))[0];
  const std::vector<Camera> voxelpose = ReadVoxelPoseCalibration(test::SharedData("shelf/calibration_shelf.json"), 1032, 776);
  ASSERT_EQ(voxelpose.size(), s.cameras.size());
  for (size_t c = 0; c < voxelpose.size(); ++c) {
    EXPECT_EQ(s.cameras[c].name, voxelpose[c].name);
    // The two files round differently: R to ~7 digits, t (4DA) vs the centre in mm (VoxelPose).
    EXPECT_LT((s.cameras[c].R - voxelpose[c].R).cwiseAbs().maxCoeff(), 2e-6) << c;
    EXPECT_LT((s.cameras[c].t - voxelpose[c].t).cwiseAbs().maxCoeff(), 1e-5) << c;  // metres
    EXPECT_LT((s.cameras[c].K - voxelpose[c].K).cwiseAbs().maxCoeff(), 1e-4) << c;  // pixels
  }
  const InputWarning* rotations = FindWarning(s.warnings, "calibration.json", "rotations re-orthonormalised");
  ASSERT_NE(rotations, nullptr);
  EXPECT_EQ(rotations->count, 5);
  EXPECT_GT(rotations->worst, 1e-7);
  EXPECT_LT(rotations->worst, 1e-5);

  // Real OpenPose scores slightly above 1 are clamped and counted per file.
  const Sequence full = ReadDataset(Request(test::SharedData(kBundle)))[0];
  const InputWarning* cam1 = FindWarning(full.warnings, "1.txt", "scores above 1 clamped to 1");
  const InputWarning* cam2 = FindWarning(full.warnings, "2.txt", "scores above 1 clamped to 1");
  ASSERT_NE(cam1, nullptr);
  ASSERT_NE(cam2, nullptr);
  EXPECT_EQ(cam1->count, 4);
  EXPECT_EQ(cam2->count, 1);
  EXPECT_LT(cam1->worst, 1.04);
  EXPECT_EQ(FindWarning(full.warnings, "0.txt", "scores above 1 clamped to 1"), nullptr);
}

// How well the greedy association recovers the annotated persons. Measured with the default
// options over all 301 frames x 5 views:
//  * found: a GT person whose 12 limb joints (shoulders ... ankles) all project inside the image
//    is found when an assembled person has >= 4 of those joints with a mean distance to the
//    projections below 10 % of the GT person's box (larger side of the projected joints' box).
//    Observed 2138 of 2323 (92.0 %); the misses were not inspected one by one.
//  * fragments: assembled persons without a neck (a leg or arm that did not connect).
//    Observed 233 of 4391 persons (5.3 %).
//  * views with more assembled persons than neck candidates (OpenPose's own count of the people
//    it saw): observed 186 of 1505 (12.4 %).
// The GT annotates only some of the people in the room (1.5 GT persons per view are inside the
// image, OpenPose sees 2-4 necks per view), so assembled persons are not compared with the
// number of GT persons.
TEST(Shelf4daFixture, AssociationFindsTheAnnotatedPersonsWithFewFragments) {
  RPT_REQUIRE_SHARED_DATA(std::string(kBundle) + "/gt.txt");
  const fs::path root = test::SharedData(kBundle);
  const Sequence s = ReadDataset(Request(root))[0];
  const std::vector<std::string> limb_joints = {"shoulder_left", "shoulder_right", "elbow_left", "elbow_right",
                                                "wrist_left",    "wrist_right",    "hip_left",   "hip_right",
                                                "knee_left",     "knee_right",     "ankle_left", "ankle_right"};
  long inside = 0, found = 0;
  for (const SequenceFrame& frame : s.frames) {
    for (size_t c = 0; c < s.cameras.size(); ++c) {
      const Camera& camera = s.cameras[c];
      const Poses2D& view = frame.views[c];
      for (int p = 0; p < frame.gt.num_persons(); ++p) {
        Eigen::Matrix2Xd uv(2, limb_joints.size());
        bool all_inside = true;
        for (size_t k = 0; k < limb_joints.size(); ++k) {
          Eigen::Vector2d x;
          const bool front = camera.Project(frame.gt.Person(p).col(FindJoint(s.gt_joints, limb_joints[k])).head<3>(), &x);
          uv.col(static_cast<Eigen::Index>(k)) = x;
          all_inside &= front && x.x() >= 0 && x.y() >= 0 && x.x() < camera.width && x.y() < camera.height;
        }
        if (!all_inside) continue;
        ++inside;
        const double box = (uv.rowwise().maxCoeff() - uv.rowwise().minCoeff()).maxCoeff();
        for (int q = 0; q < view.num_persons(); ++q) {
          double sum = 0;
          int n = 0;
          for (size_t k = 0; k < limb_joints.size(); ++k) {
            const int j = FindJoint(s.detection_joints, limb_joints[k]);
            if (view.Person(q)(2, j) <= 0) continue;
            sum += (view.Person(q).col(j).head<2>() - uv.col(static_cast<Eigen::Index>(k))).norm();
            ++n;
          }
          if (n >= 4 && sum / n < 0.1 * box) {
            ++found;
            break;
          }
        }
      }
    }
  }
  long persons = 0, fragments = 0, views = 0, views_over = 0;
  const PafAssociationOptions defaults;
  for (int c = 0; c < 5; ++c) {
    InputWarnings warnings;
    const FourDaDetections d = ReadFourDaDetections(root / "detection" / (std::to_string(c) + ".txt"), &warnings);
    for (const PafCandidates& frame : d.frames) {
      const std::vector<PafPerson> assembled = AssociatePafs(Body25PafSkeleton(), frame, defaults);
      ++views;
      persons += static_cast<long>(assembled.size());
      for (const PafPerson& person : assembled) fragments += person[1] < 0;  // BODY_25 joint 1 = neck
      views_over += static_cast<long>(assembled.size()) > frame.joints[1].cols();
    }
  }
  std::cout << "[ measured ] found " << found << " / " << inside << " GT persons inside the image; fragments "
            << fragments << " / " << persons << " assembled persons; views with more persons than necks " << views_over
            << " / " << views << "\n";
  EXPECT_GT(inside, 2000);
  EXPECT_GE(found, 0.90 * inside);
  EXPECT_LE(fragments, 0.07 * persons);
  EXPECT_LE(views_over, 0.15 * views);
}

}  // namespace
}  // namespace rpt

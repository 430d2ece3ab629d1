// SPDX-License-Identifier: MIT
// Tests of the detector statistics (datasets/detector_stats) on hand-made views with known answers.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/detector_stats/association.h"
#include "datasets/detector_stats/statistics.h"

namespace rpt::detector_stats {
namespace {

constexpr double kTol = 1e-9;
const JointNames kJoints = {"shoulder_left", "shoulder_right", "hip_left", "hip_right"};

// Pinhole 100 x 100 px looking down +z: a point (x, y, 10) projects to (10 x + 50, 10 y + 50).
Camera TestCamera() {
  Camera camera;
  camera.name = "c0";
  camera.width = 100;
  camera.height = 100;
  camera.K << 100, 0, 50, 0, 100, 50, 0, 0, 1;
  return camera;
}

// Adds a GT person whose joints (kJoints order) project to the given pixels.
void AddPerson(Poses3D* gt, const std::vector<Eigen::Vector2d>& pixels, int track) {
  auto person = gt->AddPerson(track);
  for (int k = 0; k < 4; ++k) person.col(k) << (pixels[k].x() - 50) / 10, (pixels[k].y() - 50) / 10, 10, 1;
}

// Adds a detection; `joints` are (u, v, score) in kJoints order, score 0 = missing. Detection
// joints are stored in a different order (hips first, then shoulders, then a nose nobody has).
void AddDetection(Poses2D* view, const std::vector<Eigen::Vector3d>& joints) {
  auto det = view->AddPerson();
  const int slot[4] = {3, 2, 1, 0};
  for (int k = 0; k < 4; ++k) det.col(slot[k]) = joints[k];
}

Sequence HandMadeSequence() {
  Sequence s;
  s.name = "hand";
  s.cameras = {TestCamera()};
  s.gt_joints = kJoints;
  s.detection_joints = {"hip_right", "hip_left", "shoulder_right", "shoulder_left", "nose"};
  SequenceFrame frame;
  frame.id = "f0";
  frame.gt.Clear(4);
  // A: box 40..60 x 30..70 (diagonal sqrt(2000)); B: partly right of the image (truncated), in
  // image only its right shoulder and hip; D: in view, never detected.
  AddPerson(&frame.gt, {{60, 30}, {40, 30}, {58, 70}, {42, 70}}, 0);
  AddPerson(&frame.gt, {{105, 30}, {90, 30}, {103, 70}, {92, 70}}, 1);
  AddPerson(&frame.gt, {{25, 75}, {15, 75}, {24, 95}, {16, 95}}, 2);
  frame.views.resize(1);
  Poses2D& view = frame.views[0];
  view.Clear(5);
  // E (on a person labelled in 2D only), C (a false positive) and its exact copy, A, B.
  AddDetection(&view, {{72, 85, 0.7}, {78, 85, 0.7}, {0, 0, 0}, {0, 0, 0}});
  AddDetection(&view, {{5, 5, 0.4}, {8, 5, 0.2}, {0, 0, 0}, {0, 0, 0}});
  AddDetection(&view, {{5, 5, 0.4}, {8, 5, 0.2}, {0, 0, 0}, {0, 0, 0}});
  AddDetection(&view, {{62, 30, 0.95}, {59, 31, 0.6}, {58, 74, 0.3}, {0, 0, 0}});
  AddDetection(&view, {{99, 30, 0.5}, {93, 34, 0.85}, {0, 0, 0}, {92, 70, 0.95}});
  // 2D labels: A shoulders visible, hips occluded; B none; D all visible; a box-only person.
  frame.labels_2d.resize(1);
  PersonLabel2D a{0, Eigen::Vector4d(40, 30, 60, 70), {kLabelVisible, kLabelVisible, kLabelOccluded, kLabelOccluded}};
  PersonLabel2D d{2, Eigen::Vector4d(15, 75, 25, 95), {kLabelVisible, kLabelVisible, kLabelVisible, kLabelVisible}};
  PersonLabel2D box_only{-1, Eigen::Vector4d(70, 80, 80, 95), {}};
  frame.labels_2d[0] = {a, d, box_only};
  s.frames.push_back(frame);
  return s;
}

TEST(DetectorStatsTest, PercentileInterpolatesBetweenOrderStatistics) {
  EXPECT_EQ(Percentile({}, 0.5), 0.0);
  EXPECT_EQ(Percentile({5}, 0.9), 5.0);
  EXPECT_DOUBLE_EQ(Percentile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(Percentile({4, 1, 3, 2}, 0.9), 3.7);
  EXPECT_DOUBLE_EQ(Percentile({4, 1, 3, 2}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(Percentile({4, 1, 3, 2}, 1.0), 4.0);
  const ErrorSummary s = Summarize({0.1, 0.3, 0.2});
  EXPECT_EQ(s.count, 3);
  EXPECT_DOUBLE_EQ(s.median, 0.2);
  EXPECT_NEAR(s.mean, 0.2, kTol);
}

TEST(DetectorStatsTest, ProjectionBoxIsClippedAndTruncationFlagged) {
  const Sequence s = HandMadeSequence();
  const std::vector<int> gt_index = {0, 1, 2, 3};
  const ProjectedPerson a = ProjectPerson(s.cameras[0], s.frames[0].gt, 0, gt_index);
  EXPECT_FALSE(a.truncated);
  EXPECT_EQ(a.num_in_image, 4);
  EXPECT_NEAR(a.diagonal, std::sqrt(2000.0), kTol);
  EXPECT_NEAR(a.uv(0, 2), 58, 1e-9);
  const ProjectedPerson b = ProjectPerson(s.cameras[0], s.frames[0].gt, 1, gt_index);
  EXPECT_TRUE(b.truncated);
  EXPECT_EQ(b.num_in_image, 2);
  EXPECT_EQ(b.box, Eigen::Vector4d(90, 30, 100, 70));
  EXPECT_NEAR(b.diagonal, std::sqrt(1700.0), kTol);
}

TEST(DetectorStatsTest, AssociationIsGreedyOneToOneAndGated) {
  const Camera camera = TestCamera();
  Poses3D gt;
  gt.Clear(4);
  const std::vector<Eigen::Vector2d> p1 = {{60, 30}, {40, 30}, {58, 70}, {42, 70}};
  std::vector<Eigen::Vector2d> p2 = p1;
  for (auto& uv : p2) uv.x() += 12;
  AddPerson(&gt, p1, 0);
  AddPerson(&gt, p2, 1);
  const std::vector<int> gt_index = {0, 1, 2, 3};
  std::vector<ProjectedPerson> persons = {ProjectPerson(camera, gt, 0, gt_index), ProjectPerson(camera, gt, 1, gt_index)};
  Poses2D view;
  view.Clear(4);
  auto shifted = [&](double dx, int joints) {
    auto det = view.AddPerson();
    for (int k = 0; k < joints; ++k) det.col(k) << p1[k].x() + dx, p1[k].y(), 0.9;
  };
  shifted(8, 4);   // X: 8 px from P1, 4 px from P2
  shifted(-2, 4);  // Y: 2 px from P1, 14 px from P2
  shifted(0, 1);   // one joint only: comparable with nobody
  const std::vector<int> det_index = {0, 1, 2, 3};
  EXPECT_NEAR(MeanDistance(persons[0], view, 0, det_index, 2), 8.0, kTol);
  EXPECT_EQ(MeanDistance(persons[0], view, 2, det_index, 2), -1.0);
  const Association a = Associate(persons, view, det_index, AssociationOptions{});
  EXPECT_EQ(a.detection_of_person, (std::vector<int>{1, 0}));
  EXPECT_EQ(a.person_of_detection, (std::vector<int>{1, 0, -1}));
  EXPECT_NEAR(a.distance_px[1], 4.0, kTol);
  // A detection 30 px away is beyond the gate (0.5 x sqrt(2000) = 22.4 px).
  Poses2D far;
  far.Clear(4);
  auto det = far.AddPerson();
  for (int k = 0; k < 4; ++k) det.col(k) << p1[k].x() + 30, p1[k].y(), 0.9;
  persons.pop_back();
  EXPECT_EQ(Associate(persons, far, det_index, AssociationOptions{}).detection_of_person[0], -1);
  AssociationOptions wide;
  wide.gate_relative = 1.0;
  EXPECT_EQ(Associate(persons, far, det_index, wide).detection_of_person[0], 0);
}

TEST(DetectorStatsTest, HandMadeViewGivesTheKnownStatistics) {
  StatsOptions options;
  options.joints = kJoints;
  StatsAccumulator accumulator(options);
  accumulator.Add(HandMadeSequence());
  const DetectorStats s = accumulator.Finalize();
  const double da = std::sqrt(2000.0), db = std::sqrt(1700.0);

  EXPECT_EQ(s.joints, kJoints);
  ASSERT_EQ(s.views.size(), 1u);
  const ViewStats& v = s.views[0];
  EXPECT_EQ(v.camera, "c0");
  EXPECT_EQ(v.views, 1);
  EXPECT_EQ(v.gt_in_view, 3);
  EXPECT_EQ(v.detected, 2);
  EXPECT_EQ(v.detections, 5);
  EXPECT_EQ(v.duplicates, 1);
  EXPECT_EQ(v.false_positives, 1);
  EXPECT_EQ(v.false_positives_near_gt, 0);
  EXPECT_EQ(v.on_unlabelled, 1);
  EXPECT_NEAR(v.detection_rate(), 2.0 / 3.0, kTol);
  EXPECT_EQ(s.total.detected, 2);

  EXPECT_EQ(s.persons_in_view, 3);
  EXPECT_EQ(s.persons_truncated, 1);
  EXPECT_NEAR(s.box_diagonal_px_median, 0.5 * (da + std::sqrt(500.0)), kTol);
  EXPECT_NEAR(s.box_diagonal_px_median_truncated, db, kTol);
  EXPECT_EQ(s.persons_by_label, (std::array<long, 3>{2, 1, 0}));
  EXPECT_EQ(s.detected_by_label, (std::array<long, 3>{1, 1, 0}));

  // Errors (box units): A shoulder_left 2 px, shoulder_right swapped (19.03 px), hip_left 4 px,
  // hip_right missing; B shoulder_right 5 px, hip_right 0 (B's shoulder_left is outside).
  const double a_sl = 2 / da, a_sr = std::hypot(19, 1) / da, a_hl = 4 / da, b_sr = 5 / db;
  EXPECT_EQ(s.all.count, 5);
  EXPECT_NEAR(s.all.median, a_hl, kTol);
  EXPECT_NEAR(s.all.p90, 0.30377169364145834, 1e-12);
  EXPECT_NEAR(s.all.p99, 0.4132740223154334, 1e-12);
  EXPECT_NEAR(s.all.mean, (a_sl + a_sr + a_hl + b_sr) / 5, kTol);
  const VisibilityStats& visible = s.by_visibility[kVisible];
  const VisibilityStats& occluded = s.by_visibility[kOccluded];
  const VisibilityStats& unlabelled = s.by_visibility[kNotLabelled];
  EXPECT_EQ(visible.joints, 6);
  EXPECT_EQ(occluded.joints, 2);
  EXPECT_EQ(unlabelled.joints, 2);
  EXPECT_EQ(s.by_visibility[kUnknown].joints, 0);
  EXPECT_EQ(visible.of_detected, 2);
  EXPECT_EQ(occluded.missing, 1);
  EXPECT_NEAR(occluded.missing_rate(), 0.5, kTol);
  EXPECT_NEAR(visible.error.median, 0.5 * (a_sl + a_sr), kTol);
  EXPECT_NEAR(occluded.error.median, a_hl, kTol);
  EXPECT_NEAR(unlabelled.error.median, 0.5 * b_sr, kTol);
  EXPECT_NEAR(visible.confidence_mean, 0.775, kTol);
  EXPECT_NEAR(unlabelled.confidence_mean, 0.9, kTol);
  EXPECT_EQ(s.hidden.count, 3);
  EXPECT_NEAR(s.hidden.median, a_hl, kTol);
  EXPECT_NEAR(s.hidden_share, 0.4, kTol);
  EXPECT_EQ(s.clear_persons.count, 0);
  EXPECT_EQ(s.hidden_persons.count, 5);
  EXPECT_NEAR(s.confidence_low.median, a_hl, kTol);
  EXPECT_NEAR(s.confidence_mid.median, 0.5 * (a_sr + b_sr), kTol);
  EXPECT_NEAR(s.confidence_high.median, 0.5 * a_sl, kTol);

  EXPECT_EQ(s.joints_in_image, 6);
  EXPECT_EQ(s.joints_missing, 1);
  EXPECT_EQ(s.reported_outside, 1);
  EXPECT_EQ(s.confidence_histogram, (std::array<long, 10>{0, 0, 0, 1, 0, 0, 1, 0, 1, 2}));
  EXPECT_NEAR(s.confidence_mean, 0.73, kTol);
  EXPECT_NEAR(s.confidence_median, 0.85, kTol);
  EXPECT_NEAR(s.false_positive_confidence_mean, 0.3, kTol);
  EXPECT_NEAR(s.false_positive_joints_mean, 2.0, kTol);
  EXPECT_NEAR(s.detected_joints_mean, 3.0, kTol);
  EXPECT_EQ(s.swap_candidates, 3);
  EXPECT_EQ(s.swaps, 1);

  // Offsets in the body frame (down = +v, the person's left = +u for both A and B).
  ASSERT_EQ(s.per_joint.size(), 4u);
  const JointStats& sl = s.per_joint[0];
  const JointStats& sr = s.per_joint[1];
  const JointStats& hr = s.per_joint[3];
  EXPECT_EQ(sl.joint, "shoulder_left");
  EXPECT_EQ(sl.down_count, 1);
  EXPECT_NEAR(sl.down_mean, 0.0, kTol);
  EXPECT_NEAR(sl.out_mean, 2 / da, kTol);
  EXPECT_EQ(sr.down_count, 2);
  EXPECT_NEAR(sr.down_mean, 0.5 * (1 / da + 4 / db), kTol);
  EXPECT_NEAR(sr.out_mean, 0.5 * (-19 / da - 3 / db), kTol);  // right side: outward = -u
  EXPECT_EQ(sr.in_image, 2);
  EXPECT_EQ(hr.in_image, 2);
  EXPECT_EQ(hr.missing, 1);
  EXPECT_EQ(hr.hidden, 2);  // A's is occluded, B's not labelled
  EXPECT_EQ(hr.hidden_missing, 1);
}

TEST(DetectorStatsTest, ViewsWithoutLabelsAreUnknownAndSequencesWithoutCommonJointsFail) {
  Sequence s = HandMadeSequence();
  s.frames[0].labels_2d.clear();
  StatsOptions options;
  options.joints = kJoints;
  StatsAccumulator accumulator(options);
  accumulator.Add(s);
  const DetectorStats stats = accumulator.Finalize();
  EXPECT_EQ(stats.by_visibility[kUnknown].joints, 10);
  EXPECT_EQ(stats.persons_by_label, (std::array<long, 3>{0, 0, 3}));
  EXPECT_EQ(stats.hidden_share, 0.0);
  EXPECT_EQ(stats.total.on_unlabelled, 0);
  EXPECT_EQ(stats.total.false_positives, 2) << "without labels the detection on the box-only person is false";

  StatsOptions elsewhere;
  elsewhere.joints = {"ankle_left"};
  StatsAccumulator none(elsewhere);
  EXPECT_THROW(none.Add(s), std::exception);
}

}  // namespace
}  // namespace rpt::detector_stats

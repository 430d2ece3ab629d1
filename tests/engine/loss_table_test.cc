// SPDX-License-Identifier: MIT
// The loss table (engine/loss_table.h): hand-made scenes in which each GT person is lost at a known
// step, with the exact counts of every category and detail; and on the real MVOR and Shelf-4DA
// fixtures (skipped without ../shared/data) the categories sum to the GT persons and the found
// ones are exactly the persons Recall@500 counts. Also the unmatched predictions by what they show
// in the 2D labels: scenes with labels of known kinds, and on MVOR the count equals Invalid's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/sequence.h"
#include "engine/input.h"
#include "engine/loss_table.h"
#include "engine/outputs/loss_tables.h"
#include "engine/run.h"
#include "tests/pipeline/test_scene.h"
#include "tests/test_data.h"

namespace rpt::engine {
namespace {

using test::RingCameras;
using test::StandingPerson;

constexpr double kNoTime = std::numeric_limits<double>::quiet_NaN();

// One detection of `person` in `view`: its exact projection moved by `shift_px` in u, keeping only
// the joints named in `keep` (all when empty).
void AddDetection(const Camera& camera, const Eigen::Matrix4Xd& person, Poses2D* view, double shift_px = 0,
                  const std::vector<std::string>& keep = {}) {
  const JointNames& names = CocoBodyJoints();
  if (view->num_joints == 0) view->Clear(static_cast<int>(names.size()));
  auto pose = view->AddPerson();
  for (int j = 0; j < static_cast<int>(names.size()); ++j) {
    if (!keep.empty() && FindJoint(keep, names[j]) < 0) continue;
    Eigen::Vector2d uv;
    if (camera.Project(person.col(j).head<3>(), &uv)) pose.col(j) << uv.x() + shift_px, uv.y(), 0.9;
  }
}

struct SceneFrame {
  std::vector<Eigen::Matrix4Xd> gt;
  std::vector<Poses2D> views;  // one per camera
  double time_s = kNoTime;
  std::vector<std::vector<PersonLabel2D>> labels_2d;  // per camera (empty: the frame has no 2D labels)
};

// A 2D label of `person` (gt_person: its GT index, -1 for a person labelled in 2D only) in every
// camera of `cameras` given: the box of its projected joints.
void AddLabel(const std::vector<Camera>& cameras, const std::vector<int>& in, const Eigen::Matrix4Xd& person,
              int gt_person, SceneFrame* frame) {
  frame->labels_2d.resize(cameras.size());
  for (const int c : in) {
    PersonLabel2D label;
    label.gt_person = gt_person;
    label.box_px << 1e300, 1e300, -1e300, -1e300;
    for (int j = 0; j < person.cols(); ++j) {
      Eigen::Vector2d uv;
      if (!cameras[c].Project(person.col(j).head<3>(), &uv)) continue;
      label.box_px << std::min(label.box_px[0], uv.x()), std::min(label.box_px[1], uv.y()),
          std::max(label.box_px[2], uv.x()), std::max(label.box_px[3], uv.y());
    }
    frame->labels_2d[c].push_back(label);
  }
}

SceneFrame NewFrame(int num_cameras, std::vector<Eigen::Matrix4Xd> gt, double time_s = kNoTime) {
  SceneFrame frame{std::move(gt), std::vector<Poses2D>(num_cameras), time_s, {}};
  for (Poses2D& view : frame.views) view.Clear(static_cast<int>(CocoBodyJoints().size()));
  return frame;
}

// The loss table of the frames run through the triangulator with `options`.
LossTable Losses(const std::vector<Camera>& cameras, const std::vector<SceneFrame>& frames,
                 const TriangulatorOptions& options = {}, RunResult* result = nullptr) {
  Sequence sequence;
  sequence.name = "scene";
  sequence.cameras = cameras;
  sequence.gt_joints = CocoBodyJoints();
  sequence.detection_joints = CocoBodyJoints();
  for (size_t f = 0; f < frames.size(); ++f) {
    SequenceFrame frame;
    frame.id = "f" + std::to_string(f);
    frame.timestamp_s = frames[f].time_s;
    frame.gt.Clear(static_cast<int>(CocoBodyJoints().size()));
    for (const Eigen::Matrix4Xd& person : frames[f].gt) frame.gt.AddPerson() = person;
    frame.views = frames[f].views;
    frame.labels_2d = frames[f].labels_2d;
    sequence.frames.push_back(std::move(frame));
  }
  RunOptions run_options;
  run_options.triangulator = options;
  run_options.threads = 1;
  run_options.loss_table = true;
  const std::vector<Sequence> sequences = {sequence};
  RunResult run = Run(sequences, run_options);
  EXPECT_TRUE(run.losses.has_value());
  const LossTable table = run.losses.value_or(LossTable{});
  if (result != nullptr) *result = std::move(run);
  return table;
}

// The unmatched predictions by source: "total: labelled_3d labelled_2d_only partly_2d_only unlabelled
// (by_projection)".
std::string DescribeUnmatched(const LossTable& table) {
  const auto& by = table.unmatched_by_source;
  return std::to_string(table.unmatched_with_2d_labels) + ": " + std::to_string(by[0]) + " " + std::to_string(by[1]) +
         " " + std::to_string(by[2]) + " " + std::to_string(by[3]) + " (" +
         std::to_string(table.unmatched_by_projection) + ")";
}

// Every category and detail as "key=count" (the non-zero ones), to compare a whole table at once.
std::string Describe(const LossTable& table) {
  std::string text = "gt=" + std::to_string(table.gt_persons) + " triangulable=" + std::to_string(table.triangulable);
  for (const LossRow& row : LossRows(table)) {
    if (row.persons == 0) continue;
    text += " " + row.category + (row.detail.empty() ? "" : "/" + row.detail) + "=" + std::to_string(row.persons);
  }
  return text;
}

TEST(LossTableTest, PersonSeenByEveryCameraIsFound) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], person, &frame.views[c]);
  EXPECT_EQ(Describe(Losses(cameras, {frame})), "gt=1 triangulable=1 found=1");
}

TEST(LossTableTest, PersonsDetectedInOneOrNoViewAreCountedApart) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd seen = StandingPerson(0, 0), unseen = StandingPerson(1.2, 0.8);
  SceneFrame frame = NewFrame(4, {seen, unseen});
  AddDetection(cameras[2], seen, &frame.views[2]);
  EXPECT_EQ(Describe(Losses(cameras, {frame})),
            "gt=2 triangulable=0 fewer_than_2_views=2 fewer_than_2_views/no_view=1 fewer_than_2_views/one_view=1");
}

TEST(LossTableTest, PoseWithTooFewCoreJointsMakesNoPair) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  AddDetection(cameras[0], person, &frame.views[0]);
  // Nose and shoulders: paired with the person (3 evaluated joints), but 2 core joints only.
  AddDetection(cameras[1], person, &frame.views[1], 0, {"nose", "shoulder_left", "shoulder_right"});
  EXPECT_EQ(Describe(Losses(cameras, {frame})),
            "gt=1 triangulable=1 pair_filtered=1 pair_filtered/undistort=1");
}

TEST(LossTableTest, PairOfDisagreeingViewsIsFiltered) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  AddDetection(cameras[0], person, &frame.views[0]);
  AddDetection(cameras[1], person, &frame.views[1], 80);  // 80 px off: still this person's, but ~0.4 m
  EXPECT_EQ(Describe(Losses(cameras, {frame})), "gt=1 triangulable=1 pair_filtered=1 pair_filtered/filter=1");
}

TEST(LossTableTest, PairOfASmallGroupIsDroppedByGrouping) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  AddDetection(cameras[0], person, &frame.views[0]);
  AddDetection(cameras[1], person, &frame.views[1]);
  TriangulatorOptions options;
  options.group.min_group_size = 2;  // its one pair makes a group of one
  EXPECT_EQ(Describe(Losses(cameras, {frame}, options)),
            "gt=1 triangulable=1 grouped_wrongly=1 grouped_wrongly/dropped=1");
}

TEST(LossTableTest, PersonNextToABetterSeenOneIsAbsorbedIntoItsGroup) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd seen = StandingPerson(0, 0), hidden = StandingPerson(0.12, 0);
  SceneFrame frame = NewFrame(4, {seen, hidden});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], seen, &frame.views[c]);
  AddDetection(cameras[0], hidden, &frame.views[0]);  // 12 cm beside: its one pair joins the other's group
  AddDetection(cameras[1], hidden, &frame.views[1]);
  EXPECT_EQ(Describe(Losses(cameras, {frame})),
            "gt=2 triangulable=2 found=1 grouped_wrongly=1 grouped_wrongly/absorbed=1");
}

TEST(LossTableTest, DetectionsThatAgreeOnTheWrongPlaceAreMergedOff) {
  const std::vector<Camera> cameras = RingCameras(4);
  // Every camera reports the person 0.6 m beside its GT position: consistent, so triangulated there.
  const Eigen::Matrix4Xd person = StandingPerson(0, 0), reported = StandingPerson(0.6, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], reported, &frame.views[c]);
  const LossTable table = Losses(cameras, {frame});
  EXPECT_EQ(Describe(table), "gt=1 triangulable=1 merged_wrongly=1 merged_wrongly/own_pairs_only=1");
  EXPECT_EQ(table.joints.joints, 0);  // its nearest prediction is no match: no joint to compare
}

TEST(LossTableTest, PersonThatThreeEmptyViewsContradictIsRejectedByVerify) {
  const std::vector<Camera> cameras = RingCameras(5);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(5, {person});
  AddDetection(cameras[0], person, &frame.views[0]);
  AddDetection(cameras[1], person, &frame.views[1]);
  EXPECT_EQ(Describe(Losses(cameras, {frame})), "gt=1 triangulable=1 rejected=1 rejected/verify=1");
}

TEST(LossTableTest, PersonWithThreeJointsIsRejectedByPostprocess) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  // Three joints of one side: no derived joint, fewer than postprocess.min_valid_joints (4).
  ASSERT_EQ(TriangulatorOptions{}.postprocess.min_valid_joints, 4);
  const std::vector<std::string> left = {"shoulder_left", "hip_left", "knee_left"};
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], person, &frame.views[c], 0, left);
  EXPECT_EQ(Describe(Losses(cameras, {frame})), "gt=1 triangulable=1 rejected=1 rejected/postprocess=1");
}

TEST(LossTableTest, PersonHeldBackBySpeedClippingIsPlacedOff) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd before = StandingPerson(0, 0), after = StandingPerson(1.0, 0);
  SceneFrame first = NewFrame(4, {before}, 0.0), second = NewFrame(4, {after}, 0.01);
  for (int c = 0; c < 4; ++c) {
    AddDetection(cameras[c], before, &first.views[c]);
    AddDetection(cameras[c], after, &second.views[c]);
  }
  // 1 m in 10 ms: the track continues (gate 2 m) and clip_speed lets it move 0.1 m (10 m/s).
  TriangulatorOptions options;
  options.track.max_distance_m = 2.0;
  EXPECT_EQ(Describe(Losses(cameras, {first, second}, options)), "gt=2 triangulable=2 found=1 placed_off=1");
}

TEST(LossTableTest, FramesAndSequencesAddUp) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd a = StandingPerson(0, 0), b = StandingPerson(1.2, 0.8);
  SceneFrame both = NewFrame(4, {a, b}), one = NewFrame(4, {a, b});
  for (int c = 0; c < 4; ++c) {
    AddDetection(cameras[c], a, &both.views[c]);
    AddDetection(cameras[c], b, &both.views[c]);
  }
  AddDetection(cameras[0], a, &one.views[0]);
  AddDetection(cameras[1], b, &one.views[1]);
  AddDetection(cameras[2], b, &one.views[2], 80);
  RunResult run;
  const LossTable table = Losses(cameras, {both, one}, {}, &run);
  EXPECT_EQ(Describe(table),
            "gt=4 triangulable=3 found=2 fewer_than_2_views=1 fewer_than_2_views/one_view=1 pair_filtered=1 "
            "pair_filtered/filter=1");
  // The found persons are those Recall@500 counts.
  EXPECT_DOUBLE_EQ(run.metrics.recall_500, 50.0);
  const std::string csv = LossesCsv(table);
  EXPECT_NE(csv.find("category,detail,persons,percent_of_gt\nfound,,2,50.00\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nall,,4,100.00\nall,triangulable,3,75.00\n"), std::string::npos) << csv;
  const nlohmann::ordered_json json = LossTableJson(table);
  EXPECT_EQ(json["categories"]["pair_filtered"], 1);
  EXPECT_EQ(json["details"]["pair_filtered"]["filter"], 1);
}

TEST(LossTableTest, UnmatchedPredictionsAreSplitByTheLabelsTheirDetectionsShow) {
  const std::vector<Camera> cameras = RingCameras(4);
  const std::vector<int> all = {0, 1, 2, 3};
  // a: labelled in 3D and found. b: labelled in 2D only, in every view. c: labelled nowhere. d:
  // labelled in 2D only in views 0 and 1. All four are detected in every view.
  const Eigen::Matrix4Xd a = StandingPerson(0, 0), b = StandingPerson(1.4, 0.9), c = StandingPerson(-1.4, 0.9),
                         d = StandingPerson(0, -1.5);
  SceneFrame frame = NewFrame(4, {a});
  for (int v = 0; v < 4; ++v) {
    for (const Eigen::Matrix4Xd* person : {&a, &b, &c, &d}) AddDetection(cameras[v], *person, &frame.views[v]);
  }
  AddLabel(cameras, all, a, 0, &frame);
  AddLabel(cameras, all, b, -1, &frame);
  AddLabel(cameras, {0, 1}, d, -1, &frame);
  RunResult run;
  const LossTable table = Losses(cameras, {frame}, {}, &run);
  EXPECT_EQ(Describe(table), "gt=1 triangulable=1 found=1");
  EXPECT_EQ(DescribeUnmatched(table), "3: 0 1 1 1 (0)");
  EXPECT_EQ(run.metrics.invalid_causes.Total(), 3);  // the same predictions Invalid counts
  const nlohmann::ordered_json json = LossTableJson(table)["unmatched_with_2d_labels"];
  EXPECT_EQ(json.dump(), R"({"predictions":3,"labelled_3d":0,"labelled_2d_only":1,"partly_2d_only":1,"unlabelled":1,"by_projection":0})");

  // Without 2D labels in the frame nothing is counted.
  frame.labels_2d.clear();
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {frame})), "0: 0 0 0 0 (0)");
}

TEST(LossTableTest, AnUnmatchedPredictionMadeFromALabelledPersonsDetectionsIsLabelled3d) {
  const std::vector<Camera> cameras = RingCameras(4);
  // As DetectionsThatAgreeOnTheWrongPlaceAreMergedOff: its detections are the GT person's (paired
  // with it), placed 0.6 m off. The frame has 2D labels, none of them a box: the pairing decides.
  const Eigen::Matrix4Xd person = StandingPerson(0, 0), reported = StandingPerson(0.6, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], reported, &frame.views[c]);
  frame.labels_2d.resize(4);
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {frame})), "1: 1 0 0 0 (0)");
}

TEST(LossTableTest, ASecondDetectionInsideALabelledPersonsBoxIsLabelled3d) {
  const std::vector<Camera> cameras = RingCameras(4);
  // The person is detected in every view and found; views 0 and 1 also report it a second time,
  // as if 0.45 m higher (a detector's duplicate): those two triangulate to a ghost above it. The
  // duplicates are not paired with the person (the pairing is one to one) but lie in its 2D label.
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], person, &frame.views[c]);
  const Eigen::Matrix4Xd raised = person + Eigen::Vector4d(0, 0, 0.45, 0).replicate(1, person.cols());
  for (int c = 0; c < 2; ++c) AddDetection(cameras[c], raised, &frame.views[c]);
  AddLabel(cameras, {0, 1, 2, 3}, person, 0, &frame);
  RunResult run;
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {frame}, {}, &run)), "1: 1 0 0 0 (0)");
  EXPECT_EQ(run.metrics.invalid_causes.duplicate, 1);
}

TEST(LossTableTest, ACarriedPersonIsJudgedInTheViewsItLandsIn) {
  const std::vector<Camera> cameras = RingCameras(6);
  // Near camera 0, out of the images of cameras 0, 1 and 5: seen by cameras 2-4 in frame 0 and
  // carried in frame 1, where a 2D-only label stands where it projects in views 2-4. The views
  // that do not see it have no say.
  const Eigen::Vector3d near = 0.85 * cameras[0].Center();
  const Eigen::Matrix4Xd person = StandingPerson(near.x(), near.y());
  for (int c = 0; c < 6; ++c) {
    int inside = 0;
    for (int j = 0; j < person.cols(); ++j) {
      Eigen::Vector2d uv;
      inside += cameras[c].Project(person.col(j).head<3>(), &uv) && uv.x() >= 0 && uv.y() >= 0 &&
                uv.x() < cameras[c].width && uv.y() < cameras[c].height;
    }
    ASSERT_EQ(inside, c >= 2 && c <= 4 ? 17 : 0) << "camera " << c;
  }
  SceneFrame first = NewFrame(6, {person}, 0.0), second = NewFrame(6, {}, 0.04);
  for (int c = 2; c <= 4; ++c) AddDetection(cameras[c], person, &first.views[c]);
  AddLabel(cameras, {2, 3, 4}, person, -1, &second);
  EXPECT_EQ(Describe(Losses(cameras, {first})), "gt=1 triangulable=1 found=1");
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {first, second})), "1: 0 1 0 0 (1)");
}

TEST(LossTableTest, ACarriedPersonIsJudgedByItsProjection) {
  const std::vector<Camera> cameras = RingCameras(4);
  // Frame 0: the person is seen and found. Frame 1: no detection and no GT person, so tracking
  // carries it (an unmatched prediction); a 2D-only label stands where it projects in views 0-2.
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame first = NewFrame(4, {person}, 0.0), second = NewFrame(4, {}, 0.04);
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], person, &first.views[c]);
  AddLabel(cameras, {0, 1, 2}, person, -1, &second);
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {first, second})), "1: 0 0 1 0 (1)");
  AddLabel(cameras, {3}, person, -1, &second);  // now in every view
  EXPECT_EQ(DescribeUnmatched(Losses(cameras, {first, second})), "1: 0 1 0 0 (1)");
}

// The PCP parts as "evaluated/wrong/beyond_best_pair/wrong_beyond_best_pair", all parts and then
// the parts with a count other than evaluated, by name.
std::string DescribeParts(const LossTable& table) {
  const auto counts = [](const PartLosses& part) {
    return std::to_string(part.evaluated) + "/" + std::to_string(part.wrong) + "/" +
           std::to_string(part.beyond_best_pair) + "/" + std::to_string(part.wrong_beyond_best_pair);
  };
  std::string text = counts(table.AllParts());
  for (int k = 0; k < kNumPcpParts; ++k) {
    const PartLosses& part = table.parts[k];
    if (part.wrong + part.beyond_best_pair > 0) text += " " + metrics::GenericPcpParts()[k].name + "=" + counts(part);
  }
  return text;
}

TEST(LossTableTest, PartsOfAPersonSeenExactlyAreCorrectAndWithinReach) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], person, &frame.views[c]);
  EXPECT_EQ(DescribeParts(Losses(cameras, {frame})), "10/0/0/0");
}

TEST(LossTableTest, AWristEveryViewPlacesOffItsLabelIsBeyondTheBestPair) {
  const std::vector<Camera> cameras = RingCameras(4);
  const Eigen::Matrix4Xd detected = StandingPerson(0, 0);
  // The dataset labels the left wrist 80 % of the way up the forearm; every view agrees on the
  // wrist where it is: the forearm is wrong in the output and no pair of views places it better.
  Eigen::Matrix4Xd labelled = detected;
  const int elbow = FindJoint(CocoBodyJoints(), "elbow_left"), wrist = FindJoint(CocoBodyJoints(), "wrist_left");
  labelled.col(wrist).head<3>() = detected.col(elbow).head<3>() +
                                  0.2 * (detected.col(wrist).head<3>() - detected.col(elbow).head<3>());
  SceneFrame frame = NewFrame(4, {labelled});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], detected, &frame.views[c]);
  EXPECT_EQ(DescribeParts(Losses(cameras, {frame})), "10/1/1/1 lower_arm_left=1/1/1/1");
}

TEST(LossTableTest, PartsOfAPersonLeftOutAreWrongButWithinReach) {
  const std::vector<Camera> cameras = RingCameras(5);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(5, {person});
  // Exact in two views, rejected by verify (the three empty views contradict it): nothing is output.
  AddDetection(cameras[0], person, &frame.views[0]);
  AddDetection(cameras[1], person, &frame.views[1]);
  // Every one of the 10 parts with the same counts: "10/a/b/c part=1/a'/b'/c' ...".
  const auto every_part = [](const std::string& all, const std::string& each) {
    std::string text = all;
    for (const metrics::PcpPartSpec& part : metrics::GenericPcpParts()) text += " " + part.name + "=" + each;
    return text;
  };
  EXPECT_EQ(DescribeParts(Losses(cameras, {frame})), every_part("10/10/0/0", "1/1/0/0"));
  // Its detection in one view only: no pair, so every part is beyond reach.
  frame.views[1].Clear(static_cast<int>(CocoBodyJoints().size()));
  EXPECT_EQ(DescribeParts(Losses(cameras, {frame})), every_part("10/10/10/10", "1/1/1/1"));
}

// The mean joint errors of the references: "joints: output all_views best_pair" (mm, 3 decimals).
std::string DescribeJoints(const LossTable& table) {
  const JointReferences& r = table.joints;
  const double n = static_cast<double>(std::max(1L, r.joints));
  char text[120];
  std::snprintf(text, sizeof(text), "%ld: %.3f %.3f %.3f", r.joints, r.output_mm / n, r.all_views_mm / n,
                r.best_pair_mm / n);
  return text;
}

TEST(LossTableTest, JointReferencesOfDetectionsThatAgreeOnAShiftedPersonAreTheShift) {
  const std::vector<Camera> cameras = RingCameras(4);
  // Every view reports the person 0.1 m beside its labels: each reference, and the output, 100 mm off.
  const Eigen::Matrix4Xd person = StandingPerson(0, 0), reported = StandingPerson(0.1, 0);
  SceneFrame frame = NewFrame(4, {person});
  for (int c = 0; c < 4; ++c) AddDetection(cameras[c], reported, &frame.views[c]);
  EXPECT_EQ(DescribeJoints(Losses(cameras, {frame})), "13: 100.000 100.000 100.000");
}

TEST(LossTableTest, OneViewOffMovesTheAllViewsFitButNotTheBestPair) {
  const std::vector<Camera> cameras = RingCameras(3);
  const Eigen::Matrix4Xd person = StandingPerson(0, 0);
  SceneFrame frame = NewFrame(3, {person});
  AddDetection(cameras[0], person, &frame.views[0]);
  AddDetection(cameras[1], person, &frame.views[1]);
  AddDetection(cameras[2], person, &frame.views[2], 15);  // 15 px off: still paired and merged
  const LossTable table = Losses(cameras, {frame});
  ASSERT_EQ(table.joints.joints, 13);
  EXPECT_NEAR(table.joints.best_pair_mm, 0.0, 1e-6);  // views 0 and 1 are exact
  // The third view pulls every joint of the fit off by the same amount: its ray is off by 15 px.
  EXPECT_GT(table.joints.all_views_mm / 13, 5.0);
  EXPECT_LT(table.joints.all_views_mm / 13, 50.0);
}

// Real data: the categories sum to the GT persons, and the found ones are Recall@500's.
// `parts_beyond_best_pair`: of all parts, those no pair of the person's detections reaches (a
// property of the detections and labels alone, not of the triangulator's options).
void ExpectConsistentOnRealData(const InputSpec& spec, bool has_2d_labels, long parts_evaluated,
                                long parts_beyond_best_pair) {
  Input input = OpenInput(spec);
  RunOptions options;
  options.loss_table = true;
  const RunResult run = Run(input, options);
  ASSERT_TRUE(run.losses.has_value());
  const LossTable& table = *run.losses;
  long sum = 0;
  for (const long count : table.count) sum += count;
  EXPECT_EQ(sum, table.gt_persons);
  EXPECT_EQ(table.gt_persons, run.metrics.num_gt_persons);
  EXPECT_NEAR(100.0 * table[Loss::kFound] / table.gt_persons, run.metrics.recall_500, 1e-9);
  EXPECT_EQ(table.in_no_view + table.in_one_view, table[Loss::kFewerThanTwoViews]);
  EXPECT_LE(table.triangulable, table.gt_persons);
  EXPECT_GT(table[Loss::kFound], 0);
  // The unmatched predictions by what they show: every one once, when the frames have 2D labels.
  long unmatched = 0;
  for (const long count : table.unmatched_by_source) unmatched += count;
  EXPECT_EQ(unmatched, table.unmatched_with_2d_labels);
  EXPECT_LE(table.unmatched_by_projection, table.unmatched_with_2d_labels);
  EXPECT_EQ(table.unmatched_with_2d_labels, has_2d_labels ? run.metrics.invalid_causes.Total() : 0);
  // The parts are PCP's: its denominator, and its value from the wrong ones.
  const PartLosses parts = table.AllParts();
  EXPECT_NEAR(100.0 * (parts.evaluated - parts.wrong) / parts.evaluated, run.metrics.pcp, 1e-9);
  EXPECT_LE(parts.wrong_beyond_best_pair, std::min(parts.wrong, parts.beyond_best_pair));
  EXPECT_EQ(parts.evaluated, parts_evaluated);
  EXPECT_EQ(parts.beyond_best_pair, parts_beyond_best_pair);
}

TEST(LossTableTest, MvorCategoriesSumToTheGtPersons) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  InputSpec spec;
  spec.dataset = "mvor";
  spec.root = test::SharedData("mvor").string();
  ExpectConsistentOnRealData(spec, true, 5305, 2912);
}

TEST(LossTableTest, Shelf4daCategoriesSumToTheGtPersons) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  InputSpec spec;
  spec.dataset = "shelf-4da";
  spec.root = test::SharedData("shelf/4d_association").string();
  ExpectConsistentOnRealData(spec, false, 5100, 68);
}

}  // namespace
}  // namespace rpt::engine

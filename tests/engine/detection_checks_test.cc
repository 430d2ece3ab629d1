// SPDX-License-Identifier: MIT
// The detection/GT checks behind eval's warnings: each warning fires on a constructed broken
// input and stays quiet on a clean synthetic scene and on the real MVOR fixture.
#include "engine/detection_checks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "datasets/detections.h"
#include "engine/dataset_registry.h"
#include "tests/test_data.h"
#include "datasets/synthetic/simulate_detections.h"

namespace rpt::engine {
namespace {

// The continuity the checks share with the tracker (track.max_gap_s); its default.
constexpr double kMaxGap = 1.0;

Sequence Synthetic(int frames = 120) {
  DatasetRequest request;
  request.dataset = "synthetic";
  request.params = {{"frames", std::to_string(frames)}};
  return ReadDataset(request).front();
}

std::vector<std::string> Codes(const SequenceCheck& check) {
  std::vector<std::string> codes;
  for (const CheckWarning& w : DetectionWarnings(check)) codes.push_back(w.code);
  return codes;
}

// What was measured, for failure messages.
std::string Describe(const SequenceCheck& check) {
  std::ostringstream s;
  s << check.sequence << ": " << check.frames_with_gt_no_input << "/" << check.frames_with_gt
    << " GT frames without input, " << check.shared_joints << " shared joints\n";
  for (const CameraCheck& c : check.cameras) {
    s << "  " << c.name << ": detections " << c.detections << ", empty " << c.empty_frames << "/" << c.input_frames
      << ", empty with GT in view " << c.empty_frames_gt_in_view << "/" << c.frames_gt_in_view << ", compared "
      << c.gt_compared << "/" << c.gt_in_view << ", px " << c.px_median << ", rel " << c.rel_median << "\n";
  }
  const ShiftCheck& shift = check.shift;
  s << "  shift: tested " << shift.tested << " (" << shift.reason << "), frames " << shift.frames << ", best "
    << shift.best_shift << ", win " << shift.win_share << ", motion " << shift.motion_rel << ", medians";
  for (double m : shift.rel_median) s << " " << m;
  for (const CheckWarning& w : DetectionWarnings(check)) s << "\n  warning: " << w.message;
  return s.str();
}

bool Has(const std::vector<std::string>& codes, const std::string& code) {
  return std::find(codes.begin(), codes.end(), code) != codes.end();
}

// Detections of frame f become those of frame f + k (frames without a source get none).
void ShiftDetections(Sequence* s, int k) {
  const int n = static_cast<int>(s->frames.size());
  std::vector<std::vector<Poses2D>> views(n);
  for (int f = 0; f < n; ++f) {
    if (f + k >= 0 && f + k < n) views[f] = s->frames[f + k].views;
    else views[f].assign(s->cameras.size(), Poses2D{static_cast<int>(s->detection_joints.size()), {}});
  }
  for (int f = 0; f < n; ++f) s->frames[f].views = views[f];
}

TEST(DetectionChecks, CleanSyntheticSceneRaisesNothing) {
  const Sequence s = Synthetic();
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  EXPECT_TRUE(Codes(check).empty()) << Describe(check);
  ASSERT_EQ(check.cameras.size(), s.cameras.size());
  for (const CameraCheck& c : check.cameras) {
    EXPECT_LT(c.rel_median, 0.05) << Describe(check);
    EXPECT_GT(c.gt_compared, 100);
  }
  EXPECT_TRUE(check.shift.tested) << Describe(check);
  EXPECT_LT(check.shift.win_share, 0.3) << "the true alignment k = 0 wins";
}

TEST(DetectionChecks, DetectionsShiftedByThreeFramesAreFound) {
  for (int k : {3, -2}) {
    Sequence s = Synthetic();
    ShiftDetections(&s, k);
    const SequenceCheck check = CheckDetections(s, kMaxGap);
    EXPECT_TRUE(Has(Codes(check), "detections_frame_shifted")) << Describe(check);
    EXPECT_EQ(check.shift.best_shift, k) << Describe(check);
    for (const CheckWarning& w : DetectionWarnings(check)) {
      if (w.code == "detections_frame_shifted") {
        EXPECT_NE(w.message.find("shifted by " + std::to_string(std::abs(k)) + " frame"), std::string::npos)
            << w.message;
      }
    }
  }
}

TEST(DetectionChecks, StaticSceneIsNotTestedForShifts) {
  Sequence s = Synthetic();
  // Everybody frozen in the pose of frame 0; the detector still adds fresh noise every frame.
  for (SequenceFrame& frame : s.frames) frame.gt = s.frames[0].gt;
  SimulationOptions simulation;
  SimulateDetections(simulation, &s);
  ShiftDetections(&s, 3);  // a shift of a frozen scene changes nothing
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  EXPECT_FALSE(check.shift.tested) << Describe(check);
  EXPECT_NE(check.shift.reason.find("moves less"), std::string::npos) << check.shift.reason;
  EXPECT_TRUE(Codes(check).empty()) << Describe(check);
}

TEST(DetectionChecks, FramesFarApartAreNotTestedForShifts) {
  Sequence s = Synthetic();
  ShiftDetections(&s, 3);
  for (size_t f = 0; f < s.frames.size(); ++f) s.frames[f].timestamp_s = 75.0 * f;  // MVOR-like
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  EXPECT_FALSE(check.shift.tested);
  EXPECT_NE(check.shift.reason.find("not continuous"), std::string::npos) << check.shift.reason;
  EXPECT_FALSE(Has(Codes(check), "detections_frame_shifted"));
  for (SequenceFrame& frame : s.frames) frame.timestamp_s = std::nan("");
  EXPECT_FALSE(CheckDetections(s, kMaxGap).shift.tested) << "unknown times are not continuous";
}

TEST(DetectionChecks, CameraWithoutDetectionsInAnyOrMostFrames) {
  Sequence s = Synthetic();
  for (SequenceFrame& frame : s.frames) frame.views[1].Clear(frame.views[1].num_joints);
  for (size_t f = 0; f < s.frames.size(); ++f) {
    if (f % 3 != 0) s.frames[f].views[3].Clear(s.frames[f].views[3].num_joints);  // empty in 2/3 of the frames
  }
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  const std::vector<CheckWarning> warnings = DetectionWarnings(check);
  ASSERT_EQ(warnings.size(), 2u) << Describe(check);
  EXPECT_EQ(warnings[0].code, "camera_without_detections");
  EXPECT_NE(warnings[0].message.find("camera " + s.cameras[1].name), std::string::npos) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find(s.name), std::string::npos) << warnings[0].message;
  EXPECT_EQ(warnings[1].code, "camera_often_without_detections");
  EXPECT_NE(warnings[1].message.find("camera " + s.cameras[3].name), std::string::npos) << warnings[1].message;
  EXPECT_NE(warnings[1].message.find("67 %"), std::string::npos) << warnings[1].message;
}

TEST(DetectionChecks, WrongRotationOfOneCamera) {
  Sequence s = Synthetic();
  // Turned by 0.2 rad (11 degrees) about its vertical image axis, centre kept.
  Camera& camera = s.cameras[2];
  const Eigen::Vector3d centre = camera.Center();
  camera.R = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()).toRotationMatrix() * camera.R;
  camera.t = -camera.R * centre;
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  const std::vector<CheckWarning> warnings = DetectionWarnings(check);
  ASSERT_EQ(warnings.size(), 1u) << Describe(check);
  EXPECT_EQ(warnings[0].code, "gt_far_from_detections") << Describe(check);
  EXPECT_NE(warnings[0].message.find("camera " + camera.name), std::string::npos) << warnings[0].message;
}

// Under the absolute threshold but far beyond the other cameras: a camera turned by 0.05 rad
// (about 0.17 of the box diagonal beside 0.012) is named by the relative rule, as two swapped
// cameras of Shelf are (0.21-0.23 beside 0.03); a small turn stays under kFarRelFloor.
TEST(DetectionChecks, ACameraFarBeyondTheOthersIsNamedUnderTheAbsoluteThreshold) {
  for (const double angle : {0.05, 0.01}) {
    Sequence s = Synthetic();
    Camera& camera = s.cameras[2];
    const Eigen::Vector3d centre = camera.Center();
    camera.R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix() * camera.R;
    camera.t = -camera.R * centre;
    const SequenceCheck check = CheckDetections(s, kMaxGap);
    const std::vector<CheckWarning> warnings = DetectionWarnings(check);
    const double rel = check.cameras[2].rel_median;
    if (angle == 0.01) {
      EXPECT_LT(rel, kFarRelFloor) << Describe(check);
      EXPECT_TRUE(warnings.empty()) << Describe(check);
      continue;
    }
    EXPECT_GT(rel, kFarRelFloor) << Describe(check);
    EXPECT_LT(rel, kFarRelDistance) << "the absolute rule would name it too: " << Describe(check);
    ASSERT_EQ(warnings.size(), 1u) << Describe(check);
    EXPECT_EQ(warnings[0].code, "gt_far_from_detections");
    EXPECT_NE(warnings[0].message.find("camera " + camera.name + ": projected GT is far from the detections compared "
                                       "with the other cameras"),
              std::string::npos)
        << warnings[0].message;
  }
}

TEST(DetectionChecks, SwappedCameraOrderAndAllDetectionsFarAway) {
  Sequence swapped = Synthetic();
  std::swap(swapped.cameras[0], swapped.cameras[1]);
  std::vector<std::string> codes = Codes(CheckDetections(swapped, kMaxGap));
  EXPECT_EQ(std::count(codes.begin(), codes.end(), "gt_far_from_detections"), 2) << Describe(CheckDetections(swapped, kMaxGap));

  Sequence far = Synthetic();
  for (SequenceFrame& frame : far.frames) {
    for (Poses2D& view : frame.views) {
      for (int p = 0; p < view.num_persons(); ++p) view.Person(p).row(0).array() += 400;
    }
  }
  codes = Codes(CheckDetections(far, kMaxGap));
  EXPECT_EQ(std::count(codes.begin(), codes.end(), "gt_far_from_detections"), 5) << Describe(CheckDetections(far, kMaxGap));
}

TEST(DetectionChecks, GroundTruthInMillimetres) {
  Sequence s = Synthetic();
  for (SequenceFrame& frame : s.frames) {
    for (int p = 0; p < frame.gt.num_persons(); ++p) frame.gt.Person(p).topRows<3>() *= 1000.0;
  }
  const SequenceCheck check = CheckDetections(s, kMaxGap);
  const std::vector<std::string> codes = Codes(check);
  ASSERT_EQ(codes.size(), s.cameras.size()) << Describe(check);
  for (const std::string& code : codes) {
    EXPECT_EQ(code, "gt_far_from_detections") << Describe(check);
  }
}

TEST(DetectionChecks, FramesWithoutAnyDetectionAndUnsharedJointNames) {
  Sequence s = Synthetic();
  for (size_t f = 0; f < s.frames.size(); ++f) {
    if (f % 4 != 0) s.frames[f].views.clear();  // frame ids the detections did not match
  }
  SequenceCheck check = CheckDetections(s, kMaxGap);
  EXPECT_EQ(Codes(check), std::vector<std::string>{"frames_without_detections"}) << Describe(check);
  EXPECT_NE(DetectionWarnings(check)[0].message.find("90 of 120"), std::string::npos)
      << DetectionWarnings(check)[0].message;

  Sequence renamed = Synthetic();
  for (std::string& name : renamed.gt_joints) name = "gt_" + name;
  check = CheckDetections(renamed, kMaxGap);
  EXPECT_EQ(Codes(check), std::vector<std::string>{"no_shared_joints"}) << Describe(check);
}

TEST(DetectionChecks, SamplingKeepsItFast) {
  DetectionCheckOptions options;
  options.max_frames = 20;
  options.shift_frames = 15;
  const Sequence s = Synthetic(300);
  const SequenceCheck check = CheckDetections(s, kMaxGap, options);
  EXPECT_EQ(check.measured_frames, 20);
  EXPECT_LE(check.shift.frames, 15);
  EXPECT_TRUE(Codes(check).empty()) << Describe(check);
}

// The checks stream: a checker fed frame by frame without knowing the frame count gives what the
// whole sequence gives while the sample covers every candidate, and keeps bounded samples beyond.
SequenceCheck CheckStreamed(const Sequence& s, const DetectionCheckOptions& options) {
  DetectionChecker checker(s, /*num_frames=*/-1, kMaxGap, options);
  for (const SequenceFrame& frame : s.frames) checker.Add(frame);
  return checker.Finish();
}

TEST(DetectionChecks, StreamedWithUnknownLengthMatchesTheWholeSequenceWhileSamplesCoverAll) {
  DetectionCheckOptions options;
  options.max_frames = 100;
  options.shift_frames = 60;  // up to 120 anchors are all kept
  const Sequence s = Synthetic(100);
  const SequenceCheck whole = CheckDetections(s, kMaxGap, options);
  const SequenceCheck streamed = CheckStreamed(s, options);
  EXPECT_EQ(Describe(streamed), Describe(whole));
  EXPECT_EQ(streamed.measured_frames, 100);
  EXPECT_EQ(streamed.shift.frames, 60) << "60 picked evenly from the 90 anchors (frames 5..94)";
}

TEST(DetectionChecks, StreamedLongSequenceKeepsBoundedSpreadSamples) {
  DetectionCheckOptions options;
  options.max_frames = 20;
  options.shift_frames = 15;
  const Sequence s = Synthetic(400);
  const SequenceCheck whole = CheckDetections(s, kMaxGap, options);
  const SequenceCheck streamed = CheckStreamed(s, options);
  EXPECT_EQ(streamed.measured_frames, 20);
  EXPECT_EQ(streamed.shift.frames, 15);
  EXPECT_EQ(streamed.frames, 400);
  EXPECT_EQ(streamed.frames_with_gt, whole.frames_with_gt);
  ASSERT_EQ(streamed.cameras.size(), whole.cameras.size());
  for (size_t c = 0; c < whole.cameras.size(); ++c) {
    EXPECT_EQ(streamed.cameras[c].detections, whole.cameras[c].detections) << "counts cover every frame";
    EXPECT_NEAR(streamed.cameras[c].rel_median, whole.cameras[c].rel_median, 0.01) << "other frames, same error";
  }
  EXPECT_EQ(streamed.shift.tested, whole.shift.tested);
  EXPECT_EQ(LooksShifted(streamed.shift), LooksShifted(whole.shift));
  EXPECT_TRUE(Codes(streamed).empty()) << Describe(streamed);
}

TEST(DetectionChecks, RealMvorFixtureRaisesNothing) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  DatasetRequest request;
  request.dataset = "mvor";
  request.root = test::SharedData("mvor");
  const std::vector<Sequence> sequences = ReadDataset(request);
  ASSERT_EQ(sequences.size(), 4u);
  for (const Sequence& sequence : sequences) {
    const SequenceCheck check = CheckDetections(sequence, kMaxGap);
    EXPECT_TRUE(Codes(check).empty()) << Describe(check);
    EXPECT_FALSE(check.shift.tested) << "MVOR frames are minutes apart";
    for (const CameraCheck& c : check.cameras) EXPECT_LT(c.rel_median, 0.25) << Describe(check);
  }
}

// 100 000 cameras without detections gave 99 999 warning lines: per code, ten cameras are named
// and the others counted in one line.
TEST(DetectionWarnings, ManyCamerasWithOneWarningGiveAFewLines) {
  for (const int cameras : {10, 11, 1000}) {
    SequenceCheck check;
    check.sequence = "s";
    for (int c = 0; c < cameras; ++c) {
      CameraCheck camera;
      camera.name = "cam" + std::to_string(c);
      camera.input_frames = 10;  // other cameras have detections, this one none
      check.cameras.push_back(camera);
    }
    const std::vector<CheckWarning> warnings = DetectionWarnings(check);
    ASSERT_EQ(warnings.size(), cameras > 10 ? 11u : 10u) << cameras;
    EXPECT_NE(warnings[9].message.find("s, camera cam9: no detections"), std::string::npos);
    if (cameras > 10) {
      EXPECT_EQ(warnings[10].code, "camera_without_detections");
      EXPECT_EQ(warnings[10].message, "s: " + std::to_string(cameras - 10) +
                                          " more cameras with the warning 'camera_without_detections' (" +
                                          std::to_string(cameras) + " in all; the first 10 above)");
    }
  }
}

}  // namespace
}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// Do the 2D detections of an input agree with its ground truth and cameras? Measured per camera:
// frames without detections, and the distance between each projected GT person and its nearest
// detection, in pixels and relative to the person's projected box; per sequence: whether the
// detections fit the GT of another frame better than their own (a frame shift).
//
// `rpt inspect` prints the measurements; `rpt eval` turns them into warnings
// (DetectionWarnings) with the thresholds below. docs/diagnostics.md explains each one.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "datasets/sequence.h"

namespace rpt::engine {

struct DetectionCheckOptions {
  // Frames per sequence whose GT-to-detection distances are measured, evenly spaced; 0 = all.
  int max_frames = 200;
  // Frame shifts tried by the shift test: -max_shift..max_shift.
  int max_shift = 5;
  // Frames per sequence at which the shift test compares (evenly spaced); 0 = all.
  int shift_frames = 40;
  // Joints (shared by name, GT-valid, detected, in front of the camera) a GT person and a
  // detection must have in common to be compared.
  int min_joints = 3;
};

// One camera of one sequence.
struct CameraCheck {
  std::string name;
  long detections = 0;        // detected persons, all frames
  long input_frames = 0;      // frames where some camera of the sequence has a detection
  long empty_frames = 0;      // of those: this camera has none
  // Measured frames (see max_frames) with input where a GT person projects into this camera's
  // image (box centre inside, in front of the camera), and of those, frames without detection.
  long frames_gt_in_view = 0;
  long empty_frames_gt_in_view = 0;
  long gt_in_view = 0;        // GT persons projected into the image (measured frames with input)
  long gt_compared = 0;       // of those: compared with a detection of this camera
  // Medians over the compared GT persons of the mean joint distance to the nearest detection:
  // in pixels, and divided by the diagonal of the GT person's projected box. NaN when none.
  double px_median = std::numeric_limits<double>::quiet_NaN();
  double rel_median = std::numeric_limits<double>::quiet_NaN();
};

// The frame-shift test of one sequence: detections of frame f against the GT of frame f + k.
struct ShiftCheck {
  bool tested = false;
  std::string reason;            // why it was not tested (empty when tested)
  int frames = 0;                // frames f compared at every shift
  long comparisons = 0;          // (frame, camera) pairs compared at every shift
  std::vector<double> rel_median;// per k = -max_shift..max_shift: median relative distance
  int best_shift = 0;            // k != 0 with the smallest median
  double win_share = 0;          // share of comparisons where best_shift is closer than k = 0
  double motion_rel = 0;         // median GT motion over max_shift frames, relative to the box

  double RelAt(int k) const { return rel_median[rel_median.size() / 2 + k]; }
};

struct SequenceCheck {
  std::string sequence;
  long frames = 0;
  int shared_joints = 0;               // GT joint names that also name a detection joint
  long frames_with_gt = 0;             // frames with at least one GT person
  long frames_with_gt_no_input = 0;    // of those: no detection in any camera
  long measured_frames = 0;            // frames whose distances were measured
  std::vector<CameraCheck> cameras;
  ShiftCheck shift;
};

// Measures one sequence frame by frame as the frames stream past (datasets/frame_source.h):
// counts over every frame, GT-to-detection distances on sampled frames, and the shift test on
// sampled frames with max_shift continuous neighbours on each side. It holds the last
// 2 * max_shift + 1 frames and the sampled measurements only, so memory does not grow with the
// number of frames. With the frame count known in advance (`num_frames` >= 0) the measured frames
// are max_frames evenly spaced frames; otherwise, and for the shift test's anchors, every
// stride-th candidate is kept, the stride doubling whenever more than twice the wanted number
// are kept, and the wanted number is picked evenly spaced from those (all candidates while there
// are at most twice the wanted number).
class DetectionChecker {
 public:
  // Consecutive frames further apart than max_gap_s (or with an unknown time) are not continuous:
  // the triangulator's track.max_gap_s, so the checks and the tracker share one notion.
  DetectionChecker(const SequenceHeader& header, long num_frames, double max_gap_s,
                   const DetectionCheckOptions& options = {});
  ~DetectionChecker();
  DetectionChecker(DetectionChecker&&) noexcept;
  DetectionChecker& operator=(DetectionChecker&&) noexcept;

  // The next frame of the sequence (in order; views empty or one per camera).
  void Add(const SequenceFrame& frame);
  // The measurements, once every frame was added; the checker is spent afterwards.
  SequenceCheck Finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Measures one sequence with a DetectionChecker. Fast: the distances use at most max_frames
// frames and the shift test at most shift_frames frames.
SequenceCheck CheckDetections(const Sequence& sequence, double max_gap_s, const DetectionCheckOptions& options = {});

// Warning triggers (docs/diagnostics.md; the real-data numbers behind them are there).
// A camera without detections in at least this share of the frames where GT is in its view.
inline constexpr double kEmptyCameraShare = 0.5;
// A camera whose median relative GT-to-detection distance is at least this.
inline constexpr double kFarRelDistance = 0.3;
// Or at least kFarRelFactor times the median of the sequence's other cameras (two or more judged)
// and at least kFarRelFloor: two swapped cameras of Shelf measure 0.21-0.23 beside 0.03 (under
// kFarRelDistance); an aligned real camera stays within 1.55 times the others (MVOR, Shelf-4DA 1.05).
inline constexpr double kFarRelFactor = 3.0;
inline constexpr double kFarRelFloor = 0.1;
// GT joint names the detections must share before anything can be compared.
inline constexpr int kMinSharedJoints = 3;
// GT persons in view needed before a camera's distance is judged.
inline constexpr long kMinComparedPersons = 5;
// Frame shift: tested on at least kShiftMinFrames frames, and only when the GT moves over
// max_shift frames at least as much as the detections err at their best shift (otherwise no
// shift could stand out). It warns when the best k != 0 brings the median down to at most
// kShiftMaxRatio of the median at k = 0 and is closer in at least kShiftMinWinShare of the
// (frame, camera) comparisons.
inline constexpr double kShiftMaxRatio = 0.8;
inline constexpr double kShiftMinWinShare = 0.7;
inline constexpr int kShiftMinFrames = 10;

// The verdict of a frame-shift test (the triggers above).
bool LooksShifted(const ShiftCheck& shift);

struct CheckWarning {
  std::string code;     // stable identifier, e.g. "camera_without_detections"
  std::string message;  // one line, printed as "warning: <message>"
};

// Warnings of one code about single cameras beyond this many are counted in one line.
inline constexpr long kMaxCameraWarningsShown = 10;

// The warnings the measurements of one sequence call for, in camera order.
std::vector<CheckWarning> DetectionWarnings(const SequenceCheck& check);

}  // namespace rpt::engine

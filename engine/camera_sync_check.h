// SPDX-License-Identifier: MIT
// Are the cameras' frames taken at the same instants? A camera whose clock (or frame numbering) is
// a few frames off the others gives plausible persons that are wrong by the motion between those
// frames, which neither the camera agreement (each person is made from the views that agree) nor a
// shift of all detections against the ground truth can see: one camera three frames late on a
// 2-camera synthetic rig turned MPJPE from 88 into 145 mm without a word.
//
// The check compares the detections of two cameras a few frames apart: for a detection p of
// camera a in frame f and each shift k (-kMaxSyncShift..kMaxSyncShift), the nearest of camera b's
// detections in frame f + k to the epipolar lines of p's joints (the median distance over the
// joints both have, relative to the detection's box diagonal, at most kSyncCap). Where people move,
// the true offset of b against a gives the smallest mean; k = 0 for synchronised cameras. A
// detection counts only when its match is clear (kSyncAmbiguity) and it is measured at every shift
// (paired), so that the gain of the best shift over k = 0 has a standard error: an offset is said
// when the gain is at least 10 % of the distance at k = 0 and kMinSyncZ standard errors, and at
// least kMinSyncOffset frames. With more than two cameras the camera is named whose pairs together
// show the offset. Measured (`rpt triangulate` on files with one camera's detections moved by k
// frames): a synthetic 5-camera scene, clean detector, k = 2, 3, 6 found as 2, 3, 6; the realistic
// detector (whose constant calibration error shifts the minimum) as about 4, 5, 8; real Shelf-4DA
// camera 4 moved by 6 or -4 frames found, by 2-3 not (its people move slowly); nothing on the
// unmoved files, nor on synthetic scenes of 2-16 cameras and 1-20 people of every detector profile.
// A 2-camera, 1-person scene needs about 1000 frames to show 3 frames.
//
// Frames are compared only where the sequence runs on without a pause (times known, each step more
// than 0 and at most track.max_gap_s): images sampled seconds apart (MVOR) say nothing about it.
// The cost is bounded: about kSyncWork (frame, pair) comparisons spread over the sequence, halved
// in rate each time kSyncBudget more detection pairs were measured (`rpt eval --dataset synthetic
// --param cameras=8 --param people=8`, one thread: 0.79 s against 0.73 s without the check).
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt::engine {

inline constexpr int kMaxSyncShift = 8;        // frames each way
inline constexpr int kSyncShifts = 2 * kMaxSyncShift + 1;
inline constexpr int kMinSyncJoints = 6;       // joints a detection pair must share
inline constexpr double kMinSyncScore = 0.3;   // joints below this score are not compared
inline constexpr double kSyncCap = 1.0;        // a distance above this share of the box diagonal counts as this
inline constexpr long kMinSyncPersons = 50;    // detections compared (at every shift) before a pair is judged
inline constexpr double kMaxSyncRatio = 0.9;   // the best shift's mean below this share of k = 0's: an offset
inline constexpr double kMinSyncZ = 3.0;       // the gain over k = 0 this many standard errors at least
inline constexpr int kMinSyncOffset = 2;       // frames: a 1-frame minimum is within what real rigs show (Shelf)
inline constexpr double kSyncAmbiguity = 2.0;  // a person is compared when its next match is this much farther
inline constexpr long kSyncBudget = 50000;     // detection pairs measured before fewer frames are compared
inline constexpr long kSyncWork = 600;         // about this many (frame, camera pair) comparisons per sequence

// One pair of cameras: the mean distance per shift k (index k + kMaxSyncShift) of b's frame f + k
// against a's frame f.
struct CameraPairSync {
  int a = 0, b = 0;
  // Per shift (kSyncShifts): the sum of the distances, and of the squared differences to the same
  // detection's distance at k = 0 (every detection compared is measured at every shift).
  std::vector<double> sum;
  std::vector<double> difference_squares;
  long count = 0;  // detections compared
  // The shift with the smallest mean, when it is at least kMinSyncOffset from 0 and clearly
  // better than 0 (kMaxSyncRatio, kMinSyncZ, kMinSyncPersons), else 0: b's frame f + offset shows
  // what a's frame f shows.
  int Offset() const;
  double Mean(int shift) const;
  // The mean of (distance at 0 - distance at shift) and the variance of that mean.
  double MeanGain(int shift) const;
  double GainVariance(int shift) const;
};

class CameraSyncCheck {
 public:
  // `num_frames` < 0: unknown. Allocates the ring of frames it compares once.
  CameraSyncCheck(const SequenceHeader& header, long num_frames, double max_gap_s);
  // The next frame of the sequence, in order. Allocates nothing once the ring's buffers have grown
  // to the largest frame.
  void Add(const SequenceFrame& frame);
  const std::vector<CameraPairSync>& pairs() const { return pairs_; }
  // The mean time between the frames compared (s); 0 when none were.
  double frame_step_s() const { return steps_ > 0 ? step_sum_s_ / static_cast<double>(steps_) : 0.0; }

 private:
  struct Slot {
    double time_s = 0;
    std::vector<Poses2D> views;  // pixels, then (normalised) normalised undistorted coordinates; score
    bool normalised = false;
    std::vector<std::vector<double>> diagonals;  // per camera and detection, once normalised
    std::vector<std::vector<Eigen::Vector2d>> centres;  // the same: the mean of its joints
  };
  void Normalise(Slot* slot);

  void Compare(long centre);

  const SequenceHeader& header_;
  double max_gap_s_;
  long stride_ = 1;     // every stride_-th frame is the centre of a comparison
  long measured_ = 0;   // detection pairs measured so far
  long budget_ = 0;     // measured_ above this: stride_ doubles, and so does budget_
  std::vector<Eigen::Matrix3d> essential_;  // per pair: x_b^T E x_a = 0 in normalised coordinates
  std::vector<CameraPairSync> pairs_;
  std::vector<Slot> ring_;
  long frames_ = 0;
  long run_ = 0;  // frames in a row up to the last one without a pause
  double last_time_s_ = 0;
  double step_sum_s_ = 0;
  long steps_ = 0;
  std::vector<double> distances_;     // scratch of Distance
  std::vector<Eigen::Vector3d> lines_;  // scratch: the epipolar lines of a detection's joints
};

// The warning lines of a sequence's offsets: with two cameras, the pair; with more, each camera
// whose pairs together show an offset (one at a time, the worst first, its pairs then set aside).
// `frame_step_s` > 0 adds the time.
std::vector<std::string> CameraSyncWarnings(const std::string& sequence, const std::vector<Camera>& cameras,
                                            const std::vector<CameraPairSync>& pairs, double frame_step_s);

}  // namespace rpt::engine

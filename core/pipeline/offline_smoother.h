// SPDX-License-Identifier: MIT
// Offline smoothing (smooth.mode = offline): the two-sided form of step 16, fed one frame at a
// time after Triangulator::Process, handing each frame back once the frames after it that its
// smoothing needs have arrived. It uses frames on both sides of each one, so it adds no lag to
// the positions but delays each frame by its window (3 sigma); it suits evaluation and recorded
// sequences, not live use (the causal mode runs inside Process, step 16, smooth.h).
//
// Method: per track and joint, a local polynomial fit in time with Gaussian weights (a
// Savitzky-Golay filter generalised to uneven times and missing frames; also known as LOESS with a
// Gaussian kernel). For a frame at time t0 where the joint is observed, the observations of the
// same track within |t - t0| <= 3 sigma (sigma = smooth.offline_sigma_s) are fitted with a
// polynomial of degree smooth.offline_degree in (t - t0), weighted by exp(-(t - t0)^2 / 2 sigma^2),
// and the joint becomes the fit's value at t0. A polynomial of degree >= 1 reproduces linear
// motion exactly, also at the ends of a track (where a plain moving average would lag). The
// degree drops when too few observations are in reach; a lone observation stays as it is.
//
// Rules shared with the causal filter: the sequence is cut where consecutive frames are more than
// max_gap_s apart or a time is unknown (NaN), and nothing is smoothed across a cut (even if a
// track id went on); tracks are never mixed; joints at or below `unobserved_score` (missing, or
// filled by post-processing) are neither used nor changed; coasting persons (after the first
// num_detected) and untracked persons (id -1) are left as is. Frames whose persons have another
// number of joints than the frames before them (not from the same Triangulator) also cut.
//
// Streaming: a frame is handed back (Pop) once a later frame more than 3 sigma after it has
// arrived, the sequence is cut after it, or the sequence ends (Flush); frames come back in the
// order they were pushed. The fits read the frames as pushed, never smoothed ones, so the result
// does not depend on when frames are handed back. The smoother holds the frames of one window
// (3 sigma each side of the oldest frame not handed back yet); once its buffers have grown to
// that, it no longer allocates.
//
// Timing: the smoothing of a frame (taking it in, the fits, handing it back) is timed like a step:
// it is added to time_us[smooth] and total_us of that frame's FrameStats, and count[smooth] holds
// the joints the fits changed. With smooth.mode other than offline the smoother passes every
// frame straight through, unchanged and untimed.
//
// Usage, per sequence (the temporal steps need track ids: use it with track.enabled):
//   OfflineSmoother smoother(options.smooth, options.track.max_gap_s, options.UnobservedScore());
//   for each frame: tri.Process(views, t, &persons, &stats);
//                   smoother.Push(t, persons, persons.num_persons() - stats.coasting_tracks, stats);
//                   while (smoother.Pop(&smoothed, &smoothed_stats)) use the next frame;
//   smoother.Flush(); while (smoother.Pop(&smoothed, &smoothed_stats)) use the next frame;
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/poses.h"

namespace rpt {

class OfflineSmoother {
 public:
  // `max_gap_s`: consecutive frames further apart are not continuous (track.max_gap_s);
  // `unobserved_score`: joints at or below it are not observations
  // (TriangulatorOptions::UnobservedScore()).
  OfflineSmoother(const SmoothOptions& options, double max_gap_s, double unobserved_score);

  // Takes the next frame: its time (NaN = unknown), its persons with their track ids (the first
  // `num_detected` were detected, the coasting ones follow) and its stats. Copies them.
  void Push(double timestamp_s, const Poses3D& persons, int num_detected, const FrameStats& stats);
  // Ends the sequence: every frame held becomes ready. The next frame pushed starts afresh.
  void Flush();
  // Hands back the oldest frame not handed back yet, if it is ready: its persons smoothed and its
  // stats with the smoothing counted. False when no frame is ready.
  bool Pop(Poses3D* persons, FrameStats* stats);
  // Frames pushed and not handed back yet.
  int num_waiting() const { return num_held_ - next_; }

 private:
  struct Frame {
    double timestamp_s = 0;
    long segment = 0;  // frames of one segment are continuous
    int num_detected = 0;
    Poses3D persons;  // as pushed: the fits of later frames read them
    FrameStats stats;
  };
  struct Observation {
    double t;
    Eigen::Vector3d x;
  };

  Frame& Held(int i) { return ring_[(first_ + i) % ring_.size()]; }
  const Frame& Held(int i) const { return ring_[(first_ + i) % ring_.size()]; }
  bool Ready(const Frame& frame) const;
  // Writes the fits of held frame i into `persons` (a copy of it); returns the joints changed.
  int SmoothFrame(int i, Poses3D* persons);
  // Forgets the frames handed back that no frame still to be handed back needs.
  void DropUnneeded();

  SmoothOptions options_;
  bool enabled_;
  double max_gap_s_;
  double unobserved_score_;
  double reach_s_;  // 3 sigma

  std::vector<Frame> ring_;  // the frames held, oldest at first_
  int first_ = 0;
  int num_held_ = 0;
  int next_ = 0;  // the oldest frame not handed back, counted from the oldest held

  long segment_ = 0;             // segment of the newest frame
  bool segment_closed_ = true;   // the next frame starts a new segment
  double last_timestamp_s_ = 0;  // time of the newest frame
  int segment_joints_ = -1;      // joints per person in the segment (-1: no person yet)

  std::vector<int> person_in_;             // per frame of a window: the person of the track being fitted, -1 = none
  std::vector<Observation> observations_;  // of one track and joint in a window
};

}  // namespace rpt

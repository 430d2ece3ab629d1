// SPDX-License-Identifier: MIT
// Step 16 (optional, smooth.mode = causal): causal temporal smoothing of tracked persons with a
// constant-velocity Kalman filter per track and joint.
//
// Model (the discrete white-noise acceleration model, Bar-Shalom, Li, Kirubarajan: "Estimation
// with Applications to Tracking and Navigation", 2001, section 6.3.3): a joint moves with constant
// velocity between frames, disturbed by an acceleration with standard deviation
// acceleration_m_s2 held over each interval; triangulated positions carry independent noise with
// standard deviation measurement_noise_m. x, y and z are filtered independently with the same
// 2x2 covariance (the model is isotropic), so the result does not depend on the world axes. dt is
// the time since the joint's last update, from the frame timestamps. At a fixed frame rate the
// gains settle to those of the alpha-beta filter with tracking index
// lambda = acceleration_m_s2 * dt^2 / measurement_noise_m (Kalata 1984). Unlike a low-pass filter
// it does not lag behind a joint moving at constant velocity; after a sudden change of velocity it
// overshoots for a few frames.
//
// Joints that are not observations (score <= unobserved_score: missing, or filled by
// post-processing) neither update the filter nor change. A new track, a joint first seen, or a
// joint whose last update is more than max_gap_s ago or at an unknown time (NaN) starts its filter
// afresh at the observed position with an unknown velocity: its output is the input. Coasting
// persons (after the first num_detected) are left as is.
//
// smooth.mode = offline is the two-sided form, run after Process: offline_smoother.h.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/track_states.h"
#include "core/poses.h"

namespace rpt {

// Per track and joint: the Kalman filter, carried from frame to frame in reusable slots
// (track_states.h).
struct JointFilters {
  struct Filter {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();  // position estimate (m)
    Eigen::Vector3d v = Eigen::Vector3d::Zero();  // velocity estimate (m/s)
    double p00 = 0, p01 = 0, p11 = 0;             // covariance of (position, velocity) per axis
    double timestamp_s = 0;                       // time of the last update
    bool started = false;
  };
  struct Track {
    std::vector<Filter> joints;
  };
  void Reset() { tracks.Clear(); }
  TrackStates<Track> tracks;
};

namespace steps {

struct SmoothInput {
  double timestamp_s;       // this frame's time (NaN = unknown)
  double max_gap_s;         // a joint last updated longer ago restarts its filter (track.max_gap_s)
  double unobserved_score;  // joints at or below are not observations
  int num_detected;         // the persons detected this frame (the coasting ones follow them)
};

// Smooths the detected persons of `persons` (the frame's output so far) in place. Returns the
// number of joints smoothed (filter updated and applied). Does nothing unless options.mode is
// kCausal.
int Smooth(const SmoothOptions& options, const SmoothInput& in, JointFilters* state, Poses3D* persons);

}  // namespace steps

}  // namespace rpt

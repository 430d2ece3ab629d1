// SPDX-License-Identifier: MIT
// Options of every pipeline step, one section per step, named like the step (and like the
// config-file section and the timing output). Defaults are documented in docs/algorithm.md.
//
// Units: metres (m), metres per second (m/s), pixels (px). Image-space distances that depend on
// how large a person appears are given relative to the 2D pose's bounding-box diagonal (rel).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace rpt {

// Undistortion and preparation of the 2D poses.
struct UndistortOptions {
  double min_joint_score = 0.1;    // 2D joints with a lower score are treated as missing
  bool add_derived_joints = true;  // append hip_middle, shoulder_middle, head (computed in 2D)
};

// Step 2: keep pairs whose two poses both match the same last-frame person, or neither does.
// The match radius grows with the time since the last frame, so sparsely sampled sequences
// (e.g. every 12th frame) keep their true pairs: radius = max_distance_rel + person_speed_m_s *
// elapsed / 1.8 m (1.8 m: the typical bbox diagonal of a person, to turn metres into rel).
struct PrefilterOptions {
  bool enabled = true;
  double max_distance_rel = 0.25;  // match radius at zero elapsed time (fraction of bbox diagonal)
  double person_speed_m_s = 2.0;   // assumed top speed of a person, widens the radius over time
  double ambiguity_ratio = 1.5;    // second-closest person must be this much farther for a match
  // With many cameras a tracked person yields k(k-1)/2 pairs; keep only this many per person, those
  // with the best triangulation angle (closest to 90 degrees at the person). <= 0: keep all.
  int max_pairs_per_person = 30;
};

enum class TriangulationMethod { kMidpoint, kDlt };

// Steps 3, 4 and 10.
struct TriangulateOptions {
  TriangulationMethod method = TriangulationMethod::kMidpoint;
  // Step 3: the joints used for association. Default: shoulders, hips, elbows, wrists, knees, ankles.
  std::vector<std::string> core_joints;  // empty = DefaultCoreJoints()
  int min_core_joints = 3;               // a pair needs this many core joints seen in both views
};

// Step 5: the room is an axis-aligned box. A size component <= 0 leaves that axis unbounded.
struct RoomCheckOptions {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
  double margin_m = 0.5;  // tolerance around the box
};

enum class ScoreMode { kCombined, kReprojectionOnly, kTriangulationOnly };

// How the score kernels are scaled: to the noise level estimated from the data (residuals in
// metres at the joint's depth, see noise_scale.h), or by the fixed constants of the first release
// (reprojection error relative to the pose's bounding box).
enum class ScoreScale { kAdaptive, kFixed };

// Steps 6-7: per-joint score from reprojection error, ray gap and 2D confidence; limb pruning.
struct ScoreOptions {
  ScoreMode mode = ScoreMode::kCombined;
  bool use_confidence = true;       // weight joints by their 2D confidence
  ScoreScale scale = ScoreScale::kAdaptive;
  double scale_factor = 5.0;        // adaptive: kernel scale = scale_factor x estimated noise (m)
  double noise_prior_m = 0.02;      // adaptive: noise level assumed before the data has spoken (m)
  double reprojection_scale_rel = 0.08;  // fixed: reprojection error (rel) at which the score is exp(-1)
  double ray_gap_scale_m = 0.12;    // fixed: distance between the two rays at which the score is exp(-1)
  double trim_fraction = 0.25;      // the pair score leaves out this share of its worst joints
  bool prune_limbs = true;          // invalidate joints of implausibly short or long limbs
};

// Step 8.
struct FilterOptions {
  double min_match_score = 0.7;  // pairs with a lower pair score are dropped
};

// Step 9.
struct GroupOptions {
  double max_distance_m = 0.25;  // mean core-joint distance for a proposal to join a group
  // Groups with fewer proposals are dropped. 0 = automatic: 1 below 10 cameras, 2 from 10 up (the
  // paper recommends raising it with many cameras, where accidental consistent pairs appear).
  int min_group_size = 0;
  bool exclusive_poses = true;  // a 2D pose belongs to one person: the strongest group keeps it
  bool drop_mirrored = true;    // drop a group that is another group with left/right swapped
};

// Step 11.
struct MergeOptions {
  double max_distance_m = 0.2;  // drop joint proposals this far from the mean (<= 0: keep all)
  int top_k = 3;                // then keep the k closest (<= 0: keep all)
  bool score_weighted = true;   // weighted average by joint score instead of plain mean
  double min_joint_score = 0.1; // joint proposals below are ignored
  bool keep_best_when_all_far = true;  // if the distance filter drops every candidate, keep the
                                       // highest-scoring one instead of leaving the joint missing
};

// Step 11b (an addition): re-score each person against all views, drop unsupported ones.
struct VerifyOptions {
  bool enabled = true;
  int min_empty_views = 2;             // drop when this many views (and more than support it) see nobody there
  double min_inside_fraction = 0.8;    // a view is "empty" only if this share of the joints lands in the image
};

// Step 12b (an addition, off by default): persons seen by one camera only, placed at the depth
// their 2D limb lengths imply (lift_single_views.h).
struct SingleViewOptions {
  bool enabled = false;
  double min_joint_score = 0.3;       // confidence of the joints used
  int min_core_joints = 6;            // confident core joints a pose needs
  double score_factor = 0.5;          // joint scores = 2D confidence x this (rank below triangulated persons)
  double duplicate_distance_m = 0.5;  // centre distance under which a lifted person duplicates another
  double max_overlap_iou = 0.3;       // poses overlapping a found person's projection this much are that person
};

// Step 12.
struct PostprocessOptions {
  bool enabled = true;
  int min_valid_joints = 6;         // persons with fewer valid joints are dropped
  double min_extent_m = 0.2;        // drop persons whose bounding box diagonal is smaller
  double max_extent_m = 3.0;        // ... or larger
  bool drop_outside_room = true;    // drop persons whose centre is outside the room (+ margin)
  bool replace_wrong_joints = true; // joints of implausible limbs take their neighbour's place
  bool fill_missing_joints = true;  // missing joints take their neighbour's position
  double filled_joint_score = 0.05; // score given to filled joints (> 0 so they count as present)
};

// Step 13.
struct TrackOptions {
  bool enabled = true;
  // Frames further apart than this, or without a known time (NaN timestamp), are not continuous:
  // tracks end (nothing coasts), and neither the pre-filter nor speed clipping use the frame before.
  double max_gap_s = 1.0;
  double max_distance_m = 0.5;  // mean core-joint distance to continue a track
  int max_missing_frames = 3;   // a lost person is still returned (last pose) this many frames
};

// Step 14.
struct ClipSpeedOptions {
  bool enabled = true;
  double max_speed_m_s = 10.0;  // per joint, between consecutive outputs of one track
};

// Step 15 (optional, off by default): per-track bone-length consistency. Each track keeps the
// lengths of each limb over its last `window` observations; once a limb has `min_observations`,
// a length differing from their median by more than max(tolerance_rel x median, min_tolerance_m)
// makes the limb disagree. The joints explaining the disagreeing limbs (a wrist moved 30 cm: its
// forearm disagrees, the elbow's upper arm does not) are marked missing and, with
// postprocess.fill_missing_joints, filled from their neighbour like in step 12
// (check_bone_lengths.h). Off by default until it is shown to help on real detections.
struct BoneLengthOptions {
  bool enabled = false;
  double tolerance_rel = 0.25;   // relative disagreement with the track's running length
  double min_tolerance_m = 0.05; // floor of the tolerance, for short bones (hands, face)
  int min_observations = 10;     // a limb is checked once its track has observed it this often
  int window = 50;               // observations per limb the running median is taken over
};

// Temporal smoothing of tracked persons (off by default until it is shown to help on real
// detections):
//   causal  = step 16 inside the pipeline: a constant-velocity Kalman filter per track and joint
//             (white-noise acceleration model; at a fixed frame rate its gains settle to those
//             of an alpha-beta filter), time-aware (dt from the timestamps), online, no lag on
//             constant velocity;
//   offline = after a whole sequence has been triangulated (rpt eval and friends): per track and
//             joint, a Gaussian-weighted local polynomial fit in time (Savitzky-Golay generalised
//             to uneven times and missing frames), two-sided, so no lag; not usable online.
// Neither smooths across a gap of more than track.max_gap_s or an unknown time.
enum class SmoothMode { kOff, kCausal, kOffline };

struct SmoothOptions {
  SmoothMode mode = SmoothMode::kOff;
  // causal: the filter's gains grow with acceleration_m_s2 x dt^2 / measurement_noise_m: more
  // acceleration or less noise follows the input more closely, the reverse smooths more.
  double measurement_noise_m = 0.02;  // m, standard deviation of a triangulated joint's error
  double acceleration_m_s2 = 10.0;    // m/s^2, standard deviation of a joint's acceleration
  // offline
  double offline_sigma_s = 0.1;  // s, standard deviation of the Gaussian time weights (window +-3 sigma)
  int offline_degree = 2;        // degree of the local polynomial (1: exact on constant velocity,
                                 // 2: also on constant acceleration)
};

struct TriangulatorOptions {
  UndistortOptions undistort;
  PrefilterOptions prefilter;
  TriangulateOptions triangulate;
  RoomCheckOptions room_check;
  ScoreOptions score;
  FilterOptions filter;
  GroupOptions group;
  MergeOptions merge;
  VerifyOptions verify;
  SingleViewOptions single_view;
  PostprocessOptions postprocess;
  TrackOptions track;
  ClipSpeedOptions clip_speed;
  BoneLengthOptions bone_lengths;
  SmoothOptions smooth;

  // Joints with a score at or below this are not observations for the temporal steps
  // (bone_lengths, smooth): missing ones (0) and those filled by post-processing.
  double UnobservedScore() const {
    return postprocess.enabled && postprocess.fill_missing_joints ? postprocess.filled_joint_score : 0.0;
  }

  // Empty when valid; otherwise "section.key: problem" for the first invalid value.
  std::string Check() const;
};

}  // namespace rpt

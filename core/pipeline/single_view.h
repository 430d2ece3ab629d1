// SPDX-License-Identifier: MIT
// Step 12b (`single_view`, an addition, off by default): persons seen by only one camera.
//
// Triangulation needs two views; with few cameras and heavy occlusion (3 cameras in an operating
// room) a quarter of the people are detected in one view only. This step places such a person
// on its viewing rays at the depth its 2D limb lengths imply for a typical adult (shoulder width
// 0.36 m, hip width 0.24 m, shoulder-to-hip 0.50 m, upper arm 0.29 m, forearm 0.26 m, thigh
// 0.42 m, shin 0.40 m). Foreshortening only shortens a limb in the image, so each limb's depth
// estimate is too far, never too near; the depth taken is the second nearest of the estimates
// (the nearest when there are two), which also ignores one limb detected too long.
// The joints lie on their rays at that depth (a flat pose); their scores are the 2D confidences
// times score_factor, so these persons rank below triangulated ones.
//
// A pose is lifted only when it
//   * belongs to no kept group and overlaps no person already found (box IoU < 0.3 in its view),
//   * has at least min_core_joints core joints with confidence >= min_joint_score, two limbs of
//     the list above among them,
//   * is not contradicted by the other views (view_verdict.h, the verdict of verification: fewer
//     than min_empty_views empty views; a view is empty only if min_inside_fraction of the joints
//     land in its image),
//   * is at least duplicate_distance_m (centre to centre) from every person found and lifted
//     before it (poses are taken by decreasing mean confidence).
//
// With ground_prior (off by default) the person is instead stood upright on the floor (world z
// up, z = floor_z_m): the anchor is the mean ray of its confident ankles meeting the plane
// floor_z_m + ankle_height_m (0.08 m), or, with no ankle seen, of its hips meeting
// floor_z_m + hip_height_m (0.90 m, a standing adult's hip joint). Every joint lies where its ray
// meets the vertical plane through the anchor that faces the camera (a person standing upright,
// not a flat pose parallel to the image plane, which a camera looking down would tilt). The pose
// is lifted only if, placed so, it is plausible:
//   * the anchor ray meets its plane in front of the camera, not straight below it;
//   * its body size is a person's: the second largest of (placed limb length / typical length)
//     over the typical limbs seen (foreshortening only shortens) lies in
//     [min_body_scale, max_body_scale] (0.75-1.30);
//   * it stands: the hip-to-shoulder direction is within acos(min_upright) (60 degrees) of the
//     vertical (a lying person, a false detection spread across a bed, fail);
//   * its centre lies inside the room (core/room.h; without a room this check passes);
// plus the checks above. Poses failing the prior are counted in stats->single_view_implausible.
//
// With track_assist (off by default; needs tracking) a pose is first compared with the live
// tracks whose last multi-view support (Tracks::Slot::supported_s) is at most track_max_age_s
// old: projected into the pose's view, a track's joints valid in both lie at a mean distance of
// at most track_max_distance x the pose's box diagonal. The closest such track (each used once)
// gives the depth: every joint lies on its ray at the camera depth of the track's same joint
// (of the track's core-joint centre when the track lacks it), never a guessed depth; its score is
// the 2D confidence x score_factor x exp(-age / track_decay_s). Such persons skip the ground
// prior, not the duplicate and verification checks, and are counted in stats->single_view_tracked.
#pragma once

#include <span>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"
#include "core/pipeline/track.h"
#include "core/pipeline/view_verdict.h"
#include "core/poses.h"
#include "core/room.h"

namespace rpt {

// The joints the ground prior anchors and checks on (-1 when the joint set lacks one).
struct GroundJoints {
  int ankle_left = -1, ankle_right = -1, hip_left = -1, hip_right = -1, shoulder_left = -1, shoulder_right = -1;
};
GroundJoints ResolveGroundJoints(const JointNames& joints);

// A limb with its typical adult length, resolved to joint indices.
struct TypicalLimb {
  int a = 0, b = 0;
  double length_m = 0;
};
// The limbs listed above that `joints` has.
std::vector<TypicalLimb> ResolveTypicalLimbs(const JointNames& joints);

struct SingleViewScratch {
  ViewVerdictScratch verdict;
  std::vector<char> taken;                       // per prepared pose: used by a person already
  std::vector<std::pair<double, int>> order;     // (-mean confidence, pose) of the candidates
  std::vector<double> depths;                    // per limb of one pose
  std::vector<Eigen::Vector3d> centers;          // per person: centre of its valid core joints
  Eigen::Matrix4Xd person;                       // the person being lifted
  std::vector<char> track_used;                  // per track slot: assisted a pose this frame
};

// The ground prior's placement of one pose seen by `geo`'s camera (on `person`, 4 x J, zeroed
// first; joints with score <= 0 stay zero). Returns false when the pose is implausible (see the
// header comment); `ratios` is scratch; `body_scale` (may be null) receives the body scale
// measured (0 when the pose could not be placed).
bool PlaceOnGround(const SingleViewOptions& options, const Keypoint* kps, const ViewGeometry& geo,
                   std::span<const TypicalLimb> limbs, const GroundJoints& ground, std::vector<double>* ratios,
                   Eigen::Matrix4Xd* person, double* body_scale);

namespace steps {

struct SingleViewInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  std::span<const int> core_joints;        // output-joint indices of the core joints
  std::span<const TypicalLimb> limbs;      // the limbs with typical lengths (ResolveTypicalLimbs)
  const GroundJoints& ground;              // ground prior: ankles, hips, shoulders (ResolveGroundJoints)
  const Room& room;                        // ground prior: lifted centres must lie inside it
  const Tracks* tracks = nullptr;          // track_assist: the live tracks (nullptr without tracking)
  double timestamp_s = 0;                  // track_assist: this frame's time
  const Proposals& proposals;              // triangulate_full's, whose kept groups' poses are taken
  const Groups& groups;
  const ScoreKernel& kernel;  // the frame's kernels (step 6-7): agreement scale
  const Poses3D& found;       // the persons found so far (after post-processing)
};

// Fills `lifted` (cleared first) and counts them in stats->single_view_persons (and those the
// ground prior finds implausible in stats->single_view_implausible). Returns the number lifted.
int SingleView(const SingleViewOptions& options, const SingleViewInput& in, SingleViewScratch* scratch, Poses3D* lifted,
               FrameStats* stats);

}  // namespace steps

}  // namespace rpt

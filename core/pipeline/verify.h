// SPDX-License-Identifier: MIT
// Step 11b (`verify`, an addition): re-score each merged person against all views, to reject
// phantoms: persons assembled from poses of different people that happen to agree in the two or
// three views they came from.
//
// The person's core joints are projected into every view. A view where fewer than 3 of them land
// inside the image does not see the person. A view that sees the person either
//   * supports it: it holds one of the person's own poses (the group's pairs), or some 2D pose
//     there agrees (median residual over the shared core joints, in
//     metres at the joint's depth, at most twice the score kernel's scale), or
//   * is occupied: the person's projected box overlaps a detected pose's box (IoU >= 0.1) that
//     does not agree (an occluder, or the person hidden behind someone), or
//   * is empty: at least min_inside_fraction of the person's joints land in the image and no
//     detection is there. Detectors rarely miss a person in plain view.
// A person with at least min_empty_views empty views and more empty views than supporting views
// is dropped: more cameras look at the spot and see nobody than see the person. With few
// cameras (a phantom from 2 of 3 views has at most one empty view) the check cannot decide and
// keeps the person. Only persons that could be dropped (enough views outside their own) are
// projected, so the step costs next to nothing when every person is seen by most cameras.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/poses.h"

namespace rpt {

struct VerifyScratch {
  std::vector<Eigen::Vector4d> boxes;    // per prepared pose: min u, min v, max u, max v (undistorted px)
  std::vector<Eigen::Vector2d> projected;  // per core joint of the person being verified
  std::vector<double> depth;             // per core joint: depth in the view (m)
  std::vector<double> residuals;         // per core joint: residual against one pose (m)
  std::vector<char> own_view;            // per view: holds one of the person's own poses
};

// What one view says about a person (see above).
enum class ViewVerdict { kUnseen, kSupport, kOccupied, kEmpty };

// Bounding boxes of the prepared poses' valid joints (undistorted px): min u, min v, max u, max v.
void PoseBoxes(const PreparedViews& views, std::vector<Eigen::Vector4d>* boxes);

// The verdict of `view` on `person` (4 x joints). scratch->boxes must hold PoseBoxes(views).
// `projected_box`, when given, receives the box of the person's projected core joints.
ViewVerdict JudgeView(const VerifyOptions& options, const PreparedViews& views, const ViewGeometry& geo, int view,
                      std::span<const int> core_joints, const Eigen::Ref<const Eigen::Matrix4Xd>& person,
                      double kernel_scale_m, VerifyScratch* scratch, Eigen::Vector4d* projected_box);

namespace steps {

// Person i was merged from group i of `groups` over `proposals` (step 11), whose pairs give its own
// views. `kernel_scale_m` is the score kernel's scale (proposal_scoring.h). Removes dropped persons from
// `persons` (their track ids are not assigned yet) and counts them in stats->unsupported_persons.
// Returns the number of persons kept.
int Verify(const VerifyOptions& options, const PreparedViews& views, std::span<const ViewGeometry> geometry,
           std::span<const int> core_joints, const Proposals& proposals, const Groups& groups,
           double kernel_scale_m, VerifyScratch* scratch, Poses3D* persons, FrameStats* stats);

}  // namespace steps

}  // namespace rpt

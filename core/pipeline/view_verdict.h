// SPDX-License-Identifier: MIT
// What one view says about a 3D person: the judgement shared by verification (step 11b,
// verify.h) and the single-view step (12b, single_view.h).
//
// The person's core joints are projected into the view. A view where fewer than 3 of them land
// inside the image does not see the person (unseen). A view that sees the person either
//   * supports it: some 2D pose there agrees (median residual over the shared core joints, in
//     metres at the joint's depth, at most twice the score kernel's scale), or
//   * is occupied: the person's projected box overlaps a detected pose's box (IoU >= 0.1) that
//     does not agree (an occluder, or the person hidden behind someone), or
//   * is empty: at least `min_inside_fraction` of the person's joints land in the image and no
//     detection is there. Detectors rarely miss a person in plain view.
// A view without data this frame (Poses2D::unavailable) did not look: unseen.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/pipeline/pipeline_types.h"

namespace rpt {

enum class ViewVerdict { kUnseen, kSupport, kOccupied, kEmpty };

// Reused buffers of the judgement.
struct ViewVerdictScratch {
  std::vector<Eigen::Vector4d> boxes;      // per prepared pose: min u, min v, max u, max v (undistorted px)
  std::vector<Eigen::Vector2d> projected;  // per core joint of the person being judged
  std::vector<double> depth;               // per core joint: depth in the view (m)
  std::vector<double> residuals;           // per core joint: residual against one pose (m)
};

// Bounding boxes of the prepared poses' valid joints (undistorted px): min u, min v, max u, max v.
void PoseBoxes(const PreparedViews& views, std::vector<Eigen::Vector4d>* boxes);

// The verdict of `view` (geometry `geo`) on `person` (4 x joints). scratch->boxes must hold
// PoseBoxes(views). `kernel_scale_m` is the score kernel's scale (ScoreKernel::scale_m).
// `projected_box`, when given, receives the box of the person's projected core joints.
ViewVerdict JudgeView(const PreparedViews& views, const ViewGeometry& geo, int view, std::span<const int> core_joints,
                      const Eigen::Ref<const Eigen::Matrix4Xd>& person, double kernel_scale_m,
                      double min_inside_fraction, ViewVerdictScratch* scratch, Eigen::Vector4d* projected_box);

}  // namespace rpt

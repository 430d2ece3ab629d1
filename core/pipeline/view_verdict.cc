// SPDX-License-Identifier: MIT
#include "core/pipeline/view_verdict.h"

#include <algorithm>
#include <limits>

#include "core/pipeline/box_iou.h"
#include "core/pipeline/median.h"

namespace rpt {

void PoseBoxes(const PreparedViews& views, std::vector<Eigen::Vector4d>* boxes) {
  boxes->resize(views.num_poses());
  for (int g = 0; g < views.num_poses(); ++g) {
    Eigen::Vector4d box(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
    const Keypoint* kps = views.Pose(g);
    for (int j = 0; j < views.num_joints; ++j) {
      if (kps[j].score <= 0) continue;
      box << std::min(box[0], kps[j].u), std::min(box[1], kps[j].v), std::max(box[2], kps[j].u),
          std::max(box[3], kps[j].v);
    }
    (*boxes)[g] = box;
  }
}

ViewVerdict JudgeView(const PreparedViews& views, const ViewGeometry& geo, int view, std::span<const int> core_joints,
                      const Eigen::Ref<const Eigen::Matrix4Xd>& person, double kernel_scale_m,
                      double min_inside_fraction, ViewVerdictScratch* scratch, Eigen::Vector4d* projected_box) {
  const int num_core = static_cast<int>(core_joints.size());
  scratch->projected.resize(num_core);
  scratch->depth.resize(num_core);
  scratch->residuals.resize(num_core);
  int valid = 0, inside = 0;
  Eigen::Vector4d box(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
  for (int c = 0; c < num_core; ++c) {
    scratch->depth[c] = -1;
    if (person(3, core_joints[c]) <= 0) continue;
    const Eigen::Vector3d h = geo.P.leftCols<3>() * person.col(core_joints[c]).head<3>() + geo.P.col(3);
    ++valid;
    if (h.z() <= 0) continue;
    const Eigen::Vector2d uv = h.head<2>() / h.z();
    scratch->projected[c] = uv;
    scratch->depth[c] = h.z();
    box << std::min(box[0], uv.x()), std::min(box[1], uv.y()), std::max(box[2], uv.x()), std::max(box[3], uv.y());
    if (uv.x() >= 0 && uv.y() >= 0 && uv.x() < geo.width && uv.y() < geo.height) ++inside;
  }
  if (projected_box != nullptr) *projected_box = box;
  if (inside < 3) return ViewVerdict::kUnseen;
  if (static_cast<size_t>(view) < views.unavailable.size() && views.unavailable[view]) {
    return ViewVerdict::kUnseen;  // no data this frame: it did not look
  }
  double best = std::numeric_limits<double>::infinity();
  bool occupied = false;
  for (int g = views.view_begin[view]; g < views.view_begin[view + 1]; ++g) {
    const Keypoint* kps = views.Pose(g);
    int n = 0;
    for (int c = 0; c < num_core; ++c) {
      const Keypoint& kp = kps[core_joints[c]];
      if (scratch->depth[c] <= 0 || kp.score <= 0) continue;
      scratch->residuals[n++] =
          (scratch->projected[c] - Eigen::Vector2d(kp.u, kp.v)).norm() * scratch->depth[c] / geo.focal;
    }
    if (n >= 3) best = std::min(best, UpperMedian(scratch->residuals.data(), n));
    occupied = occupied || BoxIou(box, scratch->boxes[g]) >= 0.1;
  }
  if (best <= 2.0 * kernel_scale_m) return ViewVerdict::kSupport;
  if (!occupied && inside >= min_inside_fraction * valid) return ViewVerdict::kEmpty;
  return ViewVerdict::kOccupied;
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
// Intersection over union of two 2D boxes, used by verification (step 11b) and the single-view
// step (12b) to tell whether a detection is already explained by a person.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace rpt {

// Boxes are (x_min, y_min, x_max, y_max) in pixels; 0 when they do not overlap.
inline double BoxIou(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  const double w = std::min(a[2], b[2]) - std::max(a[0], b[0]);
  const double h = std::min(a[3], b[3]) - std::max(a[1], b[1]);
  if (w <= 0 || h <= 0) return 0.0;
  const double inter = w * h;
  const double area_a = (a[2] - a[0]) * (a[3] - a[1]), area_b = (b[2] - b[0]) * (b[3] - b[1]);
  return inter / std::max(area_a + area_b - inter, 1e-12);
}

}  // namespace rpt

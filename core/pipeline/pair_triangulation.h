// SPDX-License-Identifier: MIT
// Triangulating one joint of a pose pair: the maths shared by steps 4 (triangulate_core) and 10
// (triangulate_full).
#pragma once

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/triangulation.h"

namespace rpt {

// Triangulates one joint seen as keypoints a, b in views ga, gb; false when it cannot be
// triangulated (missing in a view, parallel rays, or behind a camera). The ray gap is always the
// mid-point method's; with the DLT method the point is then replaced by the DLT estimate.
RPT_ALWAYS_INLINE bool TriangulateJoint(const ViewGeometry& ga, const ViewGeometry& gb, const Keypoint& a,
                                        const Keypoint& b, TriangulationMethod method, Eigen::Vector3d* point,
                                        double* gap) {
  if (a.score <= 0 || b.score <= 0) return false;
  if (!TriangulateMidpoint(ga.center, a.ray, gb.center, b.ray, point, gap)) return false;
  return method != TriangulationMethod::kDlt ||
         TriangulateDlt(ga.Rt, Eigen::Vector2d(a.x, a.y), gb.Rt, Eigen::Vector2d(b.x, b.y), point);
}

}  // namespace rpt

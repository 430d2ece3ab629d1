// SPDX-License-Identifier: MIT
#include "core/pipeline/view_geometry.h"

namespace rpt {

ViewGeometry MakeViewGeometry(const Camera& camera) {
  ViewGeometry g;
  g.Rt.leftCols<3>() = camera.R;
  g.Rt.col(3) = camera.t;
  g.P = camera.K * g.Rt;
  g.R_t = camera.R.transpose();
  g.center = camera.Center();
  g.fx = camera.K(0, 0);
  g.focal = 0.5 * (camera.K(0, 0) + camera.K(1, 1));
  g.fy = camera.K(1, 1);
  g.cx = camera.K(0, 2);
  g.cy = camera.K(1, 2);
  g.skew = camera.K(0, 1);
  g.width = camera.width;
  g.height = camera.height;
  return g;
}

}  // namespace rpt

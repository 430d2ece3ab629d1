// SPDX-License-Identifier: MIT
// Two-view point triangulation kernels (fixed-size, no allocation, no exceptions).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>

#include "core/fast_math.h"

namespace rpt {

// Mid-point of the closest approach of two rays X = c + s * d (s > 0).
// Writes the mid-point and the distance between the rays at their closest points ("ray gap").
// Returns false for (near-)parallel rays or when the closest points lie behind either camera.
RPT_ALWAYS_INLINE bool TriangulateMidpoint(const Eigen::Vector3d& c1, const Eigen::Vector3d& d1, const Eigen::Vector3d& c2,
                                const Eigen::Vector3d& d2, Eigen::Vector3d* point, double* gap) {
  const Eigen::Vector3d w0 = c1 - c2;
  const double a = d1.dot(d1), b = d1.dot(d2), c = d2.dot(d2);
  const double d = d1.dot(w0), e = d2.dot(w0);
  const double denom = a * c - b * b;
  if (!(denom > 1e-12 * a * c)) return false;  // parallel rays (also catches NaN)
  const double inv_denom = 1.0 / denom;  // one division for both
  const double s = (b * e - c * d) * inv_denom;
  const double t = (a * e - b * d) * inv_denom;
  if (s <= 0 || t <= 0) return false;
  const Eigen::Vector3d p1 = c1 + s * d1;
  const Eigen::Vector3d p2 = c2 + t * d2;
  *point = 0.5 * (p1 + p2);
  *gap = (p1 - p2).norm();
  return true;
}

// Linear (DLT) triangulation from normalised image coordinates and the cam_from_world [R | t]
// of both views. The four DLT equations A [X; 1] = 0 are solved for the finite point X in the
// least-squares sense through the 3x3 normal equations (closed-form inverse), with the homogeneous
// coordinate fixed to 1. This is close to, but not exactly, the SVD null vector of A (which also
// varies the homogeneous scale; equal for noise-free points), and about 20x faster.
// Returns false for a (near-)singular system or a point behind either camera.
inline bool TriangulateDlt(const Eigen::Matrix<double, 3, 4>& rt1, const Eigen::Vector2d& xy1,
                           const Eigen::Matrix<double, 3, 4>& rt2, const Eigen::Vector2d& xy2,
                           Eigen::Vector3d* point) {
  Eigen::Matrix4d A;
  A.row(0) = xy1.x() * rt1.row(2) - rt1.row(0);
  A.row(1) = xy1.y() * rt1.row(2) - rt1.row(1);
  A.row(2) = xy2.x() * rt2.row(2) - rt2.row(0);
  A.row(3) = xy2.y() * rt2.row(2) - rt2.row(1);
  const Eigen::Matrix<double, 4, 3> B = A.leftCols<3>();
  const Eigen::Matrix3d normal = B.transpose() * B;
  const double det = normal.determinant();
  if (!(std::abs(det) > 1e-18)) return false;
  *point = normal.inverse() * (-B.transpose() * A.col(3));
  const double z1 = rt1.row(2).head<3>().dot(*point) + rt1(2, 3);
  const double z2 = rt2.row(2).head<3>().dot(*point) + rt2(2, 3);
  return z1 > 0 && z2 > 0;
}

}  // namespace rpt

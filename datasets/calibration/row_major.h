// SPDX-License-Identifier: MIT
// 3x3 matrices stored as 9 numbers row by row, as the JSON calibration files write R and K.
#pragma once

#include <Eigen/Core>

namespace rpt {

// The matrix whose rows are values[0..3), values[3..6), values[6..9).
inline Eigen::Matrix3d Matrix3FromRowMajor(const double* values) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(values);
}

}  // namespace rpt

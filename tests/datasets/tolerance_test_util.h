// SPDX-License-Identifier: MIT
// Helpers for the real-world tolerance tests of the readers (datasets/input_warnings.h):
// rotations as calibration files store them (a few significant digits) or clearly wrong, and
// checks of the counted warnings.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>

#include "datasets/input_warnings.h"

namespace rpt::test {

// max |R^T R - I|.
inline double OrthonormalityError(const Eigen::Matrix3d& R) {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

// Every entry rounded to `digits` significant digits, as calibration files print rotations.
inline Eigen::Matrix3d RoundedToSignificantDigits(const Eigen::Matrix3d& R, int digits) {
  Eigen::Matrix3d out = R;
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    double& v = out.data()[i];
    if (v == 0) continue;
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(v))));
    v = std::round(v * scale) / scale;
  }
  return out;
}

// A rotation rounded to 6 significant digits, checked to be off by more than round-off (so the
// reader must count it) and by less than the tolerance.
inline Eigen::Matrix3d RoundedRotation(const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d rounded = RoundedToSignificantDigits(R, 6);
  EXPECT_GT(OrthonormalityError(rounded), kRotationRoundOff);
  EXPECT_LT(OrthonormalityError(rounded), 1e-5);
  return rounded;
}

// R scaled by 1.005: max |R^T R - I| = 0.010025, clearly not a rotation (10 x the tolerance).
inline Eigen::Matrix3d WrongRotation(const Eigen::Matrix3d& R) { return 1.005 * R; }

// Expects `warnings` to hold exactly one entry: `count` corrections of kind `what` in `source`.
inline void ExpectOneWarning(const InputWarnings& warnings, const std::string& source, const std::string& what,
                             long count) {
  std::string lines;
  for (const InputWarning& w : warnings.items()) lines += w.Line() + "\n";
  ASSERT_EQ(warnings.items().size(), 1u) << lines;
  const InputWarning& w = warnings.items()[0];
  EXPECT_EQ(w.source, source);
  EXPECT_EQ(w.what, what);
  EXPECT_EQ(w.count, count) << w.Line();
}

inline constexpr const char* kRotationsFixed = "rotations re-orthonormalised";
inline constexpr const char* kScoresClamped = "scores above 1 clamped to 1";
inline constexpr const char* kQuaternionsFixed = "quaternions normalised";

}  // namespace rpt::test

// SPDX-License-Identifier: MIT
#include "datasets/input_warnings.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt {

std::string InputWarning::Line() const {
  std::ostringstream s;
  s << source << ": " << count << " " << what;
  if (!measure.empty()) s << " (" << measure << " = " << worst << ")";
  return PrintableText(s.str());
}

void InputWarnings::Add(const std::string& source, std::string_view what, std::string_view measure, double value,
                        long count) {
  if (count <= 0) return;
  for (InputWarning& w : items_) {
    if (w.source == source && w.what == what) {
      w.count += count;
      if (value > w.worst) w.worst = value;
      return;
    }
  }
  items_.push_back(InputWarning{source, std::string(what), std::string(measure), count, value});
}

void InputWarnings::AddCount(const std::string& source, std::string_view what, long count, InputWarningKind kind) {
  if (count <= 0) return;
  for (InputWarning& w : items_) {
    if (w.source == source && w.what == what) {
      w.count += count;
      return;
    }
  }
  items_.push_back(InputWarning{source, std::string(what), "", count, 0, kind});
}

void InputWarnings::AddUnused(const std::string& source, std::string_view what, long count) {
  AddCount(source, what, count, InputWarningKind::kUnused);
}

void InputWarnings::AddMissing(const std::string& source, std::string_view what, long count) {
  AddCount(source, what, count, InputWarningKind::kMissing);
}

void InputWarnings::Merge(const InputWarnings& other) {
  for (const InputWarning& o : other.items_) {
    bool merged = false;
    for (InputWarning& w : items_) {
      if (w.source == o.source && w.what == o.what) {
        w.count += o.count;
        if (o.worst > w.worst) w.worst = o.worst;
        merged = true;
        break;
      }
    }
    if (!merged) items_.push_back(o);
  }
}

InputWarnings InputWarnings::Except(const InputWarnings& shown) const {
  InputWarnings rest;
  for (const InputWarning& w : items_) {
    bool same = false;
    for (const InputWarning& s : shown.items_) same = same || (s.source == w.source && s.what == w.what && s.count == w.count);
    if (!same) rest.items_.push_back(w);
  }
  return rest;
}

void InputWarnings::MergeRepeated(const InputWarnings& other) {
  for (const InputWarning& o : other.items_) {
    bool merged = false;
    for (InputWarning& w : items_) {
      if (w.source == o.source && w.what == o.what) {
        if (o.count > w.count) w.count = o.count;
        if (o.worst > w.worst) w.worst = o.worst;
        merged = true;
        break;
      }
    }
    if (!merged) items_.push_back(o);
  }
}

long InputWarnings::total() const {
  long n = 0;
  for (const InputWarning& w : items_) n += w.count;
  return n;
}

std::vector<InputWarning> InputWarnings::Unused() const {
  std::vector<InputWarning> out;
  for (const InputWarning& w : items_) {
    if (w.kind == InputWarningKind::kUnused) out.push_back(w);
  }
  return out;
}

Eigen::Matrix3d AcceptRotation(const Eigen::Matrix3d& R, const std::string& source, const std::string& where,
                               InputWarnings* warnings) {
  if (!R.allFinite()) throw InputError(where + ": R is not a rotation (non-finite entries)");
  const double error = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(error <= kMaxRotationError)) {
    std::ostringstream s;
    s << where << ": R is not a rotation (max |R^T R - I| = " << error << ", at most " << kMaxRotationError
      << " is accepted and re-orthonormalised)";
    throw InputError(s.str());
  }
  if (R.determinant() < 0) throw InputError(where + ": R is a reflection (det < 0), not a rotation");
  if (error <= kRotationRoundOff) return R;
  if (warnings != nullptr) warnings->Add(source, "rotations re-orthonormalised", "max |R^T R - I|", error);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

Eigen::Vector4d AcceptQuaternion(const Eigen::Vector4d& q, const std::string& source, const std::string& where,
                                 InputWarnings* warnings) {
  const double norm = q.norm();
  const double error = std::abs(norm - 1.0);
  if (!q.allFinite() || !(error <= kMaxRotationError)) {
    std::ostringstream s;
    s << where << ": quaternion (" << q[0] << ", " << q[1] << ", " << q[2] << ", " << q[3] << ") has norm " << norm
      << ", expected a unit quaternion (norms within " << kMaxRotationError << " of 1 are accepted and normalised)";
    throw InputError(s.str());
  }
  if (error <= kRotationRoundOff) return q;
  if (warnings != nullptr) warnings->Add(source, "quaternions normalised", "max ||q| - 1|", error);
  return q / norm;
}

double AcceptScoreSlow(double score, const std::string& source, InputWarnings* warnings, const std::string& where) {
  if (score > 1.0 && score <= kMaxScoreOvershoot) {
    if (warnings != nullptr) warnings->Add(source, "scores above 1 clamped to 1", "largest", score);
    return 1.0;
  }
  std::ostringstream s;
  s << where << ": score " << score << " outside [0, 1] (values up to " << kMaxScoreOvershoot
    << " are clamped to 1)";
  throw InputError(s.str());
}

}  // namespace rpt

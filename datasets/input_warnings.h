// SPDX-License-Identifier: MIT
// What readers accept from real-world input without failing, counted so that nothing changes or
// disappears silently: imprecision they correct (rotations stored with a few significant digits,
// detector confidences slightly above 1), and input they cannot use (entries of another
// category, files whose names match no pattern, detection frames or cameras that match nothing).
// Each is counted per file and kind, so a run prints one warning line per file and kind instead
// of failing or staying silent. Anything beyond the tolerances below stays an InputError.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace rpt {

// Rotations with max |R^T R - I| up to this are replaced by the nearest rotation (and counted
// when the deviation exceeds kRotationRoundOff); larger deviations are errors. The same bound
// applies to | |q| - 1 | of a stored quaternion.
inline constexpr double kMaxRotationError = 1e-3;
// Deviations up to this are double-precision round-off: the value is kept as it is, uncounted.
inline constexpr double kRotationRoundOff = 1e-9;
// Detector confidences in (1, kMaxScoreOvershoot] are clamped to 1 and counted; larger values,
// negative values and NaN are errors.
inline constexpr double kMaxScoreOvershoot = 1.5;

// Corrections change values within the tolerances above and lose nothing; unused input is input
// the run ignores (what `--strict` refuses, docs/datasets.md "Real-world tolerance"); missing
// information is what the input does not say and the run goes without (accepted by --strict).
enum class InputWarningKind {
  kCorrected,  // e.g. rotations re-orthonormalised, scores clamped to 1
  kUnused,     // e.g. skipped entries, files matching no pattern, unmatched frames, unknown cameras
  kMissing,    // e.g. frame times unknown
};

// One kind of correction (or of unused input) in one file.
struct InputWarning {
  std::string source;  // the file (or file and place) the values came from
  std::string what;    // what was corrected, plural noun phrase, e.g. "rotations re-orthonormalised"
  std::string measure; // what `worst` measures, e.g. "max |R^T R - I|"; empty = none
  long count = 0;      // how many values were corrected (or entries, files, frames not used)
  double worst = 0;    // the largest deviation seen
  InputWarningKind kind = InputWarningKind::kCorrected;

  // "SOURCE: 3 rotations re-orthonormalised (max |R^T R - I| = 1.2e-06)".
  std::string Line() const;
};

// Counted corrections and unused input, aggregated by (source, what).
class InputWarnings {
 public:
  // `count` more corrections (or implausible values kept) of kind `what` under `source`; `value`
  // is the largest deviation among them, as `measure` measures it.
  void Add(const std::string& source, std::string_view what, std::string_view measure, double value, long count = 1);
  // `count` more items of input under `source` that are not used, of kind `what` (a plural noun
  // phrase saying what happens to them, e.g. "entries of another category than person skipped").
  // A count of 0 adds nothing.
  void AddUnused(const std::string& source, std::string_view what, long count = 1);
  // `count` more items under `source` that lack information the run then goes without, of kind
  // `what` (e.g. "labels without \"timestamp\" or \"fps\": their times are unknown ..."). 0 adds nothing.
  void AddMissing(const std::string& source, std::string_view what, long count);
  // Adds the counts of `other` (corrections of other values, e.g. another sequence of the file).
  void Merge(const InputWarnings& other);
  // Folds in `other` when it describes the same corrections seen again (the same files read once
  // more, e.g. by another configuration of a sweep): per (source, what) the larger count and
  // the larger worst value are kept instead of adding.
  void MergeRepeated(const InputWarnings& other);
  // The entries that `shown` does not hold with the same count (new, or grown since it was taken):
  // what is left to print after `shown` was printed.
  InputWarnings Except(const InputWarnings& shown) const;
  const std::vector<InputWarning>& items() const { return items_; }
  bool empty() const { return items_.empty(); }
  long total() const;
  // The entries of kind kUnused (what --strict refuses).
  std::vector<InputWarning> Unused() const;

 private:
  void AddCount(const std::string& source, std::string_view what, long count, InputWarningKind kind);

  std::vector<InputWarning> items_;
};

// The nearest rotation to `R` (SVD polar factor); `R` itself when it is orthonormal to round-off
// (max |R^T R - I| <= kRotationRoundOff). Throws InputError "<where>: R is not a rotation (...)"
// when R has non-finite entries or max |R^T R - I| > kMaxRotationError, and "<where>: R is a
// reflection ..." when det < 0; `where` names the file and the place of R. Corrections beyond
// round-off are counted under `source` (the file) when `warnings` is given.
Eigen::Matrix3d AcceptRotation(const Eigen::Matrix3d& R, const std::string& source, const std::string& where,
                               InputWarnings* warnings);

// The unit quaternion q / |q| (any component order; `q` itself within round-off). Throws
// InputError "`where`: quaternion (...) has norm ..." when | |q| - 1 | > kMaxRotationError or q is
// not finite; normalisations beyond round-off are counted under `source`.
Eigen::Vector4d AcceptQuaternion(const Eigen::Vector4d& q, const std::string& source, const std::string& where,
                                 InputWarnings* warnings);

// The branch of AcceptScore below for scores outside [0, 1].
double AcceptScoreSlow(double score, const std::string& source, InputWarnings* warnings, const std::string& where);

// `score` clamped to [0, 1]: values in (1, kMaxScoreOvershoot] become 1 and are counted under
// `source`. Throws InputError "<where()>: score ... outside [0, 1]" for NaN, negative or larger
// values; `where` (a callable returning std::string) is only called on error, so the check
// costs nothing per joint.
template <class Where>
double AcceptScore(double score, const std::string& source, InputWarnings* warnings, Where&& where) {
  if (score >= 0.0 && score <= 1.0) return score;
  return AcceptScoreSlow(score, source, warnings, where());
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "datasets/detection_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rpt {
namespace {

constexpr double kMinGtScore = 0.1;  // a GT joint is valid iff its score is above (docs/metrics.md)
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One GT person projected into one camera: per usable joint, its index in the detection joints
// and its pixel.
struct Projected {
  std::vector<int> joint;
  std::vector<Eigen::Vector2d> uv;
  double diagonal = 1;   // of the box around uv, pixels (at least 1)
  bool in_view = false;  // box centre inside the image
};
using ProjectedView = std::vector<Projected>;

// The GT persons of `gt` with at least `min_joints` valid joints that project in front of `camera`
// and exist in the detection joints (`det_of_gt`).
ProjectedView ProjectPersons(const Camera& camera, const Poses3D& gt, const std::vector<int>& det_of_gt,
                             int min_joints) {
  ProjectedView out;
  for (int g = 0; g < gt.num_persons(); ++g) {
    const auto person = gt.Person(g);
    Projected p;
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d hi = -lo;
    for (int j = 0; j < gt.num_joints; ++j) {
      const int k = det_of_gt[j];
      if (k < 0 || !(person(3, j) > kMinGtScore)) continue;
      Eigen::Vector2d uv;
      if (!camera.Project(person.col(j).head<3>(), &uv) || !uv.allFinite()) continue;
      p.joint.push_back(k);
      p.uv.push_back(uv);
      lo = lo.cwiseMin(uv);
      hi = hi.cwiseMax(uv);
    }
    if (static_cast<int>(p.joint.size()) < min_joints) continue;
    p.diagonal = std::max((hi - lo).norm(), 1.0);
    const Eigen::Vector2d centre = 0.5 * (lo + hi);
    p.in_view = centre.x() >= 0 && centre.y() >= 0 && centre.x() <= camera.width && centre.y() <= camera.height;
    out.push_back(std::move(p));
  }
  return out;
}

// Mean pixel distance between `person` and the nearest person of `view`, over the joints both
// have (the view's joints with score > 0); -1 when no person of `view` shares `min_joints`.
double NearestPx(const Projected& person, const Poses2D& view, int min_joints) {
  double best = -1;
  for (int d = 0; d < view.num_persons(); ++d) {
    const auto det = view.Person(d);
    double sum = 0;
    int n = 0;
    for (size_t i = 0; i < person.joint.size(); ++i) {
      const int k = person.joint[i];
      if (!(det(2, k) > 0)) continue;
      sum += (person.uv[i] - det.col(k).head<2>()).norm();
      ++n;
    }
    if (n < min_joints) continue;
    const double e = sum / n;
    if (best < 0 || e < best) best = e;
  }
  return best;
}

// The persons of `view` (projected GT) as 2D poses with `num_joints` joints, score 1 where projected.
Poses2D AsPoses2D(const ProjectedView& view, int num_joints) {
  Poses2D poses;
  poses.Clear(num_joints);
  for (const Projected& p : view) {
    auto person = poses.AddPerson();
    for (size_t i = 0; i < p.joint.size(); ++i) person.col(p.joint[i]) << p.uv[i], 1.0;
  }
  return poses;
}

// Mean over the in-view persons of `persons` of the relative distance to the nearest person of
// `view`; -1 when no in-view person has one.
double MeanRelDistance(const ProjectedView& persons, const Poses2D& view, int min_joints) {
  double sum = 0;
  int n = 0;
  for (const Projected& p : persons) {
    if (!p.in_view) continue;
    const double px = NearestPx(p, view, min_joints);
    if (px < 0) continue;
    sum += px / p.diagonal;
    ++n;
  }
  return n > 0 ? sum / n : -1;
}

double MedianOrNaN(std::vector<double> values) {
  if (values.empty()) return kNaN;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + mid));
}

// Up to `max` of the indices 0..n-1, evenly spaced (all when max <= 0 or n <= max).
std::vector<int> EvenlySpaced(int n, int max) {
  std::vector<int> out;
  if (max <= 0 || n <= max) {
    for (int i = 0; i < n; ++i) out.push_back(i);
  } else {
    for (int i = 0; i < max; ++i) out.push_back(static_cast<int>(static_cast<long>(i) * n / max));
  }
  return out;
}

bool HasInput(const SequenceFrame& frame) {
  for (const Poses2D& view : frame.views) {
    if (view.num_persons() > 0) return true;
  }
  return false;
}

std::string Percent(double share) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.0f %%", 100.0 * share);
  return text;
}

std::string Fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

// Projected GT per (frame, camera), computed once on demand.
class ProjectionCache {
 public:
  ProjectionCache(const Sequence& s, const std::vector<int>& det_of_gt, int min_joints)
      : s_(s), det_of_gt_(det_of_gt), min_joints_(min_joints), cache_(s.frames.size()) {}
  const ProjectedView& Get(int frame, int camera) {
    std::vector<ProjectedView>& views = cache_[frame];
    if (views.empty()) {
      views.resize(s_.cameras.size());
      for (size_t c = 0; c < s_.cameras.size(); ++c) {
        views[c] = ProjectPersons(s_.cameras[c], s_.frames[frame].gt, det_of_gt_, min_joints_);
      }
    }
    return views[camera];
  }

 private:
  const Sequence& s_;
  const std::vector<int>& det_of_gt_;
  int min_joints_;
  std::vector<std::vector<ProjectedView>> cache_;
};

ShiftCheck CheckShift(const Sequence& s, const DetectionCheckOptions& options, ProjectionCache* cache) {
  ShiftCheck shift;
  const int K = options.max_shift;
  const int n = static_cast<int>(s.frames.size());
  if (K <= 0) {
    shift.reason = "disabled";
    return shift;
  }
  // breaks[i] = number of non-continuous links among frames 0..i.
  std::vector<int> breaks(std::max(n, 1), 0);
  for (int i = 1; i < n; ++i) {
    const double dt = s.frames[i].timestamp_s - s.frames[i - 1].timestamp_s;
    const bool continuous = dt > 0 && dt <= options.max_gap_s;  // false for NaN
    breaks[i] = breaks[i - 1] + (continuous ? 0 : 1);
  }
  std::vector<int> anchors;
  for (int f = K; f + K < n; ++f) {
    if (breaks[f + K] != breaks[f - K] || !HasInput(s.frames[f])) continue;
    anchors.push_back(f);
  }
  if (anchors.empty()) {
    char text[160];
    if (n > 0 && breaks[n - 1] > 0) {
      std::snprintf(text, sizeof(text), "frames are not continuous (more than %g s apart or without a time)",
                    options.max_gap_s);
    } else {
      std::snprintf(text, sizeof(text), "no frame with detections has %d continuous frames on each side", K);
    }
    shift.reason = text;
    return shift;
  }
  const int num_shifts = 2 * K + 1;
  std::vector<std::vector<double>> units;  // per (frame, camera): relative distance per shift
  std::vector<double> motion;
  for (int sample : EvenlySpaced(static_cast<int>(anchors.size()), options.shift_frames)) {
    const int f = anchors[sample];
    const SequenceFrame& frame = s.frames[f];
    bool used = false;
    for (size_t c = 0; c < s.cameras.size(); ++c) {
      const Poses2D& view = frame.views[c];
      if (view.num_persons() == 0) continue;
      std::vector<double> unit(num_shifts);
      bool complete = true;
      for (int k = -K; k <= K && complete; ++k) {
        unit[k + K] = MeanRelDistance(cache->Get(f + k, static_cast<int>(c)), view, options.min_joints);
        complete = unit[k + K] >= 0;
      }
      if (!complete) continue;
      units.push_back(std::move(unit));
      used = true;
      const Poses2D before = AsPoses2D(cache->Get(f, static_cast<int>(c)), view.num_joints);
      const double moved = MeanRelDistance(cache->Get(f + K, static_cast<int>(c)), before, options.min_joints);
      if (moved >= 0) motion.push_back(moved);
    }
    shift.frames += used ? 1 : 0;
  }
  shift.comparisons = static_cast<long>(units.size());
  shift.rel_median.assign(num_shifts, kNaN);
  if (units.empty()) {
    shift.reason = "no GT person in view next to a detection at every shift";
    return shift;
  }
  for (int i = 0; i < num_shifts; ++i) {
    std::vector<double> values;
    for (const auto& unit : units) values.push_back(unit[i]);
    shift.rel_median[i] = MedianOrNaN(values);
  }
  shift.best_shift = -K;
  for (int k = -K; k <= K; ++k) {
    if (k != 0 && shift.RelAt(k) < shift.RelAt(shift.best_shift)) shift.best_shift = k;
  }
  long wins = 0;
  for (const auto& unit : units) wins += unit[shift.best_shift + K] < unit[K] ? 1 : 0;
  shift.win_share = static_cast<double>(wins) / units.size();
  shift.motion_rel = MedianOrNaN(motion);
  if (shift.frames < kShiftMinFrames) {
    shift.reason = "only " + std::to_string(shift.frames) + " frames with " + std::to_string(K) +
                   " continuous frames on each side";
  } else if (!(shift.motion_rel >= std::min(shift.RelAt(0), shift.RelAt(shift.best_shift)))) {
    // Over K frames the GT moves less than the detections err at their best shift: a shift
    // would not stand out from the detection error.
    shift.reason = "the GT moves less over " + std::to_string(K) + " frames (median " +
                   Fixed(std::isfinite(shift.motion_rel) ? shift.motion_rel : 0, 3) +
                   " of the person's box) than the detections err (" +
                   Fixed(std::min(shift.RelAt(0), shift.RelAt(shift.best_shift)), 3) + ")";
  } else {
    shift.tested = true;
  }
  return shift;
}

}  // namespace

SequenceCheck CheckDetections(const Sequence& s, const DetectionCheckOptions& options) {
  SequenceCheck check;
  check.sequence = s.name;
  check.frames = static_cast<long>(s.frames.size());
  std::vector<int> det_of_gt(s.gt_joints.size(), -1);
  for (size_t j = 0; j < s.gt_joints.size(); ++j) {
    det_of_gt[j] = FindJoint(s.detection_joints, s.gt_joints[j]);
    check.shared_joints += det_of_gt[j] >= 0 ? 1 : 0;
  }
  ProjectionCache cache(s, det_of_gt, options.min_joints);
  const int num_cameras = static_cast<int>(s.cameras.size());
  check.cameras.resize(num_cameras);
  for (int c = 0; c < num_cameras; ++c) check.cameras[c].name = s.cameras[c].name;

  // Counts over all frames (cheap).
  for (const SequenceFrame& frame : s.frames) {
    const bool input = HasInput(frame);
    if (frame.gt.num_persons() > 0) {
      ++check.frames_with_gt;
      check.frames_with_gt_no_input += input ? 0 : 1;
    }
    if (!input) continue;
    for (int c = 0; c < num_cameras; ++c) {
      CameraCheck& camera = check.cameras[c];
      ++camera.input_frames;
      camera.detections += frame.views[c].num_persons();
      camera.empty_frames += frame.views[c].num_persons() == 0 ? 1 : 0;
    }
  }

  // Distances over the measured frames.
  std::vector<std::vector<double>> px(num_cameras), rel(num_cameras);
  const std::vector<int> measured = EvenlySpaced(static_cast<int>(s.frames.size()), options.max_frames);
  check.measured_frames = static_cast<long>(measured.size());
  for (int f : measured) {
    const SequenceFrame& frame = s.frames[f];
    if (frame.gt.num_persons() == 0 || !HasInput(frame)) continue;
    for (int c = 0; c < num_cameras; ++c) {
      CameraCheck& camera = check.cameras[c];
      const Poses2D& view = frame.views[c];
      long in_view = 0;
      for (const Projected& p : cache.Get(f, c)) {
        if (!p.in_view) continue;
        ++in_view;
        const double d = NearestPx(p, view, options.min_joints);
        if (d < 0) continue;
        px[c].push_back(d);
        rel[c].push_back(d / p.diagonal);
      }
      camera.gt_in_view += in_view;
      if (in_view > 0) {
        ++camera.frames_gt_in_view;
        camera.empty_frames_gt_in_view += view.num_persons() == 0 ? 1 : 0;
      }
    }
  }
  for (int c = 0; c < num_cameras; ++c) {
    check.cameras[c].gt_compared = static_cast<long>(px[c].size());
    check.cameras[c].px_median = MedianOrNaN(px[c]);
    check.cameras[c].rel_median = MedianOrNaN(rel[c]);
  }
  check.shift = CheckShift(s, options, &cache);
  return check;
}

std::vector<SequenceCheck> CheckDetections(const std::vector<Sequence>& sequences,
                                           const DetectionCheckOptions& options) {
  std::vector<SequenceCheck> checks;
  checks.reserve(sequences.size());
  for (const Sequence& s : sequences) checks.push_back(CheckDetections(s, options));
  return checks;
}

bool LooksShifted(const ShiftCheck& shift) {
  return shift.tested && shift.best_shift != 0 && shift.RelAt(shift.best_shift) <= kShiftMaxRatio * shift.RelAt(0) &&
         shift.win_share >= kShiftMinWinShare;
}

std::vector<CheckWarning> DetectionWarnings(const SequenceCheck& check) {
  std::vector<CheckWarning> warnings;
  const std::string& seq = check.sequence;
  if (check.frames_with_gt > 0 && check.frames_with_gt_no_input >= kEmptyCameraShare * check.frames_with_gt) {
    warnings.push_back(
        {"frames_without_detections",
         seq + ": " + std::to_string(check.frames_with_gt_no_input) + " of " + std::to_string(check.frames_with_gt) +
             " frames with GT persons (" + Percent(static_cast<double>(check.frames_with_gt_no_input) / check.frames_with_gt) +
             ") have no 2D detection in any camera; do the frame ids of the detections match the labels?"});
  }
  if (check.frames_with_gt > 0 && check.shared_joints < kMinSharedJoints) {
    warnings.push_back({"no_shared_joints", seq + ": only " + std::to_string(check.shared_joints) +
                                                " GT joint names also exist in the detections; GT and detections "
                                                "cannot be compared (joint names?)"});
  }
  for (const CameraCheck& camera : check.cameras) {
    const std::string where = seq + ", camera " + camera.name;
    if (camera.input_frames > 0 && camera.detections == 0) {
      warnings.push_back({"camera_without_detections",
                          where + ": no detections in any of the " + std::to_string(camera.input_frames) +
                              " frames where other cameras have some; is the camera's name or order in the detections "
                              "right?"});
    } else if (camera.frames_gt_in_view > 0 &&
               camera.empty_frames_gt_in_view >= kEmptyCameraShare * camera.frames_gt_in_view) {
      warnings.push_back(
          {"camera_often_without_detections",
           where + ": no detections in " + std::to_string(camera.empty_frames_gt_in_view) + " of the " +
               std::to_string(camera.frames_gt_in_view) + " frames where GT persons are in its view (" +
               Percent(static_cast<double>(camera.empty_frames_gt_in_view) / camera.frames_gt_in_view) + ")"});
    }
    if (camera.gt_compared >= kMinComparedPersons && camera.rel_median >= kFarRelDistance) {
      warnings.push_back({"gt_far_from_detections",
                          where + ": projected GT is far from the detections (median " + Fixed(camera.rel_median, 2) +
                              " of the person's box diagonal, " + Fixed(camera.px_median, 0) + " px, over " +
                              std::to_string(camera.gt_compared) + " GT persons; expected < " +
                              Fixed(kFarRelDistance, 2) + "); check calibration, camera order and units"});
    } else if (camera.detections > 0 && check.frames_with_gt > 0 && check.shared_joints >= kMinSharedJoints &&
               camera.gt_in_view == 0) {
      warnings.push_back({"gt_far_from_detections", where + ": no GT person projects into the image although the camera has " +
                                                std::to_string(camera.detections) +
                                                " detections; check calibration, camera order and units"});
    }
  }
  const ShiftCheck& shift = check.shift;
  if (LooksShifted(shift)) {
    const int k = shift.best_shift;
    warnings.push_back(
        {"detections_frame_shifted",
         seq + ": the detections of frame f fit the GT of frame f" + (k > 0 ? "+" : "") + std::to_string(k) +
             " better than their own (median " + Fixed(shift.RelAt(k), 3) + " vs " + Fixed(shift.RelAt(0), 3) +
             " of the box diagonal, closer in " + Percent(shift.win_share) + " of " +
             std::to_string(shift.comparisons) + " comparisons); are detections and labels shifted by " +
             std::to_string(std::abs(k)) + " frame(s)?"});
  }
  return warnings;
}

}  // namespace rpt

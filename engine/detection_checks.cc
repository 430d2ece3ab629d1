// SPDX-License-Identifier: MIT
#include "engine/detection_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <map>
#include <utility>

#include "core/nan.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "metrics/timing.h"

namespace rpt::engine {
// Not an anonymous namespace: DetectionChecker::State, a class with linkage, holds these types.
namespace detection_checks_internal {

constexpr double kMinGtScore = 0.1;  // a GT joint is valid iff its score is above (docs/metrics.md)

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

// metrics::Median, but NaN (not measured) for no values.
double MedianOrNaN(const std::vector<double>& values) { return values.empty() ? kNaN : metrics::Median(values); }

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

// Keeps every stride-th of the items offered (by their running index), doubling the stride
// whenever more than `max_kept` are kept: a sample spread over a stream of unknown length, in
// bounded memory. With max_kept = 0, or while at most max_kept items came, it keeps all.
template <class T>
class Thinning {
 public:
  explicit Thinning(size_t max_kept) : max_kept_(max_kept) {}
  bool Wants(long index) const { return index % stride_ == 0; }
  void Add(long index, T item) {
    if (!Wants(index)) return;
    kept_.push_back({index, std::move(item)});
    if (max_kept_ == 0 || kept_.size() <= max_kept_) return;
    stride_ *= 2;
    std::erase_if(kept_, [&](const auto& entry) { return entry.first % stride_ != 0; });
  }
  // Up to `max` of the kept items, evenly spaced (all when max <= 0).
  std::vector<const T*> Pick(int max) const {
    std::vector<const T*> out;
    for (int i : EvenlySpaced(static_cast<int>(kept_.size()), max)) out.push_back(&kept_[i].second);
    return out;
  }

 private:
  size_t max_kept_;
  long stride_ = 1;
  std::vector<std::pair<long, T>> kept_;
};

// What one measured frame contributes per camera.
struct MeasuredCamera {
  long in_view = 0;
  bool empty = false;
  std::vector<double> px, rel;
};
using MeasuredFrame = std::vector<MeasuredCamera>;  // empty: no GT person or no detection

// What one sampled shift anchor contributes: per (camera with detections) the relative distance
// per shift, and the GT motion over max_shift frames.
struct AnchorUnits {
  std::vector<std::vector<double>> units;
  std::vector<double> motion;
};

}  // namespace detection_checks_internal

using namespace detection_checks_internal;  // NOLINT(build/namespaces): this file's own helpers

// The frames the checks still need: the last 2 * max_shift + 1 (with their GT projections,
// computed once on demand), the counts, and the sampled measurements.
struct DetectionChecker::State {
  struct Entry {
    long index = 0;
    bool input = false;
    std::vector<Poses2D> views;
    Poses3D gt;
    std::vector<ProjectedView> projected;  // per camera, empty until needed
  };

  State(const SequenceHeader& h, long n, double gap, const DetectionCheckOptions& o)
      : header(h), options(o), max_gap_s(gap), num_frames(n),
        measured_thinning(n >= 0 ? 0 : 2 * static_cast<size_t>(std::max(o.max_frames, 0))),
        anchor_thinning(o.shift_frames > 0 ? 2 * static_cast<size_t>(o.shift_frames) : 0) {
    check.sequence = h.name;
    det_of_gt.assign(h.gt_joints.size(), -1);
    for (size_t j = 0; j < h.gt_joints.size(); ++j) {
      det_of_gt[j] = FindJoint(h.detection_joints, h.gt_joints[j]);
      check.shared_joints += det_of_gt[j] >= 0 ? 1 : 0;
    }
    check.cameras.resize(h.cameras.size());
    for (size_t c = 0; c < h.cameras.size(); ++c) check.cameras[c].name = h.cameras[c].name;
    if (n >= 0) measured = EvenlySpaced(static_cast<int>(n), o.max_frames);
    K = std::max(o.max_shift, 0);
  }

  Entry& At(long index) { return ring[ring.size() - 1 - (last - index)]; }
  const ProjectedView& ProjectedAt(long index, int camera) {
    Entry& e = At(index);
    if (e.projected.empty()) {
      e.projected.resize(header.cameras.size());
      for (size_t c = 0; c < header.cameras.size(); ++c) {
        e.projected[c] = ProjectPersons(header.cameras[c], e.gt, det_of_gt, options.min_joints);
      }
    }
    return e.projected[camera];
  }

  bool IsMeasured(long f) {
    if (num_frames < 0) return measured_thinning.Wants(f);
    while (next_measured < measured.size() && measured[next_measured] < f) ++next_measured;
    return next_measured < measured.size() && measured[next_measured] == f;
  }

  void Measure(long f) {
    Entry& e = At(f);
    MeasuredFrame out;
    if (e.gt.num_persons() > 0 && e.input) {
      out.resize(header.cameras.size());
      for (size_t c = 0; c < header.cameras.size(); ++c) {
        MeasuredCamera& camera = out[c];
        const Poses2D& view = e.views[c];
        camera.empty = view.num_persons() == 0;
        for (const Projected& p : ProjectedAt(f, static_cast<int>(c))) {
          if (!p.in_view) continue;
          ++camera.in_view;
          const double d = NearestPx(p, view, options.min_joints);
          if (d < 0) continue;
          camera.px.push_back(d);
          camera.rel.push_back(d / p.diagonal);
        }
      }
    }
    measured_thinning.Add(f, std::move(out));
  }

  void Anchor(long f) {
    const long a = anchors++;
    if (!anchor_thinning.Wants(a)) return;
    AnchorUnits out;
    const Entry& e = At(f);
    for (size_t c = 0; c < header.cameras.size(); ++c) {
      const Poses2D& view = e.views[c];
      if (view.num_persons() == 0) continue;
      std::vector<double> unit(2 * K + 1);
      bool complete = true;
      for (int k = -K; k <= K && complete; ++k) {
        unit[k + K] = MeanRelDistance(ProjectedAt(f + k, static_cast<int>(c)), view, options.min_joints);
        complete = unit[k + K] >= 0;
      }
      if (!complete) continue;
      out.units.push_back(std::move(unit));
      const Poses2D before = AsPoses2D(ProjectedAt(f, static_cast<int>(c)), view.num_joints);
      const double moved = MeanRelDistance(ProjectedAt(f + K, static_cast<int>(c)), before, options.min_joints);
      if (moved >= 0) out.motion.push_back(moved);
    }
    anchor_thinning.Add(a, std::move(out));
  }

  // Frame f is done with: measured if sampled, a shift anchor when its max_shift neighbours on
  // each side exist, are continuous and it has detections.
  void Process(long f, bool has_next_k) {
    if (IsMeasured(f)) Measure(f);
    if (K > 0 && has_next_k && f >= K && last_break <= f - K && At(f).input) Anchor(f);
  }

  SequenceHeader header;
  DetectionCheckOptions options;
  double max_gap_s;
  long num_frames;
  int K = 0;
  std::vector<int> det_of_gt;
  SequenceCheck check;
  std::deque<Entry> ring;
  long last = -1;             // index of the newest frame
  long next_center = 0;       // the next frame to process
  double last_time = 0;
  long last_break = 0;        // the last frame not continuous with its predecessor (0: none)
  bool any_break = false;
  std::vector<int> measured;  // with a known frame count: the measured frames
  size_t next_measured = 0;
  Thinning<MeasuredFrame> measured_thinning;
  long anchors = 0;           // eligible shift anchors seen
  Thinning<AnchorUnits> anchor_thinning;
};

DetectionChecker::DetectionChecker(const SequenceHeader& header, long num_frames, double max_gap_s,
                                   const DetectionCheckOptions& options)
    : state_(std::make_unique<State>(header, num_frames, max_gap_s, options)) {}
DetectionChecker::~DetectionChecker() = default;
DetectionChecker::DetectionChecker(DetectionChecker&&) noexcept = default;
DetectionChecker& DetectionChecker::operator=(DetectionChecker&&) noexcept = default;

void DetectionChecker::Add(const SequenceFrame& frame) {
  State& s = *state_;
  const long f = ++s.last;
  if (f > 0) {
    const double dt = frame.timestamp_s - s.last_time;
    if (!(dt > 0 && dt <= s.max_gap_s)) {  // NaN: not continuous
      s.last_break = f;
      s.any_break = true;
    }
  }
  s.last_time = frame.timestamp_s;
  ++s.check.frames;

  // Counts over all frames (cheap).
  const bool input = HasInput(frame);
  if (frame.gt.num_persons() > 0) {
    ++s.check.frames_with_gt;
    s.check.frames_with_gt_no_input += input ? 0 : 1;
  }
  if (input) {
    for (size_t c = 0; c < s.check.cameras.size(); ++c) {
      CameraCheck& camera = s.check.cameras[c];
      ++camera.input_frames;
      camera.detections += frame.views[c].num_persons();
      camera.empty_frames += frame.views[c].num_persons() == 0 ? 1 : 0;
    }
  }

  if (s.ring.size() == static_cast<size_t>(2 * s.K + 1)) {
    State::Entry recycled = std::move(s.ring.front());
    s.ring.pop_front();
    s.ring.push_back(std::move(recycled));
  } else {
    s.ring.emplace_back();
  }
  State::Entry& e = s.ring.back();
  e.index = f;
  e.input = input;
  if (input) {
    e.views = frame.views;
  } else {
    e.views.assign(s.header.cameras.size(), Poses2D{});
  }
  e.gt = frame.gt;
  e.projected.clear();
  for (; s.next_center + s.K <= f; ++s.next_center) s.Process(s.next_center, /*has_next_k=*/true);
}

SequenceCheck DetectionChecker::Finish() {
  State& s = *state_;
  for (; s.next_center <= s.last; ++s.next_center) s.Process(s.next_center, /*has_next_k=*/false);
  SequenceCheck check = std::move(s.check);
  const int num_cameras = static_cast<int>(check.cameras.size());

  // Distances over the measured frames.
  std::vector<std::vector<double>> px(num_cameras), rel(num_cameras);
  const std::vector<const MeasuredFrame*> measured = s.measured_thinning.Pick(s.num_frames >= 0 ? 0 : s.options.max_frames);
  check.measured_frames = static_cast<long>(measured.size());
  for (const MeasuredFrame* frame : measured) {
    for (int c = 0; c < static_cast<int>(frame->size()); ++c) {
      const MeasuredCamera& m = (*frame)[c];
      CameraCheck& camera = check.cameras[c];
      camera.gt_in_view += m.in_view;
      if (m.in_view > 0) {
        ++camera.frames_gt_in_view;
        camera.empty_frames_gt_in_view += m.empty ? 1 : 0;
      }
      px[c].insert(px[c].end(), m.px.begin(), m.px.end());
      rel[c].insert(rel[c].end(), m.rel.begin(), m.rel.end());
    }
  }
  for (int c = 0; c < num_cameras; ++c) {
    check.cameras[c].gt_compared = static_cast<long>(px[c].size());
    check.cameras[c].px_median = MedianOrNaN(px[c]);
    check.cameras[c].rel_median = MedianOrNaN(rel[c]);
  }

  // The frame-shift test over the sampled anchors.
  ShiftCheck& shift = check.shift;
  const int K = s.options.max_shift;
  if (K <= 0) {
    shift.reason = "disabled";
    return check;
  }
  if (s.anchors == 0) {
    char text[160];
    if (s.any_break) {
      std::snprintf(text, sizeof(text), "frames are not continuous (more than %g s apart or without a time)",
                    s.max_gap_s);
    } else {
      std::snprintf(text, sizeof(text), "no frame with detections has %d continuous frames on each side", K);
    }
    shift.reason = text;
    return check;
  }
  const int num_shifts = 2 * K + 1;
  std::vector<std::vector<double>> units;  // per (frame, camera): relative distance per shift
  std::vector<double> motion;
  for (const AnchorUnits* anchor : s.anchor_thinning.Pick(s.options.shift_frames)) {
    units.insert(units.end(), anchor->units.begin(), anchor->units.end());
    motion.insert(motion.end(), anchor->motion.begin(), anchor->motion.end());
    shift.frames += anchor->units.empty() ? 0 : 1;
  }
  shift.comparisons = static_cast<long>(units.size());
  shift.rel_median.assign(num_shifts, kNaN);
  if (units.empty()) {
    shift.reason = "no GT person in view next to a detection at every shift";
    return check;
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
                   FixedText(std::isfinite(shift.motion_rel) ? shift.motion_rel : 0, 3) +
                   " of the person's box) than the detections err (" +
                   FixedText(std::min(shift.RelAt(0), shift.RelAt(shift.best_shift)), 3) + ")";
  } else {
    shift.tested = true;
  }
  return check;
}

SequenceCheck CheckDetections(const Sequence& s, double max_gap_s, const DetectionCheckOptions& options) {
  DetectionChecker checker(s, static_cast<long>(s.frames.size()), max_gap_s, options);
  for (const SequenceFrame& frame : s.frames) checker.Add(frame);
  return checker.Finish();
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
             " frames with GT persons (" +
             PercentText(static_cast<double>(check.frames_with_gt_no_input) / check.frames_with_gt) +
             ") have no 2D detection in any camera; do the frame ids of the detections match the labels?"});
  }
  if (check.frames_with_gt > 0 && check.shared_joints < kMinSharedJoints) {
    warnings.push_back({"no_shared_joints", seq + ": only " + std::to_string(check.shared_joints) +
                                                " GT joint names also exist in the detections; GT and detections "
                                                "cannot be compared (joint names?)"});
  }
  // Per camera and code, the first kMaxCameraWarningsShown are printed and the others counted in one
  // line: 100 000 cameras gave 99 999 warning lines.
  std::map<std::string, long> per_code;
  const auto camera_warning = [&](CheckWarning warning) {
    if (++per_code[warning.code] <= kMaxCameraWarningsShown) warnings.push_back(std::move(warning));
  };
  for (const CameraCheck& camera : check.cameras) {
    const std::string where = seq + ", camera " + camera.name;
    if (camera.input_frames > 0 && camera.detections == 0) {
      camera_warning({"camera_without_detections",
                          where + ": no detections in any of the " + std::to_string(camera.input_frames) +
                              " frames where other cameras have some; is the camera's name or order in the detections "
                              "right?"});
    } else if (camera.frames_gt_in_view > 0 &&
               camera.empty_frames_gt_in_view >= kEmptyCameraShare * camera.frames_gt_in_view) {
      camera_warning({"camera_often_without_detections",
                      where + ": no detections in " + std::to_string(camera.empty_frames_gt_in_view) + " of the " +
                          std::to_string(camera.frames_gt_in_view) + " frames where GT persons are in its view (" +
                          PercentText(static_cast<double>(camera.empty_frames_gt_in_view) / camera.frames_gt_in_view) +
                          ")"});
    }
    // The median of the other judged cameras' medians (NaN with fewer than two).
    std::vector<double> others;
    for (const CameraCheck& other : check.cameras) {
      if (&other != &camera && other.gt_compared >= kMinComparedPersons && std::isfinite(other.rel_median))
        others.push_back(other.rel_median);
    }
    const double others_median = others.size() >= 2 ? MedianOrNaN(others) : kNaN;
    const bool judged = camera.gt_compared >= kMinComparedPersons;
    if (judged && camera.rel_median < kFarRelDistance && camera.rel_median >= kFarRelFloor &&
        camera.rel_median >= kFarRelFactor * others_median) {
      camera_warning({"gt_far_from_detections",
                      where + ": projected GT is far from the detections compared with the other cameras (median " +
                          FixedText(camera.rel_median, 2) + " of the person's box diagonal, " +
                          FixedText(camera.px_median, 0) + " px, over " + std::to_string(camera.gt_compared) +
                          " GT persons; " + FixedText(camera.rel_median / others_median, 1) +
                          " times the other cameras' " + FixedText(others_median, 3) +
                          "); check its calibration and that its detections are its own (camera names and order)"});
    } else if (judged && camera.rel_median >= kFarRelDistance) {
      camera_warning({"gt_far_from_detections",
                      where + ": projected GT is far from the detections (median " + FixedText(camera.rel_median, 2) +
                          " of the person's box diagonal, " + FixedText(camera.px_median, 0) + " px, over " +
                          std::to_string(camera.gt_compared) + " GT persons; expected < " +
                          FixedText(kFarRelDistance, 2) + "); check calibration, camera order and units"});
    } else if (camera.detections > 0 && check.frames_with_gt > 0 && check.shared_joints >= kMinSharedJoints &&
               camera.gt_in_view == 0) {
      camera_warning({"gt_far_from_detections", where + ": no GT person projects into the image although the camera has " +
                                                std::to_string(camera.detections) +
                                                " detections; check calibration, camera order and units"});
    }
  }
  for (const auto& [code, count] : per_code) {
    if (count > kMaxCameraWarningsShown) {
      warnings.push_back({code, seq + ": " + std::to_string(count - kMaxCameraWarningsShown) +
                                    " more cameras with the warning " + QuoteName(code) + " (" + std::to_string(count) +
                                    " in all; the first " + std::to_string(kMaxCameraWarningsShown) + " above)"});
    }
  }
  const ShiftCheck& shift = check.shift;
  if (LooksShifted(shift)) {
    const int k = shift.best_shift;
    warnings.push_back({"detections_frame_shifted",
                        seq + ": the detections of frame f fit the GT of frame f" + (k > 0 ? "+" : "") +
                            std::to_string(k) + " better than their own (median " + FixedText(shift.RelAt(k), 3) +
                            " vs " + FixedText(shift.RelAt(0), 3) + " of the box diagonal, closer in " +
                            PercentText(shift.win_share) + " of " + std::to_string(shift.comparisons) +
                            " comparisons); are detections and labels shifted by " + std::to_string(std::abs(k)) +
                            " frame(s)?"});
  }
  return warnings;
}

}  // namespace rpt::engine

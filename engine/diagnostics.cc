// SPDX-License-Identifier: MIT
#include "engine/diagnostics.h"
#include "core/printable_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson OrNull(double value) { return std::isfinite(value) ? OrderedJson(value) : OrderedJson(nullptr); }

// The first step after which no item is left in any frame, or -1.
int FirstEmptyStep(const metrics::StepCountSummary& counts) {
  for (int s = 0; s <= static_cast<int>(Step::kPostprocess); ++s) {
    if (counts.count_per_frame[s] == 0) return s;
  }
  return -1;
}

}  // namespace

std::vector<CheckWarning> ResultWarnings(const RunResult& run) {
  std::vector<CheckWarning> warnings;
  const long frames_with_gt = run.frames_with_gt;
  const long without_prediction = run.frames_with_gt_without_prediction;
  char text[400];
  if (run.output_persons == 0) {
    std::snprintf(text, sizeof(text), "no predictions at all: nobody was triangulated in %ld frames with %ld GT persons",
                  run.frames, run.gt_persons);
    std::string message = text;
    const int empty = FirstEmptyStep(run.counts);
    if (empty >= 0) {
      message += "; nothing is left after step " + QuoteName(std::string(kSteps[empty].key)) + " (see the count / frame column)";
    }
    warnings.push_back({"no_predictions", message});
    return warnings;  // the other result warnings would only repeat it
  }
  // No GT person in any frame: a labels file without "bodies3D" (or of another split) looked like
  // a triangulator whose every prediction is Invalid (F1 0), exit 0 and no word.
  if (run.gt_persons == 0) {
    std::snprintf(text, sizeof(text),
                  "no ground truth: the input has no 3D GT person in any of its %ld frames, so every one of the %ld "
                  "predictions counts as Invalid and F1 is 0; check the labels (their 3D persons, the split), or "
                  "triangulate without ground truth with `rpt triangulate`",
                  run.frames, run.output_persons);
    warnings.push_back({"no_ground_truth", text});
    return warnings;  // the other result warnings would only repeat it
  }
  if (frames_with_gt > 0 && without_prediction >= kMaxShareFramesWithoutPrediction * frames_with_gt) {
    std::snprintf(text, sizeof(text), "%ld of %ld frames with GT persons (%.0f %%) have no prediction", without_prediction,
                  frames_with_gt, 100.0 * without_prediction / frames_with_gt);
    warnings.push_back({"frames_without_predictions", text});
  }
  // A whole-body group the detector gave nothing of (OpenPose without face points): its joints are
  // neighbours' copies, and its number measures the filling, not a triangulation.
  for (const metrics::GroupResult& group : run.metrics.wholebody) {
    if (group.num_persons == 0 || group.filled_share < kMinFilledShareWarned) continue;
    std::snprintf(text, sizeof(text),
                  "whole-body group %s: %.0f %% of its measured joints were filled from a neighbour, not "
                  "triangulated (did the detector give these points?): its MPJPE measures the filling",
                  group.name.c_str(), 100.0 * group.filled_share);
    warnings.push_back({"wholebody_group_filled", text});
  }
  // Whole-body ground truth against predictions without a group's joints (body-only detections of a
  // whole-body dataset: 116 joints not measured, and "All" over 17, without a word).
  for (const metrics::GroupResult& group : run.metrics.wholebody) {
    if (group.name == "All" || group.num_gt_only_joints == 0 || group.num_joints > 0) continue;
    std::snprintf(text, sizeof(text),
                  "whole-body group %s: the ground truth has %d of its joints, the predictions none (detections "
                  "of the body only?): it is not measured, and All is over the joints both have",
                  group.name.c_str(), group.num_gt_only_joints);
    warnings.push_back({"wholebody_group_unmeasured", text});
  }
  const double recall = run.metrics.recall_500;
  if (std::isfinite(recall) && recall < kMinRecall500) {
    std::snprintf(text, sizeof(text),
                  "very low recall: Recall@500 is %.1f %% (below %.0f %%): most GT persons have no prediction within "
                  "500 mm",
                  recall, kMinRecall500);
    warnings.push_back({"low_recall", text});
  }
  return warnings;
}

std::string SpeedClipWarning(const RunResult& run, const ClipSpeedOptions& clip) {
  if (!clip.enabled || run.frames == 0 || run.sequences.empty()) return "";
  const double clipped = run.counts.count_per_frame[static_cast<size_t>(Step::kClipSpeed)];
  const double joints = static_cast<double>(run.output_persons) / static_cast<double>(run.frames) *
                        static_cast<double>(run.sequences.front().output_joints.size());
  if (!(joints > 0) || clipped <= kMaxClippedJointShare * joints) return "";
  char text[600];
  std::snprintf(text, sizeof(text),
                "%.1f %% of the joints output were moved by speed clipping (%.1f per frame, to at most "
                "clip_speed.max_speed_m_s = %g m/s from the track's last position): fast motion (a sprint's ankles, "
                "a throw's hands pass 15-20 m/s) lags behind; raise it (--set clip_speed.max_speed_m_s=30) or turn it "
                "off (--set clip_speed.enabled=false). Unless the joints jump instead: detections that land "
                "somewhere else each frame (occluded hands reported at low scores) are clipped too, and raising the "
                "limit lets them through (look at the joints clipped: `rpt render`)",
                100.0 * clipped / joints, clipped, clip.max_speed_m_s);
  return text;
}

EvalDiagnostics Diagnose(const RunResult& run) {
  EvalDiagnostics diagnostics;
  for (const SequenceResult& sequence : run.sequences) {
    if (sequence.check) diagnostics.checks.push_back(*sequence.check);
  }
  for (const SequenceCheck& check : diagnostics.checks) {
    for (CheckWarning& w : DetectionWarnings(check)) diagnostics.warnings.push_back(std::move(w));
  }
  for (const SequenceResult& sequence : run.sequences) {
    for (const std::string& line : sequence.camera_sync) diagnostics.warnings.push_back({"camera_sync", line});
  }
  for (CheckWarning& w : ResultWarnings(run)) diagnostics.warnings.push_back(std::move(w));
  return diagnostics;
}

OrderedJson CameraCheckJson(const CameraCheck& camera) {
  OrderedJson j;
  j["name"] = camera.name;
  j["detections"] = camera.detections;
  j["frames_gt_in_view"] = camera.frames_gt_in_view;
  j["empty_frames_gt_in_view"] = camera.empty_frames_gt_in_view;
  j["gt_persons_compared"] = camera.gt_compared;
  j["gt_to_detection_px_median"] = OrNull(camera.px_median);
  j["gt_to_detection_rel_median"] = OrNull(camera.rel_median);
  return j;
}

OrderedJson ShiftCheckJson(const ShiftCheck& shift) {
  OrderedJson j;
  j["tested"] = shift.tested;
  if (!shift.reason.empty()) j["reason"] = shift.reason;
  if (shift.comparisons == 0) return j;
  j["frames"] = shift.frames;
  j["comparisons"] = shift.comparisons;
  j["best_shift"] = shift.best_shift;
  j["rel_median_at_0"] = OrNull(shift.RelAt(0));
  j["rel_median_at_best"] = OrNull(shift.RelAt(shift.best_shift));
  j["win_share"] = shift.win_share;
  j["motion_rel"] = OrNull(shift.motion_rel);
  return j;
}

OrderedJson DiagnosticsJson(const EvalDiagnostics& diagnostics) {
  OrderedJson j;
  j["warnings"] = OrderedJson::array();
  for (const CheckWarning& w : diagnostics.warnings) j["warnings"].push_back({{"code", w.code}, {"message", w.message}});
  j["data_checks"] = OrderedJson::array();
  for (const SequenceCheck& check : diagnostics.checks) {
    OrderedJson seq;
    seq["sequence"] = check.sequence;
    seq["measured_frames"] = check.measured_frames;
    seq["frames_with_gt"] = check.frames_with_gt;
    seq["frames_with_gt_without_detections"] = check.frames_with_gt_no_input;
    seq["cameras"] = OrderedJson::array();
    for (const CameraCheck& camera : check.cameras) seq["cameras"].push_back(CameraCheckJson(camera));
    seq["frame_shift"] = ShiftCheckJson(check.shift);
    j["data_checks"].push_back(seq);
  }
  return j;
}

std::string ShiftLine(const ShiftCheck& shift) {
  char line[400];
  const char* what = "frame shift (detections of frame f vs GT of frame f+k)";
  if (!shift.tested) {
    std::snprintf(line, sizeof(line), "%s: not tested, %s", what, shift.reason.c_str());
  } else if (LooksShifted(shift)) {
    std::snprintf(line, sizeof(line),
                  "%s: k = %+d fits best, median %.3f vs %.3f at k = 0 of the box diagonal (closer in %.0f %% of %ld "
                  "comparisons)",
                  what, shift.best_shift, shift.RelAt(shift.best_shift), shift.RelAt(0), 100 * shift.win_share,
                  shift.comparisons);
  } else {
    std::snprintf(line, sizeof(line),
                  "%s: none, median %.3f of the box diagonal at k = 0, %.3f at the best other k = %+d (closer in %.0f %% "
                  "of %ld comparisons)",
                  what, shift.RelAt(0), shift.RelAt(shift.best_shift), shift.best_shift, 100 * shift.win_share,
                  shift.comparisons);
  }
  return line;
}

void PrintCheckSummary(std::ostream& out, const EvalDiagnostics& diagnostics) {
  double lo = INFINITY, hi = -INFINITY;
  int cameras = 0;
  for (const SequenceCheck& check : diagnostics.checks) {
    for (const CameraCheck& camera : check.cameras) {
      if (!std::isfinite(camera.rel_median)) continue;
      lo = std::min(lo, camera.rel_median);
      hi = std::max(hi, camera.rel_median);
      ++cameras;
    }
  }
  char line[320];
  if (cameras > 0) {
    char range[64];
    std::snprintf(range, sizeof(range), hi - lo < 0.0005 ? "%.3f" : "%.3f to %.3f", lo, hi);
    // Cameras of every sequence: "10 cameras over 2 sequences", not 10 cameras of one rig.
    char over[48] = "";
    if (diagnostics.checks.size() > 1) std::snprintf(over, sizeof(over), " over %zu sequences", diagnostics.checks.size());
    std::snprintf(line, sizeof(line),
                  "projected GT to nearest detection: median %s of the person's box diagonal (%d camera(s)%s; warning "
                  "from %.2f)\n",
                  range, cameras, over, kFarRelDistance);
  } else {
    std::snprintf(line, sizeof(line), "projected GT to nearest detection: nothing to compare\n");
  }
  out << line;
  const size_t n = diagnostics.checks.size();
  if (n == 1) {
    out << ShiftLine(diagnostics.checks.front().shift) << "\n";
    return;
  }
  if (n == 0) return;
  int tested = 0, shifted = 0, untested_count = 0;
  const SequenceCheck* untested = nullptr;
  bool same_reason = true;
  for (const SequenceCheck& check : diagnostics.checks) {
    tested += check.shift.tested ? 1 : 0;
    shifted += LooksShifted(check.shift) ? 1 : 0;
    if (check.shift.tested) continue;
    ++untested_count;
    if (untested == nullptr) untested = &check;
    same_reason &= check.shift.reason == untested->shift.reason;
  }
  out << "frame shift (detections of frame f vs GT of frame f+k): ";
  if (tested == 0 && same_reason) {
    out << "not tested, " << untested->shift.reason << "\n";
    return;
  }
  out << "tested in " << tested << " of " << n << " sequences, " << shifted << " shifted";
  if (untested_count == 1) {
    out << "; not tested in " << PrintableText(untested->sequence, LineBreaks::kEscape) << " ("
        << untested->shift.reason << ")";
  } else if (untested_count > 1) {
    // The first one's reason, said as the first one's (the others may have their own).
    out << "; not tested in " << untested_count << " sequences (" << PrintableText(untested->sequence, LineBreaks::kEscape)
        << ": " << untested->shift.reason << (same_reason ? ", as every other" : "; others for other reasons") << ")";
  }
  out << "\n";
}

void PrintWarnings(std::ostream& err, const EvalDiagnostics& diagnostics) {
  for (const CheckWarning& w : diagnostics.warnings) err << "warning: " << PrintableText(w.message) << "\n";
}

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
#include "datasets/sequence.h"

#include <cmath>
#include <set>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/input_warnings.h"

namespace rpt {
namespace {

std::string Where(const std::string& source, const SequenceFrame& frame) {
  return source + ": frame " + QuoteName(frame.id);
}

}  // namespace

void ValidateSequenceHeader(const SequenceHeader& sequence, const std::string& source) {
  if (sequence.cameras.empty()) throw InputError(source + ": no cameras");
  for (const Camera& camera : sequence.cameras) {
    if (const std::string error = camera.Validate(); !error.empty()) throw InputError(source + ": " + error);
  }
}

void ValidateFrame(const SequenceHeader& sequence, const SequenceFrame& frame, const std::string& source) {
  if (frame.gt.num_persons() > 0 && frame.gt.num_joints != static_cast<int>(sequence.gt_joints.size())) {
    throw InputError(Where(source, frame) + ": ground truth has " + std::to_string(frame.gt.num_joints) +
                     " joints, expected " + std::to_string(sequence.gt_joints.size()));
  }
  for (double value : frame.gt.data) {
    if (!std::isfinite(value)) throw InputError(Where(source, frame) + ": ground truth contains NaN or infinity");
  }
  if (!frame.views.empty() && frame.views.size() != sequence.cameras.size()) {
    throw InputError(Where(source, frame) + ": " + std::to_string(frame.views.size()) + " views for " +
                     std::to_string(sequence.cameras.size()) + " cameras");
  }
  if (!frame.labels_2d.empty() && frame.labels_2d.size() != sequence.cameras.size()) {
    throw InputError(Where(source, frame) + ": 2D labels for " + std::to_string(frame.labels_2d.size()) +
                     " views, expected " + std::to_string(sequence.cameras.size()));
  }
  for (const std::vector<PersonLabel2D>& labels : frame.labels_2d) {
    for (const PersonLabel2D& label : labels) {
      if (label.gt_person < -1 || label.gt_person >= frame.gt.num_persons()) {
        throw InputError(Where(source, frame) + ": 2D label of GT person " + std::to_string(label.gt_person) +
                         ", the frame has " + std::to_string(frame.gt.num_persons()));
      }
      if (!label.visibility.empty() && label.visibility.size() != sequence.gt_joints.size()) {
        throw InputError(Where(source, frame) + ": 2D label with " + std::to_string(label.visibility.size()) +
                         " joint flags, expected " + std::to_string(sequence.gt_joints.size()));
      }
    }
  }
  for (size_t v = 0; v < frame.views.size(); ++v) {
    const Poses2D& view = frame.views[v];
    // Built on error only: a valid frame is checked without allocating (the per-frame path).
    const auto where = [&] { return Where(source, frame) + ", camera " + QuoteName(sequence.cameras[v].name); };
    if (view.num_persons() > 0 && view.num_joints != static_cast<int>(sequence.detection_joints.size())) {
      throw InputError(where() + ": detections have " + std::to_string(view.num_joints) + " joints, expected " +
                       std::to_string(sequence.detection_joints.size()));
    }
    for (size_t i = 0; i < view.data.size(); i += 3) {
      const double score = view.data[i + 2];
      if (!std::isfinite(view.data[i]) || !std::isfinite(view.data[i + 1]) || !std::isfinite(score)) {
        const size_t joint = i / 3 % static_cast<size_t>(view.num_joints);
        throw InputError(where() + ": detection " + std::to_string(i / 3 / view.num_joints) + ", joint " +
                         QuoteName(sequence.detection_joints[joint]) +
                         " contains NaN or infinity (a missing joint has score 0: its coordinates are ignored)");
      }
      if (score < 0 || score > 1) {
        const size_t joint = i / 3 % static_cast<size_t>(view.num_joints);
        throw InputError(where() + ": detection " + std::to_string(i / 3 / view.num_joints) + ", joint " +
                         QuoteName(sequence.detection_joints[joint]) + ": score " + FormatNumber(score) +
                         " outside [0, 1]" +
                         (score > 1 ? " (values up to " + FormatNumber(kMaxScoreOvershoot) +
                                          " are clamped to 1 where detections are read)"
                                    : std::string()));
      }
    }
  }
}

void ValidateSequence(const Sequence& sequence, const std::string& source) {
  ValidateSequenceHeader(sequence, source);
  std::set<std::string> ids;
  for (const SequenceFrame& frame : sequence.frames) {
    if (!ids.insert(frame.id).second) throw InputError(Where(source, frame) + ": duplicate frame id");
    ValidateFrame(sequence, frame, source);
  }
}

}  // namespace rpt

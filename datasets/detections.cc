// SPDX-License-Identifier: MIT
#include "datasets/detections.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt {

void MarkUnavailableViews(const Detections& detections, bool frame_in_file, std::span<const char> listed,
                          std::span<const char> mentioned, std::span<Poses2D> views) {
  for (size_t c = 0; c < views.size(); ++c) {
    const bool is_listed = frame_in_file && c < listed.size() && listed[c];
    const bool is_mentioned = c < mentioned.size() && mentioned[c];
    views[c].unavailable = !is_listed && (!is_mentioned || detections.unlisted_cameras_unavailable);
  }
}

std::unique_ptr<Detections> WithUnlistedCamerasUnavailable(const Detections& detections) {
  if (detections.unlisted_cameras_unavailable) return nullptr;
  std::vector<std::string> cameras;  // in the order of their first mention
  std::unordered_set<std::string> seen;
  for (const FrameDetections& frame : detections.frames) {
    for (const std::string& camera : frame.cameras) {
      if (seen.insert(camera).second) cameras.push_back(camera);
    }
  }
  auto out = std::make_unique<Detections>(detections);
  out->unlisted_cameras_unavailable = true;
  const int num_joints = static_cast<int>(detections.joints.size());
  for (FrameDetections& frame : out->frames) {
    for (const std::string& camera : cameras) {
      if (std::find(frame.cameras.begin(), frame.cameras.end(), camera) != frame.cameras.end()) continue;
      frame.cameras.push_back(camera);  // it looked and saw nobody
      frame.views.emplace_back().Clear(num_joints);
    }
  }
  return out;
}

std::vector<char> CamerasMentioned(const Detections& detections, const std::vector<std::string>& cameras) {
  std::unordered_set<std::string> names;
  for (const FrameDetections& frame : detections.frames) names.insert(frame.cameras.begin(), frame.cameras.end());
  std::vector<char> mentioned(cameras.size(), 0);
  for (size_t c = 0; c < cameras.size(); ++c) mentioned[c] = names.count(cameras[c]) ? 1 : 0;
  return mentioned;
}

AttachReport AttachDetections(const Detections& detections, const std::string& source, std::span<Sequence> sequences,
                              InputWarnings* warnings) {
  struct Place {
    Sequence* sequence;
    SequenceFrame* frame;
    const std::unordered_map<std::string, int>* camera_index;
  };
  std::vector<std::unordered_map<std::string, int>> camera_index(sequences.size());
  std::unordered_map<std::string, std::vector<Place>> places;  // frame id -> the frames holding it
  for (size_t s = 0; s < sequences.size(); ++s) {
    Sequence& sequence = sequences[s];
    for (size_t c = 0; c < sequence.cameras.size(); ++c)
      camera_index[s][sequence.cameras[c].name] = static_cast<int>(c);
    for (SequenceFrame& frame : sequence.frames) places[frame.id].push_back(Place{&sequence, &frame, &camera_index[s]});
  }

  const int num_joints = static_cast<int>(detections.joints.size());
  std::vector<std::vector<char>> mentioned(sequences.size());
  for (size_t s = 0; s < sequences.size(); ++s) {
    Sequence& sequence = sequences[s];
    sequence.detection_joints = detections.joints;
    std::vector<std::string> names;
    for (const Camera& camera : sequence.cameras) names.push_back(camera.name);
    mentioned[s] = CamerasMentioned(detections, names);
    for (SequenceFrame& frame : sequence.frames) {
      frame.views.assign(sequence.cameras.size(), Poses2D{});
      for (Poses2D& view : frame.views) view.Clear(num_joints);
      MarkUnavailableViews(detections, /*frame_in_file=*/false, {}, mentioned[s], frame.views);  // until attached
    }
  }
  AttachReport report;
  std::unordered_set<const SequenceFrame*> attached;
  for (const FrameDetections& found : detections.frames) {
    const auto it = places.find(found.frame_id);
    if (it == places.end()) {
      if (report.unused_frames++ == 0) report.first_unused_frame = found.frame_id;
      continue;
    }
    for (const Place& place : it->second) {
      attached.insert(place.frame);
      std::vector<char> listed(place.frame->views.size(), 0);
      for (size_t v = 0; v < found.views.size(); ++v) {
        const auto cam = place.camera_index->find(found.cameras[v]);
        if (cam == place.camera_index->end()) {
          throw InputError(source + ": frame " + QuoteName(found.frame_id) + ": camera " + QuoteName(found.cameras[v]) +
                           " is not a camera of sequence " + QuoteName(place.sequence->name));
        }
        if (found.views[v].num_persons() > 0 && found.views[v].num_joints != num_joints) {
          throw InputError(source + ": frame " + QuoteName(found.frame_id) + ", camera " + QuoteName(found.cameras[v]) +
                           ": " + std::to_string(found.views[v].num_joints) + " joints, expected " +
                           std::to_string(num_joints));
        }
        place.frame->views[cam->second] = found.views[v];
        listed[cam->second] = 1;
      }
      const size_t s = static_cast<size_t>(place.sequence - sequences.data());
      MarkUnavailableViews(detections, /*frame_in_file=*/true, listed, mentioned[s], place.frame->views);
    }
  }

  for (const Sequence& sequence : sequences) {
    int with = 0;
    for (const SequenceFrame& frame : sequence.frames) {
      if (attached.count(&frame)) {
        ++with;
      } else if (report.frames_without++ == 0) {
        report.first_frame_without = frame.id;
      }
    }
    if (with == 0 && !sequence.frames.empty()) {
      throw NoFrameMatchesError(source, detections.frames.size(),
                                detections.frames.empty() ? "" : detections.frames.front().frame_id, sequence.name,
                                sequence.frames.front().id);
    }
    report.frames_with_detections += with;
  }
  if (warnings != nullptr) CountUnattachedFrames(report, source, warnings);
  return report;
}

void CountUnattachedFrames(const AttachReport& report, const std::string& source, InputWarnings* warnings) {
  warnings->AddUnused(
      source, "detection frames whose id is no frame of the input, ignored (first " + QuoteName(report.first_unused_frame) + ")",
      report.unused_frames);
  warnings->AddUnused(
      source,
      "frames of the input absent from it, triangulated without detections (first " + QuoteName(report.first_frame_without) + ")",
      report.frames_without);
}

InputError NoFrameMatchesError(const std::string& source, size_t num_detection_frames,
                               const std::string& first_detection_id, const std::string& sequence_name,
                               const std::string& first_frame_id) {
  return InputError(source + ": none of its " + std::to_string(num_detection_frames) + " frame ids" +
                    (num_detection_frames == 0 ? "" : " (e.g. " + QuoteName(first_detection_id) + ")") +
                    " matches a frame of sequence " + QuoteName(sequence_name) + " (e.g. " + QuoteName(first_frame_id) + ")");
}

long ReadOriginJointsAsMissing(Poses2D* view) {
  long count = 0;
  for (size_t i = 0; i + 2 < view->data.size(); i += 3) {
    if (view->data[i] == 0 && view->data[i + 1] == 0 && view->data[i + 2] > 0) {
      view->data[i + 2] = 0;
      ++count;
    }
  }
  return count;
}

}  // namespace rpt

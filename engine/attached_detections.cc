// SPDX-License-Identifier: MIT
#include "engine/attached_detections.h"

#include <algorithm>
#include <utility>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::engine {

// One sequence's frames with the file's views.
class AttachedDetections::Source final : public FrameSource {
 public:
  Source(std::unique_ptr<FrameSource> frames, AttachedDetections* file, size_t index)
      : frames_(std::move(frames)), file_(file), index_(index), header_(frames_->header()) {
    header_.detection_joints = file_->detections_.joints;
    std::vector<std::string> names;
    for (size_t c = 0; c < header_.cameras.size(); ++c) {
      camera_index_[header_.cameras[c].name] = static_cast<int>(c);
      names.push_back(header_.cameras[c].name);
    }
    mentioned_ = CamerasMentioned(file_->detections_, names);
    listed_.resize(names.size());
  }

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return frames_->num_frames(); }

  // The wrapped frame finished (its Next): the lookup needs its id, and counts the frames without detections.
  bool Pull(SequenceFrame* frame) override {
    if (!frames_->Next(frame)) {
      Finish();
      return false;
    }
    const int num_joints = static_cast<int>(header_.detection_joints.size());
    frame->views.resize(header_.cameras.size());
    for (Poses2D& view : frame->views) view.Clear(num_joints);
    if (frames_seen_++ == 0) first_frame_id_ = frame->id;
    const auto it = file_->frame_index_.find(frame->id);
    if (it == file_->frame_index_.end()) {
      AttachedDetections::Absent& absent = file_->absent_[index_];
      if (absent.count++ == 0) absent.first = frame->id;
      MarkUnavailableViews(file_->detections_, /*frame_in_file=*/false, listed_, mentioned_, frame->views);
      return true;
    }
    const FrameDetections& found = file_->detections_.frames[it->second];
    file_->used_[it->second].store(true, std::memory_order_relaxed);
    ++frames_with_;
    std::fill(listed_.begin(), listed_.end(), 0);
    for (size_t v = 0; v < found.views.size(); ++v) {
      const auto camera = camera_index_.find(found.cameras[v]);
      if (camera == camera_index_.end()) {
        throw InputError(file_->source_ + ": frame " + QuoteName(found.frame_id) + ": camera " + QuoteName(found.cameras[v]) +
                         " is not a camera of sequence " + QuoteName(header_.name));
      }
      if (found.views[v].num_persons() > 0 && found.views[v].num_joints != num_joints) {
        throw InputError(file_->source_ + ": frame " + QuoteName(found.frame_id) + ", camera " + QuoteName(found.cameras[v]) +
                         ": " + std::to_string(found.views[v].num_joints) + " joints, expected " +
                         std::to_string(num_joints));
      }
      frame->views[camera->second].data = found.views[v].data;  // capacity of the caller's buffer reused
      listed_[camera->second] = 1;
    }
    MarkUnavailableViews(file_->detections_, /*frame_in_file=*/true, listed_, mentioned_, frame->views);
    return true;
  }

  const InputWarnings& warnings() const override { return frames_->warnings(); }

 private:
  // The sequence is exhausted: it must have used the file, and its frames without detections are counted.
  void Finish() {
    if (finished_) return;
    finished_ = true;
    if (frames_with_ == 0 && frames_seen_ > 0) {
      const Detections& d = file_->detections_;
      throw InputError(file_->source_ + ": none of its " + std::to_string(d.frames.size()) + " frame ids" +
                       (d.frames.empty() ? "" : " (e.g. " + QuoteName(d.frames.front().frame_id) + ")") +
                       " matches a frame of sequence " + QuoteName(header_.name) + " (e.g. " + QuoteName(first_frame_id_) + ")");
    }
  }

  std::unique_ptr<FrameSource> frames_;
  AttachedDetections* file_;
  size_t index_;  // into file_->absent_
  SequenceHeader header_;
  std::unordered_map<std::string, int> camera_index_;
  std::vector<char> mentioned_;  // per camera: listed in some frame of the file
  std::vector<char> listed_;     // per camera: listed in the frame being pulled
  long frames_seen_ = 0, frames_with_ = 0;
  std::string first_frame_id_;
  bool finished_ = false;
};

AttachedDetections::AttachedDetections(Detections detections, std::string source, bool report_unused_frames)
    : detections_(std::move(detections)),
      source_(std::move(source)),
      report_unused_frames_(report_unused_frames),
      used_(std::make_unique<std::atomic<bool>[]>(detections_.frames.size())) {
  frame_index_.reserve(detections_.frames.size());
  for (size_t i = 0; i < detections_.frames.size(); ++i) {
    frame_index_.emplace(detections_.frames[i].frame_id, static_cast<int>(i));  // the first of repeated ids
    used_[i].store(false, std::memory_order_relaxed);
  }
}

AttachedDetections::~AttachedDetections() = default;

std::unique_ptr<FrameSource> AttachedDetections::Wrap(std::unique_ptr<FrameSource> frames) {
  absent_.emplace_back();
  return std::make_unique<Source>(std::move(frames), this, absent_.size() - 1);
}

InputWarnings AttachedDetections::Unused() const {
  long unused = 0;
  std::string first;
  const auto selected_out = [&](const std::string& id) {
    return !dataset_prefix_.empty() && id.size() > dataset_prefix_.size() && id.starts_with(dataset_prefix_) &&
           id.back() >= '0' && id.back() <= '9';
  };
  for (size_t i = 0; report_unused_frames_ && i < detections_.frames.size(); ++i) {
    if (used_[i].load(std::memory_order_relaxed) || selected_out(detections_.frames[i].frame_id)) continue;
    if (unused++ == 0) first = detections_.frames[i].frame_id;
  }
  InputWarnings warnings;
  warnings.AddUnused(source_, "detection frames whose id is no frame of the input, ignored (first " + QuoteName(first) + ")",
                     unused);
  long absent = 0;
  std::string first_absent;
  for (const Absent& a : absent_) {
    if (absent == 0) first_absent = a.first;
    absent += a.count;
  }
  warnings.AddUnused(source_,
                     "frames of the input absent from it, triangulated without detections (first " + QuoteName(first_absent) +
                         ")",
                     absent);
  return warnings;
}

}  // namespace rpt::engine

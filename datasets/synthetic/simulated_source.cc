// SPDX-License-Identifier: MIT
#include "datasets/synthetic/simulated_source.h"

#include <cstdint>
#include <utility>

namespace rpt {
namespace {

SequenceHeader WithDetectionJoints(SequenceHeader header, const JointNames& joints) {
  header.detection_joints = joints;
  return header;
}

}  // namespace

SimulatedDetectionsSource::SimulatedDetectionsSource(std::unique_ptr<FrameSource> frames,
                                                     const SimulationOptions& options)
    : frames_(std::move(frames)),
      header_(WithDetectionJoints(frames_->header(), SimulatedDetectionJoints(options, frames_->header().gt_joints))),
      detector_(SimulatedDetectorModel(options), header_.detection_joints, options.seed) {}

bool SimulatedDetectionsSource::Pull(SequenceFrame* frame) { return frames_->Pull(frame); }

void SimulatedDetectionsSource::Complete(long frame_idx, SequenceFrame* frame) const {
  frames_->Complete(frame_idx, frame);
  detector_.Detect(header_.cameras, frame->gt, header_.gt_joints,
                   SimulatedFrameIndex(frame->id, static_cast<size_t>(frame_idx)), &frame->views, nullptr,
                   &frame->labels_2d);
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "datasets/synthetic/synthetic_sequence.h"

#include <cstdio>

namespace rpt::synthetic {
namespace {

SequenceHeader HeaderOf(const Scene& scene, const std::string& name) {
  SequenceHeader header;
  header.name = name;
  header.cameras = scene.cameras;
  header.gt_joints = scene.joint_names;
  header.detection_joints = scene.joint_names;
  header.room.center_m = scene.room_center_m;
  header.room.size_m = scene.room_size_m;
  header.fps = scene.fps;
  return header;
}

// Frame `index`'s id and timestamp.
void NameFrame(const SequenceHeader& header, size_t index, SequenceFrame* frame) {
  char id[64];
  std::snprintf(id, sizeof(id), "%s_%06zu", header.name.c_str(), index);
  frame->id = id;
  frame->timestamp_s = static_cast<double>(index) / header.fps;
}

// Frame `index`'s detections and 2D labels from its ground truth (already in frame->gt).
void DetectFrame(const SequenceHeader& header, const DetectorSimulator& detector, size_t index, SequenceFrame* frame) {
  detector.Detect(header.cameras, frame->gt, header.gt_joints, index, &frame->views, nullptr, &frame->labels_2d);
}

}  // namespace

Sequence MakeSyntheticSequence(const Scene& scene, const DetectorOptions& detector_options, uint64_t seed,
                               const std::string& name) {
  Sequence sequence;
  static_cast<SequenceHeader&>(sequence) = HeaderOf(scene, name);
  const DetectorSimulator detector(detector_options, scene.joint_names, seed);
  sequence.frames.resize(scene.gt.size());
  for (size_t f = 0; f < scene.gt.size(); ++f) {
    sequence.frames[f].gt = scene.gt[f];
    NameFrame(sequence, f, &sequence.frames[f]);
    DetectFrame(sequence, detector, f, &sequence.frames[f]);
  }
  return sequence;
}

SyntheticSource::SyntheticSource(const SceneOptions& options, const DetectorOptions& detector, uint64_t seed,
                                 const std::string& name)
    : scene_(options), header_(HeaderOf(scene_.shell(), name)), detector_(detector, scene_.shell().joint_names, seed) {}

bool SyntheticSource::Pull(SequenceFrame* frame) {
  if (!scene_.Next(&frame->gt)) return false;
  NameFrame(header_, next_frame_++, frame);
  return true;
}

void SyntheticSource::Complete(long frame_idx, SequenceFrame* frame) const {
  DetectFrame(header_, detector_, static_cast<size_t>(frame_idx), frame);
}

}  // namespace rpt::synthetic

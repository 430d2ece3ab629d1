// SPDX-License-Identifier: MIT
#include "datasets/synthetic/synthetic_sequence.h"

#include <cstdio>

namespace rpt::synthetic {

Sequence MakeSyntheticSequence(const Scene& scene, const DetectorOptions& detector_options, uint64_t seed,
                               const std::string& name) {
  Sequence sequence;
  sequence.name = name;
  sequence.cameras = scene.cameras;
  sequence.gt_joints = scene.joint_names;
  sequence.detection_joints = scene.joint_names;
  sequence.room.center_m = scene.room_center_m;
  sequence.room.size_m = scene.room_size_m;
  sequence.fps = scene.fps;
  const DetectorSimulator detector(detector_options, scene.joint_names, seed);
  sequence.frames.resize(scene.gt.size());
  for (size_t f = 0; f < scene.gt.size(); ++f) {
    SequenceFrame& frame = sequence.frames[f];
    char id[64];
    std::snprintf(id, sizeof(id), "%s_%06zu", name.c_str(), f);
    frame.id = id;
    frame.timestamp_s = static_cast<double>(f) / scene.fps;
    frame.gt = scene.gt[f];
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &frame.views, nullptr, &frame.labels_2d);
  }
  return sequence;
}

}  // namespace rpt::synthetic

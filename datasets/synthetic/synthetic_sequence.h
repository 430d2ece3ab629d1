// SPDX-License-Identifier: MIT
// A generated scene plus simulated detections as a dataset-independent Sequence, so synthetic
// data runs through exactly the same evaluation path as real datasets: whole (MakeSyntheticSequence)
// or streamed frame by frame (SyntheticSource), with the same numbers.
#pragma once

#include <cstdint>
#include <string>

#include "datasets/frame_source.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt::synthetic {

// Frame ids are "<name>_000000", ...; timestamps frame / fps; detections use the scene's joints;
// labels_2d are the simulator's view of the GT (which joints its occluders hid).
Sequence MakeSyntheticSequence(const Scene& scene, const DetectorOptions& detector, uint64_t seed,
                               const std::string& name = "synthetic");

// The frames of MakeSyntheticSequence(GenerateScene(options), ...) generated on demand: the scene
// is simulated one frame ahead (SceneStream) and detected per frame, so memory does not depend on
// the number of frames. Pull walks the scene (in order); Complete runs the simulated detector,
// whose randomness depends only on the frame index, so frames can be detected in parallel.
class SyntheticSource final : public FrameSource {
 public:
  SyntheticSource(const SceneOptions& options, const DetectorOptions& detector, uint64_t seed,
                  const std::string& name = "synthetic");

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return scene_.num_frames(); }
  bool Pull(SequenceFrame* frame) override;
  void Complete(long frame_idx, SequenceFrame* frame) const override;
  const InputWarnings& warnings() const override { return warnings_; }  // none: generated data

 private:
  SceneStream scene_;
  SequenceHeader header_;
  DetectorSimulator detector_;
  InputWarnings warnings_;
  size_t next_frame_ = 0;
};

}  // namespace rpt::synthetic

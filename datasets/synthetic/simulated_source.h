// SPDX-License-Identifier: MIT
// Simulated 2D detections on streamed frames: what SimulateDetections (datasets/detections.h)
// does to a whole sequence, done frame by frame as the frames are pulled, with the same numbers.
#pragma once

#include <memory>

#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/simulate_detections.h"

namespace rpt {

class SimulatedDetectionsSource final : public FrameSource {
 public:
  SimulatedDetectionsSource(std::unique_ptr<FrameSource> frames, const SimulationOptions& options);

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return frames_->num_frames(); }
  // The next frame of the wrapped source (its Pull; Complete completes it), its views and 2D
  // labels replaced by the simulator's in Complete: the frame's randomness depends on its id's number
  // only (SimulatedFrameIndex).
  bool Pull(SequenceFrame* frame) override;
  void Complete(long frame_idx, SequenceFrame* frame) const override;
  const InputWarnings& warnings() const override { return frames_->warnings(); }

 private:
  std::unique_ptr<FrameSource> frames_;
  SequenceHeader header_;  // the wrapped header with the simulated detection joints
  synthetic::DetectorSimulator detector_;
};

}  // namespace rpt

// SPDX-License-Identifier: MIT
// Where a run's per-frame results go: a FrameSink gets every sequence's frames in order, as they
// are triangulated (engine/run.h). Writers of predictions and exports, the live output and
// in-memory collectors are sinks. Sequences may run on different threads at once: a sink keeps
// its state per sequence (the `sequence` index) and must not assume one sequence at a time.
#pragma once

#include <string>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/frame_stats.h"
#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt::engine {

// One triangulated frame.
struct FrameOutput {
  int sequence = 0;                  // index of the sequence in the input
  const SequenceFrame* input;        // id, time, GT, 2D detections
  const Poses3D* persons;            // joints in the order of the sequence's output joints
  const FrameStats* stats;           // per-step times and counts of this frame
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Before the first frame of sequence `sequence` (its header, and the joints of FrameOutput::persons).
  virtual void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) = 0;
  virtual void Frame(const FrameOutput& frame) = 0;
  // After its last frame (not called when the run fails).
  virtual void EndSequence(int sequence) = 0;
};

// Every frame's persons kept in memory, per sequence (render, report, tests): memory grows with
// the frames, so not for long runs.
class PredictionsCollector final : public FrameSink {
 public:
  struct Sequence {
    std::string name;
    JointNames output_joints;
    std::vector<std::string> frame_ids;
    std::vector<double> timestamps_s;
    std::vector<Poses3D> persons;  // per frame
  };
  // Sized for `num_sequences` sequences (the run's input).
  explicit PredictionsCollector(int num_sequences) : sequences_(static_cast<size_t>(num_sequences)) {}

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int) override {}

  const std::vector<Sequence>& sequences() const { return sequences_; }
  std::vector<Sequence>& sequences() { return sequences_; }

 private:
  std::vector<Sequence> sequences_;
};

// Hands every call on to each of `sinks` in order (null entries are skipped).
class SinkList final : public FrameSink {
 public:
  explicit SinkList(std::vector<FrameSink*> sinks) : sinks_(std::move(sinks)) {}
  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int sequence) override;

 private:
  std::vector<FrameSink*> sinks_;
};

}  // namespace rpt::engine

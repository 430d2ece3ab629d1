// SPDX-License-Identifier: MIT
#include "engine/frame_sink.h"

#include "core/errors.h"

namespace rpt::engine {

void PredictionsCollector::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  if (sequence < 0 || static_cast<size_t>(sequence) >= sequences_.size()) {
    throw std::logic_error("PredictionsCollector: sequence " + std::to_string(sequence) + " beyond the " +
                           std::to_string(sequences_.size()) + " it was made for");
  }
  Sequence& s = sequences_[sequence];
  s = Sequence{};
  s.name = header.name;
  s.output_joints = output_joints;
}

void PredictionsCollector::Frame(const FrameOutput& frame) {
  Sequence& s = sequences_[frame.sequence];
  s.frame_ids.push_back(frame.input->id);
  s.timestamps_s.push_back(frame.input->timestamp_s);
  s.persons.push_back(*frame.persons);
}

void SinkList::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  for (FrameSink* sink : sinks_) {
    if (sink != nullptr) sink->BeginSequence(sequence, header, output_joints);
  }
}

void SinkList::Frame(const FrameOutput& frame) {
  for (FrameSink* sink : sinks_) {
    if (sink != nullptr) sink->Frame(frame);
  }
}

void SinkList::EndSequence(int sequence) {
  for (FrameSink* sink : sinks_) {
    if (sink != nullptr) sink->EndSequence(sequence);
  }
}

}  // namespace rpt::engine

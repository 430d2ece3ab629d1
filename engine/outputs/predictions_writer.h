// SPDX-License-Identifier: MIT
// predictions.json, written as the frames are triangulated (a FrameSink, engine/frame_sink.h):
//   {"run_id": "...", "joints": [...],
//    "frames": [{"id": "...", "persons": [[[x, y, z, score], ...], ...], "track_ids": [...]}, ...]}
// metres in the world frame, 6 decimals (scores 4); coordinates that are not finite are null.
// Memory does not grow with the frames: each sequence streams into its own part file beside the
// target (sequences may run on different threads at once), and Finish() joins the parts in
// sequence order into the target.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "engine/frame_sink.h"

namespace rpt::engine {

class PredictionsWriter final : public FrameSink {
 public:
  // Writes `path` (meant to be inside a staged run folder: the parts are written beside it).
  PredictionsWriter(std::filesystem::path path, std::string run_id, int num_sequences);
  ~PredictionsWriter() override;

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int sequence) override;

  // Joins the parts into the target and removes them. Returns the number of strings that were not
  // valid UTF-8 (written as U+FFFD). Throws InputError naming the file when it cannot be written.
  int Finish();

 private:
  struct Part;
  std::filesystem::path path_;
  std::string run_id_;
  std::vector<std::unique_ptr<Part>> parts_;
};

}  // namespace rpt::engine

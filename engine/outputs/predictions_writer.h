// SPDX-License-Identifier: MIT
// predictions.json, written as the frames are triangulated (a FrameSink, engine/frame_sink.h):
//   {"run_id": "...", "joints": [...], "units": {"position": "m", "time": "s", "score": "1"},
//    "provenance_names": ["triangulated", "filled", "smoothed", "lifted", "predicted"],
//    "sequences": [{"name": "...", "frames": N, "fps": F or null}, ...],
//    "frames": [{"id": "...", "time": t or null, "persons": [[[x, y, z, score], ...], ...],
//                "track_ids": [...], "provenance": [[code per joint], ...]}, ...]}
// metres in the world frame, 6 decimals (scores 4); coordinates that are not finite are null;
// frames in sequence order (`sequences` says how many each has); provenance codes index
// provenance_names (core/poses.h, JointProvenance). Without ExportOptions::filled_joints a filled
// joint is written as missing: [null, null, null, 0]. Schema: docs/own_data.md.
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
#include "engine/outputs/export_options.h"

namespace rpt::engine {

class PredictionsWriter final : public FrameSink {
 public:
  // Writes `path` (meant to be inside a staged run folder: the parts are written beside it).
  PredictionsWriter(std::filesystem::path path, std::string run_id, int num_sequences, ExportOptions options = {});
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
  ExportOptions options_;
  std::vector<std::unique_ptr<Part>> parts_;
};

}  // namespace rpt::engine

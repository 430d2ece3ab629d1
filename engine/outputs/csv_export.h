// SPDX-License-Identifier: MIT
// predictions.csv (--export csv), long format, one row per written joint (missing joints have no
// row; filled ones only with ExportOptions::filled_joints):
//   sequence,frame,frame_id,time_s,track_id,joint,x_m,y_m,z_m,score,provenance
// frame = index of the frame in its sequence (from 0), time_s empty when unknown, track_id -1 when
// not tracked, metres in the world frame (6 decimals), provenance by name (ProvenanceNames()).
// Streams (a FrameSink): each sequence into its own part file, joined in sequence order by Finish.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"
#include "engine/outputs/part_files.h"

namespace rpt::engine {

class CsvExport final : public FrameSink {
 public:
  CsvExport(std::filesystem::path path, int num_sequences, ExportOptions options);

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int sequence) override;
  // Joins the parts into the file. Throws InputError naming the file when it cannot be written.
  void Finish();

 private:
  struct Sequence {
    std::string name;  // as a CSV field
    std::vector<std::string> joints;  // as CSV fields
    long frames = 0;
  };
  ExportOptions options_;
  PartFiles parts_;
  std::vector<Sequence> sequences_;
};

}  // namespace rpt::engine

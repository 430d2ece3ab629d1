// SPDX-License-Identifier: MIT
// The frames of a run kept for the array exports (predictions.npz, predictions.h5: npz_export.h,
// h5_export.h), which need the largest number of persons in any frame before they can write the
// first padded row. A FrameSink: each sequence streams its frames as binary records into a scratch
// part file of its own (sequences may run on different threads at once), keeping only counts and
// maxima in memory; after the run, Blocks reads them back in sequence order, a bounded block of
// frames at a time, padded to the run's largest person count. Memory does not grow with the frames.
//
// What a frame becomes (docs/own_data.md, "predictions.npz and predictions.h5"): per person and
// joint x, y, z (metres, world frame) and score; a missing joint (score <= 0, or filled without
// ExportOptions::filled_joints) is (NaN, NaN, NaN, 0); the rows after a frame's persons are padding:
// all four NaN, track id -1, provenance kPaddingProvenance.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"

namespace rpt::engine {

inline constexpr std::uint8_t kPaddingProvenance = 255;

class ArrayFrames final : public FrameSink {
 public:
  // The parts are written beside `name_like` (e.g. the staged run folder's predictions.npz).
  ArrayFrames(std::filesystem::path name_like, std::string run_id, int num_sequences, ExportOptions options);
  ~ArrayFrames() override;

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int sequence) override;

  // After the run: what the exports hold. Sequences that never began are left out.
  const std::string& run_id() const { return run_id_; }
  // The output joints; InputError when sequences have different ones (arrays need one joint list).
  JointNames joints() const;
  std::vector<std::string> sequence_names() const;
  std::vector<double> sequence_fps() const;                  // NaN when unknown
  std::vector<std::int64_t> sequence_frame_offsets() const;  // first frame of each, then the total
  std::int64_t num_frames() const;
  int max_persons() const;
  std::size_t max_id_code_points() const;  // of the frame ids (invalid UTF-8 replaced)
  std::size_t max_id_bytes() const;        // the same in UTF-8 bytes
  // Frames per block such that a block's poses take about 1 MiB (at least 1, at most 4096).
  std::int64_t block_frames() const;

  // The stored frames in order, `block_frames` at a time.
  class Blocks {
   public:
    Blocks(const ArrayFrames& frames, std::int64_t block_frames);
    // Reads the next block; false after the last frame.
    bool Next();
    std::int64_t first_frame() const { return first_; }
    std::int64_t frames() const { return count_; }
    // The block's frames, C order: poses frames x persons x joints x 4, track_ids frames x
    // persons, provenance frames x persons x joints; num_persons, times_s, ids per frame.
    const std::vector<double>& poses() const { return poses_; }
    const std::vector<std::int32_t>& track_ids() const { return track_ids_; }
    const std::vector<std::uint8_t>& provenance() const { return provenance_; }
    const std::vector<std::int32_t>& num_persons() const { return num_persons_; }
    const std::vector<double>& times_s() const { return times_s_; }
    const std::vector<std::string>& ids() const { return ids_; }

   private:
    bool ReadFrame(std::int64_t slot);
    const ArrayFrames& frames_;
    std::int64_t block_frames_;
    size_t part_ = 0;
    std::ifstream in_;
    std::int64_t first_ = 0, count_ = 0;
    std::vector<double> poses_;
    std::vector<std::int32_t> track_ids_;
    std::vector<std::uint8_t> provenance_;
    std::vector<std::int32_t> num_persons_;
    std::vector<double> times_s_;
    std::vector<std::string> ids_;
  };

 private:
  struct Sequence;
  std::filesystem::path name_like_;
  std::string run_id_;
  ExportOptions options_;
  std::vector<std::unique_ptr<Sequence>> sequences_;
};

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
#include "engine/outputs/h5_export.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "datasets/io/hdf5_array_writer.h"
#include "datasets/io/json_output.h"

namespace rpt::engine {

void WriteH5Export(const std::filesystem::path& path, const ArrayFrames& frames, std::int64_t block_frames) {
  if (block_frames <= 0) block_frames = frames.block_frames();
  using Type = io::Hdf5ArrayWriter::Type;
  const JointNames joints = frames.joints();
  const auto num_frames = static_cast<std::uint64_t>(frames.num_frames());
  const auto num_persons = static_cast<std::uint64_t>(frames.max_persons());
  const auto num_joints = static_cast<std::uint64_t>(joints.size());
  const auto chunk = static_cast<std::uint64_t>(block_frames);
  const size_t id_width = std::max<size_t>(1, frames.max_id_bytes());
  io::Hdf5ArrayWriter h5(path);
  h5.Create("/poses", Type::kFloat64, {num_frames, num_persons, num_joints, 4}, chunk);
  h5.Create("/track_ids", Type::kInt32, {num_frames, num_persons}, chunk);
  h5.Create("/num_persons", Type::kInt32, {num_frames}, chunk);
  h5.Create("/provenance", Type::kUInt8, {num_frames, num_persons, num_joints}, chunk);
  h5.Create("/times_s", Type::kFloat64, {num_frames}, chunk);
  h5.Create("/frame_ids", Type::kString, {num_frames}, chunk, id_width);
  ArrayFrames::Blocks blocks(frames, block_frames);
  std::vector<char> ids;
  while (blocks.Next()) {
    const auto first = static_cast<std::uint64_t>(blocks.first_frame());
    const auto count = static_cast<std::uint64_t>(blocks.frames());
    h5.WriteRows("/poses", first, count, blocks.poses().data());
    h5.WriteRows("/track_ids", first, count, blocks.track_ids().data());
    h5.WriteRows("/num_persons", first, count, blocks.num_persons().data());
    h5.WriteRows("/provenance", first, count, blocks.provenance().data());
    h5.WriteRows("/times_s", first, count, blocks.times_s().data());
    ids.assign(count * id_width, '\0');
    for (size_t f = 0; f < count; ++f) {
      const std::string id = io::ValidUtf8(blocks.ids()[f]);
      std::copy_n(id.begin(), std::min(id.size(), id_width), ids.begin() + static_cast<std::ptrdiff_t>(f * id_width));
    }
    h5.WriteRows("/frame_ids", first, count, ids.data());
  }
  h5.Strings("/joint_names", joints);
  h5.Strings("/provenance_names", ProvenanceNames());
  const std::vector<std::string> names = frames.sequence_names();
  h5.Strings("/sequence_names", names);
  h5.Int64s("/sequence_frame_offsets", frames.sequence_frame_offsets());
  h5.Doubles("/sequence_fps", {names.size()}, frames.sequence_fps());
  h5.StringAttribute("run_id", frames.run_id());
  h5.StringAttribute("position_unit", "m");
  h5.StringAttribute("time_unit", "s");
  h5.Commit();
}

}  // namespace rpt::engine

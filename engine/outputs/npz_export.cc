// SPDX-License-Identifier: MIT
#include "engine/outputs/npz_export.h"

#include <bit>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "datasets/io/npz_writer.h"

namespace rpt::engine {

// The arrays are written as they are in memory, and called little-endian ("<f8").
static_assert(std::endian::native == std::endian::little, "predictions.npz is written from little-endian memory");

void WriteNpzExport(const std::filesystem::path& path, const ArrayFrames& frames, std::int64_t block_frames) {
  if (block_frames <= 0) block_frames = frames.block_frames();
  const JointNames joints = frames.joints();
  const std::int64_t num_frames = frames.num_frames();
  const std::int64_t num_persons = frames.max_persons();
  const auto num_joints = static_cast<std::int64_t>(joints.size());
  io::NpzWriter npz(path);
  // One member streamed from the stored frames: `write` appends a block's part of it.
  const auto streamed = [&](const std::string& name, const std::string& descr, const std::vector<std::int64_t>& shape,
                            const std::function<void(const ArrayFrames::Blocks&)>& write) {
    npz.BeginArray(name, descr, shape);
    ArrayFrames::Blocks blocks(frames, block_frames);
    while (blocks.Next()) write(blocks);
    npz.EndArray();
  };
  streamed("poses", "<f8", {num_frames, num_persons, num_joints, 4},
           [&](const ArrayFrames::Blocks& b) { npz.Write(b.poses().data(), b.poses().size() * sizeof(double)); });
  streamed("track_ids", "<i4", {num_frames, num_persons}, [&](const ArrayFrames::Blocks& b) {
    npz.Write(b.track_ids().data(), b.track_ids().size() * sizeof(std::int32_t));
  });
  streamed("num_persons", "<i4", {num_frames}, [&](const ArrayFrames::Blocks& b) {
    npz.Write(b.num_persons().data(), b.num_persons().size() * sizeof(std::int32_t));
  });
  streamed("provenance", "|u1", {num_frames, num_persons, num_joints},
           [&](const ArrayFrames::Blocks& b) { npz.Write(b.provenance().data(), b.provenance().size()); });
  streamed("times_s", "<f8", {num_frames},
           [&](const ArrayFrames::Blocks& b) { npz.Write(b.times_s().data(), b.times_s().size() * sizeof(double)); });
  const size_t id_width = std::max<size_t>(1, frames.max_id_code_points());
  streamed("frame_ids", "<U" + std::to_string(id_width), {num_frames}, [&](const ArrayFrames::Blocks& b) {
    for (const std::string& id : b.ids()) npz.WriteString(id, id_width);
  });
  npz.Strings("joint_names", joints);
  npz.Strings("provenance_names", ProvenanceNames());
  const std::vector<std::string> names = frames.sequence_names();
  npz.Strings("sequence_names", names);
  npz.Int64s("sequence_frame_offsets", frames.sequence_frame_offsets());
  npz.Doubles("sequence_fps", {static_cast<std::int64_t>(names.size())}, frames.sequence_fps());
  npz.Strings("run_id", {frames.run_id()}, /*scalar=*/true);
  npz.Strings("position_unit", {"m"}, /*scalar=*/true);
  npz.Strings("time_unit", {"s"}, /*scalar=*/true);
  npz.Commit();
}

}  // namespace rpt::engine

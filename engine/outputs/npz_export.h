// SPDX-License-Identifier: MIT
// predictions.npz (--export npz): the frames an ArrayFrames kept, as a stored NPZ archive of .npy
// arrays (io::NpzWriter), each array streamed a block of frames at a time. Members (F frames, P the
// largest person count of any frame, J joints, S sequences; the layout of docs/own_data.md,
// "predictions.npz and predictions.h5", shared with predictions.h5):
//   poses                  <f8 (F, P, J, 4)  x, y, z (m, world frame), score; missing joint
//                                            (NaN, NaN, NaN, 0); padding rows all NaN
//   track_ids              <i4 (F, P)        -1: not tracked, or padding
//   num_persons            <i4 (F,)          persons of the frame (rows after them are padding)
//   provenance             |u1 (F, P, J)     JointProvenance codes; 255 padding
//   times_s                <f8 (F,)          NaN when unknown
//   frame_ids              <U  (F,)
//   joint_names            <U  (J,)
//   provenance_names       <U  (5,)          names of the codes
//   sequence_names         <U  (S,)
//   sequence_frame_offsets <i8 (S + 1,)      sequence s holds frames [offsets[s], offsets[s + 1])
//   sequence_fps           <f8 (S,)          NaN when unknown
//   run_id, position_unit ("m"), time_unit ("s")   0-d <U
#pragma once

#include <cstdint>
#include <filesystem>

#include "engine/outputs/array_frames.h"

namespace rpt::engine {

// Writes the archive (staged: `path` holds its old contents until it is complete). Throws
// InputError naming the file when it cannot be written, or when a member would pass 4 GiB.
// `block_frames`: frames read at a time (0: ArrayFrames::block_frames()).
void WriteNpzExport(const std::filesystem::path& path, const ArrayFrames& frames, std::int64_t block_frames = 0);

}  // namespace rpt::engine

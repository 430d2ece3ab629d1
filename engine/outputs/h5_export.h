// SPDX-License-Identifier: MIT
// predictions.h5 (--export h5): the frames an ArrayFrames kept, as an HDF5 file with the datasets
// of predictions.npz (npz_export.h; same names, shapes and values) at the root, written a block of
// frames at a time into chunked, extendible, compressed datasets (io::Hdf5ArrayWriter). Strings are
// fixed-width UTF-8; run_id, position_unit ("m") and time_unit ("s") are attributes of the root
// group. Layout: docs/own_data.md, "predictions.npz and predictions.h5".
#pragma once

#include <cstdint>
#include <filesystem>

#include "engine/outputs/array_frames.h"

namespace rpt::engine {

// Writes the file (staged: `path` holds its old contents until it is complete). Throws InputError
// naming the file when it cannot be written.
// `block_frames`: frames read at a time (0: ArrayFrames::block_frames()).
void WriteH5Export(const std::filesystem::path& path, const ArrayFrames& frames, std::int64_t block_frames = 0);

}  // namespace rpt::engine

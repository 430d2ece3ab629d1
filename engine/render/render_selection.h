// SPDX-License-Identifier: MIT
// What `rpt render` draws: the frame range and the cameras the user selected, and the image file
// behind a camera's frame (the --images template). Pure functions; errors are ConfigErrors naming
// the option.
#pragma once

#include <string>
#include <vector>

#include "core/camera.h"
#include "engine/outputs/file_names.h"

namespace rpt::engine {

// Frames [first, end) of a sequence, as frame indices.
struct FrameRange {
  long first = 0;
  long end = 0;
};

// "N" (one frame), "A:B" (A up to B, B excluded), "A:" (to the end), ":B", ":" (all), checked
// against the sequence's `num_frames`; an empty range or a start beyond the last frame is a
// ConfigError naming --frames, the sequence and its frame count.
FrameRange ParseFrameRange(const std::string& text, long num_frames, const std::string& sequence);

// The indices of the selected cameras, in the order given: each entry a camera name or a 0-based
// index; empty selection = every camera. An unknown name is a ConfigError listing the cameras
// (with a "did you mean").
std::vector<int> SelectCameras(const std::vector<std::string>& selection, const std::vector<Camera>& cameras,
                               const std::string& sequence);

// The image file of one camera and frame from a template with the placeholders {camera} (the
// camera's name), {camera_idx} (its 0-based index), {frame_id} (the frame's id), {frame} (the
// digits ending the frame id, e.g. 000300 of "shelf_000300"; the whole id when it ends in none)
// and {frame_idx} (the 0-based frame index in the sequence). Digits may be padded:
// {camera_idx:2} -> 03, {frame_idx:6} -> 000017. An unknown placeholder or an unclosed brace is a
// ConfigError naming --images.
std::string ImagePath(const std::string& pattern, const std::string& camera, int camera_idx,
                      const std::string& frame_id, long frame_idx);

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// The size of frame the triangulator takes: association compares every 2D pose of a view with
// every pose of the other views, so its cost grows with the square of the poses. A frame beyond
// triangulate.max_persons_per_view or triangulate.max_pairs_per_frame is refused before any work
// (the triangulator throws; the live input skips such a line with --skip-bad-lines).
#pragma once

#include <span>
#include <string>

#include "core/camera.h"
#include "core/poses.h"

namespace rpt {

// Why `views` (one per camera of `cameras`) is too large, naming the view, its camera and the
// option to raise; empty when it fits.
std::string FrameSizeProblem(std::span<const Poses2D> views, std::span<const Camera> cameras, int max_persons_per_view,
                             long long max_pairs_per_frame);

}  // namespace rpt

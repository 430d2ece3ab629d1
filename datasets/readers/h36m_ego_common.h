// SPDX-License-Identifier: MIT
// Internal helpers shared by the Human3.6M, H3WB and EgoHumans readers (not a public header:
// only included from datasets/readers/{human36m,h3wb,egohumans}*.cc and their tests).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/camera.h"
#include "datasets/io/py_value.h"

namespace rpt::h36m_ego {

// Largest per-joint distance (metres) tolerated between two views' world-frame versions of the same
// 3D pose (H36M annot.h5 camera-frame poses, H3WB camera_3d vs global_3d, H3WB json views).
// The files derive all views from one world pose with the same calibration, so real data agrees to
// far below 1 mm; a wrong subject, camera order or unit is off by decimetres to metres.
inline constexpr double kViewAgreementToleranceM = 0.01;

// Indices of the frames kept from `count` available ones: every `every`-th (starting with the
// first), at most `max_frames` of them (0 = no limit).
std::vector<std::size_t> SelectFrames(std::size_t count, int every, int max_frames);

// Zero-padded decimal, e.g. Padded(7, 6) = "000007" (negative values keep their sign).
std::string Padded(long long value, int width);

// A name made safe for frame ids and sequence names: characters other than [A-Za-z0-9._-]
// become '-' ("Directions 1" -> "Directions-1").
std::string SanitizeName(std::string_view name);

// `value` when absolute, else root / value.
std::filesystem::path ResolveUnder(const std::filesystem::path& root, const std::string& value);

// The Human3.6M camera ids in the dataset's camera order (metadata.xml camera 1..4) and image sizes
// (mmpose preprocess_h36m.py): 54138969 1000x1002, 55011271 1000x1000, 58860488 1000x1000,
// 60457274 1000x1002. Returns -1 for an unknown id.
int H36mCameraIndex(std::string_view camera_id);
void H36mImageSize(int camera_index, int* width, int* height);

// Exactly `count` finite numbers from a numeric ndarray or nested list of any shape; throws
// InputError at `view` otherwise ("expected 9 numbers, got shape (3, 2)" / "contains NaN").
std::vector<double> FiniteNumbers(const io::PyView& view, std::size_t count);

// Checks Camera::Validate(); throws InputError("<source>: <problem>").
void CheckCamera(const Camera& camera, const std::string& source);

// "<path>" for messages (the path exactly as given).
std::string PathName(const std::filesystem::path& path);

}  // namespace rpt::h36m_ego

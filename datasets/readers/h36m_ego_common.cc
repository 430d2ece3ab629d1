// SPDX-License-Identifier: MIT
#include "datasets/readers/h36m_ego_common.h"

#include <Eigen/Dense>
#include <array>
#include <charconv>
#include <cmath>

#include "core/errors.h"

namespace rpt::h36m_ego {
namespace {

struct H36mCameraEntry {
  const char* id;
  int width;
  int height;
};

constexpr std::array<H36mCameraEntry, 4> kH36mCameras = {{
    {"54138969", 1000, 1002},
    {"55011271", 1000, 1000},
    {"58860488", 1000, 1000},
    {"60457274", 1000, 1002},
}};

std::string ShapeText(const std::vector<std::int64_t>& shape) {
  std::string out = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) out += (i ? ", " : "") + std::to_string(shape[i]);
  return out + (shape.size() == 1 ? ",)" : ")");
}

}  // namespace

std::vector<std::size_t> SelectFrames(std::size_t count, int every, int max_frames) {
  std::vector<std::size_t> out;
  const std::size_t step = every > 0 ? static_cast<std::size_t>(every) : 1;
  for (std::size_t i = 0; i < count; i += step) {
    if (max_frames > 0 && out.size() >= static_cast<std::size_t>(max_frames)) break;
    out.push_back(i);
  }
  return out;
}

std::string Padded(long long value, int width) {
  std::string digits = std::to_string(value < 0 ? -value : value);
  if (static_cast<int>(digits.size()) < width) digits.insert(0, static_cast<std::size_t>(width) - digits.size(), '0');
  return value < 0 ? "-" + digits : digits;
}

std::string SanitizeName(std::string_view name) {
  std::string out(name);
  for (char& c : out) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    if (!ok) c = '-';
  }
  return out;
}

std::filesystem::path ResolveUnder(const std::filesystem::path& root, const std::string& value) {
  const std::filesystem::path p(value);
  return p.is_absolute() ? p : root / p;
}

int H36mCameraIndex(std::string_view camera_id) {
  for (std::size_t i = 0; i < kH36mCameras.size(); ++i) {
    if (camera_id == kH36mCameras[i].id) return static_cast<int>(i);
  }
  return -1;
}

void H36mImageSize(int camera_index, int* width, int* height) {
  *width = kH36mCameras.at(static_cast<std::size_t>(camera_index)).width;
  *height = kH36mCameras.at(static_cast<std::size_t>(camera_index)).height;
}

std::vector<double> FiniteNumbers(const io::PyView& view, std::size_t count) {
  const std::vector<std::int64_t> shape = view.Shape();
  std::vector<double> values = view.ToDoubles();
  if (values.size() != count) {
    view.Fail("expected " + std::to_string(count) + " numbers, got shape " + ShapeText(shape));
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) view.Fail("element " + std::to_string(i) + " is NaN or infinite");
  }
  return values;
}

void CheckCamera(const Camera& camera, const std::string& source) {
  if (const std::string problem = camera.Validate(); !problem.empty()) throw InputError(source + ": " + problem);
}

std::string PathName(const std::filesystem::path& path) { return path.string(); }

}  // namespace rpt::h36m_ego

// SPDX-License-Identifier: MIT
#include "engine/render/render_selection.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <unordered_set>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::engine {
namespace {

// A non-negative integer filling all of `text`, or -1.
long ParseIndex(const std::string& text) {
  long value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0) return -1;
  return value;
}

std::string Padded(long value, int width) {
  char text[32];
  std::snprintf(text, sizeof(text), "%0*ld", width, value);
  return text;
}

}  // namespace

FrameRange ParseFrameRange(const std::string& text, long num_frames, const std::string& sequence) {
  const std::string where = "--frames " + text + ": ";
  const size_t colon = text.find(':');
  FrameRange range;
  if (colon == std::string::npos) {
    range.first = ParseIndex(text);
    if (range.first < 0) throw ConfigError(where + "expected N, A:B, A:, :B or : (0-based frame indices, B excluded)");
    range.end = range.first + 1;
  } else {
    const std::string first = text.substr(0, colon), end = text.substr(colon + 1);
    range.first = first.empty() ? 0 : ParseIndex(first);
    range.end = end.empty() ? num_frames : ParseIndex(end);
    if (range.first < 0 || range.end < 0) {
      throw ConfigError(where + "expected N, A:B, A:, :B or : (0-based frame indices, B excluded)");
    }
    range.end = std::min(range.end, num_frames);
  }
  if (range.first >= num_frames) {
    throw ConfigError(where + "sequence " + QuoteName(sequence) + " has " + std::to_string(num_frames) + " frames (0 to " +
                      std::to_string(num_frames - 1) + ")");
  }
  if (range.end <= range.first) throw ConfigError(where + "the range is empty");
  return range;
}

std::vector<int> SelectCameras(const std::vector<std::string>& selection, const std::vector<Camera>& cameras,
                               const std::string& sequence) {
  std::vector<int> out;
  if (selection.empty()) {
    for (size_t c = 0; c < cameras.size(); ++c) out.push_back(static_cast<int>(c));
    return out;
  }
  std::vector<std::string> names;
  for (const Camera& camera : cameras) names.push_back(camera.name);
  for (const std::string& wanted : selection) {
    int found = -1;
    for (size_t c = 0; c < cameras.size() && found < 0; ++c) {
      if (cameras[c].name == wanted) found = static_cast<int>(c);
    }
    const long index = ParseIndex(wanted);
    if (found < 0 && index >= 0 && index < static_cast<long>(cameras.size())) found = static_cast<int>(index);
    if (found < 0) {
      const std::string closest = ClosestName(wanted, names);
      throw ConfigError("--cameras: sequence " + QuoteName(sequence) + " has no camera " + QuoteName(wanted) +
                        (closest.empty() ? "" : "; did you mean " + QuoteName(closest) + "?") + " (cameras: " + JoinNames(names) +
                        ", or their indices 0 to " + std::to_string(cameras.size() - 1) + ")");
    }
    out.push_back(found);
  }
  return out;
}

std::string ImagePath(const std::string& pattern, const std::string& camera, int camera_idx,
                      const std::string& frame_id, long frame_idx) {
  size_t digits = frame_id.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(frame_id[digits - 1]))) --digits;
  const std::string frame = digits < frame_id.size() ? frame_id.substr(digits) : frame_id;
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '{') {
      out += pattern[i];
      continue;
    }
    const size_t close = pattern.find('}', i);
    if (close == std::string::npos) throw ConfigError("--images " + pattern + ": '{' without '}'");
    std::string name = pattern.substr(i + 1, close - i - 1);
    int width = 0;
    if (const size_t colon = name.find(':'); colon != std::string::npos) {
      const long parsed = ParseIndex(name.substr(colon + 1));
      name = name.substr(0, colon);
      if (parsed < 0 || parsed > 20 || (name != "camera_idx" && name != "frame_idx")) {
        throw ConfigError("--images " + pattern +
                          ": a width (e.g. {frame_idx:6}) is only for {camera_idx} and {frame_idx}");
      }
      width = static_cast<int>(parsed);
    }
    if (name == "camera") {
      out += camera;
    } else if (name == "camera_idx") {
      out += Padded(camera_idx, width);
    } else if (name == "frame_id") {
      out += frame_id;
    } else if (name == "frame") {
      out += frame;
    } else if (name == "frame_idx") {
      out += Padded(frame_idx, width);
    } else {
      const std::string closest = ClosestName(name, {"camera", "camera_idx", "frame_id", "frame", "frame_idx"});
      throw ConfigError("--images " + pattern + ": unknown placeholder {" + name + "}" +
                        (closest.empty() ? "" : "; did you mean {" + closest + "}?") +
                        " (known: {camera}, {camera_idx}, {frame_id}, {frame}, {frame_idx})");
    }
    i = close;
  }
  return out;
}

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// Private helpers of the generic readers and writers (datasets/readers/generic_*.cc,
// openpose_json.cc, coco_detections.cc, detections_file.cc). Not a public header: it exposes
// nlohmann::json, a private dependency of rpt_datasets.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"

namespace rpt::generic_internal {

// The name of a file in messages: the path as given.
inline std::string Source(const std::filesystem::path& path) { return path.string(); }

// A frame id written as a string or an integer.
inline std::string IdString(const nlohmann::json& root, const std::string& pointer, const std::string& source) {
  const nlohmann::json& j = io::JsonAt(root, pointer, source);
  if (j.is_string()) {
    std::string id = j.get<std::string>();
    if (id.empty()) throw InputError(source + ": " + pointer + ": empty id");
    return id;
  }
  if (j.is_number_integer()) return std::to_string(j.get<std::int64_t>());
  throw InputError(source + ": " + pointer + ": expected a string or an integer id, got " + std::string(j.type_name()));
}

// A JSON list written one element per line (diff-friendly, compact); invalid UTF-8 is written as
// U+FFFD and counted in `*replaced` (io::DumpJson).
template <typename Json>
std::string DumpListOnePerLine(const std::vector<Json>& items, int* replaced = nullptr) {
  std::string text = "[\n";
  for (size_t i = 0; i < items.size(); ++i) {
    text += io::DumpJson(items[i], -1, replaced);
    text += i + 1 < items.size() ? ",\n" : "\n";
  }
  text += "]\n";
  return text;
}

// The first non-blank byte of a file (after a UTF-8 BOM), or 0 when it is empty/unreadable.
inline char FirstSignificantChar(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  bool first = true;
  while (in.get(c)) {
    if (first && static_cast<unsigned char>(c) == 0xEF) {  // UTF-8 BOM
      in.ignore(2);
      first = false;
      continue;
    }
    first = false;
    if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return c;
  }
  return 0;
}

}  // namespace rpt::generic_internal

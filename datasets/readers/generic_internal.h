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

#include <map>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "core/utf8.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"

namespace rpt::generic_internal {

// Throws InputError "<source>: <pointer>: <what>".
[[noreturn]] inline void Fail(const std::string& source, const std::string& pointer, const std::string& what) {
  throw InputError(source + ": " + pointer + ": " + what);
}

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

// Keys of the objects of a file (labels, frames, views) that the reader does not read: a misspelt
// optional key ("timeStamp", "bodyIds", "scenes") would otherwise drop its value silently. Counted
// per key, reported as unused input (an error under --strict): one warning per key for the first
// kMaxShownKeys keys, one for all others.
class UnknownKeys {
 public:
  static constexpr std::size_t kMaxShownKeys = 5;
  static constexpr std::size_t kMaxKeyBytes = 40;

  explicit UnknownKeys(std::vector<std::string> known) : known_(std::move(known)) {}

  void Count(const nlohmann::json& object) {
    if (!object.is_object()) return;
    for (auto it = object.begin(); it != object.end(); ++it) {
      if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
      const std::string key = Utf8Excerpt(it.key(), kMaxKeyBytes);
      if (auto found = counts_.find(key); found != counts_.end()) {
        ++found->second;
      } else if (counts_.size() < kMaxShownKeys) {
        order_.push_back(key);
        counts_[key] = 1;
      } else {
        ++others_;
      }
    }
  }

  // `objects`: what holds the keys, plural ("labels", "frames of the detections").
  void Report(const std::string& source, const std::string& objects, InputWarnings* warnings) const {
    for (const std::string& key : order_) {
      warnings->AddUnused(source, objects + " with the unknown key " + QuoteName(key) + DidYouMeanKey(key, known_) + ", not read",
                          counts_.at(key));
    }
    warnings->AddUnused(source, "other unknown keys in " + objects + " (not read)", others_);
  }

 private:
  std::vector<std::string> known_;
  std::vector<std::string> order_;  // first seen first
  std::map<std::string, long> counts_;
  long others_ = 0;
};

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

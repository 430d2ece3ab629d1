// SPDX-License-Identifier: MIT
#include "engine/input_digests.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "core/errors.h"
#include "core/utf8.h"
#include "datasets/io/file_digest.h"

namespace rpt::engine {

std::vector<std::string> InputPaths(const InputSpec& spec) {
  std::vector<std::string> paths;
  for (const std::string& path : {spec.root, spec.labels, spec.cameras, spec.detections, spec.mapping.coco_images}) {
    if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end()) paths.push_back(path);
  }
  return paths;
}

std::vector<std::pair<std::string, std::string>> InputDigests(const InputSpec& spec) {
  std::vector<std::pair<std::string, std::string>> digests;
  for (const std::string& path : InputPaths(spec)) {
    std::string digest;
    try {
      digest = io::PathDigest(path);
    } catch (const InputError&) {
      // Not recorded; the report says it cannot verify this path.
    }
    digests.emplace_back(path, digest);
  }
  return digests;
}

namespace {

// `path` read from `base` when it is relative.
std::string From(const std::filesystem::path& base, const std::string& path) {
  if (base.empty() || path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (base / path).string();
}

}  // namespace

InputSpec RebasedInput(InputSpec spec, const std::filesystem::path& base) {
  for (std::string* path : {&spec.root, &spec.labels, &spec.cameras, &spec.detections, &spec.mapping.coco_images}) {
    *path = From(base, *path);
  }
  return spec;
}

std::vector<std::string> InputDigestProblems(const nlohmann::ordered_json& run_info, const InputSpec& spec,
                                             bool* unreadable, const std::filesystem::path& base) {
  *unreadable = false;
  std::vector<std::string> problems;
  const auto recorded = run_info.find("input_digests");
  for (const std::string& given : InputPaths(spec)) {
    const std::string path = From(base, given);
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::is_regular_file(status) && !std::filesystem::is_directory(status)) {
      *unreadable = true;
      problems.push_back(path + ": " + (std::filesystem::exists(status) ? "not a regular file or folder" : "not found"));
      continue;
    }
    const nlohmann::ordered_json* digest = nullptr;
    if (recorded != run_info.end() && recorded->is_object() && recorded->contains(given)) digest = &(*recorded)[given];
    if (digest == nullptr || !digest->is_string() || digest->get<std::string>().empty()) {
      problems.push_back(path + ": run.json records no digest of it (written by an older rpt, or edited): it cannot be "
                         "verified as the run's input");
      continue;
    }
    std::string now;
    try {
      now = io::PathDigest(path);
    } catch (const InputError& e) {
      *unreadable = true;
      problems.push_back(e.what());
      continue;
    }
    if (now != digest->get<std::string>()) {
      problems.push_back(path + ": changed since the run (run.json records " + Utf8Excerpt(digest->get<std::string>(), 60) +
                         ", it is now " + now + ")");
    }
  }
  return problems;
}

}  // namespace rpt::engine

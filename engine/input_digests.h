// SPDX-License-Identifier: MIT
// The input files and folders a run read, with their content digests (io::PathDigest): `rpt eval`
// records them in run.json ("input_digests"), `rpt report` compares them with the files on disk
// before it re-loads the input, so a report never shows the recorded numbers beside values
// computed from a different input without saying so (docs/report.md).
#pragma once

#include <nlohmann/json.hpp>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "engine/input.h"

namespace rpt::engine {

// The paths the input options name (--root, --labels, --cameras, --detections, --coco-images), each once.
std::vector<std::string> InputPaths(const InputSpec& spec);

// {path, digest} of every InputPaths entry; a path that cannot be digested gets "" (the run goes on:
// the report then cannot verify it).
std::vector<std::pair<std::string, std::string>> InputDigests(const InputSpec& spec);

// What keeps the input of `spec` from being verified as the one run.json's "input_digests" records,
// one line per path ("<path>: changed since the run (...)", "<path>: run.json records no digest of
// it ..."); empty when every path matches. Sets *unreadable when a path is missing or not a regular
// file or folder (a FIFO would block a reader). Relative paths are read from `base` (the folder
// the run ran in; empty: the current folder) and looked up in run.json as they were given.
std::vector<std::string> InputDigestProblems(const nlohmann::ordered_json& run_info, const InputSpec& spec,
                                             bool* unreadable, const std::filesystem::path& base = {});

// `spec` with its relative input paths (InputPaths) taken from `base`; unchanged when `base` is empty.
InputSpec RebasedInput(InputSpec spec, const std::filesystem::path& base);

}  // namespace rpt::engine

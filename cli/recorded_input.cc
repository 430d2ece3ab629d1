// SPDX-License-Identifier: MIT
#include "cli/recorded_input.h"

#include <CLI/CLI.hpp>
#include <algorithm>

#include "cli/input_options.h"
#include "engine/input.h"

namespace rpt::cli {

std::optional<std::vector<Sequence>> ReloadRecordedInput(const engine::RecordedRun& run, std::string* why) {
  std::string problem;
  const std::vector<std::string> words = engine::RecordedWords(run, &problem);
  if (!problem.empty()) {
    *why = problem;
    return std::nullopt;
  }
  if (words.size() < 2 || (words[1] != "eval" && words[1] != "triangulate")) {
    *why = "run.json does not record an `rpt eval` or `rpt triangulate` command";
    return std::nullopt;
  }
  // The recorded command's input options; everything else (config, output) is ignored.
  CLI::App app;
  app.allow_extras();
  engine::InputSpec input;
  if (words[1] == "eval") {
    AddInputOptions(&app, &input);
  } else {
    AddDetectionInputOptions(&app, &input);
  }
  std::vector<std::string> args(words.begin() + 2, words.end());
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  try {
    app.parse(args);
    InputWarnings warnings;  // already recorded in run.json
    return engine::LoadInput(input, {}, &warnings);
  } catch (const CLI::Error& e) {
    *why = std::string("cannot parse the recorded command: ") + e.what();
  } catch (const std::exception& e) {
    *why = e.what();
  }
  return std::nullopt;
}

}  // namespace rpt::cli

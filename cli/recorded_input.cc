// SPDX-License-Identifier: MIT
#include "cli/recorded_input.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "cli/input_options.h"
#include "core/errors.h"
#include "core/text.h"
#include "engine/input.h"
#include "engine/input_digests.h"

namespace rpt::cli {

std::optional<std::vector<Sequence>> ReloadRecordedInput(const engine::RecordedRun& run, bool require_same_input,
                                                         std::string* why, std::vector<std::string>* warnings) {
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
  const auto live = [](const std::string& word) { return word == "--follow" || word.starts_with("--follow="); };
  if (words[1] == "triangulate" && std::any_of(words.begin() + 2, words.end(), live)) {
    *why = "the run read a live stream (rpt triangulate --follow), which is not read again";
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
  } catch (const CLI::Error& e) {
    *why = std::string("cannot parse the recorded command: ") + e.what();
    return std::nullopt;
  }
  // Relative paths are the run's: taken from the folder it ran in (run.json records it relative to
  // the run folder), when that folder exists; else from the current folder.
  std::filesystem::path base;
  const auto recorded_dir = run.run_info.find("working_directory");
  if (recorded_dir != run.run_info.end() && recorded_dir->is_string()) {
    const std::filesystem::path where = run.dir / recorded_dir->get<std::string>();
    std::error_code ec;
    if (std::filesystem::is_directory(where, ec)) base = where.lexically_normal();
  }
  bool unreadable = false;
  const std::vector<std::string> problems = engine::InputDigestProblems(run.run_info, input, &unreadable, base);
  if (!problems.empty() && require_same_input) {
    throw InputError("--require-same-input: the input on disk is not verified as the run's:\n  " + Join(problems, "\n  "));
  }
  for (const std::string& line : problems) warnings->push_back("input not verified as the run's: " + line);
  if (unreadable) {
    *why = Join(problems, "; ");
    return std::nullopt;
  }
  try {
    InputWarnings input_warnings;  // already recorded in run.json
    // The run's frames are the frames of predictions.json: a larger input is not the run's.
    return engine::LoadInput(engine::RebasedInput(input, base), {}, &input_warnings,
                             static_cast<long>(run.predictions.frames.size()));
  } catch (const std::exception& e) {
    if (problems.empty()) {
      *why = e.what();
    } else {
      std::fprintf(stderr, "error re-loading the input: %s\n", e.what());
      *why = "the input could not be re-loaded, and it is not verified as the run's (the reader's message went to the "
             "terminal, not into the page)";
    }
  }
  return std::nullopt;
}

}  // namespace rpt::cli

// SPDX-License-Identifier: MIT
// Where and how a result was produced: git revision, machine, compiler, threads, command line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rpt::engine {

struct RunInfo {
  std::string git_revision;
  std::string cpu;        // /proc/cpuinfo model name
  int hardware_threads = 0;
  int threads = 0;        // threads used by the run
  std::string compiler;
  std::string build_type;
  std::string command_line;               // for people: "rpt" and the arguments joined by spaces
  std::vector<std::string> command_args;  // the same as the argument vector ("rpt" first), for programs
  // The folder the command ran in (absolute; empty when unknown): its relative paths are taken from
  // there (rpt report, rpt render --run re-load the input from it). Files record it relative to the
  // folder they are written in (RunInfoJson), so a project moved as a whole still re-loads.
  std::string working_directory;
  std::string date_utc;
  std::string run_id;  // unique per run ("<date>-<pid>-<random>"); every JSON output of the run carries it
  std::vector<std::string> input_warnings;  // corrections the readers applied, one line per file and kind
  // {path, digest} of the input files and folders (engine/input_digests.h); "" = not digested.
  std::vector<std::pair<std::string, std::string>> input_digests;
  // What the input options resolved to, defaults included (engine::ResolvedInputSettings).
  std::vector<std::pair<std::string, std::string>> input_settings;
};

// The run's machine, build and time, and the command stored by SetCommand.
RunInfo CollectRunInfo(int threads);

// The process command ("rpt eval --dataset ..."), for records: call SetCommand once in main().
// The joined line is for people, each argument quoted as a POSIX shell reads it back (a path with
// a space in single quotes), so it can be pasted; programs (rpt report) read the argument vector.
std::string CommandLine(int argc, char** argv);
void SetCommand(int argc, char** argv);
const std::string& CurrentCommandLine();
const std::vector<std::string>& CurrentCommandArgs();

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// Where and how a result was produced: git revision, machine, compiler, threads, command line.
#pragma once

#include <string>
#include <vector>

namespace rpt::cli {

struct RunInfo {
  std::string git_revision;
  std::string cpu;        // /proc/cpuinfo model name
  int hardware_threads = 0;
  int threads = 0;        // threads used by the run
  std::string compiler;
  std::string build_type;
  std::string command_line;
  std::string date_utc;
  std::string run_id;  // unique per run ("<date>-<pid>-<random>"); every JSON output of the run carries it
  std::vector<std::string> input_warnings;  // corrections the readers applied, one line per file and kind
};

RunInfo CollectRunInfo(int threads, const std::string& command_line);

// The process command line ("rpt eval --dataset ..."), for records.
std::string CommandLine(int argc, char** argv);
void SetCommandLine(const std::string& command_line);
const std::string& CurrentCommandLine();

}  // namespace rpt::cli

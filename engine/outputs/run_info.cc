// SPDX-License-Identifier: MIT
#include "engine/outputs/run_info.h"

#include <filesystem>
#include <system_error>

#include <unistd.h>

#include <ctime>
#include <random>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "git_revision.h"

namespace rpt::engine {
namespace {

std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown";
}

struct StoredCommand {
  std::string line;
  std::vector<std::string> args;
};

StoredCommand& Stored() {
  static StoredCommand command;
  return command;
}

}  // namespace

RunInfo CollectRunInfo(int threads) {
  RunInfo info;
  info.git_revision = RPT_GIT_REVISION;
  info.cpu = CpuModel();
  info.hardware_threads = static_cast<int>(std::thread::hardware_concurrency());
  info.threads = threads;
#if defined(__clang__)
  info.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  info.compiler = "g++ " __VERSION__;
#endif
  info.build_type = RPT_BUILD_TYPE;
  info.command_line = CurrentCommandLine();
  info.command_args = CurrentCommandArgs();
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  if (!ec) info.working_directory = cwd.string();
  char date[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  info.date_utc = date;
  char run_id[80];
  std::strftime(date, sizeof(date), "%Y%m%dT%H%M%SZ", std::gmtime(&now));
  std::snprintf(run_id, sizeof(run_id), "%s-%d-%08x", date, static_cast<int>(::getpid()),
                static_cast<unsigned>(std::random_device{}()));
  info.run_id = run_id;
  return info;
}

namespace {

// `arg` as a POSIX shell reads it back: as it is when it holds only characters no shell treats
// specially, else in single quotes (a quote inside as '\'').
std::string ShellQuoted(const std::string& arg) {
  const bool plain = !arg.empty() && arg.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                           "0123456789_./=,:@%+-") == std::string::npos;
  if (plain) return arg;
  std::string out = "'";
  for (const char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string CommandLine(int argc, char** argv) {
  std::string out = "rpt";
  for (int i = 1; i < argc; ++i) {
    out.push_back(' ');
    out.append(ShellQuoted(argv[i]));
  }
  return out;
}

void SetCommand(int argc, char** argv) {
  Stored().line = CommandLine(argc, argv);
  Stored().args = {"rpt"};
  for (int i = 1; i < argc; ++i) Stored().args.emplace_back(argv[i]);
}
const std::string& CurrentCommandLine() { return Stored().line; }
const std::vector<std::string>& CurrentCommandArgs() { return Stored().args; }

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// Runs the rpt binary and captures stdout, stderr and the exit code.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rpt::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh, empty temporary folder unique to this test process.
inline std::filesystem::path TempDir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rpt_cli_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// `args` is appended to the binary path as-is (shell syntax); `shell_prefix` comes before it
// (shell commands and variable assignments, e.g. "ulimit -f 64; TMPDIR=/x ").
inline CommandResult RunRpt(const std::string& args, const std::string& shell_prefix = "") {
  const auto dir = std::filesystem::temp_directory_path();
  const auto out = dir / ("rpt_test_out_" + std::to_string(::getpid()));
  const auto err = dir / ("rpt_test_err_" + std::to_string(::getpid()));
  const std::string command = shell_prefix + std::string(RPT_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = ReadAll(out);
  result.err = ReadAll(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

}  // namespace rpt::test

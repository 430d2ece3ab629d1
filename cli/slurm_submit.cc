// SPDX-License-Identifier: MIT
#include "cli/slurm_submit.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/text_file.h"

extern char** environ;

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;

// The options of `rpt sweep` that are about submitting, not about the sweep: a shard runs without
// them (and gets its own --shard).
bool IsSubmitOption(const std::string& name) {
  return name == "--slurm" || name == "--slurm-option" || name == "--shard";
}

std::string ShardFile(const SlurmSweep& sweep, int k) {
  return (fs::path(sweep.out) / ("sweep-shard-" + std::to_string(k) + "-of-" + std::to_string(sweep.shards) + ".json"))
      .string();
}

// One "#SBATCH --key=value" line per --slurm-option ("time=1:00:00" and "--time=1:00:00" alike).
std::string SbatchOptionLines(const SlurmSweep& sweep) {
  std::string lines;
  for (const std::string& option : sweep.sbatch_options) {
    lines += "#SBATCH " + (option.rfind('-', 0) == 0 ? option : "--" + option) + "\n";
  }
  return lines;
}

// A path as the value of an #SBATCH line: double-quoted (sbatch reads "my proj" as one value; a
// space cut the line there), with % doubled where sbatch expands patterns (--output; `pattern` is
// appended as is, e.g. "/shard-%a-of-4.log"). A path with a double quote or a control character
// cannot be written there (a newline would start a directive of its own): ConfigError.
std::string SbatchPath(const std::string& path, const std::string& what, bool patterns, const std::string& pattern = "") {
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f || c == '"') {
      throw ConfigError(what + " " + PrintableText(path, LineBreaks::kEscape) +
                        ": a path with a double quote or a control character cannot be written into a Slurm job "
                        "script; choose another folder");
    }
  }
  std::string quoted = "\"";
  for (const char c : path) quoted += patterns && c == '%' ? std::string("%%") : std::string(1, c);
  return quoted + pattern + "\"";
}

std::string Header(const SlurmSweep& sweep, const std::string& name, const std::string& workdir,
                   const std::string& log_dir, const std::string& log_file) {
  return "#!/bin/bash\n"
         "# Written by `rpt sweep --slurm " + std::to_string(sweep.shards) + "` (docs/sweeps.md).\n"
         "#SBATCH --job-name=" + name + "\n"
         "#SBATCH --chdir=" + SbatchPath(workdir, "the working folder", false) + "\n"
         "#SBATCH --output=" + SbatchPath(log_dir, "--out", true, "/" + log_file) + "\n" + SbatchOptionLines(sweep);
}

struct Spawned {
  int exit_code = -1;   // -1: killed by a signal
  std::string out;      // its standard output (its standard error is rpt's)
};

// Runs `argv` (found on PATH) with the signals rpt blocks for its interrupt thread unblocked again.
// Returns false when it could not start (errno set).
bool Spawn(const std::vector<std::string>& argv, Spawned* result) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return false;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(pipe_fds[1]);
  if (spawned != 0) {
    close(pipe_fds[0]);
    errno = spawned;
    return false;
  }
  char buffer[4096];
  while (true) {
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n > 0) {
      result->out.append(buffer, static_cast<size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result->exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return true;
}

// `sbatch --parsable ...`, returning the job id ("<id>" or "<id>;<cluster>" on its first line).
std::string Sbatch(const std::vector<std::string>& options, const std::string& script) {
  std::vector<std::string> argv = {"sbatch", "--parsable"};
  argv.insert(argv.end(), options.begin(), options.end());
  argv.push_back(script);
  Spawned run;
  if (!Spawn(argv, &run)) {
    throw InputError(std::string("cannot run sbatch (") + std::strerror(errno) +
                     "): submitting needs Slurm's client commands on PATH; --slurm-dry-run writes the job scripts "
                     "without submitting");
  }
  if (run.exit_code != 0) {
    throw InputError("sbatch " + script + " failed (" +
                     (run.exit_code < 0 ? std::string("killed by a signal") : "exit code " + std::to_string(run.exit_code)) +
                     "; sbatch's message is above)");
  }
  std::string id = run.out.substr(0, run.out.find_first_of(";\n"));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos) {
    throw InputError("sbatch " + script + ": expected a job id from sbatch --parsable, got '" +
                     PrintableText(run.out, LineBreaks::kEscape) + "'");
  }
  return id;
}

}  // namespace

std::vector<std::string> ShardArguments(const std::vector<std::string>& args) {
  std::vector<std::string> kept;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--slurm-dry-run") continue;
    const std::string name = a.substr(0, a.find('='));
    if (IsSubmitOption(name)) {
      if (name == a) ++i;  // --name value
      continue;
    }
    kept.push_back(a);
  }
  return kept;
}

std::string ShellQuote(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-./=:,+@%") ==
                           std::string::npos) {
    return text;
  }
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string ShardsScript(const SlurmSweep& sweep, const std::string& rpt, const std::string& workdir,
                         const std::string& log_dir) {
  const std::string n = std::to_string(sweep.shards);
  std::string command = "exec " + ShellQuote(rpt);
  for (const std::string& a : ShardArguments(sweep.sweep_args)) command += " " + ShellQuote(a);
  command += " --shard \"${SLURM_ARRAY_TASK_ID}/" + n + "\"";
  // Without --threads a shard takes the CPUs Slurm gave it, not every core of the node.
  if (!sweep.threads_given) command += " --threads \"${SLURM_CPUS_PER_TASK:-1}\"";
  return Header(sweep, "rpt-sweep", workdir, log_dir, "shard-%a-of-" + n + ".log") +
         "#SBATCH --array=1-" + n + "\n" + "set -euo pipefail\n" + command + "\n";
}

std::string MergeScript(const SlurmSweep& sweep, const std::string& rpt, const std::string& workdir,
                        const std::string& log_dir) {
  std::string command = "exec " + ShellQuote(rpt) + " merge";
  for (int k = 1; k <= sweep.shards; ++k) command += " " + ShellQuote(ShardFile(sweep, k));
  command += " --out " + ShellQuote(sweep.out);
  // Submitted with --dependency=afterok:<array>; when a shard fails, Slurm cancels this job instead
  // of leaving it pending for ever.
  return Header(sweep, "rpt-sweep-merge", workdir, log_dir, "merge.log") +
         "#SBATCH --kill-on-invalid-dep=yes\n" + "set -euo pipefail\n" + command + "\n";
}

void SubmitSlurmSweep(const SlurmSweep& sweep) {
  for (const std::string& option : sweep.sbatch_options) {
    if (option.find_first_of("\n\r") != std::string::npos || option.empty()) {
      throw ConfigError("--slurm-option " + QuoteName(option) +
                        ": expected one sbatch option, e.g. time=01:00:00");
    }
  }
  std::error_code ec;
  const fs::path rpt = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw InputError("cannot find the path of the rpt binary (/proc/self/exe): " + ec.message());
  const fs::path workdir = fs::current_path();
  const fs::path log_dir = fs::absolute(fs::path(sweep.out) / "slurm");
  // Made before anything is written: a path the scripts cannot hold is refused first.
  const std::string shards_text = ShardsScript(sweep, rpt.string(), workdir.string(), log_dir.string());
  const std::string merge_text = MergeScript(sweep, rpt.string(), workdir.string(), log_dir.string());
  fs::create_directories(log_dir, ec);
  if (ec) throw InputError(log_dir.string() + ": cannot create folder: " + ec.message());
  const fs::path shards_script = log_dir / "shards.sbatch";
  const fs::path merge_script = log_dir / "merge.sbatch";
  io::WriteTextFile(shards_script, io::NamedBy::kRpt, shards_text);
  io::WriteTextFile(merge_script, io::NamedBy::kRpt, merge_text);
  std::printf("wrote %s and %s\n", PrintableText(shards_script.string(), LineBreaks::kEscape).c_str(),
              PrintableText(merge_script.string(), LineBreaks::kEscape).c_str());
  if (sweep.dry_run) {
    std::printf("dry run, nothing submitted; to submit:\n  array=$(sbatch --parsable %s)\n"
                "  sbatch --dependency=afterok:${array%%%%;*} %s\n",
                ShellQuote(shards_script.string()).c_str(), ShellQuote(merge_script.string()).c_str());
    std::fflush(stdout);
    return;
  }
  std::fflush(stdout);
  const std::string array = Sbatch({}, shards_script.string());
  std::string merge;
  try {
    merge = Sbatch({"--dependency=afterok:" + array}, merge_script.string());
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "; the shards' job array " + array +
                     " was submitted: cancel it with `scancel " + array + "` or submit the merge by hand");
  }
  std::printf("submitted job array %s (%d shards) and merge job %s (runs when every shard succeeded)\n"
              "  watch: squeue -j %s,%s\n  table:  %s/sweep.{json,csv,md,html}; logs in %s\n",
              array.c_str(), sweep.shards, merge.c_str(), array.c_str(), merge.c_str(),
              PrintableText(sweep.out, LineBreaks::kEscape).c_str(),
              PrintableText(log_dir.string(), LineBreaks::kEscape).c_str());
}

}  // namespace rpt::cli

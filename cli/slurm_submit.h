// SPDX-License-Identifier: MIT
// `rpt sweep --slurm N`: the sweep as a Slurm job array of N shards (`rpt sweep ... --shard k/N`)
// and a merge job (`rpt merge`) that starts when every shard succeeded (--dependency=afterok).
// The two job scripts are written to <out>/slurm/ (shards.sbatch, merge.sbatch; the jobs' logs go
// beside them), then submitted with `sbatch` from PATH unless it is a dry run (docs/sweeps.md).
#pragma once

#include <string>
#include <vector>

namespace rpt::cli {

struct SlurmSweep {
  int shards = 0;                            // the array's size: shards k = 1..shards
  std::vector<std::string> sweep_args;       // rpt's arguments after the program name, as given
  std::vector<std::string> sbatch_options;   // --slurm-option values, e.g. "time=01:00:00"
  std::string out;                           // the sweep's --out, as given
  bool threads_given = false;                // --threads was given (else ${SLURM_CPUS_PER_TASK:-1})
  bool dry_run = false;                      // write the scripts, do not submit
};

// The sweep's arguments for one shard: `args` without --slurm, --slurm-option, --slurm-dry-run and
// --shard (in their `--name value` and `--name=value` forms).
std::vector<std::string> ShardArguments(const std::vector<std::string>& args);

// `text` as one shell word: as is when it holds only characters the shell leaves alone, else in
// single quotes (a quote inside as '\'').
std::string ShellQuote(const std::string& text);

// The job scripts. `rpt` is the absolute path of the binary, `workdir` the absolute folder the
// jobs run in (the submitting shell's, so relative paths of the command line hold) and
// `log_dir` the absolute folder of the logs.
std::string ShardsScript(const SlurmSweep& sweep, const std::string& rpt, const std::string& workdir,
                         const std::string& log_dir);
std::string MergeScript(const SlurmSweep& sweep, const std::string& rpt, const std::string& workdir,
                        const std::string& log_dir);

// Writes <out>/slurm/{shards,merge}.sbatch and, unless a dry run, submits them; prints what it did.
// A missing or failing sbatch is an InputError with sbatch's own message.
void SubmitSlurmSweep(const SlurmSweep& sweep);

}  // namespace rpt::cli

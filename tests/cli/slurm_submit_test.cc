// SPDX-License-Identifier: MIT
// rpt sweep --slurm (cli/slurm_submit.h) without a cluster: the job scripts it writes (run here
// by hand, shard by shard, then the merge, they give the unsharded sweep's table), the sbatch
// calls it makes (a stand-in sbatch on PATH records them), and its errors. The real cluster run is
// scripts/ci_slurm.sh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli/slurm_submit.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

nlohmann::json ReadJson(const fs::path& path) { return nlohmann::json::parse(test::ReadAll(path)); }

// The rows of a sweep.json without the timing columns (the shards run apart, so their times differ).
nlohmann::json AccuracyRows(const nlohmann::json& sweep) {
  nlohmann::json rows = sweep["rows"];
  const std::regex timing("time|fps|per_s");
  for (nlohmann::json& row : rows) {
    nlohmann::json kept = nlohmann::json::object();
    for (const auto& [key, value] : row["summary"].items()) {
      if (!std::regex_search(key, timing)) kept[key] = value;
    }
    row["summary"] = kept;
  }
  return rows;
}

// A stand-in sbatch in `dir`: appends its arguments to dir/calls and prints job ids 41, then
// "42;cluster" (sbatch --parsable prints the cluster too on multi-cluster setups).
void WriteFakeSbatch(const fs::path& dir, const std::string& body = "") {
  fs::create_directories(dir);
  std::ofstream(dir / "sbatch") << "#!/bin/sh\n" << body << "echo \"$*\" >> '" << (dir / "calls").string() << "'\n"
                                << "if [ -f '" << (dir / "first").string() << "' ]; then echo '42;cluster'; else touch '"
                                << (dir / "first").string() << "'; echo 41; fi\n";
  fs::permissions(dir / "sbatch", fs::perms::owner_all);
}

TEST(SlurmSubmit, ShardArgumentsDropTheSubmitOptionsInBothForms) {
  const std::vector<std::string> args = {"sweep", "--grid", "a=1,2", "--slurm", "3", "--slurm=3", "--slurm-option",
                                         "time=5", "--slurm-option=partition=cpu", "--slurm-dry-run", "--shard", "1/2",
                                         "--shard=2/2", "--out", "o", "--threads", "2"};
  EXPECT_EQ(cli::ShardArguments(args),
            (std::vector<std::string>{"sweep", "--grid", "a=1,2", "--out", "o", "--threads", "2"}));
}

TEST(SlurmSubmit, ShellQuoteKeepsPlainWordsAndQuotesTheRest) {
  EXPECT_EQ(cli::ShellQuote("merge.top_k=0,2"), "merge.top_k=0,2");
  EXPECT_EQ(cli::ShellQuote("/a/b-c.json"), "/a/b-c.json");
  EXPECT_EQ(cli::ShellQuote("a b"), "'a b'");
  EXPECT_EQ(cli::ShellQuote("it's $HOME"), "'it'\\''s $HOME'");
  EXPECT_EQ(cli::ShellQuote(""), "''");
}

// The written scripts, run as Slurm would run them (SLURM_ARRAY_TASK_ID per shard, then the
// merge), give the table of the unsharded sweep.
TEST(SlurmSubmit, DryRunScriptsRunByHandGiveTheUnshardedTable) {
  const fs::path dir = test::TempDir("slurm_dry");
  const std::string sweep =
      "sweep --dataset synthetic --param frames=8 --grid merge.top_k=0,2,3 --grid 'prefilter.enabled=true,false'";
  ASSERT_EQ(test::RunRpt(sweep + " --threads 1 --out " + (dir / "whole").string()).exit_code, 0);
  const test::CommandResult r = test::RunRpt(sweep + " --out " + (dir / "cluster").string() +
                                             " --slurm 4 --slurm-option time=5 --slurm-option=--partition=ci --slurm-dry-run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("dry run, nothing submitted"), std::string::npos) << r.out;
  const std::string shards = test::ReadAll(dir / "cluster" / "slurm" / "shards.sbatch");
  const std::string merge = test::ReadAll(dir / "cluster" / "slurm" / "merge.sbatch");
  for (const std::string& line : {std::string("#SBATCH --array=1-4\n"), std::string("#SBATCH --time=5\n"),
                                  std::string("#SBATCH --partition=ci\n"),
                                  "#SBATCH --chdir=\"" + fs::current_path().string() + "\"\n",
                                  "#SBATCH --output=\"" + (dir / "cluster" / "slurm" / "shard-%a-of-4.log").string() + "\"\n"}) {
    EXPECT_NE(shards.find(line), std::string::npos) << line << "\n" << shards;
  }
  EXPECT_NE(shards.find(" --shard \"${SLURM_ARRAY_TASK_ID}/4\" --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n"), std::string::npos)
      << shards;
  EXPECT_NE(shards.find(" --grid merge.top_k=0,2,3 --grid prefilter.enabled=true,false "), std::string::npos) << shards;
  const std::string command = shards.substr(shards.find("\nexec "));
  EXPECT_EQ(command.find("--slurm"), std::string::npos) << command;
  EXPECT_NE(merge.find("#SBATCH --kill-on-invalid-dep=yes\n"), std::string::npos) << merge;
  EXPECT_NE(merge.find(" merge " + (dir / "cluster" / "sweep-shard-1-of-4.json").string() + " "), std::string::npos) << merge;
  EXPECT_NE(merge.find((dir / "cluster" / "sweep-shard-4-of-4.json").string() + " --out " + (dir / "cluster").string()),
            std::string::npos)
      << merge;
  EXPECT_FALSE(fs::exists(dir / "cluster" / "sweep.json"));
  for (int k = 1; k <= 4; ++k) {
    ASSERT_EQ(std::system(("SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " bash " +
                           (dir / "cluster" / "slurm" / "shards.sbatch").string() + " >/dev/null 2>&1")
                              .c_str()),
              0)
        << "shard " << k;
  }
  ASSERT_EQ(std::system(("bash " + (dir / "cluster" / "slurm" / "merge.sbatch").string() + " >/dev/null").c_str()), 0);
  const nlohmann::json whole = ReadJson(dir / "whole" / "sweep.json");
  const nlohmann::json merged = ReadJson(dir / "cluster" / "sweep.json");
  ASSERT_EQ(merged["rows"].size(), 6u);
  EXPECT_EQ(AccuracyRows(merged), AccuracyRows(whole));
  EXPECT_EQ(merged["base"], whole["base"]);
  EXPECT_EQ(merged["base_options"], whole["base_options"]);
  fs::remove_all(dir);
}

// Paths in #SBATCH lines are double-quoted (a space cut "--chdir=/my proj" at "proj"), with %
// doubled in --output (sbatch expands %-patterns there); a path that cannot be written there (a
// newline would start a directive of its own, e.g. "#SBATCH --partition=INJECTED") is refused
// before anything is written.
TEST(SlurmSubmit, PathsInSbatchLinesAreQuotedOrRefused) {
  const fs::path dir = test::TempDir("slurm_paths");
  const std::string sweep = "sweep --dataset synthetic --param frames=4 --grid merge.top_k=0,2 --slurm 2 --slurm-dry-run --out ";
  const fs::path out = dir / "my runs 100%";
  const test::CommandResult r = test::RunRpt(sweep + "'" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string shards = test::ReadAll(out / "slurm" / "shards.sbatch");
  EXPECT_NE(shards.find("#SBATCH --output=\"" + (dir / "my runs 100%%" / "slurm").string() + "/shard-%a-of-2.log\"\n"),
            std::string::npos)
      << shards;
  const test::CommandResult injected =
      test::RunRpt(sweep + "\"$(printf '%s\\n#SBATCH --partition=INJECTED' '" + (dir / "nl").string() + "')\"");
  EXPECT_EQ(injected.exit_code, 2) << injected.err;
  EXPECT_NE(injected.err.find("a path with a double quote or a control character cannot be written into a Slurm job script"),
            std::string::npos)
      << injected.err;
  EXPECT_EQ(injected.err.find('\n'), injected.err.size() - 1) << "the newline is shown escaped: " << injected.err;
  EXPECT_FALSE(fs::exists(dir / "nl\n#SBATCH --partition=INJECTED")) << "nothing written";
  fs::remove_all(dir);
}

TEST(SlurmSubmit, SubmitsTheArrayThenTheMergeAfterIt) {
  const fs::path dir = test::TempDir("slurm_submit");
  WriteFakeSbatch(dir / "bin");
  const test::CommandResult r = test::RunRpt("sweep --dataset synthetic --grid merge.top_k=0,2,3 --threads 2 --out " +
                                                 (dir / "out").string() + " --slurm 5",
                                             "PATH=" + (dir / "bin").string() + ":$PATH ");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: --slurm 5: the sweep has 3 configurations; submitting 3 shards"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("submitted job array 41 (3 shards) and merge job 42"), std::string::npos) << r.out;
  const fs::path slurm = dir / "out" / "slurm";
  EXPECT_EQ(test::ReadAll(dir / "bin" / "calls"), "--parsable " + (slurm / "shards.sbatch").string() + "\n" +
                                                      "--parsable --dependency=afterok:41 " +
                                                      (slurm / "merge.sbatch").string() + "\n");
  const std::string shards = test::ReadAll(slurm / "shards.sbatch");
  EXPECT_NE(shards.find("#SBATCH --array=1-3\n"), std::string::npos);
  // --threads given: kept as given, no ${SLURM_CPUS_PER_TASK}.
  EXPECT_NE(shards.find(" --threads 2 "), std::string::npos) << shards;
  EXPECT_EQ(shards.find("SLURM_CPUS_PER_TASK"), std::string::npos) << shards;
  fs::remove_all(dir);
}

TEST(SlurmSubmit, ErrorsAreExitCode2WithAMessage) {
  const fs::path dir = test::TempDir("slurm_errors");
  const std::string sweep = "sweep --dataset synthetic --grid merge.top_k=0,2 --out " + (dir / "out").string();
  // No sbatch on PATH.
  test::CommandResult r = test::RunRpt(sweep + " --slurm 2", "PATH=" + dir.string() + " ");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cannot run sbatch"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--slurm-dry-run"), std::string::npos) << r.err;
  // sbatch refuses the job: its message, then ours.
  WriteFakeSbatch(dir / "bin", "echo 'sbatch: error: invalid partition' >&2; exit 1\n");
  r = test::RunRpt(sweep + " --slurm 2", "PATH=" + (dir / "bin").string() + ":$PATH ");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sbatch: error: invalid partition"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("shards.sbatch failed (exit code 1"), std::string::npos) << r.err;
  // Options that do not go together, and a typo in a configuration, fail before anything is written.
  fs::remove_all(dir / "out");
  for (const std::string& args : {sweep + " --slurm 2 --shard 1/2", sweep + " --slurm-dry-run",
                                  sweep + " --slurm-option time=5", sweep + " --slurm 0",
                                  "sweep --dataset synthetic --grid merge.topk=0,2 --slurm 2 --slurm-dry-run --out " +
                                      (dir / "out").string()}) {
    r = test::RunRpt(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "slurm")) << args;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt

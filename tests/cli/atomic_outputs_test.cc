// SPDX-License-Identifier: MIT
// Outputs are atomic and checked: `rpt eval` killed (SIGKILL) at random points leaves its output
// folder holding the complete old or the complete new run; Ctrl-C (SIGINT) leaves no temporaries
// and exits 130; a write failure exits 2 naming the file; strings are escaped and invalid UTF-8
// is replaced with a warning (not an "internal error" after some outputs were written).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "engine/outputs/junit_xml.h"
#include "engine/outputs/text_escaping.h"
#include "engine/outputs/results_writer.h"
#include "datasets/readers/hdf5_cache.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

// Starts `rpt ARGS...` with its output discarded and, when `tmpdir` is not empty, TMPDIR=tmpdir.
pid_t StartRpt(const std::vector<std::string>& args, const fs::path& tmpdir = {}) {
  std::vector<char*> argv{const_cast<char*>(RPT_BINARY)};
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    // As started from a terminal: the signals at their defaults (a test runner may ignore SIGINT).
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal_number, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::freopen("/dev/null", "w", stdout);
    ::freopen("/dev/null", "w", stderr);
    if (!tmpdir.empty()) ::setenv("TMPDIR", tmpdir.c_str(), 1);
    ::execv(RPT_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

// Starts `rpt eval` on a synthetic scene of `frames` frames into `out` (output discarded).
pid_t StartEval(int frames, const fs::path& out) {
  return StartRpt({"eval", "--dataset", "synthetic", "--param", "frames=" + std::to_string(frames), "--param",
                   "people=6", "--threads", "1", "--quiet", "--out", out.string()});
}

// The exit code, or 1000 + the signal number when a signal ended the process unhandled.
int Wait(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// Entries in `dir` (recursively) whose name holds `marker`: ".tmp-" for the temporaries of
// io::StagedFile / StagedFolder, ".tmp-<pid>-" for those of one process. Entries may vanish while
// it looks (a run renaming them): errors end the walk instead of throwing.
std::vector<std::string> Temporaries(const fs::path& dir, const std::string& marker = ".tmp-") {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string().find(marker) != std::string::npos) names.push_back(it->path().string());
  }
  return names;
}

// Waits until `child` has a temporary beside or in `out` (it is writing its outputs); false when
// it exited first (then it has been reaped).
bool WaitUntilWriting(const fs::path& out, pid_t child) {
  const std::string marker = ".tmp-" + std::to_string(child) + "-";
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < deadline) {
    if (!Temporaries(out.parent_path(), marker).empty()) return true;
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

// Waits until `child` has installed its interrupt handler (SIGINT blocked in its main thread,
// /proc/<pid>/status "SigBlk"); a signal before that ends it as the default action does.
bool WaitUntilHandling(pid_t child) {
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < deadline) {
    std::istringstream status(test::ReadAll("/proc/" + std::to_string(child) + "/status"));
    for (std::string line; std::getline(status, line);) {
      if (line.rfind("SigBlk:", 0) == 0 && (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1)) & 1) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

struct RecordedRunFiles {
  std::string run_id;
  long frames = 0;
};

// Checks that `out` holds one complete run: every file there and parsing, the same run id in
// run.json, summary.json and predictions.json, the same frame count in summary.json,
// summary.csv and predictions.json.
RecordedRunFiles CheckCompleteRun(const fs::path& out) {
  RecordedRunFiles folder;
  for (const char* name : {"summary.json", "summary.csv", "summary.md", "per_joint.csv", "steps.csv", "config.json",
                           "run.json", "predictions.json"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  const Json run = Json::parse(test::ReadAll(out / "run.json"));
  const Json summary = Json::parse(test::ReadAll(out / "summary.json"));
  const Json predictions = Json::parse(test::ReadAll(out / "predictions.json"));
  EXPECT_TRUE(Json::parse(test::ReadAll(out / "config.json")).is_object());
  folder.run_id = run.at("run_id").get<std::string>();
  EXPECT_FALSE(folder.run_id.empty());
  EXPECT_EQ(summary.at("run_id"), folder.run_id);
  EXPECT_EQ(predictions.at("run_id"), folder.run_id);
  folder.frames = summary.at("frames").get<long>();
  EXPECT_EQ(static_cast<long>(predictions.at("frames").size()), folder.frames);
  std::istringstream csv(test::ReadAll(out / "summary.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  std::vector<std::string> keys, values;
  for (std::istringstream h(header); std::getline(h, keys.emplace_back(), ',');) {
  }
  for (std::istringstream r(row); std::getline(r, values.emplace_back(), ',');) {
  }
  const size_t column = std::find(keys.begin(), keys.end(), "frames") - keys.begin();
  EXPECT_LT(column, values.size()) << row;
  if (column < values.size()) {
    EXPECT_EQ(std::stol(values[column]), folder.frames) << row;
  }
  return folder;
}

// The Done-when of issue 10: killed at random points of a long run (SIGKILL, no cleanup
// possible), the folder holds the complete old or the complete new run, never a mix.
TEST(AtomicOutputs, EvalKilledAtRandomPointsLeavesTheOldOrTheNewRun) {
  const fs::path root = test::TempDir("atomic_kill");
  const fs::path out = root / "out";
  const auto start = Clock::now();
  ASSERT_EQ(Wait(StartEval(150, out)), 0);
  const double full_s = std::chrono::duration<double>(Clock::now() - start).count();
  RecordedRunFiles previous = CheckCompleteRun(out);
  ASSERT_EQ(previous.frames, 150);

  const unsigned seed = std::random_device{}();
  SCOPED_TRACE("seed " + std::to_string(seed) + ", full run " + std::to_string(full_s) + " s");
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> fraction(0.2, 1.1);
  std::uniform_int_distribution<int> write_delay_us(0, 20000);
  int old_seen = 0, new_seen = 0;
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int frames = attempt % 2 == 0 ? 151 : 150;  // tells the new run from the old one
    const pid_t child = StartEval(frames, out);
    bool reaped = false;
    if (attempt % 2 == 0) {  // anywhere in the run
      std::this_thread::sleep_for(std::chrono::duration<double>(fraction(random) * full_s));
    } else {  // while it writes its outputs
      reaped = !WaitUntilWriting(out, child);
      std::this_thread::sleep_for(std::chrono::microseconds(write_delay_us(random)));
    }
    ::kill(child, SIGKILL);
    if (!reaped) Wait(child);
    SCOPED_TRACE("attempt " + std::to_string(attempt));
    const RecordedRunFiles now = CheckCompleteRun(out);
    if (now.run_id == previous.run_id) {
      EXPECT_EQ(now.frames, previous.frames);
      ++old_seen;
    } else {
      EXPECT_EQ(now.frames, frames);
      ++new_seen;
    }
    previous = now;
  }
  EXPECT_GT(old_seen, 0);  // the kills did hit running evaluations
  // A killed process cannot clean up: only its staging temporaries may remain beside the folder.
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "out" || name.rfind("out.tmp-", 0) == 0) << name;
  }
  EXPECT_TRUE(Temporaries(out).empty());
  fs::remove_all(root);
}

// Ctrl-C (SIGINT) and SIGTERM: exit 128 + signal, no temporaries, the old run intact.
TEST(AtomicOutputs, InterruptedEvalRemovesItsTemporariesAndExits130) {
  const fs::path root = test::TempDir("atomic_interrupt");
  const fs::path out = root / "out";
  ASSERT_EQ(Wait(StartEval(150, out)), 0);
  const RecordedRunFiles before = CheckCompleteRun(out);
  struct Case {
    int signal_number;
    bool while_writing;
  };
  for (const Case c : {Case{SIGINT, false}, Case{SIGINT, true}, Case{SIGTERM, true}}) {
    SCOPED_TRACE("signal " + std::to_string(c.signal_number) + (c.while_writing ? " while writing" : " early"));
    // Early: a run long enough (5000 frames, seconds) that 100 ms into it is surely before it
    // writes; 151 frames could end within them on a fast or idle machine.
    const pid_t child = StartEval(c.while_writing ? 151 : 5000, out);
    if (c.while_writing) {
      ASSERT_TRUE(WaitUntilWriting(out, child)) << "the run ended before it wrote anything";
    } else {
      ASSERT_TRUE(WaitUntilHandling(child));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ::kill(child, c.signal_number);
    EXPECT_EQ(Wait(child), 128 + c.signal_number);  // handled: exit code, not death by the signal
    EXPECT_TRUE(Temporaries(root).empty());
    EXPECT_EQ(CheckCompleteRun(out).run_id, before.run_id);
  }
  fs::remove_all(root);
}

// `rpt bench --io` interrupted while its scratch HDF5 file (in TMPDIR) exists: exit 130 and the
// file removed with the other temporaries (it used to stay behind).
TEST(AtomicOutputs, InterruptedBenchIoRemovesItsScratchFile) {
  const fs::path tmp = test::TempDir("bench_interrupt");
  for (const int signal_number : {SIGINT, SIGTERM}) {
    SCOPED_TRACE("signal " + std::to_string(signal_number));
    const pid_t child = StartRpt({"bench", "--io", "--io-frames", "10000"}, tmp);
    ASSERT_TRUE(WaitUntilHandling(child));
    // Any file in TMPDIR, whatever its name: the scratch file exists.
    bool exited = false;
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (fs::is_empty(tmp) && Clock::now() < deadline) {
      int status = 0;
      if ((exited = ::waitpid(child, &status, WNOHANG) == child)) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ASSERT_FALSE(exited) << "the run ended before it wrote its file";
    ::kill(child, signal_number);
    EXPECT_EQ(Wait(child), 128 + signal_number);
    EXPECT_TRUE(fs::is_empty(tmp)) << "scratch file left in " << tmp;
  }
  fs::remove_all(tmp);
}

// An HDF5 write that fails (here at a file size limit of 32 KiB) exits 2 naming the file and the
// reason and leaves neither it nor a temporary. HDF5 1.10 used to crash in its clean-up at exit
// after such a failure (signal 11 after the error message). rpt ignores SIGXFSZ itself: the limit
// killed it without a word (exit 153), temporaries left, unless the shell ignored the signal first.
TEST(AtomicOutputs, Hdf5WriteFailureExits2WithoutACrash) {
  const fs::path root = test::TempDir("atomic_hdf5_write_failure");
  const test::CommandResult r =
      test::RunRpt("convert --dataset synthetic --param frames=50 --out " + (root / "cache.h5").string(), "ulimit -f 64; ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + (root / "cache.h5").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("write failed (File too large)"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(root));
  // A run folder at the limit: the error, the old run as it was, no temporary folder.
  const fs::path out = root / "run";
  ASSERT_EQ(test::RunRpt("eval --dataset synthetic --param frames=20 --quiet --out " + out.string()).exit_code, 0);
  const std::string before = test::ReadAll(out / "run.json");
  const test::CommandResult limited = test::RunRpt(
      "eval --dataset synthetic --param frames=400 --quiet --out " + out.string(), "ulimit -f 64; ");
  EXPECT_EQ(limited.exit_code, 2) << limited.err;
  // Named as the file of the folder given (it named run.tmp-<pid>-0/predictions.json.part-0.tmp-<pid>-1).
  EXPECT_NE(limited.err.find("error: " + (out / "predictions.json").string() + ": write failed (File too large)"),
            std::string::npos)
      << limited.err;
  EXPECT_EQ(test::ReadAll(out / "run.json"), before);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(root)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"run"});
  fs::remove_all(root);
}

// The outputs of `rpt convert` are renamed into place together at the end: a failure writing the
// last (here a folder where --detections-out goes) leaves the cache written before it as it was
// (it was renamed into place first, beside the old JSON files).
TEST(AtomicOutputs, ConvertReplacesItsOutputsTogether) {
  const fs::path root = test::TempDir("atomic_convert_outputs");
  const std::string cache = (root / "c.h5").string(), labels = (root / "labels.json").string();
  ASSERT_EQ(test::RunRpt("convert --dataset synthetic --param frames=5 --out " + cache + " --labels-out " + labels)
                .exit_code,
            0);
  const std::string cache_before = test::ReadAll(cache), labels_before = test::ReadAll(labels);
  fs::create_directories(root / "in_the_way");
  const test::CommandResult r =
      test::RunRpt("convert --dataset synthetic --param frames=5 --param seed=4 --out " + cache + " --labels-out " +
                   labels + " --detections-out " + (root / "in_the_way").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("in_the_way: is a folder"), std::string::npos) << r.err;
  EXPECT_EQ(test::ReadAll(cache), cache_before);
  EXPECT_EQ(test::ReadAll(labels), labels_before);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(root)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"c.h5", "in_the_way", "labels.json"}));
  fs::remove_all(root);
}

// A write failure (here a folder where predictions.json goes) exits 2 naming the file, and the
// old run stays as it was.
TEST(AtomicOutputs, WriteFailureExits2NamingTheFileAndKeepsTheOldRun) {
  const fs::path root = test::TempDir("atomic_write_failure");
  const fs::path out = root / "out";
  ASSERT_EQ(Wait(StartEval(20, out)), 0);
  fs::remove(out / "predictions.json");
  fs::create_directories(out / "predictions.json" / "in_the_way");
  const std::string before = test::ReadAll(out / "run.json");
  const test::CommandResult r =
      test::RunRpt("eval --dataset synthetic --param frames=21 --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("error: " + (out / "predictions.json").string()), std::string::npos) << r.err;
  EXPECT_EQ(test::ReadAll(out / "run.json"), before);
  EXPECT_TRUE(Temporaries(root).empty());
  // A folder that cannot be created: its name in the error.
  const test::CommandResult blocked =
      test::RunRpt("eval --dataset synthetic --param frames=5 --quiet --out " + (out / "run.json" / "x").string());
  EXPECT_EQ(blocked.exit_code, 2) << blocked.err;
  EXPECT_NE(blocked.err.find((out / "run.json").string()), std::string::npos) << blocked.err;
  fs::remove_all(root);
}

// A frame id that is not valid UTF-8 (possible in an HDF5 cache) is written as U+FFFD with a
// warning naming the file; before, nlohmann threw and eval exited 1 "internal error".
TEST(AtomicOutputs, InvalidUtf8FrameIdIsReplacedWithAWarning) {
  const fs::path root = test::TempDir("atomic_utf8");
  const test::CommandResult converted =
      test::RunRpt("convert --dataset synthetic --param frames=5 --out " + (root / "clean.h5").string());
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  std::vector<Sequence> sequences = MaterializeAll(OpenSequencesHdf5(root / "clean.h5"));
  Detections detections = ReadDetectionsHdf5(root / "clean.h5");
  ASSERT_FALSE(sequences.empty());
  const std::string bad_id = "frame\xff\xfe";
  const std::string old_id = sequences[0].frames[0].id;
  sequences[0].frames[0].id = bad_id;
  for (FrameDetections& frame : detections.frames) {
    if (frame.frame_id == old_id) frame.frame_id = bad_id;
  }
  WriteSequencesHdf5(root / "bad.h5", sequences);
  WriteDetectionsHdf5(root / "bad.h5", detections, Hdf5WriteOptions{.add_to_existing = true});
  const fs::path out = root / "out";
  const test::CommandResult r = test::RunRpt("eval --labels " + (root / "bad.h5").string() + " --detections " +
                                             (root / "bad.h5").string() + " --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + (out / "predictions.json").string() + ": 1 string(s) not valid UTF-8"),
            std::string::npos)
      << r.err;
  const Json predictions = Json::parse(test::ReadAll(out / "predictions.json"));
  EXPECT_EQ(predictions["frames"][0]["id"], "frame\xef\xbf\xbd\xef\xbf\xbd");
  CheckCompleteRun(out);
  fs::remove_all(root);
}

// What a command prints is checked too: stdout on a full disk is exit 2, not 0 with the text lost.
TEST(AtomicOutputs, FullStandardOutputIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full is absent";
  const int status = std::system((std::string(RPT_BINARY) + " datasets > /dev/full 2>/dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

TEST(AtomicOutputs, JunitXmlReplacesInvalidUtf8) {
  EXPECT_EQ(engine::XmlText("a\xff<b"), "a\xef\xbf\xbd&lt;b");
  EXPECT_EQ(engine::XmlText("caf\xc3\xa9"), "caf\xc3\xa9");  // valid UTF-8 untouched
}

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// Output folders from someone else (issue 19): links planted in a run, sweep or render folder are
// replaced, never written through, by every writer; `--out` naming a link and a write-protected old
// folder behave as docs/results.md says; `rpt render` interrupted mid-write leaves the previous
// videos intact; names from the input reach the terminal and the files escaped, and distinct
// camera names never share a file.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/printable_text.h"
#include "engine/outputs/text_escaping.h"
#include "tests/cli/cli_test_util.h"
#include "tests/hostile_input.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

const std::string kSmallRun = "--dataset synthetic --param frames=5 --param people=2 --param cameras=2 --quiet";

void WriteFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Files outside the output that planted links point to; each must keep its text.
class Outside {
 public:
  explicit Outside(const fs::path& dir) : dir_(dir) { fs::create_directories(dir_); }
  // A new file outside holding a text of its own; returns its path.
  fs::path File(const std::string& name) {
    const fs::path path = dir_ / name;
    WriteFile(path, "precious " + name);
    files_[path] = "precious " + name;
    return path;
  }
  void ExpectUntouched() const {
    for (const auto& [path, text] : files_)
      EXPECT_EQ(test::ReadAll(path), text) << path << " was written through a link";
    size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(dir_)) ++entries;
    EXPECT_EQ(entries, files_.size() + folders_) << "something was created outside the output";
  }
  fs::path Folder(const std::string& name) {
    fs::create_directories(dir_ / name);
    ++folders_;
    return dir_ / name;
  }

 private:
  fs::path dir_;
  std::map<fs::path, std::string> files_;
  size_t folders_ = 0;
};

void Plant(const fs::path& link, const fs::path& to) {
  fs::remove(link);
  fs::create_symlink(to, link);
}

void ExpectRegularFile(const fs::path& path) {
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(path))) << path << " is still a link or missing";
}

// Every name an eval run writes, plus the scratch name of its predictions.
const std::vector<std::string> kRunFiles = {"summary.json", "summary.csv", "summary.md", "per_joint.csv",
                                            "steps.csv",    "config.json", "run.json",   "predictions.json"};

TEST(OutputLinks, EvalReplacesEveryLinkInTheOldRunFolder) {
  const fs::path root = test::TempDir("links_eval");
  Outside outside(root / "outside");
  const fs::path out = root / "out";
  fs::create_directories(out);
  for (const std::string& name : kRunFiles) Plant(out / name, outside.File(name));
  Plant(out / "predictions.json.part-0", outside.File("part"));
  Plant(out / "report.html", outside.File("report"));  // not written by eval: carried over as it is
  Plant(out / "dangling.json", root / "outside" / "absent");
  const test::CommandResult r = test::RunRpt("eval " + kSmallRun + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  outside.ExpectUntouched();
  for (const std::string& name : kRunFiles) ExpectRegularFile(out / name);
  EXPECT_TRUE(fs::is_symlink(out / "report.html"));
  EXPECT_TRUE(fs::is_symlink(out / "predictions.json.part-0"));
  EXPECT_FALSE(fs::exists(root / "outside" / "absent"));
  // In place (the run folder holds the current directory): the same.
  for (const std::string& name : kRunFiles) Plant(out / name, root / "outside" / name);
  const test::CommandResult in_place = test::RunRpt("eval " + kSmallRun + " --out .", "cd " + out.string() + " && ");
  ASSERT_EQ(in_place.exit_code, 0) << in_place.err;
  outside.ExpectUntouched();
  for (const std::string& name : kRunFiles) ExpectRegularFile(out / name);
  fs::remove_all(root);
}

// A FIFO or a folder link where a file goes: replaced, no hang.
TEST(OutputLinks, EvalReplacesAFifoAndDoesNotWaitOnIt) {
  const fs::path root = test::TempDir("links_fifo");
  const fs::path out = root / "out";
  fs::create_directories(out);
  ASSERT_EQ(::mkfifo((out / "summary.json").c_str(), 0644), 0);
  Outside outside(root / "outside");
  Plant(out / "summary.csv", outside.Folder("folder"));
  const test::CommandResult r = test::RunRpt("eval " + kSmallRun + " --out " + out.string(), "timeout 120 ");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectRegularFile(out / "summary.json");
  ExpectRegularFile(out / "summary.csv");
  outside.ExpectUntouched();
  fs::remove_all(root);
}

TEST(OutputLinks, ReportReplacesALinkAtReportHtml) {
  const fs::path root = test::TempDir("links_report");
  Outside outside(root / "outside");
  const fs::path out = root / "out";
  ASSERT_EQ(test::RunRpt("eval " + kSmallRun + " --out " + out.string()).exit_code, 0);
  Plant(out / "report.html", outside.File("report"));
  const test::CommandResult r = test::RunRpt("report " + out.string() + " --max-frames 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExpectRegularFile(out / "report.html");
  // --out naming a link the user gave: the link is replaced too (what it points to is not a device).
  Plant(root / "page.html", outside.File("page"));
  ASSERT_EQ(test::RunRpt("report " + out.string() + " --max-frames 2 --out " + (root / "page.html").string()).exit_code,
            0);
  ExpectRegularFile(root / "page.html");
  outside.ExpectUntouched();
  fs::remove_all(root);
}

TEST(OutputLinks, SweepAndMergeReplaceLinks) {
  const fs::path root = test::TempDir("links_sweep");
  Outside outside(root / "outside");
  const std::string sweep =
      "sweep --grid merge.top_k=0,2 --dataset synthetic --param frames=3 --param cameras=2 --threads 1";
  const fs::path whole = root / "whole", shards = root / "shards";
  fs::create_directories(whole);
  fs::create_directories(shards);
  for (const char* ext : {"json", "csv", "md", "html"}) {
    Plant(whole / (std::string("sweep.") + ext), outside.File(std::string("whole.") + ext));
    Plant(shards / (std::string("sweep-shard-1-of-2.") + ext), outside.File(std::string("shard.") + ext));
  }
  ASSERT_EQ(test::RunRpt(sweep + " --out " + whole.string()).exit_code, 0);
  for (const int k : {1, 2}) {
    const test::CommandResult r = test::RunRpt(sweep + " --shard " + std::to_string(k) + "/2 --out " + shards.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  for (const char* ext : {"json", "csv", "md", "html"}) {
    ExpectRegularFile(whole / (std::string("sweep.") + ext));
    ExpectRegularFile(shards / (std::string("sweep-shard-1-of-2.") + ext));
    Plant(shards / (std::string("sweep.") + ext), outside.File(std::string("merged.") + ext));
  }
  const test::CommandResult merge =
      test::RunRpt("merge " + (shards / "sweep-shard-1-of-2.json").string() + " " +
                   (shards / "sweep-shard-2-of-2.json").string() + " --out " + shards.string());
  ASSERT_EQ(merge.exit_code, 0) << merge.err;
  for (const char* ext : {"json", "csv", "md", "html"}) ExpectRegularFile(shards / (std::string("sweep.") + ext));
  outside.ExpectUntouched();
  fs::remove_all(root);
}

TEST(OutputLinks, RenderReplacesFileAndFolderLinks) {
  const fs::path root = test::TempDir("links_render");
  Outside outside(root / "outside");
  const fs::path out = root / "out";
  const std::string render =
      "render --dataset synthetic --param frames=2 --param cameras=2 --frames 0:2 --out " + out.string();
  ASSERT_EQ(test::RunRpt(render).exit_code, 0);
  std::vector<fs::path> pngs;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    if (e.path().extension() == ".png") pngs.push_back(e.path());
  }
  ASSERT_EQ(pngs.size(), 4u);
  for (size_t i = 0; i < pngs.size(); ++i) Plant(pngs[i], outside.File("png" + std::to_string(i)));
  ASSERT_EQ(test::RunRpt(render).exit_code, 0);
  for (const fs::path& png : pngs) ExpectRegularFile(png);
  // The sequence folder itself a link to a folder outside: replaced by a folder, nothing written there.
  const fs::path sequence_dir = pngs[0].parent_path().parent_path();
  fs::remove_all(sequence_dir);
  Plant(sequence_dir, outside.Folder("elsewhere"));
  const test::CommandResult r = test::RunRpt(render + " --format both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_directory(fs::symlink_status(sequence_dir)));
  for (const fs::path& png : pngs) ExpectRegularFile(png);
  outside.ExpectUntouched();
  fs::remove_all(root);
}

TEST(OutputLinks, JunitAndConvertReplaceALinkTheUserNamed) {
  const fs::path root = test::TempDir("links_user");
  Outside outside(root / "outside");
  WriteFile(
      root / "thresholds.json",
      R"({"evaluations": [{"name": "small", "dataset": "synthetic", "params": {"frames": 3}, "min": {"pcp": 0}}]})");
  Plant(root / "junit.xml", outside.File("junit"));
  const test::CommandResult check = test::RunRpt("check --thresholds " + (root / "thresholds.json").string() +
                                                 " --junit " + (root / "junit.xml").string());
  ASSERT_EQ(check.exit_code, 0) << check.out << check.err;
  ExpectRegularFile(root / "junit.xml");
  Plant(root / "cache.h5", outside.File("cache"));
  const test::CommandResult convert =
      test::RunRpt("convert --dataset synthetic --param frames=3 --out " + (root / "cache.h5").string());
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  ExpectRegularFile(root / "cache.h5");
  outside.ExpectUntouched();
  fs::remove_all(root);
}

// Names of `dir` holding ".tmp-".
std::vector<std::string> Temporaries(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().filename().string().find(".tmp-") != std::string::npos) names.push_back(it->path().string());
  }
  return names;
}

TEST(OutputFolder, OutNamingALinkWritesIntoTheFolderItPointsTo) {
  const fs::path root = test::TempDir("out_link");
  fs::create_directories(root / "disk" / "real");
  WriteFile(root / "disk" / "real" / "notes.txt", "mine");
  fs::create_directory_symlink(root / "disk" / "real", root / "out");
  const test::CommandResult r = test::RunRpt("eval " + kSmallRun + " --out " + (root / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(root / "out")) << "the link stays";
  EXPECT_TRUE(fs::is_regular_file(root / "disk" / "real" / "run.json"));
  EXPECT_EQ(test::ReadAll(root / "disk" / "real" / "notes.txt"), "mine");
  EXPECT_TRUE(Temporaries(root).empty());
  // A link to nothing: exit 2 naming it, nothing created.
  fs::create_directory_symlink(root / "missing", root / "dangling");
  const test::CommandResult dangling = test::RunRpt("eval " + kSmallRun + " --out " + (root / "dangling").string());
  EXPECT_EQ(dangling.exit_code, 2);
  EXPECT_NE(dangling.err.find("is a link to a folder that does not exist"), std::string::npos) << dangling.err;
  EXPECT_FALSE(fs::exists(root / "missing"));
  EXPECT_TRUE(Temporaries(root).empty());
  fs::remove_all(root);
}

TEST(OutputFolder, AWriteProtectedOldFolderIsRefusedAndLeftAsItWas) {
  const fs::path root = test::TempDir("read_only");
  const fs::path out = root / "out";
  ASSERT_EQ(test::RunRpt("eval " + kSmallRun + " --out " + out.string()).exit_code, 0);
  const std::string run = test::ReadAll(out / "run.json");
  struct Case {
    std::string what;
    fs::path protect;
    std::string command;
  };
  fs::create_directories(out / "render" / "seq");
  const std::vector<Case> cases = {
      {"eval, the folder", out, "eval " + kSmallRun + " --out " + out.string()},
      {"eval, a folder inside", out / "render" / "seq", "eval " + kSmallRun + " --out " + out.string()},
      {"render", out, "render --dataset synthetic --param frames=1 --param cameras=2 --out " + out.string()},
      {"sweep", out,
       "sweep --grid merge.top_k=0 --dataset synthetic --param frames=2 --threads 1 --out " + out.string()},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    ::chmod(c.protect.c_str(), 0555);
    const test::CommandResult r = test::RunRpt(c.command);
    ::chmod(c.protect.c_str(), 0755);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(c.protect.string() + ": write-protected"), std::string::npos) << r.err;
    EXPECT_EQ(test::ReadAll(out / "run.json"), run);
    EXPECT_TRUE(Temporaries(root).empty()) << Temporaries(root).front();
  }
  fs::remove_all(root);
}

// Starts `rpt ARGS...` as from a terminal (signals at their defaults), output discarded.
pid_t StartRpt(const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(RPT_BINARY)};
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal_number, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::freopen("/dev/null", "w", stdout);
    ::freopen("/dev/null", "w", stderr);
    ::execv(RPT_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

int Wait(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// The bytes of every file below `dir`, by relative path.
std::map<std::string, std::string> Contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = test::ReadAll(e.path());
  }
  return files;
}

// Issue 19: Ctrl-C during `rpt render --format mp4` truncated the previous complete videos while
// the message said "finished outputs unchanged". Interrupted (SIGINT, SIGTERM) or killed (SIGKILL)
// while a video is being written, the previous render stays byte for byte.
TEST(RenderInterrupted, PreviousVideosStayIntact) {
  const fs::path root = test::TempDir("render_interrupt");
  const fs::path out = root / "out";
  const std::string scene = "--dataset synthetic --param frames=400 --param cameras=2 --param people=2";
  const test::CommandResult first =
      test::RunRpt("render " + scene + " --frames 0:3 --format both --out " + out.string());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::map<std::string, std::string> before = Contents(out);
  size_t videos = 0;
  for (const auto& [name, bytes] : before) videos += name.size() > 4 && name.substr(name.size() - 4) == ".mp4" ? 1 : 0;
  ASSERT_EQ(videos, 2u);
  for (const int signal_number : {SIGINT, SIGTERM, SIGKILL}) {
    SCOPED_TRACE("signal " + std::to_string(signal_number));
    const pid_t child = StartRpt({"render", "--dataset", "synthetic", "--param", "frames=400", "--param", "cameras=2",
                                  "--param", "people=2", "--frames", ":", "--format", "both", "--out", out.string()});
    // Wait until the videos are being written: their temporaries (".mp4.tmp-<pid>-<n>.mp4") exist.
    const std::string marker = ".mp4.tmp-" + std::to_string(child) + "-";
    bool writing = false;
    for (const auto deadline = Clock::now() + std::chrono::seconds(120); !writing && Clock::now() < deadline;) {
      std::error_code ec;
      for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
        writing |= it->path().filename().string().find(marker) != std::string::npos;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(writing) << "the render never started its videos";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // some frames into them
    ::kill(child, signal_number);
    const int code = Wait(child);
    EXPECT_EQ(code, signal_number == SIGKILL ? 1000 + SIGKILL : 128 + signal_number);
    EXPECT_EQ(Contents(out), before) << "the previous render changed";
    if (signal_number != SIGKILL) {
      EXPECT_TRUE(Temporaries(root).empty());
    }
    for (const auto& e : fs::directory_iterator(root)) {  // SIGKILL: only the staging folder may stay beside
      if (e.path() != out) fs::remove_all(e.path());
    }
  }
  fs::remove_all(root);
}

// Nothing a terminal acts on: no C0 control but newline, no DEL, no C1 control.
void ExpectPrintable(const std::string& text, const std::string& what) {
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<std::uint8_t>(text[i]);
    ASSERT_FALSE((c < 0x20 && c != '\n') || c == 0x7f) << what << ": byte " << int(c) << " at " << i << ":\n"
                                                       << PrintableText(text);
    if (c == 0xc2 && i + 1 < text.size()) {
      ASSERT_GE(static_cast<std::uint8_t>(text[i + 1]), 0xa0) << what;
    }
  }
}

TEST(HostileNames, EveryCommandPrintsThemEscapedAndWritesThemSafely) {
  const fs::path root = test::TempDir("hostile_names");
  const test::HostileInput input = test::MakeHostileInput(root);
  const auto run = [&](const std::string& what, const std::string& args) {
    const test::CommandResult r = test::RunRpt(args);
    EXPECT_EQ(r.exit_code, 0) << what << ": " << PrintableText(r.err);
    ExpectPrintable(r.out, what + " stdout");
    ExpectPrintable(r.err, what + " stderr");
    return r;
  };
  run("inspect", "inspect " + input.args());
  run("detector-stats", "detector-stats " + input.args());
  const fs::path run_dir = root / "run";
  const test::CommandResult eval = run("eval", "eval " + input.args() + " --out " + run_dir.string());
  EXPECT_NE(eval.out.find("frames"), std::string::npos);
  run("report", "report " + run_dir.string());
  const fs::path render_dir = root / "render";
  const test::CommandResult render =
      run("render", "render " + input.args() + " --frames : --out " + render_dir.string());
  // One folder per camera: 'cam a', 'cam/a' and 'cam_a' do not share one.
  size_t camera_folders = 0, pngs = 0;
  for (const auto& sequence_dir : fs::directory_iterator(render_dir)) {
    for (const auto& camera_dir : fs::directory_iterator(sequence_dir)) {
      ++camera_folders;
      for ([[maybe_unused]] const auto& png : fs::directory_iterator(camera_dir)) ++pngs;
    }
  }
  EXPECT_EQ(camera_folders, input.cameras.size());
  EXPECT_EQ(pngs, input.cameras.size() * 4);
  EXPECT_NE(render.out.find(std::to_string(input.cameras.size() * 4) + " PNG file(s)"), std::string::npos)
      << render.out;
  run("sweep", "sweep --grid merge.top_k=0,2 --threads 1 " + input.args() + " --out " + (root / "sweep").string());
  // A thresholds file whose evaluation is named with escape sequences and markup.
  Json thresholds;
  thresholds["evaluations"] = {{{"name", "\x1b[31m<!--<script> \xef\xbf\xbe =1+2"},
                                {"labels", input.labels.string()},
                                {"detections", input.detections.string()},
                                {"min", {{"pcp", 0}}}}};
  WriteFile(root / "thresholds.json", thresholds.dump());
  run("check",
      "check --thresholds " + (root / "thresholds.json").string() + " --junit " + (root / "junit.xml").string());

  // The files: summary.csv keeps its columns and no field starts a formula; summary.md one row per line.
  std::istringstream csv(test::ReadAll(run_dir / "summary.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(engine::SplitCsvLine(row).size(), engine::SplitCsvLine(header).size()) << row;
  EXPECT_EQ(engine::SplitCsvLine(row)[0], PrintableText(test::kHostileSequenceName, LineBreaks::kEscape));
  ExpectPrintable(test::ReadAll(run_dir / "summary.md"), "summary.md");
  ExpectPrintable(test::ReadAll(root / "sweep" / "sweep.md"), "sweep.md");
  ExpectPrintable(test::ReadAll(root / "junit.xml"), "junit.xml");
  fs::remove_all(root);
}

}  // namespace
}  // namespace rpt

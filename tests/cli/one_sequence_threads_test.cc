// SPDX-License-Identifier: MIT
// One sequence on several threads (issue 22; engine/frame_pipeline.h): `rpt eval` and
// `rpt triangulate` with --threads 2 write the files of --threads 1, byte for byte, except the run's
// id, its times (FPS, frame and step times) and run.json (which says the threads used); a bad frame
// in the middle of the sequence stops the run with exit code 2 naming the file and the place.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// The timing fields of the summaries (they differ between any two runs).
const std::set<std::string> kTimed = {"fps", "frame_time_us_median", "eval_frames_per_s", "step_time_us_median",
                                      "step_time_us_mean", "frame_with_grouping_us_median"};

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// A CSV file without the columns named in `timed`.
std::string WithoutColumns(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  std::vector<bool> keep;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cell_stream(line);
    for (std::string cell; std::getline(cell_stream, cell, ',');) cells.push_back(cell);
    if (keep.empty()) {
      for (const std::string& name : cells) keep.push_back(kTimed.count(name) == 0 && name.rfind("time_us", 0) != 0);
    }
    for (size_t c = 0; c < cells.size(); ++c) {
      if (c >= keep.size() || keep[c]) out += cells[c] + ",";
    }
    out += "\n";
  }
  return out;
}

// summary.md without the FPS column and the line naming the threads and the command.
std::string UntimedMarkdown(const std::string& md) {
  std::istringstream in(md);
  std::string line, out;
  int fps_column = -1;
  while (std::getline(in, line)) {
    if (line.rfind("Revision ", 0) == 0) continue;
    if (line.rfind("|", 0) == 0) {
      std::vector<std::string> cells;
      std::stringstream cell_stream(line);
      for (std::string cell; std::getline(cell_stream, cell, '|');) cells.push_back(cell);
      for (size_t c = 0; c < cells.size() && fps_column < 0; ++c) {
        if (cells[c].find("FPS") != std::string::npos) fps_column = static_cast<int>(c);
      }
      if (fps_column >= 0 && fps_column < static_cast<int>(cells.size())) cells[fps_column] = "";
      line.clear();
      for (const std::string& cell : cells) line += cell + "|";
    }
    out += line + "\n";
  }
  return out;
}

Json UntimedJson(Json j) {
  if (!j.is_object()) return j;
  for (const std::string& key : kTimed) j.erase(key);
  j.erase("run_id");
  for (auto& [key, value] : j.items()) value = UntimedJson(value);
  if (j.contains("per_sequence")) {
    for (Json& sequence : j["per_sequence"]) sequence = UntimedJson(sequence);
  }
  return j;
}

std::string RunId(const fs::path& dir) {
  return Json::parse(test::ReadAll(dir / "run.json")).at("run_id").get<std::string>();
}

// Every file of run folder `a` equals the one of `b` (same names), but for the times and run ids.
void ExpectSameOutputs(const fs::path& a, const fs::path& b) {
  std::vector<fs::path> files_a, files_b;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (e.is_regular_file()) files_a.push_back(fs::relative(e.path(), a));
  }
  for (const auto& e : fs::recursive_directory_iterator(b)) {
    if (e.is_regular_file()) files_b.push_back(fs::relative(e.path(), b));
  }
  std::sort(files_a.begin(), files_a.end());
  std::sort(files_b.begin(), files_b.end());
  ASSERT_EQ(files_a, files_b);
  ASSERT_GE(files_a.size(), 5u);
  const std::string id_a = RunId(a), id_b = RunId(b);
  for (const fs::path& file : files_a) {
    if (file == "run.json") continue;  // the run's id, date, command and threads
    std::string x = Replaced(test::ReadAll(a / file), id_a, "RUN_ID");
    std::string y = Replaced(test::ReadAll(b / file), id_b, "RUN_ID");
    if (file == "summary.json") {
      x = UntimedJson(Json::parse(x)).dump(1);
      y = UntimedJson(Json::parse(y)).dump(1);
    } else if (file.extension() == ".csv") {
      x = WithoutColumns(x);
      y = WithoutColumns(y);
    } else if (file == "summary.md") {
      x = UntimedMarkdown(x);
      y = UntimedMarkdown(y);
    }
    EXPECT_TRUE(x == y) << file << " differs between " << a << " and " << b;
  }
}

int Threads(const fs::path& dir) { return Json::parse(test::ReadAll(dir / "run.json")).at("threads").get<int>(); }

int ExpectedThreads() { return std::min(2, static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))); }

// A tracked synthetic sequence long enough to fill the pipeline's ring many times over, with the
// loss table and the text exports (predictions.json, predictions.csv, one TRC file per track).
TEST(OneSequenceThreads, EvalWritesTheFilesOfOneThread) {
  const fs::path out = test::TempDir("threads_eval");
  const std::string command =
      "eval --dataset synthetic --param frames=700 --param people=5 --loss-table --export json,csv,trc --quiet --out ";
  const test::CommandResult one = test::RunRpt(command + (out / "one").string() + " --threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const test::CommandResult two = test::RunRpt(command + (out / "two").string() + " --threads 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(Threads(out / "one"), 1);
  EXPECT_EQ(Threads(out / "two"), ExpectedThreads());
  EXPECT_NE(two.out.find("thread(s) over 1 sequence(s)"), std::string::npos) << two.out;
  ExpectSameOutputs(out / "one", out / "two");
  fs::remove_all(out);
}

TEST(OneSequenceThreads, TriangulateWritesTheFilesOfOneThread) {
  const fs::path out = test::TempDir("threads_triangulate");
  const std::string command = "triangulate --dataset synthetic --param frames=500 --export json,csv,trc --quiet --out ";
  const test::CommandResult one = test::RunRpt(command + (out / "one").string() + " --threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const test::CommandResult two = test::RunRpt(command + (out / "two").string() + " --threads 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(Threads(out / "two"), ExpectedThreads());
  ExpectSameOutputs(out / "one", out / "two");
  fs::remove_all(out);
}

// The real Shelf frames of the 4D-Association bundle (OpenPose candidates grouped by the reader).
TEST(OneSequenceThreads, Shelf4daGivesTheFilesOfOneThread) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  const fs::path out = test::TempDir("threads_shelf4da");
  const std::string command = "eval --dataset shelf-4da --root " + test::SharedData("shelf/4d_association").string() +
                              " --loss-table --quiet --out ";
  const test::CommandResult one = test::RunRpt(command + (out / "one").string() + " --threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const test::CommandResult two = test::RunRpt(command + (out / "two").string() + " --threads 2");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  ExpectSameOutputs(out / "one", out / "two");
  fs::remove_all(out);
}

// A generic labels file whose frame 200 of 400 has a GT person of 4 joints: its labels are read
// as the frame is pulled, in the middle of the run. Every thread count stops there with the
// error of one thread, no hang, and no results folder.
TEST(OneSequenceThreads, ABadFrameMidSequenceIsTheSameErrorOnEveryThreadCount) {
  const fs::path dir = test::TempDir("threads_bad_frame");
  const test::CommandResult converted =
      test::RunRpt("convert --dataset synthetic --param frames=400 --labels-out " + (dir / "labels.json").string() +
                   " --detections-out " + (dir / "detections.json").string());
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  Json labels = Json::parse(test::ReadAll(dir / "labels.json"));
  Json& person = labels.at(200).at("bodies3D").at(1);
  person = Json(std::vector<Json>(person.begin(), person.begin() + 4));
  std::ofstream(dir / "labels.json") << labels.dump();
  std::string expected;
  for (const char* threads : {"1", "2"}) {
    const fs::path out = dir / (std::string("out") + threads);
    const test::CommandResult r =
        test::RunRpt("eval --labels " + (dir / "labels.json").string() + " --detections " +
                     (dir / "detections.json").string() + " --quiet --threads " + threads + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << threads << " threads: " << r.err;
    EXPECT_NE(r.err.find("labels.json: /200/bodies3D/1: expected 17 joints"), std::string::npos) << r.err;
    if (expected.empty()) expected = r.err;
    EXPECT_EQ(r.err, expected) << threads << " threads";
    EXPECT_FALSE(fs::exists(out / "summary.json")) << "no results of a failed run";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// Files and folders from someone else (issue 19, input half): every JSON the commands read goes
// through one guarded parse (depth and size limits, short quotes), every size an input controls is
// checked before it is allocated (exit 2 naming the file, the place and the option), `rpt report`
// verifies the input it re-loads (the HDF5 cache checksums: tests/datasets/hdf5_cache_corruption_test.cc).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

void Write(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string Nested(int depth, char open, char close, const std::string& inner = "1") {
  std::string text;
  for (int i = 0; i < depth; ++i) text += open == '{' ? "{\"a\":" : std::string(1, open);
  text += inner;
  text += std::string(static_cast<size_t>(depth), close);
  return text;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class InputLimits : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::TempDir("input_limits"); }
  void TearDown() override { fs::remove_all(dir_); }

  // Labels, detections and an HDF5 cache of a small synthetic scene, written by `rpt convert`.
  void Convert(const std::string& params = "--param frames=4 --param cameras=3 --param people=2") {
    const test::CommandResult r =
        test::RunRpt("convert --dataset synthetic " + params + " --labels-out " + Path("labels.json") +
                     " --detections-out " + Path("detections.json") + " --out " + Path("cache.h5"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

// 70 000 levels of nesting ended in SIGSEGV (exit 139) in every command file: the message and the
// report serialised the value recursively. Now the parse stops at 256 levels, naming the file.
TEST_F(InputLimits, DeepNestingInEveryCommandFileIsAnInputErrorNamingTheFile) {
  const std::string deep_array = Nested(70000, '[', ']');
  const std::string deep_object = Nested(70000, '{', '}');
  Write(dir_ / "config.json", "{\"filter\": {\"min_match_score\": " + deep_array + "}}");
  Write(dir_ / "thresholds.json", "{\"evaluations\": " + deep_object + "}");
  Write(dir_ / "shard.json", "{\"total\": 1, \"rows\": [" + deep_array + "]}");
  Write(dir_ / "list.json", "[{\"name\": \"a\", \"set\": " + deep_object + "}]");
  const struct {
    std::string args, file;
  } cases[] = {
      {"config --dump --config " + Path("config.json"), "config.json"},
      {"check --thresholds " + Path("thresholds.json"), "thresholds.json"},
      {"merge " + Path("shard.json") + " --out " + Path("merged"), "shard.json"},
      {"sweep --dataset synthetic --param frames=2 --list " + Path("list.json") + " --out " + Path("sweep"), "list.json"},
  };
  for (const auto& c : cases) {
    const test::CommandResult r = test::RunRpt(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, c.file + ":1:")) << r.err;
    EXPECT_TRUE(Contains(r.err, "JSON nested deeper than 256 levels")) << r.err;
    EXPECT_LT(r.err.size(), 1000u) << "the message quotes no value";
  }
}

TEST_F(InputLimits, DeepNestingInARunFolderIsAnInputErrorOfRptReport) {
  Convert();
  const std::string run = Path("run");
  ASSERT_EQ(test::RunRpt("eval --labels " + Path("labels.json") + " --detections " + Path("detections.json") +
                         " --quiet --out " + run)
                .exit_code,
            0);
  for (const std::string file : {"summary.json", "run.json", "config.json", "predictions.json"}) {
    const std::string saved = test::ReadAll(fs::path(run) / file);
    Write(fs::path(run) / file, "{\"x\": " + Nested(50000, '[', ']') + "}");
    const test::CommandResult r = test::RunRpt("report " + run + " --out " + Path("report.html"));
    EXPECT_EQ(r.exit_code, 2) << file << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, file + ":1:")) << r.err;
    EXPECT_LT(r.err.size(), 1000u) << "no 100 KB of brackets";
    Write(fs::path(run) / file, saved);
  }
}

// Values quoted in messages are cut: a 100 000-character config value, a long thresholds value, a
// string token that runs to the end of a long line.
TEST_F(InputLimits, MessagesQuoteAShortExcerptOfAValue) {
  const std::string long_text(100000, 'x');
  Write(dir_ / "config.json", "{\"filter\": {\"min_match_score\": \"" + long_text + "\"}}");
  Write(dir_ / "object.json", "{\"filter\": {\"min_match_score\": {\"k\": [\"" + long_text + "\"]}}}");
  Write(dir_ / "thresholds.json", "{\"description\": [\"" + long_text + "\"]}");
  Write(dir_ / "broken.json", "{\"filter\": \"" + long_text + "\n\"}");
  for (const std::string& args : {"config --dump --config " + Path("config.json"),
                                 "config --dump --config " + Path("object.json"),
                                 "check --thresholds " + Path("thresholds.json"),
                                 "config --dump --config " + Path("broken.json")}) {
    const test::CommandResult r = test::RunRpt(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err.substr(0, 500);
    EXPECT_LT(r.err.size(), 600u) << args << "\n" << r.err.substr(0, 500);
    EXPECT_TRUE(Contains(r.err, "xxx...")) << r.err;
  }
}

// Whole-file reads are bounded by --max-input-mb (before the allocation) and refuse what is not a
// regular file (a FIFO blocked the read forever).
TEST_F(InputLimits, FileSizeAndFileTypeAreCheckedBeforeReading) {
  Convert("--param frames=300 --param cameras=8 --param people=3");  // labels of 2.1 MB, detections of 6.8 MB
  const test::CommandResult big = test::RunRpt("--max-input-mb 1 inspect --labels " + Path("labels.json"));
  EXPECT_EQ(big.exit_code, 2) << big.err;
  EXPECT_TRUE(Contains(big.err, Path("labels.json") + ": ")) << big.err;
  EXPECT_TRUE(Contains(big.err, "above the limit of 1.0 MB")) << big.err;
  EXPECT_TRUE(Contains(big.err, "--max-input-mb")) << big.err;
  const test::CommandResult detections = test::RunRpt("eval --labels " + Path("labels.json") + " --detections " +
                                                      Path("detections.json") + " --quiet --max-input-mb 1 --out " +
                                                      Path("out"));
  EXPECT_EQ(detections.exit_code, 2) << detections.err;
  EXPECT_TRUE(Contains(detections.err, "--max-input-mb")) << detections.err;
  EXPECT_EQ(test::RunRpt("--max-input-mb 100 inspect --labels " + Path("labels.json")).exit_code, 0);

  ASSERT_EQ(::mkfifo((dir_ / "fifo.json").c_str(), 0600), 0);
  for (const std::string& args : {"inspect --labels " + Path("fifo.json"), "config --dump --config " + Path("fifo.json"),
                                 "check --thresholds " + Path("fifo.json")}) {
    const test::CommandResult r = test::RunRpt(args, "timeout 20 ");
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, "fifo.json: not a regular file")) << r.err;
  }
  // As --cameras or --detections, under any name (it read 'file not found' or 'unknown detection
  // format' when named without an extension).
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  for (const std::string& args :
       {"cameras show " + Path("fifo"), "cameras show " + Path("fifo.json"),
        "triangulate --cameras " + Path("fifo") + " --detections " + Path("detections.json") + " --out " + Path("t1"),
        "triangulate --labels " + Path("labels.json") + " --detections " + Path("fifo") + " --out " + Path("t2")}) {
    const test::CommandResult r = test::RunRpt(args, "timeout 20 ");
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_TRUE(Contains(r.err, ": not a regular file")) << args << "\n" << r.err;
  }
}

// One label with more cameras than --max-cameras, a detections frame with more views, a
// calibration keyed by camera id: refused before the cameras are built.
TEST_F(InputLimits, CameraCountsAreBoundedByMaxCameras) {
  Convert("--param frames=2 --param cameras=5 --param people=1");
  const test::CommandResult labels = test::RunRpt("--max-cameras 4 inspect --labels " + Path("labels.json"));
  EXPECT_EQ(labels.exit_code, 2) << labels.err;
  EXPECT_TRUE(Contains(labels.err, "labels.json: /0/cameras: 5 cameras, above the limit of 4")) << labels.err;
  EXPECT_TRUE(Contains(labels.err, "--max-cameras")) << labels.err;
  const test::CommandResult detections =
      test::RunRpt("eval --max-cameras 4 --labels " + Path("labels.json") + " --detections " + Path("detections.json") +
                   " --quiet --out " + Path("out"));
  EXPECT_EQ(detections.exit_code, 2) << detections.err;
  EXPECT_TRUE(Contains(detections.err, "cameras, above the limit of 4")) << detections.err;
  EXPECT_EQ(test::RunRpt("--max-cameras 5 inspect --labels " + Path("labels.json")).exit_code, 0);
}

// Association memory grows with (persons x views)^2: a frame with more pairs than
// triangulate.max_pairs_per_frame is refused before the pair buffers grow, naming the frame.
TEST_F(InputLimits, PairsPerFrameAreBoundedBeforeTheAssociation) {
  // 4 cameras x 3 people: 6 view pairs x 9 = 54 pairs per frame (each person seen in each view).
  const std::string run = "eval --dataset synthetic --param frames=2 --param cameras=4 --param people=3 "
                          "--param noise=perfect --quiet --out " + Path("out");
  const test::CommandResult refused = test::RunRpt(run + " --set triangulate.max_pairs_per_frame=53");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(Contains(refused.err, "frame '")) << refused.err;
  EXPECT_TRUE(Contains(refused.err, "12 2D poses in 4 views make 54 pairs across views, above "
                                    "triangulate.max_pairs_per_frame (53)"))
      << refused.err;
  EXPECT_EQ(test::RunRpt(run + " --set triangulate.max_pairs_per_frame=54").exit_code, 0);
}

// A camera a million pixels wide made `rpt render` allocate gigabytes.
TEST_F(InputLimits, RenderRefusesImagesAboveMaxMegapixels) {
  Convert("--param frames=1 --param cameras=2 --param people=1");
  const std::string render = "render --labels " + Path("labels.json") + " --detections " + Path("detections.json") +
                             " --out " + Path("render");
  const test::CommandResult refused = test::RunRpt(render + " --max-megapixels 0.5");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(Contains(refused.err, "megapixels), above --max-megapixels (0.5)")) << refused.err;
  EXPECT_EQ(test::RunRpt(render).exit_code, 0);
}

// Out of memory is never "internal error": under an address-space limit just above what rpt needs
// to start (found here, it depends on the shared libraries), reading an input that does not fit
// ends in exit 2 naming the file. Steps of 5 MB above that point hit other allocations; none may
// say "internal error".
TEST_F(InputLimits, OutOfMemoryNamesTheInputInsteadOfInternalError) {
  Convert("--param frames=300 --param cameras=8 --param people=3");
  long base_kb = 0;
  for (long kb = 20000; kb <= 2000000 && base_kb == 0; kb += 5000) {
    if (test::RunRpt("config --dump", "ulimit -v " + std::to_string(kb) + "; ").exit_code == 0) base_kb = kb;
  }
  ASSERT_GT(base_kb, 0) << "rpt did not start under 2 GB of address space";
  int named = 0;
  for (long kb = base_kb; kb <= base_kb + 50000; kb += 5000) {
    const test::CommandResult r =
        test::RunRpt("inspect --labels " + Path("labels.json") + " --detections " + Path("detections.json"),
                     "ulimit -v " + std::to_string(kb) + "; ");
    EXPECT_FALSE(Contains(r.err, "internal error")) << kb << " kB: " << r.err;
    if (r.exit_code == 2 && Contains(r.err, ": out of memory reading the file")) ++named;
  }
  EXPECT_GT(named, 0) << "no run ended naming the file it could not read";
}

// A JSON file that does not fit in memory as a document (a list of millions of numbers) ended in
// an abort (exit 134): nlohmann's destructor allocates to free the half-built document. Now the
// document is freed without allocating and the error names the file (exit 2).
TEST_F(InputLimits, JsonTooLargeForMemoryNamesTheFileInsteadOfAborting) {
  {
    std::ofstream out(Path("big.json"));
    out << "[0";
    for (int i = 0; i < 5'000'000; ++i) out << ",0";
    out << "]";
  }
  long base_kb = 0;
  for (long kb = 20000; kb <= 2000000 && base_kb == 0; kb += 5000) {
    if (test::RunRpt("config --dump", "ulimit -v " + std::to_string(kb) + "; ").exit_code == 0) base_kb = kb;
  }
  ASSERT_GT(base_kb, 0) << "rpt did not start under 2 GB of address space";
  int named = 0;
  for (long kb = base_kb + 20000; kb <= base_kb + 140000; kb += 20000) {
    const test::CommandResult r = test::RunRpt("cameras show " + Path("big.json"), "ulimit -v " + std::to_string(kb) + "; ");
    EXPECT_NE(r.exit_code, 134) << kb << " kB: " << r.err;
    EXPECT_FALSE(Contains(r.err, "terminate called")) << kb << " kB: " << r.err;
    if (r.exit_code == 2 && Contains(r.err, Path("big.json") + ": out of memory parsing 9 MB of JSON")) ++named;
  }
  EXPECT_GT(named, 0) << "no run ended naming the file it could not parse";
}

// Out of memory in the middle of building a page, a run or an image used to abort (exit 134,
// "terminate called after throwing std::bad_alloc"): the exception unwound through a destructor
// that allocates (nlohmann::json frees deep values through a heap stack), came from OpenCV as a
// cv::Exception, or came from a constructor of a library that `rpt render` loads with its image and
// video module (GDCM's). Under address-space limits from just above what rpt needs to start up to
// 60 MB more (eval, report), and up to 60 MB below what render needs to finish (render loads about
// 250 MB of libraries first), every command ends with exit 0, 1 or 2, never an abort or "internal
// error", and some of them say "out of memory".
TEST_F(InputLimits, OutOfMemoryAnywhereEndsInAMessageNotAnAbort) {
  Convert("--param frames=50 --param cameras=4 --param people=3");
  const std::string input = "--labels " + Path("labels.json") + " --detections " + Path("detections.json");
  const test::CommandResult eval = test::RunRpt("eval " + input + " --out " + Path("run"));
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  const auto under = [](long kb) { return "ulimit -v " + std::to_string(kb) + "; "; };
  long base_kb = 0;
  for (long kb = 20000; kb <= 2000000 && base_kb == 0; kb += 5000) {
    if (test::RunRpt("config --dump", under(kb)).exit_code == 0) base_kb = kb;
  }
  ASSERT_GT(base_kb, 0) << "rpt did not start under 2 GB of address space";
  const std::string render = "render " + input + " --frames 0:1 --out " + Path("render");
  long render_kb = 0;
  for (long kb = base_kb; kb <= 2000000 && render_kb == 0; kb += 10000) {
    if (test::RunRpt(render, under(kb)).exit_code == 0) render_kb = kb;
  }
  ASSERT_GT(render_kb, 0) << "rpt render did not finish under 2 GB of address space";
  std::vector<std::pair<long, std::string>> runs;
  for (long kb = base_kb; kb <= base_kb + 60000; kb += 6000) {
    runs.emplace_back(kb, "eval " + input + " --out " + Path("run2"));
    runs.emplace_back(kb, "report " + Path("run"));
  }
  for (long kb = std::max(base_kb, render_kb - 60000); kb < render_kb; kb += 3000) runs.emplace_back(kb, render);
  int out_of_memory = 0, render_out_of_memory = 0;
  for (const auto& [kb, command] : runs) {
    const test::CommandResult r = test::RunRpt(command, under(kb));
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 2)
        << kb << " kB, rpt " << command << ": exit " << r.exit_code << "\n" << r.err;
    EXPECT_FALSE(Contains(r.err, "internal error") || Contains(r.err, "terminate called"))
        << kb << " kB, rpt " << command << ": " << r.err;
    if (r.exit_code != 0 && Contains(r.err, "out of memory")) {
      ++out_of_memory;
      render_out_of_memory += command == render ? 1 : 0;
    }
  }
  EXPECT_GT(out_of_memory, render_out_of_memory) << "no limit ran eval or report out of memory: the range is too generous";
  EXPECT_GT(render_out_of_memory, 0) << "no limit ran render out of memory";
}

// Misspelt optional keys were dropped silently, even under --strict.
TEST_F(InputLimits, UnknownKeysInLabelsAndDetectionsAreCountedAndRefusedUnderStrict) {
  Convert("--param frames=3 --param cameras=2 --param people=1");
  std::string labels = test::ReadAll(Path("labels.json"));
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\"timestamp\"", "\"timeStamp\""},
                                 {"\"scene\"", "\"scenes\""}}) {
    for (size_t at = labels.find(from); at != std::string::npos; at = labels.find(from, at + to.size())) {
      labels.replace(at, from.size(), to);
    }
  }
  Write(dir_ / "labels.json", labels);
  std::string detections = test::ReadAll(Path("detections.json"));
  detections.replace(detections.find("\"views\""), 7, "\"bodyIds\": [1], \"views\"");
  Write(dir_ / "detections.json", detections);
  const std::string eval = "eval --labels " + Path("labels.json") + " --detections " + Path("detections.json") +
                           " --quiet --out " + Path("out");
  const test::CommandResult lenient = test::RunRpt(eval);
  EXPECT_EQ(lenient.exit_code, 0) << lenient.err;
  EXPECT_TRUE(Contains(lenient.err, "3 labels with the unknown key 'timeStamp' (did you mean 'timestamp'?), not read"))
      << lenient.err;
  EXPECT_TRUE(Contains(lenient.err, "3 labels with the unknown key 'scenes' (did you mean 'scene'?), not read"))
      << lenient.err;
  EXPECT_TRUE(Contains(lenient.err, "1 frames with the unknown key 'bodyIds'")) << lenient.err;
  const test::CommandResult strict = test::RunRpt(eval + " --strict");
  EXPECT_EQ(strict.exit_code, 2) << strict.err;
  EXPECT_TRUE(Contains(strict.err, "--strict")) << strict.err;
  EXPECT_TRUE(Contains(strict.err, "timeStamp")) << strict.err;
}

// Many distinct unknown keys: the first five are named, the rest summed in one line.
TEST_F(InputLimits, ManyUnknownKeysGiveAFewWarningLines) {
  Convert("--param frames=1 --param cameras=2 --param people=1");
  std::string labels = test::ReadAll(Path("labels.json"));
  std::string extra;
  for (int k = 0; k < 1000; ++k) extra += "\"extra" + std::to_string(k) + "\": 1, ";
  labels.replace(labels.find("{\"id\""), 1, "{" + extra);
  Write(dir_ / "labels.json", labels);
  const test::CommandResult r = test::RunRpt("inspect --labels " + Path("labels.json"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int lines = 0;
  for (char c : r.err) lines += c == '\n';
  EXPECT_LE(lines, 8) << r.err;
  EXPECT_TRUE(Contains(r.err, "995 other unknown keys in labels (not read)")) << r.err;
}

class ReportInput : public InputLimits {
 protected:
  void SetUp() override {
    InputLimits::SetUp();
    Convert("--param frames=6 --param cameras=3 --param people=2");
    run_ = dir_ / "run";
    const test::CommandResult r = test::RunRpt("eval --labels " + Path("labels.json") + " --detections " +
                                               Path("detections.json") + " --quiet --out " + run_.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  test::CommandResult Report(const std::string& flags = "") {
    return test::RunRpt("report " + run_.string() + " --out " + Path("report.html") + " " + flags, "timeout 60 ");
  }
  void EditRunJson(const std::string& from, const std::string& to) {
    std::string text = test::ReadAll(run_ / "run.json");
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
    Write(run_ / "run.json", text);
  }
  fs::path run_;
};

// The recorded input is verified by its digest: an edited labels file (same frame ids) is a warning
// in the page and on the terminal, and an error with --require-same-input.
TEST_F(ReportInput, AChangedInputIsAWarningOrRefusedWithRequireSameInput) {
  ASSERT_TRUE(Contains(test::ReadAll(run_ / "run.json"), "\"input_digests\""));
  const test::CommandResult same = Report("--require-same-input");
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_FALSE(Contains(same.err, "not verified")) << same.err;

  std::string labels = test::ReadAll(Path("labels.json"));
  labels.replace(labels.find("\"bodies3D\": [[[") + 15, 1, "9");  // one coordinate of the first label
  Write(dir_ / "labels.json", labels);
  const test::CommandResult warned = Report();
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_TRUE(Contains(warned.err, "input not verified as the run's: " + Path("labels.json") + ": changed since the run"))
      << warned.err;
  EXPECT_TRUE(Contains(test::ReadAll(Path("report.html")), "changed since the run"));
  const test::CommandResult refused = Report("--require-same-input");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(Contains(refused.err, "--require-same-input")) << refused.err;

  // Without recorded digests (an older rpt, or an edited run.json): a warning, the input still re-loaded.
  EditRunJson("\"input_digests\"", "\"old_digests\"");
  const test::CommandResult old = Report();
  EXPECT_EQ(old.exit_code, 0) << old.err;
  EXPECT_TRUE(Contains(old.err, "run.json records no digest of it")) << old.err;
}

// A hand-edited run.json: a 10-million-frame synthetic input is not materialised, a FIFO is not
// opened, and a file that is not the run's input never reaches the page through a parse error.
TEST_F(ReportInput, AHandEditedRunJsonCannotMakeTheReportLoadAnythingElse) {
  EditRunJson("\"--labels\"", "\"--dataset\", \"synthetic\", \"--param\", \"frames=10000000\", \"--ignored\"");
  const test::CommandResult huge = Report();
  EXPECT_EQ(huge.exit_code, 0) << huge.err;
  EXPECT_TRUE(Contains(huge.err, "more than the 6 frames expected")) << huge.err;

  SetUp();
  ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  EditRunJson(Path("labels.json"), Path("fifo"));
  const test::CommandResult fifo = Report();
  EXPECT_EQ(fifo.exit_code, 0) << fifo.err;
  EXPECT_TRUE(Contains(fifo.err, "fifo: not a regular file or folder")) << fifo.err;

  SetUp();
  Write(dir_ / "secret.txt", "\"secret line of another file\n");
  EditRunJson(Path("labels.json"), Path("secret.txt"));
  const test::CommandResult other = Report();
  EXPECT_EQ(other.exit_code, 0) << other.err;
  EXPECT_TRUE(Contains(other.err, "input not verified as the run's: " + Path("secret.txt"))) << other.err;
  EXPECT_FALSE(Contains(test::ReadAll(Path("report.html")), "secret line")) << "quoted into the page";
}

}  // namespace
}  // namespace rpt

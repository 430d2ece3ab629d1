// SPDX-License-Identifier: MIT
// predictions.json as the frames stream past (engine/outputs/predictions_writer.h): names and ids
// escaped, NaN as null, sequences joined in input order whatever order their frames came in.
#include "engine/outputs/predictions_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rpt_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// One frame of sequence `sequence` with one person whose first joint is at (x, 0, 0).
void Feed(PredictionsWriter* writer, int sequence, const std::string& id, double x, int track) {
  SequenceFrame frame;
  frame.id = id;
  Poses3D persons;
  persons.Clear(2);
  auto person = persons.AddPerson(track);
  person.col(0) << x, 0, 0, 1;
  person.col(1) << 0, 0, 0, 0;
  FrameStats stats;
  writer->Frame(FrameOutput{sequence, &frame, &persons, &stats});
}

TEST(PredictionsWriter, EscapesJointNamesAndFrameIdsAndWritesNanAsNull) {
  const fs::path dir = TempDir("predictions_escape");
  PredictionsWriter writer(dir / "predictions.json", "id-1", 1);
  writer.BeginSequence(0, SequenceHeader{}, {"left \"wrist\"", "tab\there"});
  SequenceFrame frame;
  frame.id = "say \"cheese\"\\";
  Poses3D persons;
  persons.Clear(2);
  auto person = persons.AddPerson(7);
  person.col(0) << 1, 2, 3, 0.5;
  person.col(1) << 4, 5, 6, std::numeric_limits<double>::quiet_NaN();
  FrameStats stats;
  writer.Frame(FrameOutput{0, &frame, &persons, &stats});
  writer.EndSequence(0);
  EXPECT_EQ(writer.Finish(), 0);
  const Json predictions = Json::parse(ReadAll(dir / "predictions.json"));
  EXPECT_EQ(predictions["run_id"], "id-1");
  EXPECT_EQ(predictions["joints"], Json({"left \"wrist\"", "tab\there"}));
  EXPECT_EQ(predictions["frames"][0]["id"], "say \"cheese\"\\");
  EXPECT_EQ(predictions["frames"][0]["persons"][0][0], Json({1.0, 2.0, 3.0, 0.5}));
  // A NaN score, like a score of 0, is a missing joint: [null, null, null, 0], as NPZ (NaN) and CSV
  // (no row) say; its coordinates (here 4, 5, 6; often 0, 0, 0) are not written.
  EXPECT_EQ(predictions["frames"][0]["persons"][0][1], Json({nullptr, nullptr, nullptr, 0}));
  EXPECT_EQ(predictions["frames"][0]["track_ids"], Json({7}));
  fs::remove_all(dir);
}

TEST(PredictionsWriter, JoinsSequencesInInputOrderAndLeavesNoParts) {
  const fs::path dir = TempDir("predictions_order");
  PredictionsWriter writer(dir / "predictions.json", "run", 3);
  // Sequences interleaved as parallel runs would interleave them; sequence 1 has no frame.
  writer.BeginSequence(2, SequenceHeader{}, {"a", "b"});
  writer.BeginSequence(0, SequenceHeader{}, {"a", "b"});
  writer.BeginSequence(1, SequenceHeader{}, {"a", "b"});
  Feed(&writer, 2, "c0", 20, 1);
  Feed(&writer, 0, "a0", 0, 1);
  Feed(&writer, 2, "c1", 21, 1);
  Feed(&writer, 0, "a1", 1, 2);
  writer.EndSequence(1);
  writer.EndSequence(2);
  writer.EndSequence(0);
  writer.Finish();
  const std::string text = ReadAll(dir / "predictions.json");
  const Json predictions = Json::parse(text);
  ASSERT_EQ(predictions["frames"].size(), 4u);
  const char* ids[] = {"a0", "a1", "c0", "c1"};
  for (int f = 0; f < 4; ++f) EXPECT_EQ(predictions["frames"][f]["id"], ids[f]);
  EXPECT_EQ(predictions["frames"][3]["persons"][0][0][0], 21.0);
  EXPECT_EQ(predictions["frames"][1]["track_ids"], Json({2}));
  // Per sequence its frame count (sequence 1 has none), per frame its time and provenance.
  ASSERT_EQ(predictions["sequences"].size(), 3u);
  EXPECT_EQ(predictions["sequences"][0]["frames"], 2);
  EXPECT_EQ(predictions["sequences"][1]["frames"], 0);
  EXPECT_EQ(predictions["sequences"][2]["frames"], 2);
  EXPECT_EQ(predictions["frames"][0]["time"], 0.0);
  EXPECT_EQ(predictions["frames"][0]["provenance"], Json({{0, 0}}));
  EXPECT_EQ(predictions["units"]["position"], "m");
  // The file's layout: three header lines (ids and joints, units and provenance names, sequences),
  // then one frame per line.
  EXPECT_EQ(text.rfind("{\"run_id\": \"run\", \"joints\": [\"a\",\"b\"],\n\"units\": ", 0), 0u) << text;
  EXPECT_NE(text.find("],\n\"frames\": [\n{\"id\": \"a0\", \"time\": 0.000000, \"persons\": "), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 4), "\n]}\n");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1) << "the part files are removed";
  fs::remove_all(dir);
}

TEST(PredictionsWriter, ARunThatFailsLeavesNoParts) {
  const fs::path dir = TempDir("predictions_failed");
  {
    PredictionsWriter writer(dir / "predictions.json", "run", 2);
    writer.BeginSequence(0, SequenceHeader{}, {"a", "b"});
    Feed(&writer, 0, "a0", 0, 1);
  }  // destroyed without Finish: the run threw
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::engine

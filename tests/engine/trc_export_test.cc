// SPDX-License-Identifier: MIT
// TRC files (engine/outputs/trc_export.h) of tracks that end: written as soon as a frame comes
// without the track, so that only the live tracks are held (and only their part files exist); a
// track id that comes back gets a file of its own.
#include "engine/outputs/trc_export.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;

fs::path TempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rpt_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> Lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

int PartFiles(const fs::path& dir) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    count += entry.path().string().find(".part") != std::string::npos;
  return count;
}

// Frame `frame_idx` (time frame_idx / 10 s) with one person per track id, joint "a" at (track, frame, 0).
void Feed(TrcExport* trc, long frame_idx, const std::vector<int>& tracks) {
  SequenceFrame input;
  input.id = "f" + std::to_string(frame_idx);
  input.timestamp_s = frame_idx / 10.0;
  Poses3D persons;
  persons.Clear(1);
  for (const int track : tracks) persons.AddPerson(track).col(0) << track, static_cast<double>(frame_idx), 0, 1;
  FrameStats stats;
  trc->Frame(FrameOutput{0, &input, &persons, &stats});
}

// Sequence "s" at 10 frames a second, the one every test here writes.
SequenceHeader SequenceS() {
  SequenceHeader header;
  header.name = "s";
  header.fps = 10;
  return header;
}

TEST(TrcExport, WritesATracksFileWhenItEndsAndAReturningIdToAFileOfItsOwn) {
  const fs::path dir = TempDir("trc_ended");
  TrcExport trc(dir / "trc", 1, ExportOptions{});
  trc.BeginSequence(0, SequenceS(), {"a"});
  Feed(&trc, 0, {0, 1});
  Feed(&trc, 1, {0, 1});
  EXPECT_EQ(trc.files(), 0);
  Feed(&trc, 2, {0});
  EXPECT_EQ(trc.files(), 1) << "track 1 ended with frame 2";
  ASSERT_TRUE(fs::exists(dir / "trc" / "s_track1.trc"));
  Feed(&trc, 3, {});
  EXPECT_EQ(trc.files(), 2);
  EXPECT_EQ(PartFiles(dir / "trc"), 0) << "no live track, no part file";
  Feed(&trc, 4, {0});  // the id comes back
  trc.EndSequence(0);
  EXPECT_EQ(trc.files(), 3);
  EXPECT_EQ(PartFiles(dir / "trc"), 0);

  const auto track1 = Lines(dir / "trc" / "s_track1.trc");
  ASSERT_EQ(track1.size(), 8u);
  EXPECT_EQ(track1[2], "10\t10\t2\t1\tm\t10\t1\t2");
  EXPECT_EQ(track1[6], "1\t0.000000\t1.000000\t0.000000\t0.000000");
  EXPECT_EQ(track1[7], "2\t0.100000\t1.000000\t1.000000\t0.000000");
  const auto track0 = Lines(dir / "trc" / "s_track0.trc");
  ASSERT_EQ(track0.size(), 9u);
  EXPECT_EQ(track0[2], "10\t10\t3\t1\tm\t10\t1\t3");
  EXPECT_EQ(track0[8], "3\t0.200000\t0.000000\t2.000000\t0.000000");
  const auto again = Lines(dir / "trc" / "s_track0_from5.trc");
  ASSERT_EQ(again.size(), 7u);
  EXPECT_EQ(again[0], "PathFileType\t4\t(X/Y/Z)\ts_track0_from5.trc");
  EXPECT_EQ(again[2], "10\t10\t1\t1\tm\t10\t5\t1");
  EXPECT_EQ(again[6], "5\t0.400000\t0.000000\t4.000000\t0.000000");
  fs::remove_all(dir);
}

// Without a frame rate: a track's rate from its own times; a track of one frame (MVOR's images give
// such tracks) the sequence's mean rate from the frames so far (it was 0); a sequence of one frame
// has none.
TEST(TrcExport, OneFrameTracksWithoutFrameRateGetTheSequencesRate) {
  const fs::path dir = TempDir("trc_rate");
  TrcExport trc(dir / "trc", 1, ExportOptions{});
  SequenceHeader header = SequenceS();
  header.fps = 0;
  trc.BeginSequence(0, header, {"a"});
  Feed(&trc, 0, {0});      // frame 0 at 0 s: track 0 of one frame, ends in frame 1
  Feed(&trc, 1, {1});      // track 1: frames 1-2
  Feed(&trc, 2, {1});
  Feed(&trc, 3, {2});      // frames 0.1 s apart: 10 frames a second so far
  Feed(&trc, 4, {});
  trc.EndSequence(0);
  EXPECT_EQ(Lines(dir / "trc" / "s_track0.trc").at(2), "10\t10\t1\t1\tm\t10\t1\t1") << "written at frame 1: 2 frames";
  EXPECT_EQ(Lines(dir / "trc" / "s_track1.trc").at(2), "10\t10\t2\t1\tm\t10\t2\t2") << "its own times";
  EXPECT_EQ(Lines(dir / "trc" / "s_track2.trc").at(2), "10\t10\t1\t1\tm\t10\t4\t1") << "the sequence's, frames 0-4";
  TrcExport single(dir / "single", 1, ExportOptions{});
  single.BeginSequence(0, header, {"a"});
  Feed(&single, 0, {0});
  single.EndSequence(0);
  EXPECT_EQ(Lines(dir / "single" / "s_track0.trc").at(2), "0\t0\t1\t1\tm\t0\t1\t1");
  fs::remove_all(dir);
}

// Frame `frame_idx` at `time_s`, one person of track 0.
void FeedAt(TrcExport* trc, long frame_idx, double time_s) {
  SequenceFrame input;
  input.id = "f" + std::to_string(frame_idx);
  input.timestamp_s = time_s;
  Poses3D persons;
  persons.Clear(1);
  persons.AddPerson(0).col(0) << 0, static_cast<double>(frame_idx), 0, 1;
  FrameStats stats;
  trc->Frame(FrameOutput{0, &input, &persons, &stats});
}

// Frames the input skipped (a detector that dropped 3 of them; Panoptic's every=12): with the
// frame rate, Frame# follows the time, so Frame# / DataRate gives each row's Time (it counted rows:
// 0.3 s off after the gap); without it, the rate is the median step (a pause no longer lowers it:
// a mean gave 22.47 for a 25 Hz camera) and the rows are numbered from their times at that rate
// alike; the rate's digits are kept (29.97002997, not 29.97).
TEST(TrcExport, FrameNumbersFollowTheTimesAcrossSkippedFrames) {
  const fs::path dir = TempDir("trc_skipped");
  TrcExport trc(dir / "trc", 1, ExportOptions{});
  SequenceHeader header = SequenceS();  // 10 frames a second
  trc.BeginSequence(0, header, {"a"});
  const std::vector<double> times = {100.0, 100.1, 100.2, 100.6, 100.7};
  for (size_t f = 0; f < times.size(); ++f) FeedAt(&trc, static_cast<long>(f), times[f]);
  trc.EndSequence(0);
  const auto rows = Lines(dir / "trc" / "s_track0.trc");
  ASSERT_EQ(rows.size(), 11u);
  EXPECT_EQ(rows[2], "10\t10\t5\t1\tm\t10\t1\t5");
  const std::vector<std::string> numbers = {"1", "2", "3", "7", "8"};
  for (size_t r = 0; r < numbers.size(); ++r) {
    EXPECT_EQ(rows[6 + r].substr(0, rows[6 + r].find('\t')), numbers[r]) << rows[6 + r];
  }

  TrcExport timed(dir / "timed", 1, ExportOptions{});
  header.fps = 0;
  timed.BeginSequence(0, header, {"a"});
  for (size_t f = 0; f < times.size(); ++f) FeedAt(&timed, static_cast<long>(f), times[f]);
  timed.EndSequence(0);
  const auto timed_rows = Lines(dir / "timed" / "s_track0.trc");
  ASSERT_EQ(timed_rows.size(), 11u);
  EXPECT_EQ(timed_rows[2], "10\t10\t5\t1\tm\t10\t1\t5") << "the median step (0.1 s), not the mean (0.175 s)";
  // The rows numbered from their times at that rate too (they were the frame's index + 1: 4 and 5
  // after the gap, Frame# / DataRate 0.3 s before Time: a biomechanics user's finding).
  for (size_t r = 0; r < numbers.size(); ++r) {
    EXPECT_EQ(timed_rows[6 + r], rows[6 + r]) << "as with the frame rate";
  }

  TrcExport ntsc(dir / "ntsc", 1, ExportOptions{});
  header.fps = 30000.0 / 1001.0;
  ntsc.BeginSequence(0, header, {"a"});
  FeedAt(&ntsc, 0, 0.0);
  ntsc.EndSequence(0);
  EXPECT_EQ(Lines(dir / "ntsc" / "s_track0.trc").at(2).substr(0, 12), "29.97002997\t");
  fs::remove_all(dir);
}

// Joint names come from the input ("extra_" + anything is a valid joint name): a tab or line break
// in one must not add a column or a line to the tab-separated header.
TEST(TrcExport, JointNamesFromTheInputKeepTheHeadersColumns) {
  const fs::path dir = TempDir("trc_names");
  TrcExport trc(dir / "trc", 1, ExportOptions{});
  trc.BeginSequence(0, SequenceS(), {"extra_a\tb\nc\r\x1b[2J"});
  Feed(&trc, 0, {0});
  trc.EndSequence(0);
  const auto lines = Lines(dir / "trc" / "s_track0.trc");
  ASSERT_EQ(lines.size(), 7u) << "five header lines (the fifth empty) and one frame";
  EXPECT_EQ(lines[3], "Frame#\tTime\textra_a\\x09b\\x0ac\\x0d\\x1b[2J\t\t");
  EXPECT_EQ(lines[4], "\t\tX1\tY1\tZ1");
  fs::remove_all(dir);
}

TEST(TrcExport, HoldsOnlyTheLiveTracksPartFiles) {
  const fs::path dir = TempDir("trc_many");
  TrcExport trc(dir / "trc", 1, ExportOptions{});
  trc.BeginSequence(0, SequenceS(), {"a"});
  // 200 tracks, two alive at a time, each for three frames.
  for (long f = 0; f < 200; ++f) {
    std::vector<int> tracks;
    for (int t = static_cast<int>(f / 3) * 2; t < static_cast<int>(f / 3) * 2 + 2; ++t) tracks.push_back(t);
    Feed(&trc, f, tracks);
    EXPECT_LE(PartFiles(dir / "trc"), 2) << "frame " << f;
  }
  trc.EndSequence(0);
  EXPECT_EQ(trc.files(), 134);
  EXPECT_EQ(PartFiles(dir / "trc"), 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::engine

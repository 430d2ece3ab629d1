// SPDX-License-Identifier: MIT
// rpt triangulate end to end on files the test writes from a generated scene: cameras (our JSON)
// and detections in every detection format (generic JSON, HDF5 cache, OpenPose folder, COCO result
// list), each triangulated without labels and compared with `rpt eval` on labels of the same frames
// (same engine loop: equal predictions); the exports read back (CSV and TRC by small parsers here,
// NPZ by our NPY reader, HDF5 by the HDF5 C API) and compared with predictions.json; a reused
// output folder holds only the new run's exports; bad input exits 2 naming the file and the place.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/joints.h"
#include "datasets/calibration/calibration.h"
#include "datasets/io/npy.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "engine/input.h"
#include "tests/cli/cli_test_util.h"
#include "tests/cli/triangulate_test_util.h"
#include "tests/hdf5_test_file.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

using test::Coco17;
using test::ExpectSameFrames;
using test::Ids;
using test::kFps;
using test::ReadJson;
using test::Scene;
using test::WriteCocoResults;
using test::WriteLabelsAs;
using test::WriteOpenPoseFolder;
using Triangulate = test::SceneFilesTest;

TEST_F(Triangulate, GenericJsonEqualsEval) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  Detections detections = Coco17(scene_, ids);
  WriteGenericDetections(dir_ / "detections.json", detections);
  CompareWithEval("json", dir_ / "detections.json", ids);
}

TEST_F(Triangulate, Hdf5CacheEqualsEval) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteDetectionsHdf5(dir_ / "detections.h5", Coco17(scene_, ids));
  CompareWithEval("h5", dir_ / "detections.h5", ids);
}

TEST_F(Triangulate, OpenPoseFolderEqualsEval) {
  const std::vector<std::string> ids = Ids("", kFrames);
  WriteOpenPoseFolder(dir_ / "openpose", Coco17(scene_, ids));
  CompareWithEval("openpose", dir_ / "openpose", ids);
}

TEST_F(Triangulate, CocoResultsEqualEval) {
  // MVOR image ids number the cameras from 1.
  for (size_t c = 0; c < scene_.cameras.size(); ++c) scene_.cameras[c].name = "cam" + std::to_string(c + 1);
  WriteCalibration(dir_ / "cameras.json", scene_.cameras);
  const std::vector<std::string> ids = Ids("mvor_day1_", kFrames);
  WriteCocoResults(dir_ / "results.json", Coco17(scene_, ids));
  CompareWithEval("coco", dir_ / "results.json", ids);
}

TEST_F(Triangulate, VoxelPoseCacheEqualsEval) {
  // Frame ids "<prefix>_<frame, 6 digits>": the prefix is the labels' sequence name for eval and
  // the cache's file name for triangulate, so both are "take".
  scene_.name = "take";
  const std::vector<std::string> ids = Ids("take_", kFrames);
  test::WriteVoxelPoseCache(dir_ / "take.pkl", Coco17(scene_, ids));
  CompareWithEval("pkl", dir_ / "take.pkl", ids);
}

// Frames missing from the detections (files deleted from an OpenPose folder, a detector that
// skipped some): with --fps the times follow the numbers the frame ids end in, so the frames after
// the gap keep their times (they were shifted by the gap, and speed clipping then moved joints by
// up to 0.4 m); the skipped numbers are counted. Frames out of order are counted, their times
// follow the file's order.
TEST_F(Triangulate, FrameTimesFollowTheNumbersOfTheFrameIds) {
  const std::vector<std::string> ids = Ids("", kFrames);
  const Detections detections = Coco17(scene_, ids);
  WriteOpenPoseFolder(dir_ / "openpose", detections);
  for (const std::string& camera : detections.frames[0].cameras) {
    for (int f = 5; f <= 7; ++f) {
      char name[64];
      std::snprintf(name, sizeof(name), "video_%012d_keypoints.json", f);
      ASSERT_TRUE(fs::remove(dir_ / "openpose" / camera / name)) << camera << " " << name;
    }
  }
  // `rpt triangulate` of `detections` at --fps 25 into the folder `out`.
  const auto triangulate = [&](const fs::path& detections, const std::string& out) {
    return test::RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                        detections.string() + " --fps 25 --out " + (dir_ / out).string());
  };
  const test::CommandResult gap = triangulate(dir_ / "openpose", "gap");
  ASSERT_EQ(gap.exit_code, 0) << gap.err;
  EXPECT_NE(gap.err.find(": 3 frame numbers missing between the frame ids (frames the detections skip): the times "
                         "follow the ids' numbers at --fps, with a gap there"),
            std::string::npos)
      << gap.err;
  const Json frames = ReadJson(dir_ / "gap" / "predictions.json")["frames"];
  ASSERT_EQ(frames.size(), static_cast<size_t>(kFrames - 3));
  for (const Json& frame : frames) {
    EXPECT_DOUBLE_EQ(frame["time"].get<double>(), std::stoi(frame["id"].get<std::string>()) / kFps) << frame["id"];
  }

  Detections shuffled = Coco17(scene_, Ids("take_", kFrames));
  std::swap(shuffled.frames[3], shuffled.frames[9]);
  WriteGenericDetections(dir_ / "shuffled.json", shuffled);
  const test::CommandResult out_of_order = triangulate(dir_ / "shuffled.json", "shuffled");
  ASSERT_EQ(out_of_order.exit_code, 0) << out_of_order.err;
  EXPECT_NE(out_of_order.err.find(": 2 frames whose id's number is not after the previous frame's (first 'take_000004' "
                                  "after 'take_000009'): out of order, so the times follow the file's order"),
            std::string::npos)
      << out_of_order.err;
  const Json order = ReadJson(dir_ / "shuffled" / "predictions.json")["frames"];
  EXPECT_EQ(order[3]["id"], "take_000009");
  EXPECT_DOUBLE_EQ(order[3]["time"].get<double>(), 3 / kFps);
  // Numbers that are no frame counter (capture times in milliseconds: steps of 40): the file's
  // order, no gap counted. Consecutive numbers: no warning (every other test of this file).
  Detections stamped = Coco17(scene_, Ids("take_", kFrames));
  for (size_t f = 0; f < stamped.frames.size(); ++f) stamped.frames[f].frame_id = "cap_" + std::to_string(1000 + 40 * f);
  WriteGenericDetections(dir_ / "stamped.json", stamped);
  const test::CommandResult ms = triangulate(dir_ / "stamped.json", "stamped");
  ASSERT_EQ(ms.exit_code, 0) << ms.err;
  EXPECT_EQ(ms.err.find("warning"), std::string::npos) << ms.err;
  const Json stamped_frames = ReadJson(dir_ / "stamped" / "predictions.json")["frames"];
  EXPECT_DOUBLE_EQ(stamped_frames[kFrames - 1]["time"].get<double>(), (kFrames - 1) / kFps);
  // Every id 2 after the one before (a detector run on every other frame): the file's order, said.
  Detections every_other = Coco17(scene_, Ids("take_", kFrames));
  for (size_t f = 0; f < every_other.frames.size(); ++f) every_other.frames[f].frame_id = "take_" + std::to_string(2 * f);
  WriteGenericDetections(dir_ / "every_other.json", every_other);
  const test::CommandResult two = triangulate(dir_ / "every_other.json", "every_other");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_NE(two.err.find(": 15 frames whose id's number is 2 after the previous frame's (a counter's frames, 2 apart?): "
                         "the times follow the file's order, frame i at i / --fps; if the ids count the camera's "
                         "frames, give --fps as its rate / 2"),
            std::string::npos)
      << two.err;
}

// Joints at pixel (0, 0) with a confidence (some detectors' "not found") in a detections file: read
// as missing and counted; before, two such wrists per pose made the calibration check doubt a
// right camera. (The live lines: Follow.JointsAtPixelZeroAreMissing.)
TEST_F(Triangulate, JointsAtPixelZeroAreMissing) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  Detections origin = Coco17(scene_, ids), missing = origin;
  long planted = 0;
  for (size_t f = 0; f < origin.frames.size(); ++f) {
    for (size_t v = 0; v < 2 && v < origin.frames[f].views.size(); ++v) {
      Poses2D& view = origin.frames[f].views[v];
      for (int p = 0; p < view.num_persons(); ++p) {
        for (const int j : {9, 10}) {  // the wrists
          view.Person(p)(0, j) = view.Person(p)(1, j) = 0;
          view.Person(p)(2, j) = 0.9;
          missing.frames[f].views[v].Person(p)(2, j) = 0;
          ++planted;
        }
      }
    }
  }
  WriteGenericDetections(dir_ / "origin.json", origin);
  WriteGenericDetections(dir_ / "missing.json", missing);
  const std::string cameras = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --fps 25 --detections ";
  const test::CommandResult r = test::RunRpt(cameras + (dir_ / "origin.json").string() + " --out " + (dir_ / "o").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + (dir_ / "origin.json").string() + ": " + std::to_string(planted) +
                       " detected joints at pixel (0, 0) with a score above 0 read as missing"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("is its calibration right"), std::string::npos) << r.err;
  ASSERT_EQ(test::RunRpt(cameras + (dir_ / "missing.json").string() + " --quiet --out " + (dir_ / "m").string()).exit_code, 0);
  ExpectSameFrames(ReadJson(dir_ / "m" / "predictions.json"), ReadJson(dir_ / "o" / "predictions.json"), "origin");
}

// A "time" per frame in generic detections JSON (the live lines' key): the frames' times, with or
// without --fps, so a camera of varying frame rate keeps its clock. It was an unknown key.
TEST_F(Triangulate, TimesOfTheFramesInGenericJson) {
  Detections detections = Coco17(scene_, Ids("take_", kFrames));
  // 25 frames per second with a clock's jitter of a few milliseconds.
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    detections.frames[f].time_s = 100.0 + f / kFps + 0.002 * (static_cast<int>(f % 3) - 1);
  }
  WriteGenericDetections(dir_ / "timed.json", detections);
  const std::string input = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                            (dir_ / "timed.json").string();
  for (const std::string fps : {"", " --fps 25"}) {
    const test::CommandResult r = test::RunRpt(input + fps + " --out " + (dir_ / "timed").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const Json frames = ReadJson(dir_ / "timed" / "predictions.json")["frames"];
    ASSERT_EQ(frames.size(), detections.frames.size());
    for (size_t f = 0; f < frames.size(); ++f) EXPECT_NEAR(frames[f]["time"].get<double>(), detections.frames[f].time_s, 1e-6);
    EXPECT_GE(frames[kFrames - 1]["track_ids"][0].get<int>(), 0) << "times known: tracked" << fps;
  }
  // --fps that the times contradict (60 Hz times, --fps 30): the times are used, and a warning says
  // --fps is only the rate the exports state (25 above agrees with its times: no warning).
  Detections regular = Coco17(scene_, Ids("take_", kFrames));
  for (size_t f = 0; f < regular.frames.size(); ++f) regular.frames[f].time_s = f / 60.0;
  WriteGenericDetections(dir_ / "sixty.json", regular);
  const test::CommandResult contradicted =
      test::RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                   (dir_ / "sixty.json").string() + " --fps 30 --out " + (dir_ / "sixty").string());
  ASSERT_EQ(contradicted.exit_code, 0) << contradicted.err;
  EXPECT_NE(contradicted.err.find("sixty.json: 1 frame rates given with --fps (30.0) that the frames' \"time\" "
                                  "contradict: the times are used"),
            std::string::npos)
      << contradicted.err;
  EXPECT_NE(contradicted.err.find("(frames per second of the median time step = 60)"), std::string::npos)
      << contradicted.err;
  // Read back as written; a time that is not a number is an error at its place.
  EXPECT_EQ(ReadGenericDetections(dir_ / "timed.json").frames[5].time_s, detections.frames[5].time_s);
  std::string text = test::ReadAll(dir_ / "timed.json");
  text.replace(text.find("\"time\":"), 7, "\"time\":\"x\",\"t\":");
  std::ofstream(dir_ / "bad.json") << text;
  const test::CommandResult bad = test::RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() +
                                               " --detections " + (dir_ / "bad.json").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.json: /frames/0/time: expected the time in seconds (a number) or null"), std::string::npos)
      << bad.err;
}

// TRC holds tracks: without times nobody is tracked, and the run says that no TRC file was
// written instead of leaving an empty trc/ folder without a word.
TEST_F(Triangulate, TrcWithoutTimesSaysNothingWasWritten) {
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, Ids("take_", kFrames)));
  const std::string input =
      "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " + (dir_ / "detections.json").string();
  const test::CommandResult none = test::RunRpt(input + " --export trc --quiet --out " + (dir_ / "none").string());
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_NE(none.err.find("warning: " + (dir_ / "none" / "trc").string() + ": no TRC file written: no person was tracked"),
            std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(dir_ / "none" / "trc")) << "no empty folder beside the warning";
  const test::CommandResult timed = test::RunRpt(input + " --fps 25 --export trc --quiet --out " + (dir_ / "timed").string());
  ASSERT_EQ(timed.exit_code, 0) << timed.err;
  EXPECT_EQ(timed.err.find("no TRC file written"), std::string::npos) << timed.err;
  EXPECT_FALSE(fs::is_empty(dir_ / "timed" / "trc"));
}

TEST_F(Triangulate, LabelsWithDetectionsEqualEval) {
  // --labels FILE --detections FILE: the labels give the cameras, frames and times only.
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, ids));
  WriteLabelsAs(dir_ / "labels.json", scene_, ids);
  const std::string input =
      " --labels " + (dir_ / "labels.json").string() + " --detections " + (dir_ / "detections.json").string();
  const test::CommandResult e = test::RunRpt("eval" + input + " --quiet --out " + (dir_ / "eval").string());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const test::CommandResult t = test::RunRpt("triangulate" + input + " --quiet --out " + (dir_ / "tri").string());
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const Json tri = ReadJson(dir_ / "tri" / "predictions.json");
  ExpectSameFrames(ReadJson(dir_ / "eval" / "predictions.json"), tri, "labels");
  EXPECT_EQ(tri["sequences"][0]["fps"], kFps) << "the labels' times";
  EXPECT_EQ(ReadJson(dir_ / "tri" / "summary.json")["evaluated"], false);
  EXPECT_GE(tri["frames"][kFrames - 1]["track_ids"][0].get<int>(), 0) << "times known: tracked";
}

// CSV rows and TRC files of a run, read back, against its predictions.json.
std::vector<std::string> SplitLine(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  std::stringstream s(line);
  while (std::getline(s, field, separator)) fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.push_back("");
  return fields;
}

// A TRC file: header values by name, marker names, rows of (frame#, time, coordinates or NaN).
struct Trc {
  std::map<std::string, std::string> header;
  std::vector<std::string> markers;
  std::vector<std::vector<double>> rows;
};
Trc ReadTrc(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  Trc trc;
  EXPECT_GE(lines.size(), 6u);
  EXPECT_EQ(SplitLine(lines[0], '\t')[0], "PathFileType");
  const auto keys = SplitLine(lines[1], '\t'), values = SplitLine(lines[2], '\t');
  EXPECT_EQ(keys.size(), values.size());
  for (size_t i = 0; i < keys.size() && i < values.size(); ++i) trc.header[keys[i]] = values[i];
  const auto names = SplitLine(lines[3], '\t');
  for (size_t i = 2; i < names.size(); i += 3) trc.markers.push_back(names[i]);
  EXPECT_EQ(lines[5], "") << "a blank line after the header";
  for (size_t l = 6; l < lines.size(); ++l) {
    std::vector<double> row;
    for (const std::string& field : SplitLine(lines[l], '\t')) row.push_back(field.empty() ? NAN : std::stod(field));
    EXPECT_EQ(row.size(), 2 + 3 * trc.markers.size()) << path << ":" << l + 1;
    trc.rows.push_back(row);
  }
  return trc;
}

TEST_F(Triangulate, ExportsReadBackEqualTheJson) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, ids));
  const std::string input =
      "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " + (dir_ / "detections.json").string() + " --fps 25 --quiet";
  const test::CommandResult r = test::RunRpt(input + " --export json,csv,trc --out " + (dir_ / "all").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json p = ReadJson(dir_ / "all" / "predictions.json");
  EXPECT_EQ(p["units"]["position"], "m");
  EXPECT_EQ(p["units"]["time"], "s");
  EXPECT_EQ(p["provenance_names"], Json({"triangulated", "filled", "smoothed", "lifted", "predicted"}));
  ASSERT_EQ(p["sequences"].size(), 1u);
  EXPECT_EQ(p["sequences"][0]["frames"], kFrames);
  EXPECT_EQ(p["sequences"][0]["fps"], 25.0);
  const Json& joints = p["joints"];

  // CSV: one row per present joint, the same numbers, times and provenance names.
  std::ifstream csv(dir_ / "all" / "predictions.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "sequence,frame,frame_id,time_s,track_id,joint,x_m,y_m,z_m,score,provenance");
  std::map<std::tuple<int, int, std::string>, std::vector<std::string>> rows;  // (frame, track, joint) -> fields
  while (std::getline(csv, line)) {
    const auto fields = SplitLine(line, ',');
    ASSERT_EQ(fields.size(), 11u) << line;
    EXPECT_EQ(fields[0], "detections");
    EXPECT_EQ(fields[2], ids[std::stoi(fields[1])]);
    rows[{std::stoi(fields[1]), std::stoi(fields[4]), fields[5]}] = fields;
  }
  size_t present = 0;
  int filled_joints = 0;
  std::map<int, int> rows_per_track;
  for (int f = 0; f < kFrames; ++f) {
    const Json& frame = p["frames"][f];
    EXPECT_DOUBLE_EQ(frame["time"].get<double>(), f / kFps);
    for (size_t q = 0; q < frame["persons"].size(); ++q) {
      const int track = frame["track_ids"][q];
      ++rows_per_track[track];
      for (size_t j = 0; j < joints.size(); ++j) {
        const Json& joint = frame["persons"][q][j];
        if (!(joint[3].get<double>() > 0)) continue;
        ++present;
        const auto it = rows.find({f, track, joints[j].get<std::string>()});
        ASSERT_NE(it, rows.end()) << "frame " << f << " track " << track << " " << joints[j];
        const auto& fields = it->second;
        EXPECT_DOUBLE_EQ(std::stod(fields[3]), f / kFps);
        for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(std::stod(fields[6 + k]), joint[k].get<double>());
        EXPECT_DOUBLE_EQ(std::stod(fields[9]), joint[3].get<double>());
        EXPECT_EQ(fields[10], p["provenance_names"][frame["provenance"][q][j].get<int>()]);
        // Filled joints are those post-processing gave its fill score (postprocess.filled_joint_score).
        const bool filled = frame["provenance"][q][j] == 1;
        filled_joints += filled;
        if (filled) {
          EXPECT_EQ(joint[3].get<double>(), 0.05);
        } else {
          EXPECT_NE(joint[3].get<double>(), 0.05) << "frame " << f << " joint " << joints[j];
        }
      }
    }
  }
  EXPECT_EQ(rows.size(), present);
  EXPECT_GT(filled_joints, 0) << "the generated detections miss some joints, which are filled";
  ASSERT_GE(rows_per_track.size(), 2u);

  // TRC: one file per track, a row per frame of the track, z up as is; y up rotated.
  const test::CommandResult y = test::RunRpt(input + " --export trc --trc-axes y-up --trc-units mm --out " + (dir_ / "yup").string());
  ASSERT_EQ(y.exit_code, 0) << y.err;
  // Without TRC files they would be read as applying to the other formats (always z up, metres).
  for (const std::string option : {"--trc-axes y-up", "--trc-units mm"}) {
    const test::CommandResult without =
        test::RunRpt(input + " --export json,csv " + option + " --out " + (dir_ / "no").string());
    EXPECT_EQ(without.exit_code, 2) << option;
    EXPECT_NE(
        without.err.find(option.substr(0, option.find(' ')) + " sets the TRC files, which this run does not write: add "
                                                              "trc to --export"),
        std::string::npos)
        << without.err;
  }
  for (const auto& [track, count] : rows_per_track) {
    const std::string name = "detections_track" + std::to_string(track) + ".trc";
    const Trc trc = ReadTrc(dir_ / "all" / "trc" / name);
    const Trc yup = ReadTrc(dir_ / "yup" / "trc" / name);
    EXPECT_EQ(trc.header.at("NumFrames"), std::to_string(count));
    EXPECT_EQ(trc.header.at("NumMarkers"), std::to_string(joints.size()));
    EXPECT_EQ(trc.header.at("Units"), "m");
    EXPECT_EQ(yup.header.at("Units"), "mm");
    EXPECT_EQ(std::stod(trc.header.at("DataRate")), kFps);
    ASSERT_EQ(trc.rows.size(), static_cast<size_t>(count));
    ASSERT_EQ(yup.rows.size(), static_cast<size_t>(count));
    for (size_t j = 0; j < joints.size(); ++j) EXPECT_EQ(trc.markers[j], joints[j]);
    for (size_t r = 0; r < trc.rows.size(); ++r) {
      const int f = static_cast<int>(trc.rows[r][0]) - 1;
      const Json& frame = p["frames"][f];
      EXPECT_DOUBLE_EQ(trc.rows[r][1], f / kFps);
      size_t q = 0;
      while (q < frame["track_ids"].size() && frame["track_ids"][q] != track) ++q;
      ASSERT_LT(q, frame["track_ids"].size()) << "frame " << f << " has track " << track;
      for (size_t j = 0; j < joints.size(); ++j) {
        const Json& joint = frame["persons"][q][j];
        const double* xyz = &trc.rows[r][2 + 3 * j];
        const double* xyz_up = &yup.rows[r][2 + 3 * j];
        if (!(joint[3].get<double>() > 0)) {
          EXPECT_TRUE(std::isnan(xyz[0])) << "missing joint: empty fields";
          continue;
        }
        for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(xyz[k], joint[k].get<double>());
        // The JSON rounds to 1e-6 m: 5e-4 mm.
        EXPECT_NEAR(xyz_up[0], 1000 * joint[0].get<double>(), 1e-3);
        EXPECT_NEAR(xyz_up[1], 1000 * joint[2].get<double>(), 1e-3) << "y up = the world's z";
        EXPECT_NEAR(xyz_up[2], -1000 * joint[1].get<double>(), 1e-3);
      }
    }
  }

  // Filled joints not written: no CSV row, null in the JSON; --no-predictions writes none.
  const test::CommandResult nf =
      test::RunRpt(input + " --export json,csv --no-filled-joints --out " + (dir_ / "nofill").string());
  ASSERT_EQ(nf.exit_code, 0) << nf.err;
  const std::string nofill_csv = test::ReadAll(dir_ / "nofill" / "predictions.csv");
  EXPECT_EQ(nofill_csv.find(",filled\n"), std::string::npos);
  const Json nofill = ReadJson(dir_ / "nofill" / "predictions.json");
  for (size_t f = 0; f < nofill["frames"].size(); ++f) {
    const Json& frame = nofill["frames"][f];
    for (size_t q = 0; q < frame["persons"].size(); ++q) {
      for (size_t j = 0; j < joints.size(); ++j) {
        if (frame["provenance"][q][j] != 1) continue;
        EXPECT_TRUE(frame["persons"][q][j][0].is_null());
        EXPECT_EQ(frame["persons"][q][j][3], 0);
      }
    }
  }
  const test::CommandResult none = test::RunRpt(input + " --no-predictions --out " + (dir_ / "none").string());
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_FALSE(fs::exists(dir_ / "none" / "predictions.json"));
  EXPECT_TRUE(fs::exists(dir_ / "none" / "run.json"));
  EXPECT_EQ(test::RunRpt(input + " --no-predictions --export csv --out " + (dir_ / "x").string()).exit_code, 2);
}


// One array of predictions.npz or predictions.h5, whichever was read: shape and values.
struct Array {
  std::vector<std::int64_t> shape;
  std::vector<double> values;
  std::vector<std::string> strings;
};
using Arrays = std::map<std::string, Array>;

Arrays ReadNpzArrays(const fs::path& path) {
  Arrays arrays;
  for (const auto& [name, view] : io::ReadNpz(path)) {
    const io::NdArray& a = view.AsArray();
    Array& out = arrays[name];
    out.shape = a.shape;
    if (a.dtype.kind == 'U') {
      for (size_t i = 0; i < a.Size(); ++i) out.strings.push_back(a.ElementAsString(i));
    } else {
      out.values = a.ToDoubles();
    }
  }
  return arrays;
}

Arrays ReadH5Arrays(const fs::path& path) {
  const test::Hdf5TestFile h5(path);
  EXPECT_TRUE(h5.ok()) << path;
  Arrays arrays;
  for (const std::string name :
       {"poses", "track_ids", "num_persons", "provenance", "times_s", "sequence_frame_offsets", "sequence_fps"}) {
    arrays[name] = {h5.Shape("/" + name), h5.Doubles("/" + name), {}};
  }
  for (const std::string name : {"frame_ids", "joint_names", "provenance_names", "sequence_names"}) {
    arrays[name] = {h5.Shape("/" + name), {}, h5.Strings("/" + name)};
  }
  for (const std::string name : {"run_id", "position_unit", "time_unit"}) arrays[name] = {{}, {}, {h5.Attribute(name)}};
  return arrays;
}

// The arrays hold predictions.json's frames: values (the JSON's 6 decimals, scores 4), track ids,
// provenance, times and ids; padding after each frame's persons. Returns the filled joints with a
// position.
int ExpectArraysEqualTheJson(const Arrays& a, const Json& p, const std::string& what) {
  const size_t num_frames = p["frames"].size(), num_joints = p["joints"].size();
  size_t num_persons = 0;
  for (const Json& frame : p["frames"]) num_persons = std::max(num_persons, frame["persons"].size());
  EXPECT_GE(num_persons, 2u) << what;
  const auto n = [](size_t v) { return static_cast<std::int64_t>(v); };
  EXPECT_EQ(a.at("poses").shape, (std::vector<std::int64_t>{n(num_frames), n(num_persons), n(num_joints), 4})) << what;
  EXPECT_EQ(a.at("track_ids").shape, (std::vector<std::int64_t>{n(num_frames), n(num_persons)})) << what;
  EXPECT_EQ(a.at("provenance").shape, (std::vector<std::int64_t>{n(num_frames), n(num_persons), n(num_joints)}))
      << what;
  if (a.at("poses").values.size() != num_frames * num_persons * num_joints * 4) return 0;
  EXPECT_EQ(a.at("joint_names").strings, p["joints"].get<std::vector<std::string>>()) << what;
  EXPECT_EQ(a.at("provenance_names").strings, p["provenance_names"].get<std::vector<std::string>>()) << what;
  EXPECT_EQ(a.at("sequence_names").strings, std::vector<std::string>{p["sequences"][0]["name"].get<std::string>()})
      << what;
  EXPECT_EQ(a.at("sequence_frame_offsets").values, (std::vector<double>{0.0, static_cast<double>(num_frames)})) << what;
  EXPECT_EQ(a.at("sequence_fps").values, std::vector<double>{p["sequences"][0]["fps"].get<double>()}) << what;
  EXPECT_EQ(a.at("run_id").strings, std::vector<std::string>{p["run_id"].get<std::string>()}) << what;
  EXPECT_EQ(a.at("position_unit").strings, std::vector<std::string>{p["units"]["position"].get<std::string>()}) << what;
  EXPECT_EQ(a.at("time_unit").strings, std::vector<std::string>{p["units"]["time"].get<std::string>()}) << what;
  int filled = 0;
  for (size_t f = 0; f < num_frames; ++f) {
    const Json& frame = p["frames"][f];
    EXPECT_EQ(a.at("frame_ids").strings[f], frame["id"]) << what;
    EXPECT_NEAR(a.at("times_s").values[f], frame["time"].get<double>(), 5e-7) << what;
    EXPECT_EQ(a.at("num_persons").values[f], static_cast<double>(frame["persons"].size())) << what;
    for (size_t q = 0; q < num_persons; ++q) {
      const bool real = q < frame["persons"].size();
      const double track = a.at("track_ids").values[f * num_persons + q];
      EXPECT_EQ(track, real ? frame["track_ids"][q].get<double>() : -1.0) << what << " frame " << f << " person " << q;
      for (size_t j = 0; j < num_joints; ++j) {
        const double* v = &a.at("poses").values[((f * num_persons + q) * num_joints + j) * 4];
        const double provenance = a.at("provenance").values[(f * num_persons + q) * num_joints + j];
        const std::string at =
            what + " frame " + std::to_string(f) + " person " + std::to_string(q) + " joint " + std::to_string(j);
        if (!real) {
          EXPECT_TRUE(std::isnan(v[0]) && std::isnan(v[3])) << at << ": padding";
          EXPECT_EQ(provenance, 255) << at;
          continue;
        }
        const Json& joint = frame["persons"][q][j];
        EXPECT_EQ(provenance, frame["provenance"][q][j].get<double>()) << at;
        if (joint[3].is_number() && joint[3].get<double>() > 0) {
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[k], joint[k].get<double>(), 5e-7) << at;
          EXPECT_NEAR(v[3], joint[3].get<double>(), 5e-5) << at;
          filled += provenance == 1;
        } else {
          EXPECT_TRUE(std::isnan(v[0]) && std::isnan(v[1]) && std::isnan(v[2])) << at << ": missing";
          EXPECT_EQ(v[3], 0) << at;
        }
      }
    }
  }
  return filled;
}

TEST_F(Triangulate, ArrayExportsReadBackEqualTheJson) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, ids));
  const std::string input = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                            (dir_ / "detections.json").string() + " --fps 25 --quiet --export json,npz,h5";
  for (const bool filled_joints : {true, false}) {
    const fs::path out = dir_ / (filled_joints ? "arrays" : "arrays_nofill");
    const test::CommandResult r =
        test::RunRpt(input + (filled_joints ? "" : " --no-filled-joints") + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json p = ReadJson(out / "predictions.json");
    const Arrays npz = ReadNpzArrays(out / "predictions.npz"), h5 = ReadH5Arrays(out / "predictions.h5");
    const int npz_filled = ExpectArraysEqualTheJson(npz, p, "npz");
    const int h5_filled = ExpectArraysEqualTheJson(h5, p, "h5");
    EXPECT_EQ(npz_filled, h5_filled);
    // The generated detections miss some joints: filled, unless --no-filled-joints (then missing).
    if (filled_joints) {
      EXPECT_GT(npz_filled, 0);
    } else {
      EXPECT_EQ(npz_filled, 0) << "--no-filled-joints: every filled joint is NaN";
    }
    for (const auto& entry : fs::directory_iterator(out)) {
      EXPECT_EQ(entry.path().filename().string().find(".part"), std::string::npos) << entry.path();
    }
  }
}

TEST_F(Triangulate, AReusedOutputFolderHoldsOnlyTheNewRunsExports) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, ids));
  const fs::path out = dir_ / "reused";
  const std::string input = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                            (dir_ / "detections.json").string() + " --fps 25 --quiet --out " + out.string();
  const std::vector<std::string> exports = {"predictions.json", "predictions.csv", "trc", "predictions.npz",
                                            "predictions.h5"};
  const auto present = [&]() {
    std::vector<std::string> names;
    for (const std::string& name : exports) {
      if (fs::exists(out / name)) names.push_back(name);
    }
    return names;
  };
  ASSERT_EQ(test::RunRpt(input + " --export json,csv,trc,npz,h5").exit_code, 0);
  EXPECT_EQ(present(), exports);
  std::ofstream(out / "notes.txt") << "the user's own file\n";
  std::ofstream(out / "trc" / "detections_track99.trc") << "an earlier run's track\n";
  ASSERT_EQ(test::RunRpt(input + " --export csv").exit_code, 0);
  EXPECT_EQ(present(), std::vector<std::string>{"predictions.csv"});
  EXPECT_TRUE(fs::exists(out / "notes.txt")) << "other files stay";
  ASSERT_EQ(test::RunRpt(input + " --export trc,h5").exit_code, 0);
  EXPECT_EQ(present(), (std::vector<std::string>{"trc", "predictions.h5"}));
  // A TRC file of an earlier run goes too, also when this run writes TRC.
  std::ofstream(out / "trc" / "detections_track99.trc") << "an earlier run's track\n";
  ASSERT_EQ(test::RunRpt(input + " --export trc").exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "trc" / "detections_track99.trc"));
  EXPECT_TRUE(fs::exists(out / "trc" / "detections_track0.trc"));
  ASSERT_EQ(test::RunRpt(input + " --no-predictions").exit_code, 0);
  EXPECT_EQ(present(), std::vector<std::string>{});
  EXPECT_TRUE(fs::exists(out / "run.json"));
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
}

// The summary line counts the track ids the run started: as many as people when ids hold.
TEST(TriangulateDataset, TheSummaryLineCountsTheTrackIds) {
  const fs::path dir = test::TempDir("triangulate_tracks");
  const test::CommandResult t = test::RunRpt(
      "triangulate --dataset synthetic --param frames=20 --param people=2 --param noise=perfect --out " +
      (dir / "tri").string());
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("40 persons triangulated (2.00 per frame), 2 track ids\n"), std::string::npos) << t.out;
  fs::remove_all(dir);
}

TEST(TriangulateDataset, WithoutGroundTruthEqualsEval) {
  const fs::path dir = test::TempDir("triangulate_dataset");
  const std::string input = "--dataset synthetic --param frames=20 --param people=2";
  ASSERT_EQ(test::RunRpt("eval " + input + " --quiet --out " + (dir / "eval").string()).exit_code, 0);
  const test::CommandResult t = test::RunRpt("triangulate " + input + " --quiet --out " + (dir / "tri").string());
  ASSERT_EQ(t.exit_code, 0) << t.err;
  ExpectSameFrames(ReadJson(dir / "eval" / "predictions.json"), ReadJson(dir / "tri" / "predictions.json"), "synthetic");
  fs::remove_all(dir);
}

// Cameras 2-4 of five drop out for frames 4-11 (left out of those frames of the detections) while
// cameras 0 and 1 still see both people: a camera with no data does not vote against them in
// verification, so the persons stay, as with a calibration of cameras 0 and 1 only. Written as
// cameras that looked and saw nobody (`"poses": []`), three empty views outvote two and the
// persons go.
TEST_F(Triangulate, CamerasWithoutDataInAFrameDoNotRemoveThePersonsTheOthersSee) {
  engine::InputSpec spec;
  spec.dataset = "synthetic";
  spec.params = {"frames=16", "people=2", "cameras=5", "noise=perfect"};
  InputWarnings warnings;
  const Sequence scene = engine::LoadInput(spec, {}, &warnings).at(0);
  WriteCalibration(dir_ / "five.json", scene.cameras);
  const std::vector<std::string> ids = Ids("take_", 16);
  const Detections all = Coco17(scene, ids);
  Detections dropped = all, empty = all;
  for (int f = 4; f < 12; ++f) {
    dropped.frames[f].cameras.resize(2);
    dropped.frames[f].views.resize(2);
    for (size_t v = 2; v < empty.frames[f].views.size(); ++v) empty.frames[f].views[v].Clear(17);
  }
  dropped.unlisted_cameras_unavailable = empty.unlisted_cameras_unavailable = true;
  WriteGenericDetections(dir_ / "all.json", all);
  WriteGenericDetections(dir_ / "dropped.json", dropped);
  WriteGenericDetections(dir_ / "empty.json", empty);
  // Persons per frame of `rpt triangulate` (without tracking, so nothing coasts).
  const auto persons = [&](const std::string& name) {
    const test::CommandResult run =
        test::RunRpt("triangulate --quiet --cameras " + (dir_ / "five.json").string() + " --detections " +
                     (dir_ / (name + ".json")).string() + " --out " + (dir_ / name).string());
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const Json predictions = ReadJson(dir_ / name / "predictions.json");
    std::vector<size_t> counts;
    for (const Json& frame : predictions["frames"]) counts.push_back(frame["persons"].size());
    return counts;
  };
  const std::vector<size_t> full = persons("all"), without = persons("dropped"), nobody = persons("empty");
  ASSERT_EQ(full, std::vector<size_t>(16, 2));
  EXPECT_EQ(without, full);
  for (int f = 4; f < 12; ++f) EXPECT_EQ(nobody[f], 0u) << f;
  // The same through the HDF5 cache: the cameras left out stay without data.
  WriteDetectionsHdf5(dir_ / "dropped.h5", dropped);
  const test::CommandResult cached =
      test::RunRpt("triangulate --quiet --cameras " + (dir_ / "five.json").string() + " --detections " +
                   (dir_ / "dropped.h5").string() + " --out " + (dir_ / "cached").string());
  ASSERT_EQ(cached.exit_code, 0) << cached.err;
  const Json cached_predictions = ReadJson(dir_ / "cached" / "predictions.json");
  std::vector<size_t> cached_counts;
  for (const Json& frame : cached_predictions["frames"]) cached_counts.push_back(frame["persons"].size());
  EXPECT_EQ(cached_counts, full);
  // A camera the file never names gave nothing in the whole take: said (it was silent, --strict too,
  // while a camera missing in some frames was counted).
  Detections never = all;
  for (FrameDetections& frame : never.frames) {
    frame.cameras.pop_back();
    frame.views.pop_back();
  }
  never.unlisted_cameras_unavailable = true;
  WriteGenericDetections(dir_ / "never.json", never);
  const test::CommandResult missing =
      test::RunRpt("triangulate --quiet --strict --cameras " + (dir_ / "five.json").string() + " --detections " +
                   (dir_ / "never.json").string() + " --out " + (dir_ / "never").string());
  EXPECT_EQ(missing.exit_code, 0) << "missing information, not unused input: " << missing.err;
  EXPECT_NE(missing.err.find("never.json: 1 cameras of the calibration the detections never name, so nothing of theirs "
                             "in any frame (cameras " + scene.cameras.back().name + "): triangulated from the others"),
            std::string::npos)
      << missing.err;
  const test::CommandResult complete =
      test::RunRpt("triangulate --quiet --cameras " + (dir_ / "five.json").string() + " --detections " +
                   (dir_ / "all.json").string() + " --out " + (dir_ / "complete").string());
  EXPECT_EQ(complete.err.find("never name"), std::string::npos) << complete.err;
}

TEST_F(Triangulate, BadInputExitsWith2NamingFileAndPlace) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  Detections detections = Coco17(scene_, ids);
  detections.frames[3].cameras[1] = "cam9";
  detections.unlisted_cameras_unavailable = true;  // written as it is (no other frame lists cam9)
  WriteGenericDetections(dir_ / "bad.json", detections);
  const std::string cameras = " --cameras " + (dir_ / "cameras.json").string();
  const test::CommandResult unknown = test::RunRpt("triangulate" + cameras + " --detections " + (dir_ / "bad.json").string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find((dir_ / "bad.json").string() + ": frame 'take_000003': camera 'cam9' is not in the calibration"),
            std::string::npos)
      << unknown.err;
  const test::CommandResult no_file = test::RunRpt("triangulate --cameras /no/such/cams.yml --detections x.json");
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_NE(no_file.err.find("/no/such/cams.yml"), std::string::npos) << no_file.err;
  EXPECT_EQ(test::RunRpt("triangulate" + cameras).exit_code, 2) << "--cameras without --detections";
  // An empty --export wrote JSON, the default, as if it had not been given.
  const test::CommandResult no_format = test::RunRpt("triangulate" + cameras + " --detections " +
                                                     (dir_ / "bad.json").string() + " --export ''");
  EXPECT_EQ(no_format.exit_code, 2);
  EXPECT_NE(no_format.err.find("error: --export '': no format given"), std::string::npos) << no_format.err;
  EXPECT_EQ(test::RunRpt("triangulate" + cameras + " --detections " + (dir_ / "bad.json").string() + " --export json,xls")
                .exit_code,
            2);
  WriteLabelsAs(dir_ / "labels.json", scene_, ids);
  const test::CommandResult param =
      test::RunRpt("eval --labels " + (dir_ / "labels.json").string() + " --simulate --param bogus=1 --quiet");
  EXPECT_EQ(param.exit_code, 2) << "--param with --labels is applied or refused";
  EXPECT_NE(param.err.find("bogus"), std::string::npos) << param.err;
  const test::CommandResult tri_param = test::RunRpt("triangulate --labels " + (dir_ / "labels.json").string() +
                                                     " --detections " + (dir_ / "bad.json").string() + " --param bogus=1");
  EXPECT_EQ(tri_param.exit_code, 2);
}

// An output folder that is, lies in or holds an input folder is refused before anything is read or
// written: the run folder is swapped in as a whole, which would move the input's files.
TEST_F(Triangulate, AnOutputFolderInTheInputIsRefused) {
  const std::vector<std::string> ids = Ids("", kFrames);
  WriteOpenPoseFolder(dir_ / "openpose", Coco17(scene_, ids));
  const auto files = [&] {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir_ / "openpose")) {
      names.push_back(entry.path().lexically_relative(dir_).string());
    }
    std::sort(names.begin(), names.end());
    return names;
  };
  const std::vector<std::string> before = files();
  const std::string run = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                          (dir_ / "openpose").string() + " --quiet --out ";
  // The folder that holds the calibration file is refused too (the first input it holds is named).
  const std::vector<std::tuple<fs::path, std::string, fs::path>> cases = {
      {dir_ / "openpose", "is the input", dir_ / "openpose"},
      {dir_ / "openpose" / "run", "lies inside the input folder", dir_ / "openpose"},
      {dir_, "holds the input", dir_ / "cameras.json"}};
  for (const auto& [out, what, input] : cases) {
    const test::CommandResult r = test::RunRpt(run + out.string());
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_NE(r.err.find("--out '" + out.string() + "': " + what + " '" + input.string() +
                         "'; rpt does not write into its input"),
              std::string::npos)
        << r.err;
  }
  // A take folder holding the detector's predictions.json, given as --out: the run's own
  // predictions.json replaced the detections (exit 0; the next run failed on them).
  fs::create_directories(dir_ / "take");
  WriteGenericDetections(dir_ / "take" / "predictions.json", Coco17(scene_, ids));
  const std::string detections_before = test::ReadAll(dir_ / "take" / "predictions.json");
  const test::CommandResult take = test::RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() +
                                                " --detections " + (dir_ / "take" / "predictions.json").string() +
                                                " --quiet --out " + (dir_ / "take").string());
  EXPECT_EQ(take.exit_code, 2) << take.err;
  EXPECT_NE(take.err.find("holds the input '" + (dir_ / "take" / "predictions.json").string() + "'"), std::string::npos)
      << take.err;
  EXPECT_EQ(test::ReadAll(dir_ / "take" / "predictions.json"), detections_before);
  const test::CommandResult slash = test::RunRpt(run + (dir_ / "openpose").string() + "/");  // a trailing separator
  EXPECT_EQ(slash.exit_code, 2) << slash.err;
  EXPECT_NE(slash.err.find("is the input"), std::string::npos) << slash.err;
  EXPECT_EQ(files(), before) << "the input folder is as it was";
  EXPECT_EQ(test::RunRpt(run + (dir_ / "elsewhere").string()).exit_code, 0) << "beside it is fine";
}

// The default output folder is named after the detections: takeA/detections.json and
// takeB/detections.json both go to out/triangulate-detections. A loop over takes kept only the last
// one's results; now a run there of other input is not replaced (the same input is), and --out is
// the way.
TEST_F(Triangulate, TakesOfOneNameDoNotReplaceEachOthersDefaultFolder) {
  const Detections detections = Coco17(scene_, Ids("take_", kFrames));
  for (const char* take : {"takeA", "takeB"}) {
    fs::create_directories(dir_ / take);
    WriteGenericDetections(dir_ / take / "detections.json", detections);
  }
  const std::string in_dir = "cd '" + dir_.string() + "' && ";
  const auto take = [&](const std::string& name) {
    return test::RunRpt("triangulate --cameras cameras.json --detections " + name + "/detections.json --fps 25 --quiet",
                        in_dir);
  };
  ASSERT_EQ(take("takeA").exit_code, 0);
  EXPECT_EQ(take("takeA").exit_code, 0) << "the same input again replaces its own run";
  const test::CommandResult other = take("takeB");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("out/triangulate-detections: the default output folder holds the run of other input "
                           "(cameras.json, takeA/detections.json)"),
            std::string::npos)
      << other.err;
  EXPECT_NE(ReadJson(dir_ / "out" / "triangulate-detections" / "run.json")["command"].get<std::string>().find("takeA"),
            std::string::npos)
      << "takeA's results are still there";
  EXPECT_EQ(test::RunRpt("triangulate --cameras cameras.json --detections takeB/detections.json --fps 25 --quiet --out "
                         "out/takeB",
                         in_dir)
                .exit_code,
            0);
}

// The mistakes of someone's own first run: each said, none silently wrong.
TEST_F(Triangulate, OwnDataMistakesAreSaidNotSilent) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  const Detections detections = Coco17(scene_, ids);
  WriteGenericDetections(dir_ / "detections.json", detections);
  const std::string input = " --detections " + (dir_ / "detections.json").string();
  const std::string cameras = " --cameras " + (dir_ / "cameras.json").string();
  // A calibration in millimetres is read with --cameras-units (the options of `rpt cameras show`):
  // the same persons as from metres.
  WriteCalibration(dir_ / "cameras_mm.toml", scene_.cameras, {.units = LengthUnit::kMillimetres});
  const test::CommandResult metres = test::RunRpt("triangulate" + cameras + input + " --fps 25 --quiet --out " +
                                                  (dir_ / "m").string());
  ASSERT_EQ(metres.exit_code, 0) << metres.err;
  const test::CommandResult mm =
      test::RunRpt("triangulate --cameras " + (dir_ / "cameras_mm.toml").string() + " --cameras-units mm" + input +
                   " --fps 25 --quiet --out " + (dir_ / "mm").string());
  ASSERT_EQ(mm.exit_code, 0) << mm.err;
  // Every camera's persons match its detections (the counts behind the swapped-camera warning).
  const Json summary = ReadJson(dir_ / "m" / "summary.json");
  ASSERT_EQ(summary["camera_agreement"].size(), scene_.cameras.size());
  for (const Json& camera : summary["camera_agreement"]) {
    EXPECT_GT(camera["persons_in_view"].get<long>(), 0) << camera;
    EXPECT_GE(camera["persons_matching"].get<double>(), 0.8 * camera["persons_in_view"].get<double>()) << camera;
  }
  const Json a = ReadJson(dir_ / "m" / "predictions.json"), b = ReadJson(dir_ / "mm" / "predictions.json");
  ASSERT_EQ(a["frames"].size(), b["frames"].size());
  for (size_t f = 0; f < a["frames"].size(); ++f) {
    ASSERT_EQ(a["frames"][f]["persons"].size(), b["frames"][f]["persons"].size());
    for (size_t p = 0; p < a["frames"][f]["persons"].size(); ++p) {
      for (size_t j = 0; j < a["frames"][f]["persons"][p].size(); ++j) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(a["frames"][f]["persons"][p][j][k].get<double>(), b["frames"][f]["persons"][p][j][k].get<double>(),
                      1e-6);
        }
      }
    }
  }
  // Without it, the same file is read as metres: 1000 times too far, and the warning says so.
  const test::CommandResult as_metres = test::RunRpt("triangulate --cameras " + (dir_ / "cameras_mm.toml").string() +
                                                     input + " --quiet --out " + (dir_ / "as_m").string());
  EXPECT_NE(as_metres.err.find("check the units"), std::string::npos) << as_metres.err;
  // The calibration's images at half the detections' size: joints beyond the image are counted.
  std::vector<Camera> small = scene_.cameras;
  for (Camera& camera : small) {
    camera.width /= 4;
    camera.height /= 4;
  }
  WriteCalibration(dir_ / "small.json", small);
  const test::CommandResult outside = test::RunRpt("triangulate --cameras " + (dir_ / "small.json").string() + input +
                                                   " --quiet --out " + (dir_ / "small").string());
  EXPECT_NE(outside.err.find("detected joints beyond the " + std::to_string(small[0].width) + "x" +
                             std::to_string(small[0].height) + " image of camera '" + small[0].name +
                             "' by more than a tenth of its side"),
            std::string::npos)
      << outside.err;
  EXPECT_EQ(metres.err.find("beyond the"), std::string::npos) << "the right image size warns of nothing:\n" << metres.err;
  EXPECT_EQ(metres.err.find("top-left quarter"), std::string::npos) << metres.err;
  // The calibration's images at twice the detections' size (detections from half-size images):
  // every joint in the top-left quarter, said per camera.
  std::vector<Camera> large = scene_.cameras;
  for (Camera& camera : large) {
    camera.width *= 2;
    camera.height *= 2;
  }
  WriteCalibration(dir_ / "large.json", large);
  const test::CommandResult quarter = test::RunRpt("triangulate --cameras " + (dir_ / "large.json").string() + input +
                                                   " --quiet --out " + (dir_ / "large").string());
  EXPECT_NE(quarter.err.find(" detected joints of camera '" + large[0].name + "', all in the top-left quarter of its " +
                             std::to_string(large[0].width) + "x" + std::to_string(large[0].height) +
                             " image (detections from a smaller image, such as a half-size or 1080p proxy video?"),
            std::string::npos)
      << quarter.err;
  // A frame rate of 0 or infinity is refused in words, not as a range of 300 digits.
  for (const std::string rate : {"0", "inf", "-3"}) {
    const test::CommandResult fps = test::RunRpt("triangulate" + cameras + input + " --fps " + rate);
    EXPECT_EQ(fps.exit_code, 2) << rate;
    EXPECT_NE(fps.err.find("--fps: expected a frame rate above 0 (frames per second), got " + rate), std::string::npos)
        << fps.err;
  }
  // inspect takes the same flags and shows the cameras and detections read.
  const test::CommandResult inspect = test::RunRpt("inspect" + cameras + input);
  EXPECT_EQ(inspect.exit_code, 0) << inspect.err;
  EXPECT_NE(inspect.out.find(std::to_string(kFrames) + " frames (" + std::to_string(kFrames) + " with detections)"),
            std::string::npos)
      << inspect.out;
  EXPECT_NE(inspect.out.find("  room: none (nothing is dropped for being outside it"), std::string::npos) << inspect.out;
  // A calibration of one camera: the file and the camera named, and what is needed (it was "the
  // triangulator needs at least 2 cameras, got 1"); inspect still shows that camera's detections.
  const std::vector<Camera> one(scene_.cameras.begin(), scene_.cameras.begin() + 1);
  WriteCalibration(dir_ / "one.json", one);
  Detections one_view = detections;
  for (FrameDetections& frame : one_view.frames) {
    frame.cameras.resize(1);
    frame.views.resize(1);
  }
  WriteGenericDetections(dir_ / "one_view.json", one_view);
  const std::string one_input =
      " --cameras " + (dir_ / "one.json").string() + " --detections " + (dir_ / "one_view.json").string();
  const test::CommandResult single = test::RunRpt("triangulate" + one_input + " --fps 25 --out " + (dir_ / "one").string());
  EXPECT_EQ(single.exit_code, 2) << single.err;
  EXPECT_NE(single.err.find("error: " + (dir_ / "one.json").string() + ": sequence 'one_view': 1 camera ('" +
                            one[0].name + "'): rpt triangulates from 2 or more calibrated cameras"),
            std::string::npos)
      << single.err;
  EXPECT_FALSE(fs::exists(dir_ / "one")) << "nothing written";
  EXPECT_EQ(test::RunRpt("inspect" + one_input).exit_code, 0);
  // A detections file without frames is named (the cameras file was, with --param selections the
  // command did not use).
  Detections none = detections;
  none.frames.clear();
  WriteGenericDetections(dir_ / "none.json", none);
  const test::CommandResult empty = test::RunRpt("triangulate" + cameras + " --detections " +
                                                 (dir_ / "none.json").string() + " --out " + (dir_ / "e").string());
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("error: " + (dir_ / "none.json").string() +
                           ": no frame to triangulate (the detections file has no frames)"),
            std::string::npos)
      << empty.err;
  // Frames whose views are all empty: nothing to triangulate, said so (the warning sent the user to
  // the calibration); with poses but nobody triangulated, the calibration hint stays.
  Detections blank = detections;
  for (FrameDetections& frame : blank.frames) {
    for (Poses2D& view : frame.views) view.Clear(view.num_joints);
  }
  WriteGenericDetections(dir_ / "blank.json", blank);
  const test::CommandResult nobody = test::RunRpt("triangulate" + cameras + " --detections " +
                                                  (dir_ / "blank.json").string() + " --quiet --out " + (dir_ / "b").string());
  EXPECT_EQ(nobody.exit_code, 0);
  EXPECT_NE(nobody.err.find("the detections hold no usable 2D pose in any camera"), std::string::npos) << nobody.err;
  EXPECT_EQ(nobody.err.find("calibration's convention"), std::string::npos) << nobody.err;
  // Scores on another scale (heatmap values of 0-0.05): every joint below undistort.min_joint_score,
  // named with its value and how to lower it.
  Detections faint = detections;
  for (FrameDetections& frame : faint.frames) {
    for (Poses2D& view : frame.views) {
      for (size_t i = 2; i < view.data.size(); i += 3) view.data[i] *= 0.05;
    }
  }
  WriteGenericDetections(dir_ / "faint.json", faint);
  const test::CommandResult unscored = test::RunRpt("triangulate" + cameras + " --detections " +
                                                    (dir_ / "faint.json").string() + " --quiet --out " + (dir_ / "f").string());
  EXPECT_EQ(unscored.exit_code, 0) << unscored.err;
  EXPECT_NE(unscored.err.find("no pose with undistort.min_core_joints = 3 core joints scored at least "
                              "undistort.min_joint_score = 0.1: scores on another scale"),
            std::string::npos)
      << unscored.err;
  // --json holds what a script over many takes needs: the run, the folder, the counts of the text
  // line and the warnings (it had none of them).
  const test::CommandResult json = test::RunRpt("triangulate" + cameras + " --detections " + (dir_ / "blank.json").string() +
                                                " --json --out " + (dir_ / "bj").string());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const Json printed = Json::parse(json.out);
  EXPECT_EQ(printed["run_id"], ReadJson(dir_ / "bj" / "run.json")["run_id"]);
  EXPECT_EQ(printed["output"], (dir_ / "bj").string());
  EXPECT_EQ(printed["cameras"], scene_.cameras.size());
  EXPECT_EQ(printed["track_ids"], 0);
  ASSERT_FALSE(printed["warnings"].empty());
  EXPECT_EQ(printed["warnings"].back()["code"], "no_predictions");
  const Json tracked = Json::parse(
      test::RunRpt("triangulate" + cameras + input + " --fps 25 --json --out " + (dir_ / "tj").string()).out);
  EXPECT_GT(tracked["track_ids"].get<long>(), 0);
  for (const Json& w : tracked["warnings"]) EXPECT_NE(w["code"], "no_predictions") << w;
}

// Detections of mirrored images in every camera (u -> width - u: a webcam's selfie view): each
// camera's projections still match well enough that nothing was said, with 6.7 persons per frame
// for 4 people. Named now; the detections as they were are not.
TEST(TriangulateChecks, MirroredImagesInEveryCameraAreNamed) {
  const fs::path dir = test::TempDir("triangulate_mirrored");
  const test::CommandResult converted =
      test::RunRpt("convert --dataset synthetic --param frames=60 --param noise=clean --labels-out " +
                   (dir / "labels.json").string() + " --detections-out " + (dir / "detections.json").string());
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  Json detections = ReadJson(dir / "detections.json");
  for (Json& frame : detections["frames"]) {
    for (Json& view : frame["views"]) {
      for (Json& pose : view["poses"]) {
        for (Json& joint : pose) {
          if (joint[2].get<double>() > 0) joint[0] = 1920.0 - joint[0].get<double>();
        }
      }
    }
  }
  std::ofstream(dir / "mirrored.json") << detections.dump();
  for (const std::string name : {"detections", "mirrored"}) {
    const test::CommandResult r =
        test::RunRpt("triangulate --cameras " + (dir / "labels.json").string() + " --detections " +
                     (dir / (name + ".json")).string() + " --fps 25 --quiet --out " + (dir / name).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const size_t said = r.err.find("persons with nose, shoulders and hips triangulated");
    if (name == "detections") {
      EXPECT_EQ(said, std::string::npos) << r.err;
    } else {
      EXPECT_NE(said, std::string::npos) << r.err;
      EXPECT_NE(r.err.find("as mirror images have (real detections: under 2 %): are the detections of mirrored images "
                           "in every camera"),
                std::string::npos)
          << r.err;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt

namespace rpt {
namespace {

// --no-predicted-joints (a biomechanics user's finding: a coasting track's last pose went into the
// TRC files as frozen marker rows): on the real Shelf frames, whose lost tracks coast, every joint of
// provenance 'predicted' is written as missing in JSON, CSV and TRC; the persons and every other
// joint are as without the flag.
TEST(TriangulateExports, PredictedJointsAreWrittenAsMissingOnRequest) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association");
  const std::filesystem::path dir = test::TempDir("no_predicted");
  const std::string input = "triangulate --dataset shelf-4da --root " +
                            test::SharedData("shelf/4d_association").string() + " --export json,csv,trc --out ";
  const test::CommandResult with = test::RunRpt(input + (dir / "with").string());
  ASSERT_EQ(with.exit_code, 0) << with.err;
  const test::CommandResult without = test::RunRpt(input + (dir / "without").string() + " --no-predicted-joints");
  ASSERT_EQ(without.exit_code, 0) << without.err;
  const nlohmann::json a = test::ReadJson(dir / "with" / "predictions.json");
  const nlohmann::json b = test::ReadJson(dir / "without" / "predictions.json");
  ASSERT_EQ(a["frames"].size(), b["frames"].size());
  long predicted = 0, others = 0;
  for (size_t f = 0; f < a["frames"].size(); ++f) {
    const nlohmann::json &fa = a["frames"][f], &fb = b["frames"][f];
    ASSERT_EQ(fa["track_ids"], fb["track_ids"]) << "the same persons, frame " << f;
    for (size_t p = 0; p < fa["persons"].size(); ++p) {
      for (size_t j = 0; j < fa["persons"][p].size(); ++j) {
        if (fa["provenance"][p][j] == 4 && fa["persons"][p][j][3].get<double>() > 0) {
          ++predicted;
          EXPECT_TRUE(fb["persons"][p][j][0].is_null()) << "frame " << f;
          EXPECT_EQ(fb["persons"][p][j][3], 0);
        } else {
          ++others;
          EXPECT_EQ(fb["persons"][p][j], fa["persons"][p][j]) << "frame " << f;
        }
      }
    }
  }
  EXPECT_GT(predicted, 100) << "Shelf-4DA's lost tracks coast";
  EXPECT_GT(others, 10 * predicted);
  const std::string csv_with = test::ReadAll(dir / "with" / "predictions.csv");
  const std::string csv_without = test::ReadAll(dir / "without" / "predictions.csv");
  EXPECT_NE(csv_with.find(",predicted\n"), std::string::npos);
  EXPECT_EQ(csv_without.find(",predicted\n"), std::string::npos);
  EXPECT_EQ(
      std::count(csv_with.begin(), csv_with.end(), '\n') - std::count(csv_without.begin(), csv_without.end(), '\n'),
      predicted);
  // TRC: the same files with the same rows; the predicted joints' fields are empty.
  long trc_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "with" / "trc")) {
    ++trc_files;
    const std::string name = entry.path().filename().string();
    const std::string x = test::ReadAll(entry.path()), y = test::ReadAll(dir / "without" / "trc" / name);
    EXPECT_EQ(std::count(x.begin(), x.end(), '\n'), std::count(y.begin(), y.end(), '\n')) << name;
    EXPECT_LE(y.size(), x.size()) << name;
  }
  EXPECT_GT(trc_files, 3);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rpt

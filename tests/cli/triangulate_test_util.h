// SPDX-License-Identifier: MIT
// A generated scene written as cameras, labels and detections in each detection format, for the
// end-to-end tests of rpt triangulate, eval, render and the detection mapping flags; and the
// comparison of two predictions.json files.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/calibration/calibration.h"
#include "datasets/detections.h"
#include "datasets/readers/generic_labels.h"
#include "engine/input.h"
#include "tests/cli/cli_test_util.h"
#include "tests/datasets/io_test_util.h"

namespace rpt::test {

namespace fs = std::filesystem;
using Json = nlohmann::json;

inline constexpr double kFps = 25.0;

inline Json ReadJson(const fs::path& path) { return Json::parse(ReadAll(path)); }

// A generated scene with simulated detections, its frame times i / kFps.
inline Sequence Scene(int frames) {
  engine::InputSpec spec;
  spec.dataset = "synthetic";
  spec.params = {"frames=" + std::to_string(frames), "people=2", "cameras=4"};
  InputWarnings warnings;
  std::vector<Sequence> sequences = engine::LoadInput(spec, {}, &warnings);
  Sequence scene = std::move(sequences.at(0));
  for (size_t i = 0; i < scene.frames.size(); ++i) scene.frames[i].timestamp_s = static_cast<double>(i) / kFps;
  return scene;
}

// The scene's detections of the COCO-17 joints (what OpenPose and COCO files can hold), frame ids
// as given.
inline Detections Coco17(const Sequence& scene, const std::vector<std::string>& frame_ids) {
  std::vector<int> from;
  for (const std::string& name : CocoBodyJoints()) {
    const auto it = std::find(scene.detection_joints.begin(), scene.detection_joints.end(), name);
    EXPECT_NE(it, scene.detection_joints.end()) << name;
    from.push_back(static_cast<int>(it - scene.detection_joints.begin()));
  }
  Detections detections;
  detections.joints = CocoBodyJoints();
  for (size_t f = 0; f < scene.frames.size(); ++f) {
    FrameDetections frame;
    frame.frame_id = frame_ids[f];
    for (size_t c = 0; c < scene.cameras.size(); ++c) {
      const Poses2D& view = scene.frames[f].views[c];
      Poses2D out;
      out.Clear(17);
      for (int p = 0; p < view.num_persons(); ++p) {
        auto person = out.AddPerson();
        for (int j = 0; j < 17; ++j) person.col(j) = view.Person(p).col(from[j]);
      }
      frame.cameras.push_back(scene.cameras[c].name);
      frame.views.push_back(std::move(out));
    }
    detections.frames.push_back(std::move(frame));
  }
  return detections;
}

// Labels of the scene (GT, cameras, times) with these frame ids.
inline void WriteLabelsAs(const fs::path& path, Sequence scene, const std::vector<std::string>& frame_ids) {
  for (size_t f = 0; f < scene.frames.size(); ++f) scene.frames[f].id = frame_ids[f];
  WriteLabels(path, {scene});
}

// OpenPose COCO-18 order of the COCO-17 joints (index into CocoBodyJoints(); -1 = the neck).
inline constexpr int kOpenPoseCoco18[18] = {0, -1, 6, 8, 10, 5, 7, 9, 12, 14, 16, 11, 13, 15, 2, 1, 4, 3};

inline void WriteOpenPoseFolder(const fs::path& dir, const Detections& detections) {
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    for (size_t c = 0; c < frame.cameras.size(); ++c) {
      Json people = Json::array();
      const Poses2D& view = frame.views[c];
      for (int p = 0; p < view.num_persons(); ++p) {
        std::vector<double> flat;
        for (int k : kOpenPoseCoco18) {
          for (int r = 0; r < 3; ++r) flat.push_back(k < 0 ? 0.0 : view.Person(p)(r, k));
        }
        people.push_back({{"pose_keypoints_2d", flat}});
      }
      fs::create_directories(dir / frame.cameras[c]);
      char name[64];
      std::snprintf(name, sizeof(name), "video_%012zu_keypoints.json", f);
      std::ofstream(dir / frame.cameras[c] / name) << Json{{"version", 1.3}, {"people", people}}.dump();
    }
  }
}

// COCO results with MVOR ids (day 1, camera number from "cam<N>").
inline void WriteCocoResults(const fs::path& path, const Detections& detections) {
  Json results = Json::array();
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    for (size_t c = 0; c < frame.cameras.size(); ++c) {
      const long long cam = std::stoll(frame.cameras[c].substr(3));
      const long long image_id = 10000000000LL + cam * 10000000LL + static_cast<long long>(f);
      for (int p = 0; p < frame.views[c].num_persons(); ++p) {
        std::vector<double> flat;
        for (int j = 0; j < 17; ++j) {
          for (int r = 0; r < 3; ++r) flat.push_back(frame.views[c].Person(p)(r, j));
        }
        results.push_back({{"image_id", image_id}, {"category_id", 1}, {"score", 0.9}, {"keypoints", flat}});
      }
    }
  }
  std::ofstream(path) << results.dump();
}

inline std::vector<std::string> Ids(const std::string& prefix, int frames) {
  std::vector<std::string> ids;
  for (int f = 0; f < frames; ++f) {
    char id[64];
    std::snprintf(id, sizeof(id), "%s%06d", prefix.c_str(), f);
    ids.push_back(id);
  }
  return ids;
}

// A VoxelPose 2D cache (datasets/readers/voxelpose_detections.h) of COCO-17 detections: keys
// "<camera>_<frame number>", the number being the digits that end the frame id; `key_cameras`
// renames cameras in the keys (absent = as named).
inline void WriteVoxelPoseCache(const fs::path& path, const Detections& detections,
                                const std::map<std::string, std::string>& key_cameras = {}) {
  PickleWriter w;
  w.Proto(3).Global("collections", "defaultdict").None().Tuple1().Reduce().Mark();
  for (const FrameDetections& frame : detections.frames) {
    const long number = std::stol(frame.frame_id.substr(frame.frame_id.find_last_not_of("0123456789") + 1));
    for (size_t c = 0; c < frame.cameras.size(); ++c) {
      const auto renamed = key_cameras.find(frame.cameras[c]);
      w.Str((renamed == key_cameras.end() ? frame.cameras[c] : renamed->second) + "_" + std::to_string(number));
      w.EmptyList();
      const Poses2D& view = frame.views[c];
      if (view.num_persons() == 0) continue;
      w.Mark();
      for (int p = 0; p < view.num_persons(); ++p) {
        std::vector<double> rows;  // 17 x 3: x, y, score
        for (int j = 0; j < 17; ++j) {
          for (int r = 0; r < 3; ++r) rows.push_back(view.Person(p)(r, j));
        }
        w.EmptyDict().Str("pred").Array({17, 3}, "f8", "<", false, RawOf(rows)).SetItem();
      }
      w.Appends();
    }
  }
  w.SetItems().Stop();
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(w.bytes.data()), static_cast<std::streamsize>(w.bytes.size()));
}

// The frames of two predictions.json files are equal (ids, times, persons, track ids, provenance).
inline void ExpectSameFrames(const Json& a, const Json& b, const std::string& what) {
  EXPECT_EQ(a["joints"], b["joints"]) << what;
  ASSERT_EQ(a["frames"].size(), b["frames"].size()) << what;
  int persons = 0;
  for (size_t f = 0; f < a["frames"].size(); ++f) {
    EXPECT_EQ(a["frames"][f], b["frames"][f]) << what << ", frame " << f;
    persons += static_cast<int>(a["frames"][f]["persons"].size());
  }
  EXPECT_GT(persons, static_cast<int>(a["frames"].size())) << what << ": about two persons per frame";
}

// A fixture: the scene of kFrames frames, its cameras written to dir_ / "cameras.json".
class SceneFilesTest : public ::testing::Test {
 protected:
  static constexpr int kFrames = 16;
  void SetUp() override {
    dir_ = TempDir("triangulate");
    scene_ = Scene(kFrames);
    WriteCalibration(dir_ / "cameras.json", scene_.cameras);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // eval on labels + detections and triangulate on cameras + detections give the same frames;
  // `flags` (e.g. detection mapping flags) are given to both.
  void CompareWithEval(const std::string& format, const fs::path& detections, const std::vector<std::string>& ids,
                       const std::string& flags = "") {
    WriteLabelsAs(dir_ / (format + "_labels.json"), scene_, ids);
    const fs::path eval = dir_ / (format + "_eval"), tri = dir_ / (format + "_tri");
    const CommandResult e = RunRpt("eval --labels " + (dir_ / (format + "_labels.json")).string() + " --detections " +
                                   detections.string() + " --out " + eval.string() + " --quiet " + flags);
    ASSERT_EQ(e.exit_code, 0) << format << ": " << e.err;
    const CommandResult t = RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                                   detections.string() + " --fps 25 --out " + tri.string() + " " + flags);
    ASSERT_EQ(t.exit_code, 0) << format << ": " << t.err;
    EXPECT_NE(t.out.find(std::to_string(kFrames) + " frames, 4 cameras"), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("make_pairs"), std::string::npos) << "the step table:\n" << t.out;
    ExpectSameFrames(ReadJson(eval / "predictions.json"), ReadJson(tri / "predictions.json"), format);
    EXPECT_FALSE(fs::exists(tri / "per_joint.csv")) << "no GT, no per-joint errors";
    EXPECT_EQ(ReadJson(tri / "summary.json")["evaluated"], false);
  }

  fs::path dir_;
  Sequence scene_;
};

}  // namespace rpt::test

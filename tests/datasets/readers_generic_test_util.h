// SPDX-License-Identifier: MIT
// Fixtures for the generic-format tests, made at run time (nothing copied from shared/data).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/camera.h"
#include "core/errors.h"
#include "core/joints.h"
#include "datasets/detections.h"
#include "datasets/sequence.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"

namespace rpt::test {


inline std::filesystem::path WriteText(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir.path() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  return path;
}

// A camera looking at the origin from `center`, with the given lens model.
inline Camera LookAtCamera(const std::string& name, const Eigen::Vector3d& center, DistortionModel model) {
  const Eigen::Vector3d forward = (-center).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d R;
  R.row(0) = right.transpose();
  R.row(1) = down.transpose();
  R.row(2) = forward.transpose();
  Camera camera = Camera::FromCenter(R, center);
  camera.name = name;
  camera.width = 1920;
  camera.height = 1080;
  camera.K << 1000.5, 0, 960.25, 0, 1001.75, 540.5, 0, 0, 1;
  camera.model = model;
  switch (model) {
    case DistortionModel::kNone:
      break;
    case DistortionModel::kOpenCV:
    case DistortionModel::kH36M:
      camera.dist = {-0.21, 0.07, 0.0011, -0.0007, -0.012};
      break;
    case DistortionModel::kFisheye:
      camera.dist = {0.05, -0.011, 0.0021, -0.0003, 0};
      break;
  }
  return camera;
}

// A sequence with three cameras (pinhole, OpenCV, fisheye), `frames` frames of two persons
// (the second one untracked in odd frames), some invisible joints.
inline Sequence MakeLabelSequence(const std::string& name, int frames, const std::string& id_prefix) {
  Sequence sequence;
  sequence.name = name;
  sequence.fps = 30;
  sequence.room.center_m = Eigen::Vector3d(0.5, -0.25, 1.0);
  sequence.room.size_m = Eigen::Vector3d(8, 6, 2.5);
  sequence.cameras = {LookAtCamera("cam_a", {4, 0.5, 2}, DistortionModel::kNone),
                      LookAtCamera("cam_b", {-0.5, 4, 2.5}, DistortionModel::kOpenCV),
                      LookAtCamera("cam_c", {-3.5, -3, 1.5}, DistortionModel::kFisheye)};
  sequence.gt_joints = AddDerivedJoints(CocoBodyJoints());
  const int J = static_cast<int>(sequence.gt_joints.size());
  for (int f = 0; f < frames; ++f) {
    SequenceFrame& frame = sequence.frames.emplace_back();
    char id[64];
    std::snprintf(id, sizeof(id), "%s%06d", id_prefix.c_str(), f);
    frame.id = id;
    frame.timestamp_s = f / 30.0 + 0.001;
    frame.gt.Clear(J);
    for (int p = 0; p < 2; ++p) {
      auto joints = frame.gt.AddPerson(p == 1 && f % 2 ? -1 : p + 7);
      for (int j = 0; j < J; ++j) {
        joints(0, j) = 0.1 * p + 0.01 * j + 0.001 * f + 1.0 / 3.0;
        joints(1, j) = -0.2 * p + 0.02 * j;
        joints(2, j) = 0.05 * j + 0.3;
        joints(3, j) = (j + f + p) % 5 == 0 ? 0.0 : 1.0;
      }
    }
  }
  return sequence;
}

// Detections over `frames` frames and the cameras named; a few empty views, missing joints
// (score 0) and non-trivial decimals.
inline Detections MakeDetections(int frames, const std::vector<std::string>& cameras, const JointNames& joints,
                                 const std::string& id_prefix = "frame_") {
  Detections detections;
  detections.joints = joints;
  const int J = static_cast<int>(joints.size());
  for (int f = 0; f < frames; ++f) {
    FrameDetections& frame = detections.frames.emplace_back();
    char id[64];
    std::snprintf(id, sizeof(id), "%s%06d", id_prefix.c_str(), f);
    frame.frame_id = id;
    for (size_t c = 0; c < cameras.size(); ++c) {
      frame.cameras.push_back(cameras[c]);
      Poses2D& view = frame.views.emplace_back();
      view.Clear(J);
      const int persons = (f + static_cast<int>(c)) % 3;  // 0, 1 or 2 persons
      for (int p = 0; p < persons; ++p) {
        auto person = view.AddPerson();
        for (int j = 0; j < J; ++j) {
          const bool missing = (j + p + f) % 7 == 3;
          person(0, j) = missing ? 0.0 : 100.125 + 13.37 * j + 101.1 * p + 0.7 * f;
          person(1, j) = missing ? 0.0 : 50.5 + 7.25 * j + 3.3 * c;
          person(2, j) = missing ? 0.0 : 0.25 + 0.5 * ((j * 7 + p) % 11) / 10.0;
        }
      }
    }
  }
  return detections;
}

inline void ExpectDetectionsNear(const Detections& a, const Detections& b, double tolerance) {
  ASSERT_EQ(a.joints, b.joints);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (size_t f = 0; f < a.frames.size(); ++f) {
    SCOPED_TRACE("frame " + a.frames[f].frame_id);
    EXPECT_EQ(a.frames[f].frame_id, b.frames[f].frame_id);
    ASSERT_EQ(a.frames[f].cameras, b.frames[f].cameras);
    ASSERT_EQ(a.frames[f].views.size(), b.frames[f].views.size());
    for (size_t v = 0; v < a.frames[f].views.size(); ++v) {
      const Poses2D& x = a.frames[f].views[v];
      const Poses2D& y = b.frames[f].views[v];
      ASSERT_EQ(x.num_persons(), y.num_persons());
      ASSERT_EQ(x.data.size(), y.data.size());
      for (size_t i = 0; i < x.data.size(); ++i) {
        if (tolerance == 0) {
          ASSERT_EQ(x.data[i], y.data[i]) << "value " << i;
        } else {
          ASSERT_NEAR(x.data[i], y.data[i], tolerance * std::max(1.0, std::abs(x.data[i]))) << "value " << i;
        }
      }
    }
  }
}

inline void ExpectCamerasNear(const Camera& a, const Camera& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.model, b.model) << a.name;
  EXPECT_TRUE(a.K.isApprox(b.K, 1e-14)) << a.name;
  EXPECT_TRUE(a.R.isApprox(b.R, 1e-14)) << a.name;
  EXPECT_LT((a.t - b.t).norm(), 1e-12) << a.name;
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(a.dist[i], b.dist[i]) << a.name << " dist " << i;
}

inline void ExpectSequencesNear(const Sequence& a, const Sequence& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_DOUBLE_EQ(a.fps, b.fps);
  EXPECT_EQ(a.gt_joints, b.gt_joints);
  EXPECT_TRUE(a.room.center_m.isApprox(b.room.center_m));
  EXPECT_TRUE(a.room.size_m.isApprox(b.room.size_m));
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (size_t c = 0; c < a.cameras.size(); ++c) ExpectCamerasNear(a.cameras[c], b.cameras[c]);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (size_t f = 0; f < a.frames.size(); ++f) {
    EXPECT_EQ(a.frames[f].id, b.frames[f].id);
    EXPECT_DOUBLE_EQ(a.frames[f].timestamp_s, b.frames[f].timestamp_s);
    EXPECT_EQ(a.frames[f].gt.num_joints, b.frames[f].gt.num_joints);
    EXPECT_EQ(a.frames[f].gt.data, b.frames[f].gt.data);
    EXPECT_EQ(a.frames[f].gt.track_ids, b.frames[f].gt.track_ids);
  }
}

}  // namespace rpt::test

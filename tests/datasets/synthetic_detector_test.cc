// SPDX-License-Identifier: MIT
// Tests of the simulated 2D detector.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/synthetic/camera_rig.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt::synthetic {
namespace {

Scene TestScene(int num_frames, uint64_t seed = 17, bool whole_body = false) {
  SceneOptions options;
  options.num_frames = num_frames;
  options.seed = seed;
  options.whole_body = whole_body;
  return GenerateScene(options);
}

// Bounding-box diagonal of the projections of all joints in front of the camera.
double ProjectedDiagonal(const Camera& camera, const Poses3D& gt, int p) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (int k = 0; k < gt.num_joints; ++k) {
    Eigen::Vector2d uv;
    if (camera.Project(gt.Person(p).col(k).head<3>(), &uv)) {
      lo = lo.cwiseMin(uv);
      hi = hi.cwiseMax(uv);
    }
  }
  return std::min((hi - lo).norm(), std::hypot(camera.width, camera.height));
}

bool InImage(const Camera& camera, const Eigen::Vector2d& uv) {
  return uv.x() >= 0 && uv.x() < camera.width && uv.y() >= 0 && uv.y() < camera.height;
}

TEST(SyntheticDetectorTest, PerfectReproducesProjectionExactly) {
  for (bool whole_body : {false, true}) {
    const Scene scene = TestScene(20, 4, whole_body);
    const DetectorSimulator detector(DetectorOptions::Perfect(), scene.joint_names, 1);
    std::vector<Poses2D> views;
    std::vector<std::vector<DetectionSource>> sources;
    int compared = 0;
    for (size_t f = 0; f < scene.gt.size(); ++f) {
      const Poses3D& gt = scene.gt[f];
      detector.Detect(scene.cameras, gt, scene.joint_names, f, &views, &sources);
      ASSERT_EQ(views.size(), scene.cameras.size());
      for (size_t c = 0; c < views.size(); ++c) {
        const Camera& camera = scene.cameras[c];
        ASSERT_EQ(views[c].num_joints, static_cast<int>(scene.joint_names.size()));
        int expected_persons = 0;
        for (int p = 0; p < gt.num_persons(); ++p) {
          bool any = false;
          for (int k = 0; k < gt.num_joints; ++k) {
            Eigen::Vector2d uv;
            any |= camera.Project(gt.Person(p).col(k).head<3>(), &uv) && InImage(camera, uv);
          }
          expected_persons += any;
        }
        ASSERT_EQ(views[c].num_persons(), expected_persons);
        for (int d = 0; d < views[c].num_persons(); ++d) {
          const int p = sources[c][d].gt_person;
          ASSERT_GE(p, 0);
          EXPECT_FALSE(sources[c][d].swapped);
          if (d > 0) {
            EXPECT_GT(p, sources[c][d - 1].gt_person) << "GT order kept";
          }
          const auto detection = views[c].Person(d);
          for (int k = 0; k < gt.num_joints; ++k) {
            Eigen::Vector2d uv;
            const bool visible = camera.Project(gt.Person(p).col(k).head<3>(), &uv) && InImage(camera, uv);
            if (visible) {
              ASSERT_EQ(detection(0, k), uv.x());
              ASSERT_EQ(detection(1, k), uv.y());
              ASSERT_EQ(detection(2, k), 1.0);
              ++compared;
            } else {
              ASSERT_EQ(detection(2, k), 0.0);
            }
          }
        }
      }
    }
    EXPECT_GT(compared, 1000);
  }
}

TEST(SyntheticDetectorTest, SameFrameSameResultInAnyOrder) {
  const Scene scene = TestScene(10);
  const DetectorSimulator a(DetectorOptions::Clean(), scene.joint_names, 5);
  const DetectorSimulator b(DetectorOptions::Clean(), scene.joint_names, 5);
  const DetectorSimulator other(DetectorOptions::Clean(), scene.joint_names, 6);
  std::vector<Poses2D> first, second, third;
  for (int f : {7, 3, 9}) a.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &first);
  a.Detect(scene.cameras, scene.gt[3], scene.joint_names, 3, &first);
  b.Detect(scene.cameras, scene.gt[3], scene.joint_names, 3, &second);
  other.Detect(scene.cameras, scene.gt[3], scene.joint_names, 3, &third);
  bool differs = false;
  for (size_t c = 0; c < first.size(); ++c) {
    EXPECT_EQ(first[c].data, second[c].data);
    differs |= first[c].data != third[c].data;
  }
  EXPECT_TRUE(differs);
  // Another frame index gives other noise for the same GT.
  b.Detect(scene.cameras, scene.gt[3], scene.joint_names, 4, &second);
  differs = false;
  for (size_t c = 0; c < first.size(); ++c) differs |= first[c].data != second[c].data;
  EXPECT_TRUE(differs);
}

// Clean detector with everything but the pixel noise and confidences switched off.
DetectorOptions NoiseOnly() {
  DetectorOptions options = DetectorOptions::Clean();
  options.outlier_probability = 0;
  options.joint_dropout = 0;
  options.person_miss = 0;
  options.false_positives_per_view = 0;
  options.left_right_swap = 0;
  return options;
}

TEST(SyntheticDetectorTest, CleanNoiseScalesWithPersonSize) {
  const Scene scene = TestScene(100);
  for (bool with_outliers : {false, true}) {
    DetectorOptions options = NoiseOnly();
    if (with_outliers) options.outlier_probability = 0.01;
    const DetectorSimulator detector(options, scene.joint_names, 3);
    const DetectorSimulator perfect(DetectorOptions::Perfect(), scene.joint_names, 3);
    std::vector<Poses2D> views, exact;
    std::vector<std::vector<DetectionSource>> sources, exact_sources;
    double ratio_sum = 0, score_sum = 0, big_errors = 0;
    int count = 0;
    double low_score_error = 0, high_score_error = 0;
    int low_score_count = 0, high_score_count = 0;
    for (size_t f = 0; f < scene.gt.size(); ++f) {
      detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views, &sources);
      perfect.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &exact, &exact_sources);
      for (size_t c = 0; c < views.size(); ++c) {
        for (int d = 0; d < views[c].num_persons(); ++d) {
          const int p = sources[c][d].gt_person;
          const auto it = std::find_if(exact_sources[c].begin(), exact_sources[c].end(),
                                       [&](const DetectionSource& s) { return s.gt_person == p; });
          ASSERT_NE(it, exact_sources[c].end());
          const auto truth = exact[c].Person(static_cast<int>(it - exact_sources[c].begin()));
          const auto noisy = views[c].Person(d);
          const double sigma = 0.008 * ProjectedDiagonal(scene.cameras[c], scene.gt[f], p) + 0.5;
          for (int k = 0; k < views[c].num_joints; ++k) {
            ASSERT_EQ(noisy(2, k) > 0, truth(2, k) > 0);
            if (truth(2, k) == 0) continue;
            const double error = (noisy.col(k) - truth.col(k)).head<2>().norm();
            // Errors clamped at the image border are smaller; skip joints near it.
            if (truth(0, k) < 50 || truth(1, k) < 50 || truth(0, k) > 1870 || truth(1, k) > 1030) continue;
            ratio_sum += error / sigma;
            score_sum += noisy(2, k);
            big_errors += error > 5 * sigma;
            ++count;
            EXPECT_GE(noisy(2, k), 0.05);
            EXPECT_LE(noisy(2, k), 1.0);
            if (noisy(2, k) < 0.8) {
              low_score_error += error / sigma;
              ++low_score_count;
            } else {
              high_score_error += error / sigma;
              ++high_score_count;
            }
          }
        }
      }
    }
    ASSERT_GT(count, 10000);
    const double mean_ratio = ratio_sum / count;  // Rayleigh mean: sqrt(pi / 2) = 1.2533
    SCOPED_TRACE(with_outliers ? "with outliers" : "gaussian only");
    if (with_outliers) {
      EXPECT_GT(mean_ratio, 1.25 + 0.005);
      EXPECT_LT(mean_ratio, 1.25 + 0.15);
      // Outliers have a per-axis sigma of ~5-6 inlier sigmas: about 2/3 of them exceed 5 sigma.
      EXPECT_GT(big_errors / count, 0.004);
      EXPECT_LT(big_errors / count, 0.012);
    } else {
      EXPECT_NEAR(mean_ratio, std::sqrt(M_PI / 2), 0.03);
      EXPECT_LT(big_errors / count, 1e-4);
    }
    EXPECT_NEAR(score_sum / count, 0.95 - 0.1 * mean_ratio, 0.02);
    // Confidences fall with the error.
    ASSERT_GT(low_score_count, 100);
    EXPECT_GT(low_score_error / low_score_count, 1.3 * high_score_error / high_score_count);
  }
}

TEST(SyntheticDetectorTest, DropoutMissAndSwapRatesMatchOptions) {
  const Scene scene = TestScene(200, 23);
  DetectorOptions options = DetectorOptions::Clean();
  options.false_positives_per_view = 0;
  options.shuffle_persons = false;
  const DetectorSimulator detector(options, scene.joint_names, 8);
  DetectorOptions reference_options = DetectorOptions::Perfect();
  reference_options.min_visible_joints = options.min_visible_joints;
  const DetectorSimulator perfect(reference_options, scene.joint_names, 8);
  std::vector<Poses2D> views, exact;
  std::vector<std::vector<DetectionSource>> sources, exact_sources;
  int persons = 0, detected = 0, swapped = 0, joints = 0, dropped = 0;
  for (size_t f = 0; f < scene.gt.size(); ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views, &sources);
    perfect.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &exact, &exact_sources);
    for (size_t c = 0; c < views.size(); ++c) {
      persons += exact[c].num_persons();
      detected += views[c].num_persons();
      for (int d = 0; d < views[c].num_persons(); ++d) {
        const DetectionSource& source = sources[c][d];
        ASSERT_GE(source.gt_person, 0);
        swapped += source.swapped;
        if (source.swapped) continue;
        const auto it = std::find_if(exact_sources[c].begin(), exact_sources[c].end(),
                                     [&](const DetectionSource& s) { return s.gt_person == source.gt_person; });
        ASSERT_NE(it, exact_sources[c].end()) << "detected persons have >= 5 in-image joints";
        const auto truth = exact[c].Person(static_cast<int>(it - exact_sources[c].begin()));
        for (int k = 0; k < views[c].num_joints; ++k) {
          if (truth(2, k) == 0) {
            EXPECT_EQ(views[c].Person(d)(2, k), 0.0);
            continue;
          }
          ++joints;
          dropped += views[c].Person(d)(2, k) == 0.0;
        }
      }
    }
  }
  ASSERT_GT(persons, 2000);
  EXPECT_NEAR(1.0 - static_cast<double>(detected) / persons, 0.03, 0.01);
  EXPECT_NEAR(static_cast<double>(swapped) / detected, 0.01, 0.006);
  EXPECT_NEAR(static_cast<double>(dropped) / joints, 0.03, 0.003);
}

TEST(SyntheticDetectorTest, FalsePositivesAreHumanShapedAtTheConfiguredRate) {
  Scene scene = TestScene(1);
  Poses3D empty;
  empty.Clear(17);
  DetectorOptions options = DetectorOptions::Clean();
  const DetectorSimulator detector(options, scene.joint_names, 2);
  std::vector<Poses2D> views;
  std::vector<std::vector<DetectionSource>> sources;
  int num_views = 0, num_false = 0;
  const JointNames& names = scene.joint_names;
  for (int f = 0; f < 400; ++f) {
    detector.Detect(scene.cameras, empty, names, f, &views, &sources);
    for (size_t c = 0; c < views.size(); ++c) {
      ++num_views;
      num_false += views[c].num_persons();
      for (int d = 0; d < views[c].num_persons(); ++d) {
        EXPECT_EQ(sources[c][d].gt_person, -1);
        const auto person = views[c].Person(d);
        int visible = 0;
        for (int k = 0; k < person.cols(); ++k) visible += person(2, k) > 0;
        EXPECT_GE(visible, 4);  // >= 5 in the image before the joint dropout
        EXPECT_LE(person.row(2).maxCoeff(), 0.7 + 1e-12);
        // Upright: the head is above the ankles whenever both are seen.
        const int nose = FindJoint(names, "nose"), ankle = FindJoint(names, "ankle_left");
        if (person(2, nose) > 0 && person(2, ankle) > 0) {
          EXPECT_LT(person(1, nose), person(1, ankle));
        }
      }
    }
  }
  EXPECT_NEAR(static_cast<double>(num_false) / num_views, 0.2, 0.035);
}

TEST(SyntheticDetectorTest, LeftRightSwapExchangesSides) {
  const Scene scene = TestScene(3);
  DetectorOptions options = DetectorOptions::Perfect();
  options.left_right_swap = 1.0;
  const DetectorSimulator swapping(options, scene.joint_names, 1);
  const DetectorSimulator perfect(DetectorOptions::Perfect(), scene.joint_names, 1);
  std::vector<Poses2D> swapped, exact;
  std::vector<std::vector<DetectionSource>> sources;
  swapping.Detect(scene.cameras, scene.gt[0], scene.joint_names, 0, &swapped, &sources);
  perfect.Detect(scene.cameras, scene.gt[0], scene.joint_names, 0, &exact);
  const JointNames& names = scene.joint_names;
  const int shoulder_left = FindJoint(names, "shoulder_left"), shoulder_right = FindJoint(names, "shoulder_right");
  const int nose = FindJoint(names, "nose");
  int checked = 0;
  for (size_t c = 0; c < swapped.size(); ++c) {
    ASSERT_EQ(swapped[c].num_persons(), exact[c].num_persons());
    for (int d = 0; d < swapped[c].num_persons(); ++d) {
      EXPECT_TRUE(sources[c][d].swapped);
      const auto s = swapped[c].Person(d);
      const auto e = exact[c].Person(d);
      EXPECT_EQ(s.col(shoulder_left), e.col(shoulder_right));
      EXPECT_EQ(s.col(shoulder_right), e.col(shoulder_left));
      EXPECT_EQ(s.col(nose), e.col(nose));
      for (int k = 0; k < s.cols(); ++k) EXPECT_EQ(s.col(k), e.col(swapping.mirror_indices()[k]));
      ++checked;
    }
  }
  EXPECT_GT(checked, 5);
  EXPECT_EQ(rpt::MirrorJointName("hand_index_2_left"), "hand_index_2_right");
  EXPECT_EQ(rpt::MirrorJointName("ear_right"), "ear_left");
  EXPECT_EQ(rpt::MirrorJointName("leftover"), "leftover");
}

TEST(SyntheticDetectorTest, TruncationZeroesJointsOutsideTheImage) {
  // A camera close to the person sees only the upper body.
  const Scene scene = TestScene(1, 31);
  const Eigen::Vector3d hips = 0.5 * (scene.gt[0].Person(0).col(11) + scene.gt[0].Person(0).col(12)).head<3>();
  const Eigen::Vector3d head = scene.gt[0].Person(0).col(0).head<3>();
  const Eigen::Vector3d center = hips + Eigen::Vector3d(1.2, 0.0, 0.6);
  Camera camera = scene.cameras[0];
  camera.R = LookAtRotation(center, head);
  camera.t = -camera.R * center;
  Poses3D one;
  one.Clear(17);
  one.AddPerson(0) = scene.gt[0].Person(0);
  const std::vector<Camera> cameras = {camera};
  std::vector<Poses2D> views;
  const DetectorSimulator perfect(DetectorOptions::Perfect(), scene.joint_names, 1);
  perfect.Detect(cameras, one, scene.joint_names, 0, &views);
  ASSERT_EQ(views[0].num_persons(), 1);
  int inside = 0, outside = 0;
  for (int k = 0; k < 17; ++k) {
    Eigen::Vector2d uv;
    const bool in_front = camera.Project(one.Person(0).col(k).head<3>(), &uv);
    if (in_front && InImage(camera, uv)) {
      ++inside;
      EXPECT_EQ(views[0].Person(0)(2, k), 1.0);
    } else {
      ++outside;
      EXPECT_EQ(views[0].Person(0)(2, k), 0.0);
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
  // Fewer than min_visible_joints in the image: not detected.
  DetectorOptions strict = DetectorOptions::Perfect();
  strict.min_visible_joints = inside + 1;
  const DetectorSimulator strict_detector(strict, scene.joint_names, 1);
  strict_detector.Detect(cameras, one, scene.joint_names, 0, &views);
  EXPECT_EQ(views[0].num_persons(), 0);
}

TEST(SyntheticDetectorTest, PointsBehindTheCameraAreNeverVisible) {
  const Scene scene = TestScene(1);
  Camera camera = scene.cameras[0];
  // Turn the camera around: everybody is behind it.
  const Eigen::Vector3d center = camera.Center();
  camera.R = LookAtRotation(center, center + (center - Eigen::Vector3d(0, 0, 1)));
  camera.t = -camera.R * center;
  const std::vector<Camera> cameras = {camera};
  std::vector<Poses2D> views;
  const DetectorSimulator perfect(DetectorOptions::Perfect(), scene.joint_names, 1);
  perfect.Detect(cameras, scene.gt[0], scene.joint_names, 0, &views);
  EXPECT_EQ(views[0].num_persons(), 0);
}

TEST(SyntheticDetectorTest, MapsJointsByNameFromAnyGroundTruth) {
  const Scene scene = TestScene(2);
  // GT in reversed joint order, with one joint marked invisible.
  JointNames reversed(scene.joint_names.rbegin(), scene.joint_names.rend());
  Poses3D gt;
  gt.Clear(17);
  for (int p = 0; p < scene.gt[0].num_persons(); ++p) {
    auto person = gt.AddPerson(p);
    for (int k = 0; k < 17; ++k) person.col(16 - k) = scene.gt[0].Person(p).col(k);
  }
  gt.Person(0)(3, 16 - FindJoint(scene.joint_names, "knee_left")) = 0.1;  // treated as absent
  JointNames output = scene.joint_names;
  output.push_back("hip_middle");  // not in the GT: always missing
  const DetectorSimulator mapped(DetectorOptions::Perfect(), output, 1);
  const DetectorSimulator direct(DetectorOptions::Perfect(), scene.joint_names, 1);
  std::vector<Poses2D> a, b;
  mapped.Detect(scene.cameras, gt, reversed, 0, &a);
  direct.Detect(scene.cameras, scene.gt[0], scene.joint_names, 0, &b);
  const int knee = FindJoint(scene.joint_names, "knee_left");
  for (size_t c = 0; c < a.size(); ++c) {
    ASSERT_EQ(a[c].num_joints, 18);
    ASSERT_EQ(a[c].num_persons(), b[c].num_persons());
    for (int d = 0; d < a[c].num_persons(); ++d) {
      EXPECT_EQ(a[c].Person(d)(2, 17), 0.0);
      for (int k = 0; k < 17; ++k) {
        if (d == 0 && k == knee) {
          EXPECT_EQ(a[c].Person(d)(2, k), 0.0);
        } else {
          EXPECT_EQ(a[c].Person(d).col(k), b[c].Person(d).col(k));
        }
      }
    }
  }
  // Whole-body output from body-only GT: only the 17 body joints can be present.
  const DetectorSimulator whole(DetectorOptions::Clean(), CocoWholeBodyJoints(), 1);
  whole.Detect(scene.cameras, scene.gt[0], scene.joint_names, 0, &a);
  for (const Poses2D& view : a) {
    ASSERT_EQ(view.num_joints, 133);
  }
  EXPECT_THROW(whole.Detect(scene.cameras, scene.gt[0], reversed.size() > 3 ? JointNames(reversed.begin(), reversed.begin() + 3) : reversed, 0, &a),
               std::exception);
}

TEST(SyntheticDetectorTest, WholeBodyDetectionsAndDistortedRigs) {
  SceneOptions options;
  options.num_frames = 5;
  options.whole_body = true;
  options.rig.distortion = DistortionModel::kFisheye;
  const Scene scene = GenerateScene(options);
  const DetectorSimulator perfect(DetectorOptions::Perfect(), scene.joint_names, 1);
  std::vector<Poses2D> views;
  std::vector<std::vector<DetectionSource>> sources;
  perfect.Detect(scene.cameras, scene.gt[2], scene.joint_names, 2, &views, &sources);
  int persons = 0;
  for (size_t c = 0; c < views.size(); ++c) {
    for (int d = 0; d < views[c].num_persons(); ++d) {
      ++persons;
      const auto person = views[c].Person(d);
      for (int k = 0; k < 133; ++k) {
        if (person(2, k) == 0) continue;
        // Round trip through the lens model lands on the GT ray.
        const Eigen::Vector3d point = scene.gt[2].Person(sources[c][d].gt_person).col(k).head<3>();
        const Eigen::Vector3d in_camera = scene.cameras[c].R * point + scene.cameras[c].t;
        const Eigen::Vector2d xy = scene.cameras[c].PixelToNormalized(person.col(k).head<2>());
        EXPECT_NEAR(xy.x(), in_camera.x() / in_camera.z(), 1e-6);
        EXPECT_NEAR(xy.y(), in_camera.y() / in_camera.z(), 1e-6);
      }
    }
  }
  EXPECT_GT(persons, 10);
}

}  // namespace
}  // namespace rpt::synthetic

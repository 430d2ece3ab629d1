// SPDX-License-Identifier: MIT
// End-to-end recovery on generated scenes: exact with a perfect detector, robust with a
// realistic one (noise, dropout, misses, false positives, left/right swaps, truncation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt {
namespace {

using synthetic::DetectorOptions;
using synthetic::DetectorSimulator;
using synthetic::GenerateScene;
using synthetic::Scene;
using synthetic::SceneOptions;

// Mean distance over the joints both have (GT by name; prediction joints above `min_score` and
// triangulated or filled, not placed from one view).
double MeanJointError(const Poses3D& gt, int g, const JointNames& gt_names, const Poses3D& pred, int p,
                      const JointNames& pred_names, double min_score, int* count = nullptr) {
  double sum = 0;
  int n = 0;
  for (size_t j = 0; j < gt_names.size(); ++j) {
    const int pj = FindJoint(pred_names, gt_names[j]);
    if (pj < 0 || gt.Person(g)(3, j) <= 0.1 || pred.Person(p)(3, pj) <= min_score) continue;
    // Joints placed from one view (refine.one_view_joints) sit at a guessed depth: not exact.
    if (pred.Provenance(p, pj) == JointProvenance::kLifted) continue;
    sum += (gt.Person(g).col(j).head<3>() - pred.Person(p).col(pj).head<3>()).norm();
    ++n;
  }
  if (count) *count = n;
  return n > 0 ? sum / n : 1e9;
}

// Number of core joints of GT person `g` visible (score > 0) in both views; a detection with
// swapped left/right labels does not count (it cannot pair with a correct one).
int CommonCoreJoints(const std::vector<Poses2D>& views, const std::vector<std::vector<synthetic::DetectionSource>>& src,
                     const JointNames& names, int g, int va, int vb) {
  auto find = [&](int v) -> int {
    for (size_t d = 0; d < src[v].size(); ++d) {
      if (src[v][d].gt_person == g && !src[v][d].swapped) return static_cast<int>(d);
    }
    return -1;
  };
  const int da = find(va), db = find(vb);
  if (da < 0 || db < 0) return 0;
  int n = 0;
  for (const auto& name : DefaultCoreJoints()) {
    const int j = FindJoint(names, name);
    n += (views[va].Person(da)(2, j) > 0 && views[vb].Person(db)(2, j) > 0) ? 1 : 0;
  }
  return n;
}

// Best common-core-joint count of person g over all view pairs.
int BestPairVisibility(const std::vector<Poses2D>& views, const std::vector<std::vector<synthetic::DetectionSource>>& src,
                       const JointNames& names, int g) {
  int best = 0;
  for (size_t a = 0; a < views.size(); ++a) {
    for (size_t b = a + 1; b < views.size(); ++b) {
      best = std::max(best, CommonCoreJoints(views, src, names, g, static_cast<int>(a), static_cast<int>(b)));
    }
  }
  return best;
}

struct RecoveryCase {
  int cameras;
  int people;
  bool whole_body;
};

void CheckExactRecovery(const RecoveryCase& c) {
  SceneOptions options;
  options.rig.num_cameras = c.cameras;
  options.num_people = c.people;
  options.whole_body = c.whole_body;
  options.num_frames = 40;
  options.seed = 100 + c.cameras * 17 + c.people;
  const Scene scene = GenerateScene(options);
  DetectorOptions perfect = DetectorOptions::Perfect();
  const DetectorSimulator detector(perfect, scene.joint_names, options.seed);
  TriangulatorOptions tri_options;
  tri_options.track.enabled = false;  // exactness per frame: no coasting of persons out of view
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  const double filled = tri_options.postprocess.filled_joint_score;

  std::vector<Poses2D> views;
  std::vector<std::vector<synthetic::DetectionSource>> sources;
  Poses3D persons;
  FrameStats stats;
  for (int f = 0; f < options.num_frames; f += 8) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views, &sources);
    tri.Process(views, f / scene.fps, &persons, &stats);
    const Poses3D& gt = scene.gt[f];
    std::vector<int> matched(gt.num_persons(), 0);
    for (int p = 0; p < persons.num_persons(); ++p) {
      int best_g = -1, count = 0;
      double best = 1e9;
      for (int g = 0; g < gt.num_persons(); ++g) {
        int n = 0;
        const double e = MeanJointError(gt, g, scene.joint_names, persons, p, tri.output_joints(), filled, &n);
        if (e < best) {
          best = e;
          best_g = g;
          count = n;
        }
      }
      ASSERT_GE(best_g, 0);
      EXPECT_LT(best, 1e-3) << "person " << p << " frame " << f << " (" << count << " joints)";
      EXPECT_GE(count, tri_options.postprocess.min_valid_joints);  // a person of fewer joints is dropped
      ++matched[best_g];
    }
    for (int g = 0; g < gt.num_persons(); ++g) {
      const int visibility = BestPairVisibility(views, sources, scene.joint_names, g);
      EXPECT_LE(matched[g], 1) << "duplicate of person " << g << " frame " << f;
      if (visibility >= 6) {
        EXPECT_EQ(matched[g], 1) << "missed person " << g << " frame " << f;
      }
      if (visibility < 3) {
        EXPECT_EQ(matched[g], 0) << "person " << g << " cannot be triangulated, frame " << f;
      }
    }
  }
}

TEST(SyntheticRecovery, NoiseFreeBodyScenesAreRecoveredExactly) {
  for (int cameras = 2; cameras <= 10; ++cameras) {
    for (int people = 1; people <= 10; ++people) {
      SCOPED_TRACE(testing::Message() << cameras << " cameras, " << people << " people");
      CheckExactRecovery({cameras, people, false});
      if (HasFatalFailure()) return;
    }
  }
}

TEST(SyntheticRecovery, NoiseFreeWholeBodyScenesAreRecoveredExactly) {
  for (int cameras = 2; cameras <= 10; ++cameras) {
    for (int people = 1; people <= 10; ++people) {
      SCOPED_TRACE(testing::Message() << cameras << " cameras, " << people << " people (whole body)");
      CheckExactRecovery({cameras, people, true});
      if (HasFatalFailure()) return;
    }
  }
}

// A simulated detector on fixed seeds (5 cameras, 4 people, 150 frames): how many persons seen
// well by at least two views are found (within 0.15 m), how many output persons are phantoms
// (farther than 0.25 m from every real person), and the mean joint error of those found.
struct RecoveryCounts {
  int present = 0, found = 0, output = 0, phantoms = 0, false_positive_views = 0;
  double mean_error_m = 0;
};

RecoveryCounts MeasureRecovery(const DetectorOptions& detector_options, uint64_t seed) {
  SceneOptions options;
  options.rig.num_cameras = 5;
  options.num_people = 4;
  options.num_frames = 150;
  options.seed = seed;
  const Scene scene = GenerateScene(options);
  const DetectorSimulator detector(detector_options, scene.joint_names, seed);
  TriangulatorOptions tri_options;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  std::vector<Poses2D> views;
  std::vector<std::vector<synthetic::DetectionSource>> sources;
  Poses3D persons;
  FrameStats stats;
  RecoveryCounts counts;
  double error_sum = 0;
  for (int f = 0; f < options.num_frames; ++f) {
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views, &sources);
    for (const auto& s : sources) {
      for (const auto& d : s) counts.false_positive_views += d.gt_person < 0 ? 1 : 0;
    }
    tri.Process(views, f / scene.fps, &persons, &stats);
    const Poses3D& gt = scene.gt[f];
    counts.output += persons.num_persons();
    for (int p = 0; p < persons.num_persons(); ++p) {
      double best = 1e9;
      for (int g = 0; g < gt.num_persons(); ++g) {
        best = std::min(best, MeanJointError(gt, g, scene.joint_names, persons, p, tri.output_joints(), 0.0));
      }
      counts.phantoms += best > 0.25 ? 1 : 0;
    }
    for (int g = 0; g < gt.num_persons(); ++g) {
      if (BestPairVisibility(views, sources, scene.joint_names, g) < 8) continue;
      ++counts.present;
      double best = 1e9;
      for (int p = 0; p < persons.num_persons(); ++p) {
        best = std::min(best, MeanJointError(gt, g, scene.joint_names, persons, p, tri.output_joints(), 0.0));
      }
      if (best < 0.15) {
        ++counts.found;
        error_sum += best;
      }
    }
  }
  counts.mean_error_m = error_sum / std::max(counts.found, 1);
  return counts;
}

// The clean profile (Gaussian noise, 1 % outliers): every person is found, no phantom.
TEST(SyntheticRecovery, CleanDetectorFindsEveryPersonAndNoPhantom) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const RecoveryCounts c = MeasureRecovery(DetectorOptions::Clean(), seed);
    EXPECT_GT(c.false_positive_views, 50) << "the detector must actually produce false positives";
    EXPECT_GT(c.present, 400);
    EXPECT_EQ(c.found, c.present);
    EXPECT_EQ(c.phantoms, 0);
    EXPECT_LT(c.mean_error_m, 0.025) << "mean joint error (m)";
  }
}

// The realistic profile (fitted to real OpenPose: heavy tails, occluded joints reported at wrong
// places, stray joints, skeleton offsets, calibration error): at least 99 % of the persons are
// found and at most 1 % of the output persons are phantoms (the synthetic target);
// observed 597-599 of 599 found, 0-4 phantoms of about 600, 42-43 mm.
TEST(SyntheticRecovery, RealisticDetectorFinds99PercentAndAtMostOnePercentPhantoms) {
  for (uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const RecoveryCounts c = MeasureRecovery(DetectorOptions::Realistic(), seed);
    EXPECT_GT(c.false_positive_views, 50) << "the detector must actually produce false positives";
    EXPECT_GT(c.present, 400);
    EXPECT_GE(c.found, 0.99 * c.present);
    EXPECT_LE(c.phantoms, 0.01 * c.output);
    EXPECT_GT(c.mean_error_m, 0.03) << "the realistic errors are not applied";
    EXPECT_LT(c.mean_error_m, 0.05) << "mean joint error (m)";
  }
}

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// Randomised evaluation frames for the streaming tests: several GT persons and predictions per
// frame, invalid and NaN GT joints, missing predicted joints, duplicated predictions (ties in error
// and score), scores from a small set (ties), frames without GT (some without joint names), frames
// without predictions and predictions far away. Deterministic for a seed on every platform (own
// mapping from the 64-bit Mersenne Twister to numbers).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "tests/metrics/metrics_test_util.h"

namespace rpt::metrics::test {

struct RandomFrame {
  std::string id;
  Poses3D gt, pred;
  const JointNames* gt_names;
  const JointNames* pred_names;
  std::vector<double> scores;  // person scores, or empty
};

class RandomFrames {
 public:
  // Whole-body data carries the 133 COCO-WholeBody joints (face and hand groups), body data the 17
  // COCO body joints; the GT also has the two Shelf14 head joints (legacy PCP).
  RandomFrames(std::uint64_t seed, bool wholebody, bool person_scores)
      : rng_(seed), person_scores_(person_scores) {
    const JointNames& body = wholebody ? CocoWholeBodyJoints() : CocoBodyJoints();
    gt_names_ = body;
    gt_names_.push_back("head_bottom");
    gt_names_.push_back("head_top");
    pred_names_.assign(body.rbegin(), body.rend());
    template_ = wholebody ? WholeBodyTemplate() : CocoBodyTemplate();
  }

  RandomFrame Next() {
    RandomFrame frame;
    frame.id = "frame_" + std::to_string(index_++);
    const int num_joints = static_cast<int>(template_.cols());
    frame.gt.Clear(num_joints + 2);
    frame.pred.Clear(num_joints);
    frame.gt_names = &gt_names_;
    frame.pred_names = &pred_names_;
    const int num_gt = Chance(0.2) ? 0 : Int(1, 4);
    std::vector<Eigen::Matrix3Xd> gt_xyz;
    for (int g = 0; g < num_gt; ++g) {
      Eigen::Matrix3Xd xyz = Shifted(template_, {Uniform(-3, 3), Uniform(-3, 3), 0.0});
      gt_xyz.push_back(xyz);
      Eigen::Matrix4Xd person(4, num_joints + 2);
      person.topLeftCorner(3, num_joints) = xyz;
      const Eigen::Vector3d head = xyz.col(0);
      person.block<3, 1>(0, num_joints) = head - Eigen::Vector3d(0, 0, 0.15);
      person.block<3, 1>(0, num_joints + 1) = head + Eigen::Vector3d(0, 0, 0.1);
      const bool dropped = Chance(0.05);  // no valid joint at all
      for (int j = 0; j < num_joints + 2; ++j) {
        person(3, j) = dropped || Chance(0.1) ? 0.05 : 1.0;
        if (!Chance(0.03)) continue;
        // NaN joints; a hip's with an invalid score, else pelvis-aligned errors are all NaN and MPJPE +inf.
        person.block<3, 1>(0, j).setConstant(std::numeric_limits<double>::quiet_NaN());
        if (j == kHipLeft || j == kHipRight) person(3, j) = 0.05;
      }
      const int track_id = Int(-1, 4);
      frame.gt.AddPerson(track_id) = person;
    }
    // Predictions: most GT persons get one (some twice, identical), plus far and near false positives.
    std::vector<Eigen::Matrix4Xd> preds;
    for (int g = 0; g < num_gt; ++g) {
      if (!Chance(0.8)) continue;
      const double sigma = std::vector<double>{0.005, 0.03, 0.12, 0.4}[Int(0, 3)];
      const Eigen::Vector3d offset(Normal(sigma), Normal(sigma), Normal(sigma / 2));
      Eigen::Matrix4Xd person(4, num_joints);
      const double joint_score = JointScore();
      for (int j = 0; j < num_joints; ++j) {
        person.block<3, 1>(0, j) = gt_xyz[g].col(j) + offset + Eigen::Vector3d(Normal(0.02), Normal(0.02), Normal(0.02));
        person(3, j) = Chance(0.08) ? 0.0 : joint_score;
        if (Chance(0.01) && j != kHipLeft && j != kHipRight) {
          person.block<3, 1>(0, j).setConstant(std::numeric_limits<double>::quiet_NaN());
        }
      }
      preds.push_back(person);
      if (Chance(0.15)) preds.push_back(person);
    }
    const int num_far = Chance(0.3) ? Int(1, 2) : 0;
    for (int k = 0; k < num_far; ++k) {
      const bool far = Chance(0.5);
      const Eigen::Vector3d at(far ? 10.0 + Uniform(0, 5) : Uniform(-3, 3), Uniform(-3, 3), 0.0);
      Eigen::Matrix4Xd person(4, num_joints);
      person.topRows<3>() = Shifted(template_, at);
      person.row(3).setConstant(JointScore());
      preds.push_back(person);
    }
    for (size_t i = preds.size(); i > 1; --i) std::swap(preds[i - 1], preds[Int(0, static_cast<int>(i) - 1)]);
    for (const Eigen::Matrix4Xd& person : preds) {
      Eigen::Matrix4Xd reordered(4, num_joints);
      for (int j = 0; j < num_joints; ++j) reordered.col(num_joints - 1 - j) = person.col(j);
      frame.pred.AddPerson() = reordered;
      if (person_scores_) frame.scores.push_back(std::vector<double>{0.5, 0.7, 0.9}[Int(0, 2)]);
    }
    // Frames without GT may omit the GT joint names, frames without predictions the prediction's.
    if (num_gt == 0 && Chance(0.5)) {
      frame.gt_names = &empty_;
      frame.gt.Clear(0);
    }
    if (preds.empty() && Chance(0.5)) {
      frame.pred_names = &empty_;
      frame.pred.Clear(0);
    }
    return frame;
  }

 private:
  double Unit() { return static_cast<double>(rng_() >> 11) * 0x1.0p-53; }  // [0, 1)
  bool Chance(double p) { return Unit() < p; }
  double Uniform(double a, double b) { return a + (b - a) * Unit(); }
  int Int(int a, int b) { return a + static_cast<int>(rng_() % static_cast<std::uint64_t>(b - a + 1)); }
  double Normal(double sigma) {  // Box-Muller, one value per call
    const double u = 1.0 - Unit();
    return sigma * std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * Unit());
  }
  double JointScore() { return std::vector<double>{0.3, 0.6, 0.9}[Int(0, 2)]; }

  static constexpr int kHipLeft = 11, kHipRight = 12;  // CocoBodyJoints() order, also the whole-body's
  std::mt19937_64 rng_;
  bool person_scores_;
  int index_ = 0;
  JointNames gt_names_, pred_names_, empty_;
  Eigen::Matrix3Xd template_;
};

}  // namespace rpt::metrics::test

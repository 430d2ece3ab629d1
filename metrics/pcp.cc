// SPDX-License-Identifier: MIT
#include "metrics/pcp.h"

#include <cmath>
#include <limits>

#include "metrics/reducers/reducers.h"

namespace rpt::metrics {
namespace {

// Legacy parts as Shelf14 joint pairs; the torso (index 9) is handled separately.
constexpr std::array<std::array<int, 2>, 9> kLegacyLimbs = {
    {{0, 1}, {1, 2}, {3, 4}, {4, 5}, {6, 7}, {7, 8}, {9, 10}, {10, 11}, {12, 13}}};

// Parts of each reported group (VoxelPose bone_group).
const std::array<std::vector<int>, kNumLegacyGroups>& LegacyGroupParts() {
  static const std::array<std::vector<int>, kNumLegacyGroups> parts = {
      {{8}, {9}, {5, 6}, {4, 7}, {1, 2}, {0, 3}}};
  return parts;
}

// Endpoint of a generic part: mean of its two joints; valid iff both are.
bool Endpoint(const EvalPerson& person, const std::array<int, 2>& joints, Eigen::Vector3d* point) {
  if (!person.valid(joints[0]) || !person.valid(joints[1])) return false;
  *point = 0.5 * (person.xyz_mm.col(joints[0]) + person.xyz_mm.col(joints[1]));
  return true;
}

}  // namespace

bool IsPartCorrect(const Eigen::Vector3d& pred_a,
                   const Eigen::Vector3d& pred_b,
                   const Eigen::Vector3d& gt_a,
                   const Eigen::Vector3d& gt_b,
                   double alpha) {
  const double error = 0.5 * ((pred_a - gt_a).norm() + (pred_b - gt_b).norm());
  return error <= alpha * (gt_a - gt_b).norm();  // false for NaN
}

// ------------------------------------------------------------------------------------------------
// Generic PCP

const std::vector<PcpPartSpec>& GenericPcpParts() {
  static const std::vector<PcpPartSpec> parts = {
      {"upper_arm_left", {"shoulder_left", "shoulder_left"}, {"elbow_left", "elbow_left"}},
      {"upper_arm_right", {"shoulder_right", "shoulder_right"}, {"elbow_right", "elbow_right"}},
      {"lower_arm_left", {"elbow_left", "elbow_left"}, {"wrist_left", "wrist_left"}},
      {"lower_arm_right", {"elbow_right", "elbow_right"}, {"wrist_right", "wrist_right"}},
      {"upper_leg_left", {"hip_left", "hip_left"}, {"knee_left", "knee_left"}},
      {"upper_leg_right", {"hip_right", "hip_right"}, {"knee_right", "knee_right"}},
      {"lower_leg_left", {"knee_left", "knee_left"}, {"ankle_left", "ankle_left"}},
      {"lower_leg_right", {"knee_right", "knee_right"}, {"ankle_right", "ankle_right"}},
      {"torso", {"hip_left", "hip_right"}, {"shoulder_left", "shoulder_right"}},
      {"head", {"shoulder_left", "shoulder_right"}, {"nose", "nose"}},
  };
  return parts;
}

GenericPcpLayout MakeGenericPcpLayout(const JointNames& joint_names) {
  GenericPcpLayout layout;
  for (const PcpPartSpec& spec : GenericPcpParts()) {
    GenericPcpLayout::Part part;
    part.a = {FindJoint(joint_names, spec.a.joint_1), FindJoint(joint_names, spec.a.joint_2)};
    part.b = {FindJoint(joint_names, spec.b.joint_1), FindJoint(joint_names, spec.b.joint_2)};
    part.defined = part.a[0] >= 0 && part.a[1] >= 0 && part.b[0] >= 0 && part.b[1] >= 0;
    layout.parts.push_back(part);
  }
  return layout;
}

std::vector<PartOutcome> EvaluateGenericPcp(const GenericPcpLayout& layout,
                                            const EvalPerson& gt,
                                            const EvalPerson* pred,
                                            double alpha) {
  std::vector<PartOutcome> outcomes(layout.parts.size(), PartOutcome::kNotEvaluated);
  for (size_t k = 0; k < layout.parts.size(); ++k) {
    const GenericPcpLayout::Part& part = layout.parts[k];
    if (!part.defined) continue;
    Eigen::Vector3d gt_a, gt_b, pred_a, pred_b;
    if (!Endpoint(gt, part.a, &gt_a) || !Endpoint(gt, part.b, &gt_b)) continue;
    const bool predicted = pred != nullptr && Endpoint(*pred, part.a, &pred_a) && Endpoint(*pred, part.b, &pred_b);
    outcomes[k] = predicted && IsPartCorrect(pred_a, pred_b, gt_a, gt_b, alpha) ? PartOutcome::kCorrect
                                                                                : PartOutcome::kWrong;
  }
  return outcomes;
}

// ------------------------------------------------------------------------------------------------
// Legacy PCP

const JointNames& Shelf14Joints() {
  static const JointNames names = {"ankle_right",    "knee_right",    "hip_right",   "hip_left",   "knee_left",
                                   "ankle_left",     "wrist_right",   "elbow_right", "shoulder_right",
                                   "shoulder_left",  "elbow_left",    "wrist_left",  "head_bottom",
                                   "head_top"};
  return names;
}

const std::array<std::string, kNumLegacyGroups>& LegacyPcpGroupNames() {
  static const std::array<std::string, kNumLegacyGroups> names = {
      "Head", "Torso", "Upper arms", "Lower arms", "Upper legs", "Lower legs"};
  return names;
}

Shelf14 CocoToShelf14(const Coco17& c, LegacyPcpLayout layout) {
  constexpr std::array<int, 12> kCocoForShelf = {16, 14, 12, 11, 13, 15, 10, 8, 6, 5, 7, 9};
  Shelf14 shelf;
  for (int j = 0; j < 12; ++j) shelf.col(j) = c.col(kCocoForShelf[j]);

  const Eigen::Vector3d mid_sho = 0.5 * (c.col(5) + c.col(6));
  const Eigen::Vector3d head_center = 0.5 * (c.col(3) + c.col(4));  // mid-ears
  const Eigen::Vector3d head_bottom = 0.5 * (mid_sho + head_center);
  const Eigen::Vector3d head_top = head_bottom + 2.0 * (head_center - head_bottom);
  if (layout == LegacyPcpLayout::kCampus) {
    shelf.col(12) = head_bottom;
    shelf.col(13) = head_top;
    return shelf;
  }
  // Shelf: start from mid-shoulder and nose, stretch the nose direction 1.5x upwards (z) and 0.75x
  // horizontally, then blend 75 % / 25 % with the ear-based estimate (VoxelPose coco2shelf3D).
  const Eigen::Vector3d nose = c.col(0);
  const Eigen::Vector3d top = mid_sho + (nose - mid_sho).cwiseProduct(Eigen::Vector3d(0.75, 0.75, 1.5));
  const Eigen::Vector3d bottom = mid_sho + 0.5 * (nose - mid_sho);
  constexpr double kAlpha = 0.75;
  shelf.col(13) = kAlpha * top + (1.0 - kAlpha) * head_top;
  shelf.col(12) = kAlpha * bottom + (1.0 - kAlpha) * head_bottom;
  return shelf;
}

LegacyPcpEvaluator::LegacyPcpEvaluator(const EvalOptions& options) : options_(options) {}

void LegacyPcpEvaluator::AddFrame(std::span<const LegacyActor> gt, std::span<const Shelf14> preds) {
  ++num_frames_;
  if (preds.empty() && options_.legacy_pcp_skip_empty_frames) {
    ++num_skipped_frames_;
    return;
  }
  const double alpha = options_.legacy_pcp_alpha;
  for (const LegacyActor& actor : gt) {
    ActorCounts& counts = actors_[actor.actor_id];
    ++counts.num_frames;
    ++num_actor_frames_;
    if (preds.empty()) continue;  // all 10 parts wrong (mvpose behaviour)

    // Nearest prediction: smallest mean joint error over the 14 joints (missing joints: +inf).
    int best = 0;
    double best_error = std::numeric_limits<double>::infinity();
    for (size_t p = 0; p < preds.size(); ++p) {
      double sum = 0.0;
      for (int j = 0; j < 14; ++j) {
        const double e = (preds[p].col(j) - actor.joints_mm.col(j)).norm();
        sum += std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
      }
      if (sum / 14.0 < best_error) {
        best_error = sum / 14.0;
        best = static_cast<int>(p);
      }
    }
    if (best_error < 500.0) ++num_recalled_;

    const Shelf14& pred = preds[best];
    const Shelf14& g = actor.joints_mm;
    for (size_t k = 0; k < kLegacyLimbs.size(); ++k) {
      const auto [a, b] = kLegacyLimbs[k];
      if (IsPartCorrect(pred.col(a), pred.col(b), g.col(a), g.col(b), alpha)) ++counts.correct[k];
    }
    const Eigen::Vector3d pred_hip = 0.5 * (pred.col(2) + pred.col(3));
    const Eigen::Vector3d gt_hip = 0.5 * (g.col(2) + g.col(3));
    if (IsPartCorrect(pred_hip, pred.col(12), gt_hip, g.col(12), alpha)) ++counts.correct[9];
  }
}

void LegacyPcpEvaluator::Merge(const LegacyPcpEvaluator& other) {
  for (const auto& [actor_id, counts] : other.actors_) {
    ActorCounts& mine = actors_[actor_id];
    mine.num_frames += counts.num_frames;
    for (int k = 0; k < kNumLegacyParts; ++k) mine.correct[k] += counts.correct[k];
  }
  num_frames_ += other.num_frames_;
  num_skipped_frames_ += other.num_skipped_frames_;
  num_actor_frames_ += other.num_actor_frames_;
  num_recalled_ += other.num_recalled_;
}

LegacyPcpResult LegacyPcpEvaluator::Finalize() const {
  LegacyPcpResult result;
  result.num_frames = num_frames_;
  result.num_skipped_frames = num_skipped_frames_;
  result.recall_500 = Percent(num_recalled_, num_actor_frames_);

  int num_averaged = 0;
  for (const auto& [actor_id, counts] : actors_) {
    LegacyPcpResult::Actor actor;
    actor.actor_id = actor_id;
    actor.num_frames = counts.num_frames;
    int correct = 0;
    for (const int c : counts.correct) correct += c;
    actor.pcp = Percent(correct, kNumLegacyParts * counts.num_frames);
    for (int group = 0; group < kNumLegacyGroups; ++group) {
      int group_correct = 0;
      for (const int part : LegacyGroupParts()[group]) group_correct += counts.correct[part];
      actor.group_pcp[group] =
          Percent(group_correct, static_cast<double>(counts.num_frames) * LegacyGroupParts()[group].size());
    }
    if (actor_id >= 0 && actor_id < options_.legacy_pcp_actors && counts.num_frames > 0) {
      actor.averaged = true;
      ++num_averaged;
      result.average_pcp += actor.pcp;
      for (int group = 0; group < kNumLegacyGroups; ++group) result.average_group_pcp[group] += actor.group_pcp[group];
    }
    result.actors.push_back(actor);
  }
  if (num_averaged > 0) {
    result.average_pcp /= num_averaged;
    for (double& value : result.average_group_pcp) value /= num_averaged;
  } else {
    result.average_pcp = std::numeric_limits<double>::quiet_NaN();
    result.average_group_pcp.fill(std::numeric_limits<double>::quiet_NaN());
  }
  return result;
}

}  // namespace rpt::metrics

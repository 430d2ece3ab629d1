// SPDX-License-Identifier: MIT
#include "metrics/accumulator.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/options_check.h"
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void CheckPoses(const Poses3D& poses, const JointNames& names, std::string_view what, std::string_view frame_id) {
  const size_t expected = static_cast<size_t>(poses.num_persons()) * poses.num_joints * 4;
  if (poses.num_joints < 0 || poses.data.size() != expected) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::string(what) +
                     " poses hold " + std::to_string(poses.data.size()) + " values, expected " +
                     std::to_string(expected));
  }
  if (poses.num_persons() > 0 && static_cast<size_t>(poses.num_joints) != names.size()) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::string(what) + " poses have " +
                     std::to_string(poses.num_joints) + " joints but " + std::to_string(names.size()) +
                     " joint names");
  }
}

// Millimetre position of joint `j` of a person, or NaN when absent / below the score threshold.
Eigen::Vector3d JointMmOrNaN(const Poses3D& poses, int person_idx, int j, double min_score) {
  if (j < 0) return Eigen::Vector3d::Constant(kNaN);
  const auto joints = poses.Person(person_idx);
  if (joints(3, j) <= min_score) return Eigen::Vector3d::Constant(kNaN);
  return 1000.0 * joints.col(j).head<3>();
}

}  // namespace

const std::vector<WholeBodyGroup>& WholeBodyGroups() {
  static const std::vector<WholeBodyGroup> groups = {
      {"All", 0, 132}, {"Body", 0, 22}, {"Face", 23, 90}, {"Hands", 91, 132}};
  return groups;
}

MetricsAccumulator::MetricsAccumulator(const EvalOptions& options) : options_(options) {
  ThrowIfInvalid(options_);
  evaluated_ = options_.EvaluatedJoints();
  pcp_layout_ = MakeGenericPcpLayout(evaluated_);
  records_.evaluated = evaluated_;
  records_.gt_valid_per_joint.assign(evaluated_.size(), 0);
  records_.pcp_total.assign(pcp_layout_.parts.size(), 0);
  records_.pcp_correct_nearest.assign(pcp_layout_.parts.size(), 0);
  records_.group_num_joints.assign(WholeBodyGroups().size(), 0);
  if (options_.legacy_pcp != LegacyPcpLayout::kNone) records_.legacy.emplace(options_);
}

void MetricsAccumulator::UpdateLayout(const JointNames& gt_names, const JointNames& pred_names) {
  if (layout_valid_ && gt_names == layout_.gt_names && pred_names == layout_.pred_names) return;
  Layout layout;
  layout.gt_names = gt_names;
  layout.pred_names = pred_names;
  // Joint lists are checked whenever given, so a misconfiguration fails on the first frame.
  layout.gt_eval = gt_names.empty() ? std::vector<int>(evaluated_.size(), -1)
                                    : MapJointNames(evaluated_, gt_names, "ground-truth");
  layout.pred_eval = pred_names.empty() ? std::vector<int>(evaluated_.size(), -1)
                                        : MapJointNames(evaluated_, pred_names, "prediction");

  if (options_.alignment == Alignment::kPelvis) {
    const JointNames hips = {"hip_left", "hip_right"};
    if (!gt_names.empty()) {
      const std::vector<int> idx = MapJointNames(hips, gt_names, "ground-truth (pelvis alignment)");
      layout.gt_hip_left = idx[0];
      layout.gt_hip_right = idx[1];
    }
    if (!pred_names.empty()) {
      const std::vector<int> idx = MapJointNames(hips, pred_names, "prediction (pelvis alignment)");
      layout.pred_hip_left = idx[0];
      layout.pred_hip_right = idx[1];
    }
  }

  if (options_.wholebody_groups) {
    // Group joints by COCO-WholeBody index, resolved by name; only joints present in both lists.
    const JointNames& wholebody = CocoWholeBodyJoints();
    for (size_t k = 0; k < WholeBodyGroups().size(); ++k) {
      const WholeBodyGroup& group = WholeBodyGroups()[k];
      std::vector<int> gt_idx, pred_idx;
      for (int i = group.first_index; i <= group.last_index; ++i) {
        const int g = FindJoint(gt_names, wholebody[i]);
        const int p = FindJoint(pred_names, wholebody[i]);
        if (g < 0 || p < 0) continue;
        gt_idx.push_back(g);
        pred_idx.push_back(p);
      }
      layout.gt_group.push_back(std::move(gt_idx));
      layout.pred_group.push_back(std::move(pred_idx));
    }
  }

  if (records_.legacy) {
    const JointNames& shelf = options_.legacy_pcp_gt_joints.empty() ? Shelf14Joints() : options_.legacy_pcp_gt_joints;
    if (!gt_names.empty()) layout.gt_legacy = MapJointNames(shelf, gt_names, "ground-truth (legacy PCP, Shelf14)");
    if (!pred_names.empty()) {
      layout.pred_legacy = MapJointNames(CocoBodyJoints(), pred_names, "prediction (legacy PCP, COCO-17)");
    }
  }

  layout_ = std::move(layout);
  layout_valid_ = true;
  // Only report group sizes for lists that actually carry persons' joints.
  if (options_.wholebody_groups && !gt_names.empty() && !pred_names.empty()) {
    for (size_t k = 0; k < WholeBodyGroups().size(); ++k) {
      records_.group_num_joints[k] = static_cast<int>(layout_.gt_group[k].size());
    }
  }
}

PairRecord MetricsAccumulator::MakePair(const Poses3D& gt,
                                                            int gt_idx,
                                                            const EvalPerson& gt_person,
                                                            const Poses3D& predictions,
                                                            int pred_idx,
                                                            const EvalPerson& pred_person,
                                                            double error_mm,
                                                            double score) const {
  PairRecord record;
  record.match = MatchRecord{-1, error_mm, score};
  record.joint_errors = JointErrors(gt_person, pred_person);

  // Offsets subtracted before the reported errors: zero, or each person's own pelvis.
  Eigen::Vector3d gt_offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d pred_offset = Eigen::Vector3d::Zero();
  bool aligned = true;
  if (options_.alignment == Alignment::kPelvis) {
    const auto gt_pelvis =
        PelvisMm(gt, gt_idx, layout_.gt_hip_left, layout_.gt_hip_right, options_.min_gt_score);
    const auto pred_pelvis =
        PelvisMm(predictions, pred_idx, layout_.pred_hip_left, layout_.pred_hip_right, options_.min_pred_score);
    aligned = gt_pelvis.has_value() && pred_pelvis.has_value();
    if (aligned) {
      gt_offset = *gt_pelvis;
      pred_offset = *pred_pelvis;
    }
  }
  if (!aligned) {
    record.report_error_mm = kNaN;
    record.report_joint_errors = Eigen::ArrayXd::Constant(record.joint_errors.size(), kNaN);
  } else if (options_.alignment == Alignment::kNone) {
    record.report_error_mm = error_mm;
    record.report_joint_errors = record.joint_errors;
  } else {
    record.report_joint_errors = JointErrors(gt_person, pred_person, gt_offset, pred_offset);
    record.report_error_mm = MeanFiniteError(record.report_joint_errors);
  }

  if (options_.wholebody_groups) {
    for (size_t k = 0; k < layout_.gt_group.size(); ++k) {
      double sum = 0.0;
      int count = 0;
      if (aligned) {
        for (size_t i = 0; i < layout_.gt_group[k].size(); ++i) {
          const Eigen::Vector3d g = JointMmOrNaN(gt, gt_idx, layout_.gt_group[k][i], options_.min_gt_score);
          const Eigen::Vector3d p =
              JointMmOrNaN(predictions, pred_idx, layout_.pred_group[k][i], options_.min_pred_score);
          if (g.hasNaN() || p.hasNaN()) continue;  // GT-invalid or not predicted
          sum += ((p - pred_offset) - (g - gt_offset)).norm();
          ++count;
        }
      }
      record.group_errors.push_back(count > 0 ? sum / count : kNaN);
    }
  }
  record.pcp = EvaluateGenericPcp(pcp_layout_, gt_person, &pred_person, options_.pcp_alpha);
  return record;
}

void MetricsAccumulator::AddLegacyFrame(const Poses3D& gt, const Poses3D& predictions) {
  std::vector<LegacyActor> actors;
  for (int g = 0; g < gt.num_persons(); ++g) {
    LegacyActor actor;
    // The actor id is the GT track id (actorsGT.mat actor index); untracked GT falls back to the order.
    actor.actor_id = gt.track_ids[g] >= 0 ? gt.track_ids[g] : g;
    // Shelf/Campus GT is complete: scores are ignored, as in VoxelPose.
    const auto joints = gt.Person(g);
    for (int j = 0; j < 14; ++j) actor.joints_mm.col(j) = 1000.0 * joints.col(layout_.gt_legacy[j]).head<3>();
    actors.push_back(actor);
  }
  std::vector<Shelf14> preds;
  for (int p = 0; p < predictions.num_persons(); ++p) {
    Coco17 coco;
    for (int j = 0; j < 17; ++j) {
      coco.col(j) = JointMmOrNaN(predictions, p, layout_.pred_legacy[j], options_.min_pred_score);
    }
    preds.push_back(CocoToShelf14(coco, options_.legacy_pcp));
  }
  records_.legacy->AddFrame(actors, preds);
}

void MetricsAccumulator::Add(std::string_view frame_id,
                             const Poses3D& gt,
                             const JointNames& gt_names,
                             const Poses3D& predictions,
                             const JointNames& pred_names,
                             std::span<const double> pred_scores) {
  CheckPoses(gt, gt_names, "ground-truth", frame_id);
  CheckPoses(predictions, pred_names, "prediction", frame_id);
  if (!pred_scores.empty() && pred_scores.size() != static_cast<size_t>(predictions.num_persons())) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::to_string(pred_scores.size()) +
                     " person scores for " + std::to_string(predictions.num_persons()) + " predictions");
  }
  if (!frame_ids_.insert(std::string(frame_id)).second) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "' was added twice");
  }
  UpdateLayout(gt_names, pred_names);
  ++records_.num_frames;

  // Kept GT persons: at least one valid evaluated joint.
  std::vector<EvalPerson> gt_persons;
  std::vector<int> gt_source;  // index in `gt` of each kept person
  for (int g = 0; g < gt.num_persons(); ++g) {
    EvalPerson person = ExtractPerson(gt, g, layout_.gt_eval, options_.min_gt_score);
    if (!person.valid.any()) {
      ++records_.num_dropped_gt;
      continue;
    }
    for (Eigen::Index j = 0; j < person.valid.size(); ++j) records_.gt_valid_per_joint[j] += person.valid(j) ? 1 : 0;
    gt_persons.push_back(std::move(person));
    gt_source.push_back(g);
  }
  std::vector<EvalPerson> pred_persons;
  std::vector<double> scores;
  for (int p = 0; p < predictions.num_persons(); ++p) {
    pred_persons.push_back(ExtractPerson(predictions, p, layout_.pred_eval, options_.min_pred_score));
    scores.push_back(pred_scores.empty() ? pred_persons.back().mean_score : pred_scores[p]);
  }

  const int num_gt = static_cast<int>(gt_persons.size());
  const int num_pred = static_cast<int>(pred_persons.size());
  const int gt_id_base = records_.num_gt;
  records_.num_gt += num_gt;
  if (num_gt > 0) ++records_.num_frames_with_gt;
  const bool counted = num_gt > 0 || options_.count_preds_without_gt;
  records_.num_pred_total += num_pred;
  if (counted) records_.num_pred_counted += num_pred;

  Eigen::MatrixXd cost(num_pred, num_gt);
  for (int p = 0; p < num_pred; ++p) {
    for (int g = 0; g < num_gt; ++g) cost(p, g) = PersonMpjpe(gt_persons[g], pred_persons[p]);
  }

  // Candidate pairs of this frame; (pred, gt) -> index in records_.pairs.
  std::vector<PairRecord>& pairs = records_.pairs;
  const size_t first_record = pairs.size();
  auto find_or_add = [&](int p, int g) -> PairRecord& {
    for (size_t r = first_record; r < pairs.size(); ++r) {
      if (pairs[r].pred_idx == p && pairs[r].gt_idx == g) return pairs[r];
    }
    PairRecord record;
    if (g >= 0) {
      record = MakePair(gt, gt_source[g], gt_persons[g], predictions, p, pred_persons[p], cost(p, g), scores[p]);
      record.match.gt_id = gt_id_base + g;
    } else {
      record.match = MatchRecord{-1, kInf, scores[p]};
    }
    record.pred_idx = p;
    record.gt_idx = g;
    record.counted = counted;
    pairs.push_back(std::move(record));
    return pairs.back();
  };

  const std::vector<int> nearest = NearestGt(cost);
  for (int p = 0; p < num_pred; ++p) find_or_add(p, nearest[p]).flags |= kNearest;

  if (options_.matching == MatchingMode::kHungarian) {
    const std::pair<double, std::uint8_t> gates[] = {
        {options_.match_threshold_mm, kHungarianMatch}, {100.0, kHungarian100}, {500.0, kHungarian500}};
    for (const auto& [gate, flag] : gates) {
      const std::vector<int> assignment = HungarianMatch(cost, gate);
      for (int p = 0; p < num_pred; ++p) {
        if (assignment[p] >= 0) find_or_add(p, assignment[p]).flags |= flag;
      }
    }
  }

  // Generic PCP against the nearest prediction of each GT person (no gate; misses are all wrong).
  const std::vector<int> nearest_pred = NearestPrediction(cost);
  for (int g = 0; g < num_gt; ++g) {
    const EvalPerson* pred = nearest_pred[g] >= 0 ? &pred_persons[nearest_pred[g]] : nullptr;
    const std::vector<PartOutcome> outcomes = EvaluateGenericPcp(pcp_layout_, gt_persons[g], pred, options_.pcp_alpha);
    for (size_t k = 0; k < outcomes.size(); ++k) {
      if (outcomes[k] == PartOutcome::kNotEvaluated) continue;
      ++records_.pcp_total[k];
      if (outcomes[k] == PartOutcome::kCorrect) ++records_.pcp_correct_nearest[k];
    }
  }

  if (records_.legacy) AddLegacyFrame(gt, predictions);
}

MetricsResult MetricsAccumulator::Finalize() const {
  MetricsResult result;
  const MatchSets matches = SelectMatches(records_, options_);
  for (const MetricReducer reduce : MetricReducers()) reduce(records_, matches, options_, &result);
  return result;
}

}  // namespace rpt::metrics

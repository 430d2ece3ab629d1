// SPDX-License-Identifier: MIT
#include "metrics/accumulator.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/options_check.h"
#include "metrics/matching.h"

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

MetricsAccumulator::MetricsAccumulator(const EvalOptions& options)
    : options_((ThrowIfInvalid(options), options)), totals_(options_) {
  evaluated_ = options_.EvaluatedJoints();
  pcp_layout_ = MakeGenericPcpLayout(evaluated_);
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

  if (options_.legacy_pcp != LegacyPcpLayout::kNone) {
    const JointNames& shelf = options_.legacy_pcp_gt_joints.empty() ? Shelf14Joints() : options_.legacy_pcp_gt_joints;
    if (!gt_names.empty()) layout.gt_legacy = MapJointNames(shelf, gt_names, "ground-truth (legacy PCP, Shelf14)");
    if (!pred_names.empty()) {
      layout.pred_legacy = MapJointNames(CocoBodyJoints(), pred_names, "prediction (legacy PCP, COCO-17)");
    }
  }

  layout_ = std::move(layout);
  layout_valid_ = true;
  // Only report group sizes for lists that actually carry persons' joints.
  group_num_joints_.clear();
  group_gt_only_joints_.clear();
  if (options_.wholebody_groups && !gt_names.empty() && !pred_names.empty()) {
    for (const std::vector<int>& group : layout_.gt_group) group_num_joints_.push_back(static_cast<int>(group.size()));
    for (const WholeBodyGroup& group : WholeBodyGroups()) {
      int gt_only = 0;
      for (int i = group.first_index; i <= group.last_index; ++i) {
        const std::string& name = CocoWholeBodyJoints()[static_cast<size_t>(i)];
        gt_only += FindJoint(gt_names, name) >= 0 && FindJoint(pred_names, name) < 0 ? 1 : 0;
      }
      group_gt_only_joints_.push_back(gt_only);
    }
  }
}

PairRecord MetricsAccumulator::MakePair(const Poses3D& gt, int gt_idx, const EvalPerson& gt_person,
                                        const Poses3D& predictions, int pred_idx, const EvalPerson& pred_person,
                                        double error_mm, double score) const {
  PairRecord record;
  record.error_mm = error_mm;
  record.score = score;
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
      int count = 0, filled = 0;
      if (aligned) {
        for (size_t i = 0; i < layout_.gt_group[k].size(); ++i) {
          const Eigen::Vector3d g = JointMmOrNaN(gt, gt_idx, layout_.gt_group[k][i], options_.min_gt_score);
          const Eigen::Vector3d p =
              JointMmOrNaN(predictions, pred_idx, layout_.pred_group[k][i], options_.min_pred_score);
          if (g.hasNaN() || p.hasNaN()) continue;  // GT-invalid or not predicted
          sum += ((p - pred_offset) - (g - gt_offset)).norm();
          ++count;
          filled += predictions.Provenance(pred_idx, layout_.pred_group[k][i]) == JointProvenance::kFilled ? 1 : 0;
        }
      }
      record.group_errors.push_back(count > 0 ? sum / count : kNaN);
      record.group_joints.push_back(count);
      record.group_filled.push_back(filled);
    }
  }
  record.pcp = EvaluateGenericPcp(pcp_layout_, gt_person, &pred_person, options_.pcp_alpha);
  return record;
}

void MetricsAccumulator::CollectLegacyInputs(const Poses3D& gt, const Poses3D& predictions) {
  for (int g = 0; g < gt.num_persons(); ++g) {
    LegacyActor actor;
    // The actor id is the GT track id (actorsGT.mat actor index); untracked GT falls back to the order.
    actor.actor_id = gt.track_ids[g] >= 0 ? gt.track_ids[g] : g;
    // Shelf/Campus GT is complete: scores are ignored, as in VoxelPose.
    const auto joints = gt.Person(g);
    for (int j = 0; j < 14; ++j) actor.joints_mm.col(j) = 1000.0 * joints.col(layout_.gt_legacy[j]).head<3>();
    frame_.legacy_actors.push_back(actor);
  }
  for (int p = 0; p < predictions.num_persons(); ++p) {
    Coco17 coco;
    for (int j = 0; j < 17; ++j) {
      coco.col(j) = JointMmOrNaN(predictions, p, layout_.pred_legacy[j], options_.min_pred_score);
    }
    frame_.legacy_predictions.push_back(CocoToShelf14(coco, options_.legacy_pcp));
  }
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
  if (!frame_ids_.Insert(frame_id)) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "' was added twice");
  }
  UpdateLayout(gt_names, pred_names);

  FrameRecords& frame = frame_;
  frame.kept_gt_idx.clear();
  frame.gt.clear();
  frame.num_dropped_gt = 0;
  frame.pairs.clear();
  frame.pcp_nearest.clear();
  frame.group_num_joints = group_num_joints_;
  frame.group_gt_only_joints = group_gt_only_joints_;
  frame.legacy_actors.clear();
  frame.legacy_predictions.clear();

  // Kept GT persons: at least one valid evaluated joint.
  for (int g = 0; g < gt.num_persons(); ++g) {
    EvalPerson person = ExtractPerson(gt, g, layout_.gt_eval, options_.min_gt_score);
    if (!person.valid.any()) {
      ++frame.num_dropped_gt;
      continue;
    }
    frame.gt.push_back(std::move(person));
    frame.kept_gt_idx.push_back(g);
  }
  std::vector<EvalPerson> pred_persons;
  std::vector<double> scores;
  for (int p = 0; p < predictions.num_persons(); ++p) {
    pred_persons.push_back(ExtractPerson(predictions, p, layout_.pred_eval, options_.min_pred_score));
    scores.push_back(pred_scores.empty() ? pred_persons.back().mean_score : pred_scores[p]);
  }

  const int num_gt = static_cast<int>(frame.gt.size());
  const int num_pred = static_cast<int>(pred_persons.size());
  frame.num_predictions = num_pred;
  frame.counted = num_gt > 0 || options_.count_preds_without_gt;

  Eigen::MatrixXd cost(num_pred, num_gt);
  for (int p = 0; p < num_pred; ++p) {
    for (int g = 0; g < num_gt; ++g) cost(p, g) = PersonMpjpe(frame.gt[g], pred_persons[p]);
  }

  // Candidate pairs of this frame: first each prediction's nearest GT, then the Hungarian pairs.
  std::vector<PairRecord>& pairs = frame.pairs;
  auto find_or_add = [&](int p, int g) -> PairRecord& {
    for (PairRecord& pair : pairs) {
      if (pair.pred_idx == p && pair.gt_idx == g) return pair;
    }
    PairRecord record;
    if (g >= 0) {
      record = MakePair(gt, frame.kept_gt_idx[g], frame.gt[g], predictions, p, pred_persons[p], cost(p, g), scores[p]);
    } else {
      record.error_mm = kInf;
      record.score = scores[p];
    }
    record.pred_idx = p;
    record.gt_idx = g;
    pairs.push_back(std::move(record));
    return pairs.back();
  };

  const std::vector<int> nearest = NearestGt(cost);
  for (int p = 0; p < num_pred; ++p) find_or_add(p, nearest[p]).flags |= kNearest;

  const std::pair<double, std::uint8_t> gates[] = {
      {options_.match_threshold_mm, kMatch}, {100.0, kMatch100}, {500.0, kMatch500}};
  if (options_.matching == MatchingMode::kHungarian) {
    for (const auto& [gate, flag] : gates) {
      const std::vector<int> assignment = HungarianMatch(cost, gate);
      for (int p = 0; p < num_pred; ++p) {
        if (assignment[p] >= 0) find_or_add(p, assignment[p]).flags |= flag;
      }
    }
  } else {
    // Greedy matching of the frame's nearest-GT pairs (pairs[p] for prediction p): the frame's part
    // of the greedy matching over the whole run (eval_records.h).
    const std::vector<MatchRecord> nearest_records = NearestMatchRecords(frame);
    for (const auto& [gate, flag] : gates) {
      const std::vector<bool> is_match = GreedyMatch(nearest_records, gate);
      for (int p = 0; p < num_pred; ++p) {
        if (is_match[p]) pairs[p].flags |= flag;
      }
    }
  }

  // Generic PCP against the nearest prediction of each GT person (no gate; misses are all wrong).
  const std::vector<int> nearest_pred = NearestPrediction(cost);
  for (int g = 0; g < num_gt; ++g) {
    const EvalPerson* pred = nearest_pred[g] >= 0 ? &pred_persons[nearest_pred[g]] : nullptr;
    frame.pcp_nearest.push_back(EvaluateGenericPcp(pcp_layout_, frame.gt[g], pred, options_.pcp_alpha));
  }

  if (options_.legacy_pcp != LegacyPcpLayout::kNone) CollectLegacyInputs(gt, predictions);
  totals_.Fold(frame);
}

void MetricsAccumulator::Merge(const MetricsAccumulator& other) {
  const std::string different = FirstDifferentOption(options_, other.options_);
  if (!different.empty()) {
    throw ConfigError("metrics: cannot merge accumulators whose option '" + different + "' differs");
  }
  const long shared = frame_ids_.CountShared(other.frame_ids_);
  if (shared > 0) {
    throw InputError("metrics: cannot merge accumulators: " + std::to_string(shared) +
                     " frame id(s) were added to both");
  }
  frame_ids_.Merge(other.frame_ids_);
  totals_.Merge(other.totals_);
}

MetricsResult MetricsAccumulator::Finalize() const {
  MetricsResult result;
  for (const MetricReducer reduce : MetricReducers()) reduce(totals_, options_, &result);
  return result;
}

}  // namespace rpt::metrics

// SPDX-License-Identifier: MIT
#include "metrics/accumulator.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/errors.h"
#include "metrics/average_precision.h"

namespace rpt::metrics {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double Percent(double numerator, double denominator) {
  return denominator > 0 ? 100.0 * numerator / denominator : kNaN;
}

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
  options_.Check();
  evaluated_ = options_.EvaluatedJoints();
  pcp_layout_ = MakeGenericPcpLayout(evaluated_);
  gt_valid_per_joint_.assign(evaluated_.size(), 0);
  pcp_total_.assign(pcp_layout_.parts.size(), 0);
  pcp_correct_nearest_.assign(pcp_layout_.parts.size(), 0);
  group_num_joints_.assign(WholeBodyGroups().size(), 0);
  if (options_.legacy_pcp != LegacyPcpLayout::kNone) legacy_.emplace(options_);
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

  if (legacy_) {
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
      group_num_joints_[k] = static_cast<int>(layout_.gt_group[k].size());
    }
  }
}

MetricsAccumulator::PairRecord MetricsAccumulator::MakePair(const Poses3D& gt,
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
  legacy_->AddFrame(actors, preds);
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
  ++num_frames_;

  // Kept GT persons: at least one valid evaluated joint.
  std::vector<EvalPerson> gt_persons;
  std::vector<int> gt_source;  // index in `gt` of each kept person
  for (int g = 0; g < gt.num_persons(); ++g) {
    EvalPerson person = ExtractPerson(gt, g, layout_.gt_eval, options_.min_gt_score);
    if (!person.valid.any()) {
      ++num_dropped_gt_;
      continue;
    }
    for (Eigen::Index j = 0; j < person.valid.size(); ++j) gt_valid_per_joint_[j] += person.valid(j) ? 1 : 0;
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
  const int gt_id_base = num_gt_;
  num_gt_ += num_gt;
  if (num_gt > 0) ++num_frames_with_gt_;
  const bool counted = num_gt > 0 || options_.count_preds_without_gt;
  num_pred_total_ += num_pred;
  if (counted) num_pred_counted_ += num_pred;

  Eigen::MatrixXd cost(num_pred, num_gt);
  for (int p = 0; p < num_pred; ++p) {
    for (int g = 0; g < num_gt; ++g) cost(p, g) = PersonMpjpe(gt_persons[g], pred_persons[p]);
  }

  // Candidate pairs of this frame; (pred, gt) -> index in records_.
  const size_t first_record = records_.size();
  auto find_or_add = [&](int p, int g) -> PairRecord& {
    for (size_t r = first_record; r < records_.size(); ++r) {
      if (records_[r].pred_idx == p && records_[r].gt_idx == g) return records_[r];
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
    records_.push_back(std::move(record));
    return records_.back();
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
      ++pcp_total_[k];
      if (outcomes[k] == PartOutcome::kCorrect) ++pcp_correct_nearest_[k];
    }
  }

  if (legacy_) AddLegacyFrame(gt, predictions);
}

MetricsResult MetricsAccumulator::Finalize() const {
  MetricsResult result;
  result.num_frames = num_frames_;
  result.num_frames_with_gt = num_frames_with_gt_;
  result.num_gt_persons = num_gt_;
  result.num_dropped_gt_persons = num_dropped_gt_;
  result.num_predictions = num_pred_counted_;
  result.num_predictions_total = num_pred_total_;

  // The nearest-GT records drive greedy matching and AP.
  std::vector<size_t> nearest_idx;
  std::vector<MatchRecord> nearest_records;
  std::vector<MatchRecord> ap_records;
  for (size_t r = 0; r < records_.size(); ++r) {
    if (!(records_[r].flags & kNearest)) continue;
    nearest_idx.push_back(r);
    nearest_records.push_back(records_[r].match);
    if (records_[r].counted) ap_records.push_back(records_[r].match);
  }

  // Match sets: at the gate, at 100 mm and at 500 mm.
  std::vector<bool> in_match(records_.size(), false), in_100(records_.size(), false),
      in_500(records_.size(), false);
  if (options_.matching == MatchingMode::kGreedy) {
    const std::pair<double, std::vector<bool>*> sets[] = {
        {options_.match_threshold_mm, &in_match}, {100.0, &in_100}, {500.0, &in_500}};
    for (const auto& [threshold, set] : sets) {
      const std::vector<bool> is_tp = GreedyMatch(nearest_records, threshold);
      for (size_t i = 0; i < is_tp.size(); ++i) (*set)[nearest_idx[i]] = is_tp[i];
    }
  } else {
    for (size_t r = 0; r < records_.size(); ++r) {
      in_match[r] = records_[r].flags & kHungarianMatch;
      in_100[r] = records_[r].flags & kHungarian100;
      in_500[r] = records_[r].flags & kHungarian500;
    }
  }

  int tp = 0, tp_100 = 0, tp_500 = 0;
  for (size_t r = 0; r < records_.size(); ++r) {
    tp += in_match[r] ? 1 : 0;
    tp_100 += in_100[r] ? 1 : 0;
    tp_500 += in_500[r] ? 1 : 0;
  }
  const int fp = num_pred_counted_ - tp;
  const int fn = num_gt_ - tp;
  result.num_matches = tp;
  result.recall_100 = Percent(tp_100, num_gt_);
  result.recall_500 = Percent(tp_500, num_gt_);
  result.invalid = Percent(fp, num_pred_counted_);
  result.f1 = Percent(2.0 * tp, 2.0 * tp + fp + fn);

  // Joint- and person-level errors over the matched pairs.
  const size_t num_joints = evaluated_.size();
  std::vector<double> joint_error_sum(num_joints, 0.0);
  std::vector<int> joint_error_count(num_joints, 0), joint_hits_100(num_joints, 0), joint_matched_gt(num_joints, 0);
  int hits_100 = 0, hits_500 = 0, matched_valid = 0;
  double mpjpe_sum = 0.0;
  int mpjpe_count = 0;
  std::vector<double> group_sum(WholeBodyGroups().size(), 0.0);
  std::vector<int> group_count(WholeBodyGroups().size(), 0);
  std::vector<int> pcp_correct_matched(pcp_layout_.parts.size(), 0);
  for (size_t r = 0; r < records_.size(); ++r) {
    if (!in_match[r]) continue;
    const PairRecord& record = records_[r];
    if (std::isnan(record.report_error_mm)) {
      ++result.num_unaligned_matches;
    } else {
      mpjpe_sum += record.report_error_mm;
      ++mpjpe_count;
    }
    for (size_t j = 0; j < num_joints; ++j) {
      const double e = record.joint_errors(j);
      if (std::isnan(e)) continue;  // GT-invalid
      ++matched_valid;
      ++joint_matched_gt[j];
      if (std::isinf(e)) ++result.num_missing_pred_joints;
      if (e < 100.0) {
        ++hits_100;
        ++joint_hits_100[j];
      }
      if (e < 500.0) ++hits_500;
      const double reported = record.report_joint_errors(j);
      if (std::isfinite(reported)) {
        joint_error_sum[j] += reported;
        ++joint_error_count[j];
      }
    }
    for (size_t k = 0; k < record.group_errors.size(); ++k) {
      if (std::isnan(record.group_errors[k])) continue;
      group_sum[k] += record.group_errors[k];
      ++group_count[k];
    }
    for (size_t k = 0; k < record.pcp.size(); ++k) {
      if (record.pcp[k] == PartOutcome::kCorrect) ++pcp_correct_matched[k];
    }
  }
  result.mpjpe_mm = mpjpe_count > 0 ? mpjpe_sum / mpjpe_count : kNaN;

  int all_valid = 0;
  for (const int n : gt_valid_per_joint_) all_valid += n;
  const bool all_gt = options_.pck_denominator == PckDenominator::kAllGt;
  const int pck_denominator = all_gt ? all_valid : matched_valid;
  result.pck_100 = Percent(hits_100, pck_denominator);
  result.pck_500 = Percent(hits_500, pck_denominator);

  for (size_t j = 0; j < num_joints; ++j) {
    JointResult joint;
    joint.name = evaluated_[j];
    joint.count = joint_error_count[j];
    joint.mean_error_mm = joint.count > 0 ? joint_error_sum[j] / joint.count : kNaN;
    joint.num_gt = all_gt ? gt_valid_per_joint_[j] : joint_matched_gt[j];
    joint.pck_100 = Percent(joint_hits_100[j], joint.num_gt);
    result.joints.push_back(joint);
  }

  for (size_t k = 0; k < kApThresholdsMm.size(); ++k) {
    result.ap[k] = 100.0 * AveragePrecision(ap_records, num_gt_, kApThresholdsMm[k]);
  }

  // Generic PCP, pooled over all evaluable parts of all GT persons.
  const bool nearest_pcp = options_.pcp_matching == PcpMatching::kNearest;
  int pcp_correct = 0, pcp_total = 0;
  for (size_t k = 0; k < pcp_layout_.parts.size(); ++k) {
    PcpPartResult part;
    part.name = GenericPcpParts()[k].name;
    part.correct = nearest_pcp ? pcp_correct_nearest_[k] : pcp_correct_matched[k];
    part.total = pcp_total_[k];
    part.pcp = Percent(part.correct, part.total);
    pcp_correct += part.correct;
    pcp_total += part.total;
    result.pcp_parts.push_back(part);
  }
  result.pcp = Percent(pcp_correct, pcp_total);

  if (options_.wholebody_groups) {
    for (size_t k = 0; k < WholeBodyGroups().size(); ++k) {
      GroupResult group;
      group.name = WholeBodyGroups()[k].name;
      group.num_persons = group_count[k];
      group.num_joints = group_num_joints_[k];
      group.mpjpe_mm = group_count[k] > 0 ? group_sum[k] / group_count[k] : kNaN;
      result.wholebody.push_back(group);
    }
  }

  if (legacy_) result.legacy_pcp = legacy_->Finalize();
  return result;
}

}  // namespace rpt::metrics

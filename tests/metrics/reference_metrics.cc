// SPDX-License-Identifier: MIT
// A frozen copy of metrics/accumulator.cc, metrics/eval_records.cc and metrics/reducers/*.cc at
// commit 826ae86 (before the metrics streamed), in one file because it is one oracle; only the
// names changed (namespace reference, one State struct, the reducers as one function). Do not
// "improve" it: its job is to be the old definition.
#include "tests/metrics/reference_metrics.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <utility>

#include "core/errors.h"
#include "metrics/average_precision.h"
#include "metrics/matching.h"
#include "metrics/pcp.h"
#include "metrics/person_error.h"

namespace rpt::metrics::reference {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double Percent(double numerator, double denominator) {
  return denominator > 0 ? 100.0 * numerator / denominator : kNaN;
}

enum PairFlag : std::uint8_t { kNearest = 1, kHungarianMatch = 2, kHungarian100 = 4, kHungarian500 = 8 };

struct PairRecord {
  MatchRecord match;
  std::uint8_t flags = 0;
  int frame = -1;  // the frame's number in the order added
  int pred_idx = -1;
  int gt_idx = -1;
  bool counted = true;
  double report_error_mm = 0.0;
  Eigen::ArrayXd joint_errors;
  Eigen::ArrayXd report_joint_errors;
  std::vector<double> group_errors;
  std::vector<PartOutcome> pcp;
};

struct EvalRecords {
  JointNames evaluated;
  std::vector<PairRecord> pairs;
  int num_frames = 0;
  int num_frames_with_gt = 0;
  int num_gt = 0;
  int num_dropped_gt = 0;
  int num_pred_counted = 0;
  int num_pred_total = 0;
  std::vector<int> gt_valid_per_joint;
  std::vector<int> pcp_total;
  std::vector<int> pcp_correct_nearest;
  std::vector<int> group_num_joints;
  std::optional<LegacyPcpEvaluator> legacy;
};

struct MatchSets {
  std::vector<bool> at_gate, at_100, at_500;
};

MatchSets SelectMatches(const EvalRecords& records, const EvalOptions& options) {
  const std::vector<PairRecord>& pairs = records.pairs;
  MatchSets sets;
  sets.at_gate.assign(pairs.size(), false);
  sets.at_100.assign(pairs.size(), false);
  sets.at_500.assign(pairs.size(), false);
  if (options.matching == MatchingMode::kGreedy) {
    std::vector<size_t> nearest_idx;
    std::vector<MatchRecord> nearest_records;
    for (size_t r = 0; r < pairs.size(); ++r) {
      if (!(pairs[r].flags & kNearest)) continue;
      nearest_idx.push_back(r);
      nearest_records.push_back(pairs[r].match);
    }
    const std::pair<double, std::vector<bool>*> gates[] = {
        {options.match_threshold_mm, &sets.at_gate}, {100.0, &sets.at_100}, {500.0, &sets.at_500}};
    for (const auto& [threshold, set] : gates) {
      const std::vector<bool> is_tp = GreedyMatch(nearest_records, threshold);
      for (size_t i = 0; i < is_tp.size(); ++i) (*set)[nearest_idx[i]] = is_tp[i];
    }
  } else {
    for (size_t r = 0; r < pairs.size(); ++r) {
      sets.at_gate[r] = pairs[r].flags & kHungarianMatch;
      sets.at_100[r] = pairs[r].flags & kHungarian100;
      sets.at_500[r] = pairs[r].flags & kHungarian500;
    }
  }
  return sets;
}

int CountMatches(const std::vector<bool>& matched) {
  int count = 0;
  for (const bool m : matched) count += m ? 1 : 0;
  return count;
}

void CheckPoses(const Poses3D& poses, const JointNames& names, std::string_view what, std::string_view frame_id) {
  const size_t expected = static_cast<size_t>(poses.num_persons()) * poses.num_joints * 4;
  if (poses.num_joints < 0 || poses.data.size() != expected) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::string(what) + " poses hold " +
                     std::to_string(poses.data.size()) + " values, expected " + std::to_string(expected));
  }
  if (poses.num_persons() > 0 && static_cast<size_t>(poses.num_joints) != names.size()) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::string(what) + " poses have " +
                     std::to_string(poses.num_joints) + " joints but " + std::to_string(names.size()) +
                     " joint names");
  }
}

Eigen::Vector3d JointMmOrNaN(const Poses3D& poses, int person_idx, int j, double min_score) {
  if (j < 0) return Eigen::Vector3d::Constant(kNaN);
  const auto joints = poses.Person(person_idx);
  if (joints(3, j) <= min_score) return Eigen::Vector3d::Constant(kNaN);
  return 1000.0 * joints.col(j).head<3>();
}

struct Layout {
  JointNames gt_names, pred_names;
  std::vector<int> gt_eval, pred_eval;
  std::vector<std::vector<int>> gt_group, pred_group;
  int gt_hip_left = -1, gt_hip_right = -1, pred_hip_left = -1, pred_hip_right = -1;
  std::vector<int> gt_legacy, pred_legacy;
};

}  // namespace

struct ReferenceAccumulator::State {
  EvalOptions options_;
  JointNames evaluated_;
  GenericPcpLayout pcp_layout_;
  Layout layout_;
  bool layout_valid_ = false;
  std::unordered_set<std::string> frame_ids_;
  EvalRecords records_;
  std::vector<std::pair<size_t, size_t>> frame_pairs_;  // [first, end) of each frame's pairs
  std::vector<int> frame_num_pred_;

  void UpdateLayout(const JointNames& gt_names, const JointNames& pred_names);
  void AddLegacyFrame(const Poses3D& gt, const Poses3D& predictions);
  PairRecord MakePair(const Poses3D& gt, int gt_idx, const EvalPerson& gt_person, const Poses3D& predictions,
                      int pred_idx, const EvalPerson& pred_person, double error_mm, double score) const;
};

ReferenceAccumulator::ReferenceAccumulator(const EvalOptions& options) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.options_ = options;
  s.options_.Check();
  s.evaluated_ = s.options_.EvaluatedJoints();
  s.pcp_layout_ = MakeGenericPcpLayout(s.evaluated_);
  s.records_.evaluated = s.evaluated_;
  s.records_.gt_valid_per_joint.assign(s.evaluated_.size(), 0);
  s.records_.pcp_total.assign(s.pcp_layout_.parts.size(), 0);
  s.records_.pcp_correct_nearest.assign(s.pcp_layout_.parts.size(), 0);
  s.records_.group_num_joints.assign(WholeBodyGroups().size(), 0);
  if (s.options_.legacy_pcp != LegacyPcpLayout::kNone) s.records_.legacy.emplace(s.options_);
}

ReferenceAccumulator::~ReferenceAccumulator() = default;

void ReferenceAccumulator::State::UpdateLayout(const JointNames& gt_names, const JointNames& pred_names) {
  if (layout_valid_ && gt_names == layout_.gt_names && pred_names == layout_.pred_names) return;
  Layout layout;
  layout.gt_names = gt_names;
  layout.pred_names = pred_names;
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
  if (options_.wholebody_groups && !gt_names.empty() && !pred_names.empty()) {
    for (size_t k = 0; k < WholeBodyGroups().size(); ++k) {
      records_.group_num_joints[k] = static_cast<int>(layout_.gt_group[k].size());
    }
  }
}

PairRecord ReferenceAccumulator::State::MakePair(const Poses3D& gt, int gt_idx, const EvalPerson& gt_person,
                                                 const Poses3D& predictions, int pred_idx,
                                                 const EvalPerson& pred_person, double error_mm,
                                                 double score) const {
  PairRecord record;
  record.match = MatchRecord{-1, error_mm, score};
  record.joint_errors = JointErrors(gt_person, pred_person);
  Eigen::Vector3d gt_offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d pred_offset = Eigen::Vector3d::Zero();
  bool aligned = true;
  if (options_.alignment == Alignment::kPelvis) {
    const auto gt_pelvis = PelvisMm(gt, gt_idx, layout_.gt_hip_left, layout_.gt_hip_right, options_.min_gt_score);
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
          if (g.hasNaN() || p.hasNaN()) continue;
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

void ReferenceAccumulator::State::AddLegacyFrame(const Poses3D& gt, const Poses3D& predictions) {
  std::vector<LegacyActor> actors;
  for (int g = 0; g < gt.num_persons(); ++g) {
    LegacyActor actor;
    actor.actor_id = gt.track_ids[g] >= 0 ? gt.track_ids[g] : g;
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

void ReferenceAccumulator::Add(std::string_view frame_id, const Poses3D& gt, const JointNames& gt_names,
                               const Poses3D& predictions, const JointNames& pred_names,
                               std::span<const double> pred_scores) {
  State& s = *state_;
  const EvalOptions& options_ = s.options_;
  EvalRecords& records_ = s.records_;
  CheckPoses(gt, gt_names, "ground-truth", frame_id);
  CheckPoses(predictions, pred_names, "prediction", frame_id);
  if (!pred_scores.empty() && pred_scores.size() != static_cast<size_t>(predictions.num_persons())) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "': " + std::to_string(pred_scores.size()) +
                     " person scores for " + std::to_string(predictions.num_persons()) + " predictions");
  }
  if (!s.frame_ids_.insert(std::string(frame_id)).second) {
    throw InputError("metrics: frame '" + std::string(frame_id) + "' was added twice");
  }
  s.UpdateLayout(gt_names, pred_names);
  ++records_.num_frames;

  std::vector<EvalPerson> gt_persons;
  std::vector<int> gt_source;
  for (int g = 0; g < gt.num_persons(); ++g) {
    EvalPerson person = ExtractPerson(gt, g, s.layout_.gt_eval, options_.min_gt_score);
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
    pred_persons.push_back(ExtractPerson(predictions, p, s.layout_.pred_eval, options_.min_pred_score));
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

  std::vector<PairRecord>& pairs = records_.pairs;
  const size_t first_record = pairs.size();
  auto find_or_add = [&](int p, int g) -> PairRecord& {
    for (size_t r = first_record; r < pairs.size(); ++r) {
      if (pairs[r].pred_idx == p && pairs[r].gt_idx == g) return pairs[r];
    }
    PairRecord record;
    if (g >= 0) {
      record = s.MakePair(gt, gt_source[g], gt_persons[g], predictions, p, pred_persons[p], cost(p, g), scores[p]);
      record.match.gt_id = gt_id_base + g;
    } else {
      record.match = MatchRecord{-1, kInf, scores[p]};
    }
    record.frame = records_.num_frames;
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

  const std::vector<int> nearest_pred = NearestPrediction(cost);
  for (int g = 0; g < num_gt; ++g) {
    const EvalPerson* pred = nearest_pred[g] >= 0 ? &pred_persons[nearest_pred[g]] : nullptr;
    const std::vector<PartOutcome> outcomes =
        EvaluateGenericPcp(s.pcp_layout_, gt_persons[g], pred, options_.pcp_alpha);
    for (size_t k = 0; k < outcomes.size(); ++k) {
      if (outcomes[k] == PartOutcome::kNotEvaluated) continue;
      ++records_.pcp_total[k];
      if (outcomes[k] == PartOutcome::kCorrect) ++records_.pcp_correct_nearest[k];
    }
  }

  if (records_.legacy) s.AddLegacyFrame(gt, predictions);
  s.frame_pairs_.emplace_back(first_record, pairs.size());
  s.frame_num_pred_.push_back(num_pred);
}

MetricsResult ReferenceAccumulator::Finalize() const {
  const EvalRecords& records = state_->records_;
  const EvalOptions& options = state_->options_;
  const MatchSets matches = SelectMatches(records, options);
  MetricsResult result;

  // ReduceCounts
  result.num_frames = records.num_frames;
  result.num_frames_with_gt = records.num_frames_with_gt;
  result.num_gt_persons = records.num_gt;
  result.num_dropped_gt_persons = records.num_dropped_gt;
  result.num_predictions = records.num_pred_counted;
  result.num_predictions_total = records.num_pred_total;
  result.num_matches = CountMatches(matches.at_gate);

  // ReduceRecall
  result.recall_100 = Percent(CountMatches(matches.at_100), records.num_gt);
  result.recall_500 = Percent(CountMatches(matches.at_500), records.num_gt);

  // ReduceInvalid
  {
    const int false_positives = records.num_pred_counted - CountMatches(matches.at_gate);
    result.invalid = Percent(false_positives, records.num_pred_counted);
    // The unmatched counted predictions by their nearest pair: matched = any pair of the same
    // (frame, prediction) matched at the gate.
    std::set<std::pair<int, int>> matched, matched_gt;  // (frame, prediction), (frame, GT person)
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      matched.insert({records.pairs[r].frame, records.pairs[r].pred_idx});
      matched_gt.insert({records.pairs[r].frame, records.pairs[r].gt_idx});
    }
    const double gate = options.match_threshold_mm;
    for (const PairRecord& pair : records.pairs) {
      if (!(pair.flags & kNearest) || !pair.counted || matched.count({pair.frame, pair.pred_idx}) > 0) continue;
      InvalidCauses& c = result.invalid_causes;
      if (pair.gt_idx < 0) {
        ++c.no_gt;
      } else if (pair.match.error_mm < gate) {
        ++c.duplicate;
      } else if (pair.match.error_mm < 2 * gate) {
        ++(matched_gt.count({pair.frame, pair.gt_idx}) > 0 ? c.near_matched_gt : c.near_missed_gt);
      } else {
        ++c.far_from_gt;
      }
    }
  }

  // ReduceF1
  {
    const int tp = CountMatches(matches.at_gate);
    const int fp = records.num_pred_counted - tp;
    const int fn = records.num_gt - tp;
    result.f1 = Percent(2.0 * tp, 2.0 * tp + fp + fn);
  }

  // ReduceMpjpe
  {
    double sum = 0.0;
    int count = 0;
    int unaligned = 0;
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      const double error = records.pairs[r].report_error_mm;
      if (std::isnan(error)) {
        ++unaligned;
      } else {
        sum += error;
        ++count;
      }
    }
    result.mpjpe_mm = count > 0 ? sum / count : kNaN;
    result.num_unaligned_matches = unaligned;
  }

  // ReducePck
  {
    int hits_100 = 0, hits_500 = 0, matched_valid = 0, missing = 0;
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      const Eigen::ArrayXd& errors = records.pairs[r].joint_errors;
      for (Eigen::Index j = 0; j < errors.size(); ++j) {
        const double e = errors(j);
        if (std::isnan(e)) continue;
        ++matched_valid;
        if (std::isinf(e)) ++missing;
        if (e < 100.0) ++hits_100;
        if (e < 500.0) ++hits_500;
      }
    }
    int all_valid = 0;
    for (const int n : records.gt_valid_per_joint) all_valid += n;
    const int denominator = options.pck_denominator == PckDenominator::kAllGt ? all_valid : matched_valid;
    result.pck_100 = Percent(hits_100, denominator);
    result.pck_500 = Percent(hits_500, denominator);
    result.num_missing_pred_joints = missing;
  }

  // ReducePerJoint
  {
    const size_t num_joints = records.evaluated.size();
    std::vector<double> error_sum(num_joints, 0.0);
    std::vector<int> error_count(num_joints, 0), hits_100(num_joints, 0), matched_gt(num_joints, 0);
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      const PairRecord& record = records.pairs[r];
      for (size_t j = 0; j < num_joints; ++j) {
        const double e = record.joint_errors(j);
        if (std::isnan(e)) continue;
        ++matched_gt[j];
        if (e < 100.0) ++hits_100[j];
        const double reported = record.report_joint_errors(j);
        if (std::isfinite(reported)) {
          error_sum[j] += reported;
          ++error_count[j];
        }
      }
    }
    const bool all_gt = options.pck_denominator == PckDenominator::kAllGt;
    for (size_t j = 0; j < num_joints; ++j) {
      JointResult joint;
      joint.name = records.evaluated[j];
      joint.count = error_count[j];
      joint.mean_error_mm = joint.count > 0 ? error_sum[j] / joint.count : kNaN;
      joint.num_gt = all_gt ? records.gt_valid_per_joint[j] : matched_gt[j];
      joint.pck_100 = Percent(hits_100[j], joint.num_gt);
      result.joints.push_back(joint);
    }
  }

  // ReduceAp
  {
    std::vector<MatchRecord> ap_records;
    for (const PairRecord& record : records.pairs) {
      if ((record.flags & kNearest) && record.counted) ap_records.push_back(record.match);
    }
    for (size_t k = 0; k < kApThresholdsMm.size(); ++k) {
      result.ap[k] = 100.0 * AveragePrecision(ap_records, records.num_gt, kApThresholdsMm[k]);
    }
  }

  // ReducePcp
  {
    const size_t num_parts = records.pcp_total.size();
    std::vector<int> correct_matched(num_parts, 0);
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      const std::vector<PartOutcome>& outcomes = records.pairs[r].pcp;
      for (size_t k = 0; k < outcomes.size(); ++k) {
        if (outcomes[k] == PartOutcome::kCorrect) ++correct_matched[k];
      }
    }
    const bool nearest = options.pcp_matching == PcpMatching::kNearest;
    int correct = 0, total = 0;
    for (size_t k = 0; k < num_parts; ++k) {
      PcpPartResult part;
      part.name = GenericPcpParts()[k].name;
      part.correct = nearest ? records.pcp_correct_nearest[k] : correct_matched[k];
      part.total = records.pcp_total[k];
      part.pcp = Percent(part.correct, part.total);
      correct += part.correct;
      total += part.total;
      result.pcp_parts.push_back(part);
    }
    result.pcp = Percent(correct, total);
  }

  // ReduceLegacyPcp
  if (records.legacy) result.legacy_pcp = records.legacy->Finalize();

  // ReduceWholeBody
  if (options.wholebody_groups) {
    const size_t num_groups = WholeBodyGroups().size();
    std::vector<double> sum(num_groups, 0.0);
    std::vector<int> count(num_groups, 0);
    for (size_t r = 0; r < records.pairs.size(); ++r) {
      if (!matches.at_gate[r]) continue;
      const std::vector<double>& errors = records.pairs[r].group_errors;
      for (size_t k = 0; k < errors.size(); ++k) {
        if (std::isnan(errors[k])) continue;
        sum[k] += errors[k];
        ++count[k];
      }
    }
    for (size_t k = 0; k < num_groups; ++k) {
      GroupResult group;
      group.name = WholeBodyGroups()[k].name;
      group.num_persons = count[k];
      group.num_joints = records.group_num_joints[k];
      group.mpjpe_mm = count[k] > 0 ? sum[k] / count[k] : kNaN;
      result.wholebody.push_back(group);
    }
  }
  return result;
}

std::vector<ReferenceAccumulator::FrameMatches> ReferenceAccumulator::PerFrameMatches() const {
  const EvalRecords& records = state_->records_;
  const MatchSets matches = SelectMatches(records, state_->options_);
  std::vector<FrameMatches> frames;
  for (size_t f = 0; f < state_->frame_pairs_.size(); ++f) {
    FrameMatches frame;
    const int num_pred = state_->frame_num_pred_[f];
    frame.pred_matched.assign(num_pred, false);
    frame.pred_matched_gt.assign(num_pred, -1);
    frame.pred_error_mm.assign(num_pred, kInf);
    for (size_t r = state_->frame_pairs_[f].first; r < state_->frame_pairs_[f].second; ++r) {
      const PairRecord& pair = records.pairs[r];
      if (pair.flags & kNearest) frame.pred_error_mm[pair.pred_idx] = pair.match.error_mm;
      if (!matches.at_gate[r]) continue;
      frame.pred_matched[pair.pred_idx] = true;
      frame.pred_matched_gt[pair.pred_idx] = pair.gt_idx;
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace rpt::metrics::reference

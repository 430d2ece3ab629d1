// SPDX-License-Identifier: MIT
#include "engine/loss_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/pipeline/box_iou.h"
#include "core/triangulation.h"
#include "metrics/person_error.h"

namespace rpt::engine {
namespace {

// What a detection, or a prediction's projection into one view, shows (UnmatchedSource's rules).
enum class Shows { kNobody, kLabelled2dOnly, kLabelled3d };

// The box (x0, y0, x1, y1) of the points added, and how many there were.
struct PointsBox {
  Eigen::Vector4d box{1e300, 1e300, -1e300, -1e300};
  int points = 0;
  void Add(double x, double y) {
    box << std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y);
    ++points;
  }
};

// The box of the detection's joints with a positive confidence.
PointsBox JointsBox(const Poses2D& view, int detection) {
  const auto person = view.Person(detection);
  PointsBox box;
  for (int j = 0; j < view.num_joints; ++j) {
    if (!(person(2, j) > 0) || !std::isfinite(person(0, j)) || !std::isfinite(person(1, j))) continue;
    box.Add(person(0, j), person(1, j));
  }
  return box;
}

}  // namespace

const char* LossKey(Loss loss) {
  switch (loss) {
    case Loss::kFound: return "found";
    case Loss::kFewerThanTwoViews: return "fewer_than_2_views";
    case Loss::kPairFiltered: return "pair_filtered";
    case Loss::kGroupedWrongly: return "grouped_wrongly";
    case Loss::kMergedWrongly: return "merged_wrongly";
    case Loss::kRejected: return "rejected";
    case Loss::kPlacedOff: return "placed_off";
  }
  return "?";
}

const char* UnmatchedSourceKey(UnmatchedSource source) {
  switch (source) {
    case UnmatchedSource::kLabelled3d: return "labelled_3d";
    case UnmatchedSource::kLabelled2dOnly: return "labelled_2d_only";
    case UnmatchedSource::kPartly2dOnly: return "partly_2d_only";
    case UnmatchedSource::kUnlabelled: return "unlabelled";
  }
  return "?";
}

void PartLosses::Merge(const PartLosses& other) {
  evaluated += other.evaluated;
  wrong += other.wrong;
  beyond_best_pair += other.beyond_best_pair;
  wrong_beyond_best_pair += other.wrong_beyond_best_pair;
}

void JointReferences::Merge(const JointReferences& other) {
  joints += other.joints;
  output_mm += other.output_mm;
  all_views_mm += other.all_views_mm;
  best_pair_mm += other.best_pair_mm;
}

PartLosses LossTable::AllParts() const {
  PartLosses all;
  for (const PartLosses& part : parts) all.Merge(part);
  return all;
}

void LossTable::Merge(const LossTable& other) {
  gt_persons += other.gt_persons;
  triangulable += other.triangulable;
  for (int k = 0; k < kNumLosses; ++k) count[k] += other.count[k];
  found_fewer_than_2_views += other.found_fewer_than_2_views;
  in_no_view += other.in_no_view;
  in_one_view += other.in_one_view;
  for (size_t s = 0; s < pairs_dropped_by.size(); ++s) pairs_dropped_by[s] += other.pairs_dropped_by[s];
  grouped_dropped += other.grouped_dropped;
  grouped_absorbed += other.grouped_absorbed;
  merged_mixed += other.merged_mixed;
  merged_own_pairs_only += other.merged_own_pairs_only;
  rejected_by_verify += other.rejected_by_verify;
  rejected_by_postprocess += other.rejected_by_postprocess;
  unmatched_with_2d_labels += other.unmatched_with_2d_labels;
  unmatched_by_projection += other.unmatched_by_projection;
  for (int k = 0; k < kNumUnmatchedSources; ++k) unmatched_by_source[k] += other.unmatched_by_source[k];
  for (int k = 0; k < kNumPcpParts; ++k) parts[k].Merge(other.parts[k]);
  joints.Merge(other.joints);
}

LossAccumulator::LossAccumulator(const SequenceHeader& header, const JointNames& output_joints,
                                 const metrics::EvalOptions& eval, const LossTableOptions& options)
    : cameras_(header.cameras), options_(options), min_pred_score_(eval.min_pred_score) {
  // The association joints: the evaluated joints both the GT and the detections have (as
  // `rpt detector-stats` takes them).
  const JointNames& evaluated = eval.EvaluatedJoints();
  for (const std::string& name : evaluated) {
    const int g = FindJoint(header.gt_joints, name), d = FindJoint(header.detection_joints, name);
    if (g < 0 || d < 0) continue;
    gt_index_.push_back(g);
    det_index_.push_back(d);
  }
  pred_eval_ = metrics::FindJointNames(evaluated, output_joints);
  det_eval_ = metrics::FindJointNames(evaluated, header.detection_joints);
  for (const Camera& camera : cameras_) {
    Eigen::Matrix<double, 3, 4> rt;
    rt << camera.R, camera.t;
    world_to_camera_.push_back(rt);
  }
  pcp_layout_ = metrics::MakeGenericPcpLayout(evaluated);
  pcp_alpha_ = eval.pcp_alpha;
  if (pcp_layout_.parts.size() != kNumPcpParts) throw std::logic_error("loss table: kNumPcpParts is not the number of PCP parts");
}

void LossAccumulator::LabelDetections(const SequenceFrame& frame) {
  const int num_views = static_cast<int>(frame.views.size());
  label_.resize(num_views);
  detecting_views_.assign(frame.gt.num_persons(), 0);
  std::vector<detector_stats::ProjectedPerson> persons;
  std::vector<int> original;
  for (int c = 0; c < num_views && c < static_cast<int>(cameras_.size()); ++c) {
    const Poses2D& view = frame.views[c];
    label_[c].assign(view.num_persons(), -1);
    if (view.num_persons() == 0 || gt_index_.empty()) continue;
    persons.clear();
    for (int p = 0; p < frame.gt.num_persons(); ++p) {
      detector_stats::ProjectedPerson person = detector_stats::ProjectPerson(cameras_[c], frame.gt, p, gt_index_);
      if (std::find(person.present.begin(), person.present.end(), 1) != person.present.end()) {
        persons.push_back(std::move(person));
      }
    }
    if (persons.empty()) continue;
    // Exact copies of an earlier detection are associated as their original (as detector-stats).
    original.assign(view.num_persons(), -1);
    Poses2D unique;
    unique.Clear(view.num_joints);
    std::vector<int> unique_of(view.num_persons(), -1);
    for (int d = 0; d < view.num_persons(); ++d) {
      for (int e = 0; e < d && original[d] < 0; ++e) {
        if (original[e] < 0 && view.Person(e) == view.Person(d)) original[d] = e;
      }
      if (original[d] < 0) {
        unique_of[d] = unique.num_persons();
        unique.AddPerson() = view.Person(d);
      }
    }
    const detector_stats::Association association =
        detector_stats::Associate(persons, unique, det_index_, options_.association);
    for (int d = 0; d < view.num_persons(); ++d) {
      const int u = unique_of[original[d] < 0 ? d : original[d]];
      const int i = association.person_of_detection[u];
      // Only persons in view are detected (a pairing with a person mostly outside counts for nobody).
      if (i < 0 || persons[i].num_in_image < options_.min_joints_in_image) continue;
      label_[c][d] = persons[i].gt_person;
      if (original[d] < 0) ++detecting_views_[persons[i].gt_person];
    }
  }
}

void LossAccumulator::CountUnmatched(const SequenceFrame& frame, const FrameTrace& trace, const Poses3D& predictions,
                                    const metrics::FrameRecords& records, const std::vector<int>& owner) {
  // What a box (a detection's or a projection's joints) in view v shows: its best label.
  const auto best_label = [&](size_t v, const Eigen::Vector4d& box) {
    double best_iou = options_.label_min_iou;
    Shows best = Shows::kNobody;
    if (v >= frame.labels_2d.size()) return best;
    for (const PersonLabel2D& label : frame.labels_2d[v]) {
      if (label.box_px.isZero()) continue;  // no box
      const double iou = BoxIou(box, label.box_px);
      if (iou < best_iou) continue;
      best_iou = iou;
      best = label.gt_person >= 0 ? Shows::kLabelled3d : Shows::kLabelled2dOnly;
    }
    return best;
  };
  std::array<int, 3> shown{};  // per Shows: detections or views
  const auto show = [&](Shows what) { ++shown[static_cast<int>(what)]; };
  const auto& filtered = trace.pairs[FrameTrace::kFilter];
  const int merged = static_cast<int>(trace.after_postprocess.size());
  for (int q = 0; q < records.num_predictions && q < predictions.num_persons(); ++q) {
    if (metrics::IsMatchedPrediction(records, q)) continue;
    ++table_.unmatched_with_2d_labels;
    shown.fill(0);
    if (q < merged) {  // merged from pairs: the persons after postprocess come first, in order (triangulator.cc)
      const int g = trace.after_postprocess[q];
      for (size_t i = 0; i < filtered.size() && i < trace.group_of_pair.size(); ++i) {
        if (trace.group_of_pair[i] != g) continue;
        for (const int pose : filtered[i]) {
          const size_t v = static_cast<size_t>(trace.pose_view[pose]);
          if (owner[pose] >= 0) {
            show(Shows::kLabelled3d);
            continue;
          }
          // A box of fewer than 2 joints has no area: it overlaps no label.
          show(v < frame.views.size() ? best_label(v, JointsBox(frame.views[v], trace.pose_person[pose]).box)
                                      : Shows::kNobody);
        }
      }
    } else {  // placed from one view or carried by tracking: where it lands in each image
      ++table_.unmatched_by_projection;
      const auto person = predictions.Person(q);
      for (size_t c = 0; c < cameras_.size(); ++c) {
        const Camera& camera = cameras_[c];
        PointsBox inside;  // the joints that land in the image
        for (int j = 0; j < predictions.num_joints; ++j) {
          Eigen::Vector2d uv;
          if (!(person(3, j) > 0) || !camera.Project(person.col(j).head<3>(), &uv)) continue;
          if (uv.x() < 0 || uv.y() < 0 || uv.x() >= camera.width || uv.y() >= camera.height) continue;
          inside.Add(uv.x(), uv.y());
        }
        if (inside.points >= 2) show(best_label(c, inside.box));  // a view that does not see it has no say
      }
    }
    const int views = shown[0] + shown[1] + shown[2];
    const int two_d_only = shown[static_cast<int>(Shows::kLabelled2dOnly)];
    const UnmatchedSource source = shown[static_cast<int>(Shows::kLabelled3d)] > 0 ? UnmatchedSource::kLabelled3d
                                   : views > 0 && two_d_only == views            ? UnmatchedSource::kLabelled2dOnly
                                   : two_d_only > 0                              ? UnmatchedSource::kPartly2dOnly
                                                                                 : UnmatchedSource::kUnlabelled;
    ++table_.unmatched_by_source[static_cast<int>(source)];
  }
}

void LossAccumulator::AddJointReferences(const metrics::FrameRecords& records, int k, size_t num_pairs) {
  const metrics::PairRecord* match = nullptr;
  for (const metrics::PairRecord& pair : records.pairs) {
    if (pair.gt_idx == k && (pair.flags & metrics::kMatch)) match = &pair;
  }
  if (match == nullptr) return;
  const int num_eval = static_cast<int>(det_eval_.size());
  const int views = static_cast<int>(own_views_.size());
  const metrics::EvalPerson& gt = records.gt[k];
  for (int e = 0; e < num_eval && e < match->joint_errors.size(); ++e) {
    if (!gt.valid(e) || !std::isfinite(match->joint_errors[e])) continue;
    // All views: minimise sum_v w_v |(I - r_v r_v^T)(X - c_v)|^2 over the unit rays r_v.
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    int seen = 0;
    for (int v = 0; v < views; ++v) {
      const size_t at = static_cast<size_t>(v) * num_eval + e;
      if (!own_xy_[at].allFinite() || !(own_confidence_[at] > 0)) continue;
      const Camera& camera = cameras_[own_views_[v]];
      const Eigen::Vector3d ray = (camera.R.transpose() * own_xy_[at].homogeneous()).normalized();
      const Eigen::Matrix3d p = own_confidence_[at] * (Eigen::Matrix3d::Identity() - ray * ray.transpose());
      a += p;
      b += p * camera.Center();
      ++seen;
    }
    if (seen < 2 || !(std::abs(a.determinant()) > 1e-12)) continue;
    double best_pair = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < num_pairs; ++i) {
      const Eigen::Vector3d& point = pair_points_mm_[i * num_eval + e];
      if (point.allFinite()) best_pair = std::min(best_pair, (point - gt.xyz_mm.col(e)).norm());
    }
    if (!std::isfinite(best_pair)) continue;
    const Eigen::Vector3d all_views = 1000.0 * a.inverse() * b;
    ++table_.joints.joints;
    table_.joints.output_mm += match->joint_errors[e];
    table_.joints.all_views_mm += (all_views - gt.xyz_mm.col(e)).norm();
    table_.joints.best_pair_mm += best_pair;
  }
}

void LossAccumulator::CountParts(const SequenceFrame& frame, const metrics::FrameRecords& records) {
  const int num_eval = static_cast<int>(det_eval_.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t k = 0; k < records.kept_gt_idx.size() && k < records.pcp_nearest.size(); ++k) {
    const int p = records.kept_gt_idx[k];
    // Its detections: the first one labelled p in each view, undistorted.
    own_views_.clear();
    own_xy_.clear();
    own_confidence_.clear();
    for (size_t c = 0; c < label_.size() && c < cameras_.size(); ++c) {
      const auto it = std::find(label_[c].begin(), label_[c].end(), p);
      if (it == label_[c].end()) continue;
      own_views_.push_back(static_cast<int>(c));
      const auto detection = frame.views[c].Person(static_cast<int>(it - label_[c].begin()));
      for (int e = 0; e < num_eval; ++e) {
        const int d = det_eval_[e];
        const bool present = d >= 0 && detection(2, d) > 0 && std::isfinite(detection(0, d)) &&
                             std::isfinite(detection(1, d));
        own_xy_.push_back(present ? cameras_[c].PixelToNormalized(Eigen::Vector2d(detection(0, d), detection(1, d)))
                                  : Eigen::Vector2d(nan, nan));
        own_confidence_.push_back(present ? std::min(1.0, detection(2, d)) : 0.0);
      }
    }
    // Every pair of them, every joint both hold (mm, as the metrics).
    pair_points_mm_.clear();
    const int views = static_cast<int>(own_views_.size());
    for (int a = 0; a < views; ++a) {
      for (int b = a + 1; b < views; ++b) {
        for (int e = 0; e < num_eval; ++e) {
          const Eigen::Vector2d& xa = own_xy_[static_cast<size_t>(a) * num_eval + e];
          const Eigen::Vector2d& xb = own_xy_[static_cast<size_t>(b) * num_eval + e];
          Eigen::Vector3d point(nan, nan, nan);
          if (xa.allFinite() && xb.allFinite() &&
              TriangulateDlt(world_to_camera_[own_views_[a]], xa, world_to_camera_[own_views_[b]], xb, &point)) {
            point *= 1000.0;
          } else {
            point.setConstant(nan);
          }
          pair_points_mm_.push_back(point);
        }
      }
    }
    const size_t num_pairs = pair_points_mm_.size() / std::max(1, num_eval);
    const metrics::EvalPerson& gt = records.gt[k];
    // The GT endpoint (mean of its two joints) and the distance of the nearest pair's endpoint to it.
    const auto gt_endpoint = [&](const std::array<int, 2>& joints) {
      return Eigen::Vector3d(0.5 * (gt.xyz_mm.col(joints[0]) + gt.xyz_mm.col(joints[1])));
    };
    const auto nearest_pair = [&](const std::array<int, 2>& joints, const Eigen::Vector3d& target) {
      double best = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i < num_pairs; ++i) {
        const Eigen::Vector3d& first = pair_points_mm_[i * num_eval + joints[0]];
        const Eigen::Vector3d& second = pair_points_mm_[i * num_eval + joints[1]];
        if (!first.allFinite() || !second.allFinite()) continue;
        best = std::min(best, (0.5 * (first + second) - target).norm());
      }
      return best;
    };
    AddJointReferences(records, static_cast<int>(k), num_pairs);
    const std::vector<metrics::PartOutcome>& outcomes = records.pcp_nearest[k];
    for (int part = 0; part < kNumPcpParts && part < static_cast<int>(outcomes.size()); ++part) {
      if (outcomes[part] == metrics::PartOutcome::kNotEvaluated) continue;
      const metrics::GenericPcpLayout::Part& layout = pcp_layout_.parts[part];
      const Eigen::Vector3d gt_a = gt_endpoint(layout.a), gt_b = gt_endpoint(layout.b);
      // PCP's test (metrics/pcp.h IsPartCorrect) with the nearest pair's endpoints.
      const bool reached =
          0.5 * (nearest_pair(layout.a, gt_a) + nearest_pair(layout.b, gt_b)) <= pcp_alpha_ * (gt_a - gt_b).norm();
      const bool wrong = outcomes[part] == metrics::PartOutcome::kWrong;
      PartLosses& counts = table_.parts[part];
      ++counts.evaluated;
      counts.wrong += wrong ? 1 : 0;
      counts.beyond_best_pair += reached ? 0 : 1;
      counts.wrong_beyond_best_pair += wrong && !reached ? 1 : 0;
    }
  }
}

void LossAccumulator::Add(const SequenceFrame& frame, const FrameTrace& trace, const Poses3D& predictions,
                          const metrics::FrameRecords& records) {
  LabelDetections(frame);
  // The GT person of each traced pose (-1: none).
  std::vector<int> owner(trace.pose_view.size(), -1);
  for (size_t g = 0; g < owner.size(); ++g) {
    const int v = trace.pose_view[g], d = trace.pose_person[g];
    if (v < static_cast<int>(label_.size()) && d < static_cast<int>(label_[v].size())) owner[g] = label_[v][d];
  }
  const auto true_pair_of = [&](const std::array<int, 2>& pair) {
    const int a = owner[pair[0]];
    return a >= 0 && a == owner[pair[1]] ? a : -1;
  };
  // Per kept group: its pairs, its true pairs per GT person, and its owner: the person with more
  // true pairs in it than anybody else (-1: none, or a tie).
  const int num_groups = trace.merged.num_persons();
  const int num_gt = frame.gt.num_persons();
  std::vector<int> pairs_in_group(static_cast<size_t>(num_groups) * num_gt, 0), group_size(num_groups, 0);
  std::vector<int> group_owner(num_groups, -1);
  const auto& filtered = trace.pairs[FrameTrace::kFilter];
  for (size_t i = 0; i < filtered.size() && i < trace.group_of_pair.size(); ++i) {
    const int g = trace.group_of_pair[i];
    if (g < 0) continue;
    ++group_size[g];
    const int p = true_pair_of(filtered[i]);
    if (p >= 0) ++pairs_in_group[static_cast<size_t>(g) * num_gt + p];
  }
  for (int g = 0; g < num_groups; ++g) {
    int best = 0;
    for (int p = 0; p < num_gt; ++p) {
      const int n = pairs_in_group[static_cast<size_t>(g) * num_gt + p];
      if (n > best) {
        best = n;
        group_owner[g] = p;
      } else if (n == best && n > 0) {
        group_owner[g] = -1;  // a tie: nobody's own
      }
    }
  }

  last_.clear();
  const int num_kept = static_cast<int>(records.kept_gt_idx.size());
  std::vector<char> found(num_kept, 0);
  for (const metrics::PairRecord& pair : records.pairs) {
    if (pair.gt_idx >= 0 && (pair.flags & metrics::kMatch500)) found[pair.gt_idx] = 1;
  }
  for (int k = 0; k < num_kept; ++k) {
    const int p = records.kept_gt_idx[k];
    const int views = detecting_views_[p];
    ++table_.gt_persons;
    if (views >= 2) ++table_.triangulable;
    Loss loss = Loss::kPlacedOff;
    if (found[k]) {
      loss = Loss::kFound;
      if (views < 2) ++table_.found_fewer_than_2_views;
    } else if (views < 2) {
      loss = Loss::kFewerThanTwoViews;
      ++(views == 0 ? table_.in_no_view : table_.in_one_view);
    } else {
      // The last stage at which a true pair of p was left.
      int last_stage = -1;
      for (int s = 0; s < FrameTrace::kNumPairStages; ++s) {
        const auto& list = trace.pairs[s];
        if (std::any_of(list.begin(), list.end(), [&](const std::array<int, 2>& pair) { return true_pair_of(pair) == p; })) {
          last_stage = s;
        }
      }
      if (last_stage < FrameTrace::kFilter) {
        loss = Loss::kPairFiltered;
        // The next step dropped them; none made (-1): undistort left its poses in one view only.
        ++table_.pairs_dropped_by[last_stage + 1];
      } else {
        bool in_kept_group = false, own_group = false, mixed = false, merged_near = false, verified = false,
             kept = false;
        for (int g = 0; g < num_groups; ++g) {
          const int n = pairs_in_group[static_cast<size_t>(g) * num_gt + p];
          if (n == 0) continue;
          in_kept_group = true;
          if (group_owner[g] != p) continue;
          own_group = true;
          mixed |= n < group_size[g];
          const metrics::EvalPerson merged = metrics::ExtractPerson(trace.merged, g, pred_eval_, min_pred_score_);
          if (!(metrics::PersonMpjpe(records.gt[k], merged) < 500.0)) continue;
          merged_near = true;
          const bool after_verify =
              std::find(trace.after_verify.begin(), trace.after_verify.end(), g) != trace.after_verify.end();
          const bool after_postprocess = std::find(trace.after_postprocess.begin(), trace.after_postprocess.end(),
                                                   g) != trace.after_postprocess.end();
          verified |= after_verify;
          kept |= after_postprocess;
        }
        if (!own_group) {
          loss = Loss::kGroupedWrongly;
          ++(in_kept_group ? table_.grouped_absorbed : table_.grouped_dropped);
        } else if (!merged_near) {
          loss = Loss::kMergedWrongly;
          ++(mixed ? table_.merged_mixed : table_.merged_own_pairs_only);
        } else if (!kept) {
          loss = Loss::kRejected;
          ++(verified ? table_.rejected_by_postprocess : table_.rejected_by_verify);
        }
      }
    }
    ++table_[loss];
    last_.push_back(loss);
  }
  if (!frame.labels_2d.empty() && records.counted) CountUnmatched(frame, trace, predictions, records, owner);
  CountParts(frame, records);
}

}  // namespace rpt::engine

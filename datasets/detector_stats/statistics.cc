// SPDX-License-Identifier: MIT
#include "datasets/detector_stats/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>

#include "core/errors.h"
#include "core/joints.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::detector_stats {
namespace {

const PersonLabel2D* FindLabel(const SequenceFrame& frame, size_t view, int gt_person) {
  if (view >= frame.labels_2d.size()) return nullptr;
  for (const PersonLabel2D& label : frame.labels_2d[view]) {
    if (label.gt_person == gt_person) return &label;
  }
  return nullptr;
}

// True when at least half of the detection's reported joints lie in the box of a person labelled
// in 2D only (grown by 10 % of its size on every side).
bool OnUnlabelledPerson(const SequenceFrame& frame, size_t view, const Poses2D& detections, int d) {
  if (view >= frame.labels_2d.size()) return false;
  const auto det = detections.Person(d);
  for (const PersonLabel2D& label : frame.labels_2d[view]) {
    if (label.gt_person >= 0 || label.box_px.isZero()) continue;
    const Eigen::Vector2d margin = 0.1 * (label.box_px.tail<2>() - label.box_px.head<2>()).cwiseAbs();
    const Eigen::Vector2d lo = label.box_px.head<2>() - margin, hi = label.box_px.tail<2>() + margin;
    int reported = 0, inside = 0;
    for (int k = 0; k < det.cols(); ++k) {
      if (!(det(2, k) > 0)) continue;
      ++reported;
      inside += (det.col(k).head<2>().array() >= lo.array()).all() && (det.col(k).head<2>().array() <= hi.array()).all();
    }
    if (reported > 0 && 2 * inside >= reported) return true;
  }
  return false;
}

double Mean(const std::vector<double>& values) {
  return values.empty() ? 0 : std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double Ratio(long a, long b) { return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : 0; }

}  // namespace

const char* VisibilityName(int visibility) {
  static const char* const kNames[kNumVisibilities] = {"visible", "occluded", "not labelled", "unknown"};
  return visibility >= 0 && visibility < kNumVisibilities ? kNames[visibility] : "?";
}

double Percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

ErrorSummary Summarize(const std::vector<double>& values) {
  ErrorSummary out;
  out.count = static_cast<long>(values.size());
  out.median = Percentile(values, 0.5);
  out.p90 = Percentile(values, 0.9);
  out.p99 = Percentile(values, 0.99);
  out.mean = Mean(values);
  return out;
}

StatsAccumulator::StatsAccumulator(StatsOptions options) : options_(std::move(options)) {}

void StatsAccumulator::Add(const Sequence& sequence) {
  const JointNames& requested = !options_.joints.empty()            ? options_.joints
                                : !sequence.evaluated_joints.empty() ? sequence.evaluated_joints
                                                                     : EvaluationJoints13();
  JointNames joints;
  std::vector<int> gt_index, det_index, global;
  for (const std::string& name : requested) {
    const int g = FindJoint(sequence.gt_joints, name), d = FindJoint(sequence.detection_joints, name);
    if (g < 0 || d < 0 || FindJoint(joints, name) >= 0) continue;
    joints.push_back(name);
    gt_index.push_back(g);
    det_index.push_back(d);
    int index = FindJoint(joints_, name);
    if (index < 0) {
      joints_.push_back(name);
      per_joint_.emplace_back();
      index = static_cast<int>(joints_.size()) - 1;
    }
    global.push_back(index);
  }
  if (joints.empty()) {
    throw InputError("detector statistics: sequence " + QuoteName(sequence.name) + ": none of the joints " + Join(requested) +
                     " is in both its ground truth and its detections");
  }
  const int num_joints = static_cast<int>(joints.size());
  std::vector<int> mirror(num_joints), side(num_joints);
  for (int k = 0; k < num_joints; ++k) {
    const int m = FindJoint(joints, MirrorJointName(joints[k]));
    mirror[k] = m != k ? m : -1;
    side[k] = JointSide(joints[k]);
  }
  // Shoulders and hips of the GT, for the body frame of the offsets.
  std::vector<int> body_index;
  for (const char* name : {"shoulder_left", "shoulder_right", "hip_left", "hip_right"}) {
    body_index.push_back(FindJoint(sequence.gt_joints, name));
  }
  std::vector<size_t> view_of_camera;
  for (const Camera& camera : sequence.cameras) {
    size_t v = 0;
    while (v < views_.size() && views_[v].camera != camera.name) ++v;
    if (v == views_.size()) views_.push_back(ViewStats{camera.name});
    view_of_camera.push_back(v);
  }

  std::vector<ProjectedPerson> persons;
  std::vector<int> detecting_views;  // per GT person of the frame; -1 = in no view
  for (const SequenceFrame& frame : sequence.frames) {
    if (frame.views.empty()) continue;
    detecting_views.assign(frame.gt.num_persons(), -1);
    for (size_t c = 0; c < frame.views.size(); ++c) {
      const Camera& camera = sequence.cameras[c];
      const Poses2D& view = frame.views[c];
      ViewStats& stats = views_[view_of_camera[c]];
      ++stats.views;
      stats.detections += view.num_persons();
      persons.clear();
      for (int p = 0; p < frame.gt.num_persons(); ++p) {
        ProjectedPerson person = ProjectPerson(camera, frame.gt, p, gt_index);
        if (std::find(person.present.begin(), person.present.end(), 1) != person.present.end()) {
          persons.push_back(std::move(person));
        }
      }
      // Exact copies of an earlier detection of the view (a file artifact, e.g. MVOR's OpenPose
      // file) take no part: they are counted apart.
      const Poses2D* associated = &view;
      Poses2D unique;
      std::vector<int> original;  // per unique detection, its index in `view`
      for (int d = 0; d < view.num_persons(); ++d) {
        bool copy = false;
        for (int e = 0; e < d && !copy; ++e) copy = view.Person(e) == view.Person(d);
        if (!copy) original.push_back(d);
      }
      if (static_cast<int>(original.size()) < view.num_persons()) {
        stats.duplicates += view.num_persons() - static_cast<long>(original.size());
        unique.Clear(view.num_joints);
        for (int d : original) unique.AddPerson() = view.Person(d);
        associated = &unique;
      }
      const Poses2D& detections = *associated;
      const Association association = Associate(persons, detections, det_index, options_.association);

      const bool view_labelled = c < frame.labels_2d.size();
      for (size_t i = 0; i < persons.size(); ++i) {
        const ProjectedPerson& person = persons[i];
        if (person.num_in_image < options_.min_joints_in_image) continue;
        const PersonLabel2D* label = FindLabel(frame, c, person.gt_person);
        std::vector<int> visibility(num_joints, kUnknown);
        int visible = 0, hidden = 0;
        for (int k = 0; k < num_joints; ++k) {
          if (!person.in_image[k]) continue;
          if (view_labelled) {
            const int8_t flag =
                label != nullptr && !label->visibility.empty() ? label->visibility[gt_index[k]] : int8_t{kLabelAbsent};
            visibility[k] = flag == kLabelVisible ? kVisible : flag == kLabelOccluded ? kOccluded : kNotLabelled;
          }
          ++by_visibility_[visibility[k]].joints;
          visible += visibility[k] == kVisible;
          hidden += visibility[k] == kOccluded || visibility[k] == kNotLabelled;
        }
        const int label_class = !view_labelled ? 2 : 2 * visible >= person.num_in_image ? 0 : 1;
        ++stats.gt_in_view;
        ++persons_in_view_;
        detecting_views[person.gt_person] = std::max(detecting_views[person.gt_person], 0);
        ++persons_by_label_[label_class];
        persons_truncated_ += person.truncated;
        (person.truncated ? diagonals_truncated_ : diagonals_).push_back(person.diagonal);
        const int d = association.detection_of_person[i];
        if (d < 0) continue;
        ++detecting_views[person.gt_person];
        ++stats.detected;
        ++detected_by_label_[label_class];
        const auto det = detections.Person(d);
        ++detected_count_;
        for (int k = 0; k < num_joints; ++k) detected_joint_count_ += det(2, det_index[k]) > 0;
        const double diagonal = std::max(person.diagonal, 1.0);
        const bool clear = !person.truncated && hidden == 0;

        // Body frame in the image: axis from the shoulder centre to the hip centre, lateral
        // towards the person's left.
        const ProjectedPerson body = ProjectPerson(camera, frame.gt, person.gt_person, body_index);
        bool has_axis = false, has_lateral = false;
        Eigen::Vector2d axis = Eigen::Vector2d::Zero(), lateral = Eigen::Vector2d::Zero();
        if (std::all_of(body.present.begin(), body.present.end(), [](char p) { return p != 0; })) {
          axis = 0.5 * (body.uv.col(2) + body.uv.col(3) - body.uv.col(0) - body.uv.col(1));
          has_axis = axis.norm() >= 0.05 * diagonal;
          if (has_axis) {
            axis.normalize();
            lateral = body.uv.col(0) - body.uv.col(1) + body.uv.col(2) - body.uv.col(3);
            lateral -= lateral.dot(axis) * axis;
            has_lateral = lateral.norm() >= 0.05 * diagonal;
            if (has_lateral) lateral.normalize();
          }
        }

        for (int k = 0; k < num_joints; ++k) {
          const int j = det_index[k];
          const bool reported = det(2, j) > 0;
          if (!person.in_image[k]) {
            reported_outside_ += person.present[k] && reported;
            continue;
          }
          JointSamples& samples = per_joint_[global[k]];
          VisibilitySamples& category = by_visibility_[visibility[k]];
          const bool is_hidden = visibility[k] == kOccluded || visibility[k] == kNotLabelled;
          ++joints_in_image_;
          ++samples.in_image;
          samples.hidden += is_hidden;
          ++category.of_detected;
          if (!reported) {
            ++joints_missing_;
            ++samples.missing;
            samples.hidden_missing += is_hidden;
            ++category.missing;
            continue;
          }
          const Eigen::Vector2d error_px = det.col(j).head<2>() - person.uv.col(k);
          const double error = error_px.norm() / diagonal;
          const double score = det(2, j);
          all_.push_back(error);
          samples.error.push_back(error);
          samples.confidence_sum += score;
          category.error.push_back(error);
          category.confidence_sum += score;
          (clear ? clear_ : hidden_persons_).push_back(error);
          (score <= 0.5 ? low_ : score < 0.9 ? mid_ : high_).push_back(error);
          confidences_.push_back(score);
          ++histogram_[std::clamp(static_cast<int>(score * 10), 0, 9)];
          ++category.histogram[std::clamp(static_cast<int>(score * 10), 0, 9)];
          if (has_axis) samples.down.push_back(error_px.dot(axis) / diagonal);
          if (has_lateral) samples.out.push_back((side[k] < 0 ? -1.0 : 1.0) * error_px.dot(lateral) / diagonal);
          const int m = mirror[k];
          if (m >= 0 && person.in_image[m] &&
              (person.uv.col(k) - person.uv.col(m)).norm() >= options_.swap_min_separation * diagonal) {
            ++swap_candidates_;
            swaps_ += (det.col(j).head<2>() - person.uv.col(m)).norm() < error_px.norm();
          }
        }
      }

      for (int d = 0; d < detections.num_persons(); ++d) {
        if (association.person_of_detection[d] >= 0) continue;
        if (OnUnlabelledPerson(frame, c, detections, d)) {
          ++stats.on_unlabelled;
          continue;
        }
        ++stats.false_positives;
        for (size_t i = 0; i < persons.size(); ++i) {
          const double distance =
              MeanDistance(persons[i], detections, d, det_index, options_.association.min_common_joints);
          if (distance >= 0 && distance <= options_.association.gate_relative * std::max(persons[i].diagonal, 1.0)) {
            ++stats.false_positives_near_gt;
            break;
          }
        }
        const auto det = detections.Person(d);
        for (int k = 0; k < num_joints; ++k) {
          const double score = det(2, det_index[k]);
          if (score > 0) {
            fp_confidence_sum_ += score;
            ++fp_confidence_count_;
          }
        }
      }
    }
    for (int views : detecting_views) {
      if (views >= 0) ++persons_by_detecting_views_[std::min(views, 3)];
    }
  }
}

DetectorStats StatsAccumulator::Finalize() const {
  DetectorStats out;
  out.joints = joints_;
  out.views = views_;
  out.total.camera = "all";
  for (const ViewStats& v : views_) {
    out.total.views += v.views;
    out.total.gt_in_view += v.gt_in_view;
    out.total.detected += v.detected;
    out.total.detections += v.detections;
    out.total.false_positives += v.false_positives;
    out.total.on_unlabelled += v.on_unlabelled;
    out.total.false_positives_near_gt += v.false_positives_near_gt;
    out.total.duplicates += v.duplicates;
  }
  out.persons_in_view = persons_in_view_;
  out.persons_truncated = persons_truncated_;
  out.truncated_share = Ratio(persons_truncated_, persons_in_view_);
  out.persons_by_label = persons_by_label_;
  out.detected_by_label = detected_by_label_;
  for (int c = 0; c < 3; ++c) out.detection_rate_by_label[c] = Ratio(detected_by_label_[c], persons_by_label_[c]);
  out.persons_by_detecting_views = persons_by_detecting_views_;
  for (long n : persons_by_detecting_views_) out.persons_in_any_view += n;
  out.box_diagonal_px_median = Percentile(diagonals_, 0.5);
  out.box_diagonal_px_median_truncated = Percentile(diagonals_truncated_, 0.5);
  out.all = Summarize(all_);
  std::vector<double> hidden;
  long hidden_joints = 0, labelled_view_joints = 0;
  for (int v = 0; v < kNumVisibilities; ++v) {
    const VisibilitySamples& samples = by_visibility_[v];
    VisibilityStats& stats = out.by_visibility[v];
    stats.joints = samples.joints;
    stats.of_detected = samples.of_detected;
    stats.missing = samples.missing;
    stats.error = Summarize(samples.error);
    stats.confidence_mean = samples.error.empty() ? 0 : samples.confidence_sum / samples.error.size();
    stats.confidence_histogram = samples.histogram;
    if (v == kOccluded || v == kNotLabelled) {
      hidden.insert(hidden.end(), samples.error.begin(), samples.error.end());
      hidden_joints += samples.joints;
    }
    if (v != kUnknown) labelled_view_joints += samples.joints;
  }
  out.hidden = Summarize(hidden);
  out.hidden_share = Ratio(hidden_joints, labelled_view_joints);
  out.clear_persons = Summarize(clear_);
  out.hidden_persons = Summarize(hidden_persons_);
  out.confidence_low = Summarize(low_);
  out.confidence_mid = Summarize(mid_);
  out.confidence_high = Summarize(high_);
  out.joints_in_image = joints_in_image_;
  out.joints_missing = joints_missing_;
  out.missing_rate = Ratio(joints_missing_, joints_in_image_);
  out.reported_outside = reported_outside_;
  out.confidence_histogram = histogram_;
  out.confidence_mean = Mean(confidences_);
  out.confidence_median = Percentile(confidences_, 0.5);
  out.false_positive_confidence_mean = fp_confidence_count_ > 0 ? fp_confidence_sum_ / fp_confidence_count_ : 0;
  out.false_positive_joints_mean = Ratio(fp_confidence_count_, out.total.false_positives);
  out.detected_joints_mean = Ratio(detected_joint_count_, detected_count_);
  out.swap_candidates = swap_candidates_;
  out.swaps = swaps_;
  out.swap_rate = Ratio(swaps_, swap_candidates_);
  for (size_t k = 0; k < joints_.size(); ++k) {
    const JointSamples& s = per_joint_[k];
    JointStats j;
    j.joint = joints_[k];
    j.error = Summarize(s.error);
    j.in_image = s.in_image;
    j.missing = s.missing;
    j.hidden = s.hidden;
    j.hidden_missing = s.hidden_missing;
    j.confidence_mean = s.error.empty() ? 0 : s.confidence_sum / s.error.size();
    j.down_count = static_cast<long>(s.down.size());
    j.out_count = static_cast<long>(s.out.size());
    j.down_mean = Mean(s.down);
    j.down_median = Percentile(s.down, 0.5);
    j.out_mean = Mean(s.out);
    j.out_median = Percentile(s.out, 0.5);
    out.per_joint.push_back(j);
  }
  return out;
}

}  // namespace rpt::detector_stats

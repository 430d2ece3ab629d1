// SPDX-License-Identifier: MIT
// How a 2D detector errs, measured against projected 3D ground truth: detection rate, false
// positives, joint errors relative to the person's size (overall, by visibility, by confidence),
// missing joints, confidences, left/right swaps, per-joint systematic offsets and truncation.
// Works on any Sequence with GT and detections (real, or simulated by the detector model), so the
// simulated detector can be fitted to a real one (docs/detector_model.md; `rpt detector-stats`).
//
// Definitions (statistic joints = joints in both the GT and the detections, see StatsOptions):
// - box: the box of the GT person's statistic joints projected into the camera (Camera::Project,
//   joints in front of the camera), clipped to the image; relative errors are pixel distances
//   divided by its diagonal ("box units").
// - a GT person is in view of a camera when >= min_joints_in_image statistic joints project into
//   the image; it is truncated when one of its statistic joints is outside the image or behind
//   the camera.
// - exact duplicates of a detection in the same view are counted and otherwise ignored.
// - association: per view, GT persons and detections pair one-to-one, greedily by mean distance
//   over the joints both have (association.h). A detection paired with nobody is a false positive,
//   unless it lies on a person the dataset labels in 2D only (no 3D GT): then it is counted apart.
// - joint errors: reported joints (score > 0) of paired persons whose GT joint is in the image.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/joints.h"
#include "datasets/detector_stats/association.h"
#include "datasets/sequence.h"

namespace rpt::detector_stats {

struct StatsOptions {
  JointNames joints;            // statistic joints; empty = each sequence's evaluated joints (empty: the
                                // paper's 13); only those in both its GT and its detections are used
  AssociationOptions association;
  int min_joints_in_image = 2;  // a GT person is in view with this many statistic joints in the image
  double swap_min_separation = 0.05;  // box units: left/right GT partners closer than this are not judged
};

// Distribution of relative joint errors (box units).
struct ErrorSummary {
  long count = 0;
  double median = 0, p90 = 0, p99 = 0, mean = 0;
};

struct ViewStats {
  std::string camera;          // camera name; views of several sequences with the same name add up
  long views = 0;              // frames with detections for this camera
  long gt_in_view = 0;         // GT persons in view
  long detected = 0;           // of those, paired with a detection
  long detections = 0;         // all detections
  long duplicates = 0;         // exact copies of another detection of the same view (ignored otherwise)
  long false_positives = 0;    // paired with no GT person and not on a 2D-only labelled person
  long false_positives_near_gt = 0;  // of those, within the gate of a GT person paired with another detection
  long on_unlabelled = 0;      // paired with no GT person, on a person labelled in 2D only
  double detection_rate() const { return gt_in_view > 0 ? static_cast<double>(detected) / gt_in_view : 0; }
  double false_positives_per_view() const { return views > 0 ? static_cast<double>(false_positives) / views : 0; }
};

// How a dataset's 2D label (or the simulator) sees a GT joint that projects into the image.
enum Visibility : int {
  kVisible = 0,      // labelled visible
  kOccluded = 1,     // labelled occluded
  kNotLabelled = 2,  // the view has 2D labels, but not for this joint (MVOR: flag 0 or no label of the person)
  kUnknown = 3,      // the view has no 2D labels at all (e.g. a dataset without them)
};
constexpr int kNumVisibilities = 4;
const char* VisibilityName(int visibility);  // "visible", "occluded", "not labelled", "unknown"

struct VisibilityStats {
  long joints = 0;            // in-image statistic joints of GT persons in view
  long of_detected = 0;       // of those, of persons paired with a detection
  long missing = 0;           // of those, not reported
  ErrorSummary error;
  double confidence_mean = 0;
  std::array<long, 10> confidence_histogram{};  // reported joints, bins of 0.1
  double missing_rate() const { return of_detected > 0 ? static_cast<double>(missing) / of_detected : 0; }
};

struct JointStats {
  std::string joint;
  ErrorSummary error;
  long in_image = 0;       // GT joints in the image of paired persons
  long missing = 0;        // of those, not reported
  long hidden = 0;         // of those, occluded or not labelled
  long hidden_missing = 0; // of those, not reported
  double confidence_mean = 0;  // of the reported ones
  // Systematic offset in box units in the person's image frame: "down" along the body axis
  // (shoulder centre -> hip centre), "out" across it, away from the body's midline for left/right
  // joints and towards the person's left for the others. Needs both GT shoulders and hips.
  long down_count = 0, out_count = 0;
  double down_mean = 0, down_median = 0, out_mean = 0, out_median = 0;
};

struct DetectorStats {
  JointNames joints;            // statistic joints (union over the sequences)
  std::vector<ViewStats> views; // per camera name, in order of appearance
  ViewStats total;              // camera "all"

  // GT persons in view (over all views), and the detection rate by how the 2D labels see them:
  // mostly visible (at least half of the in-image statistic joints kVisible), mostly hidden
  // (occluded or not labelled), unknown (the view has no 2D labels).
  long persons_in_view = 0, persons_truncated = 0;
  double truncated_share = 0;
  std::array<long, 3> persons_by_label{}, detected_by_label{};
  std::array<double, 3> detection_rate_by_label{};
  double box_diagonal_px_median = 0, box_diagonal_px_median_truncated = 0;
  // Multi-view reach: GT persons (per frame, in view of at least one camera) by the number of
  // views whose detections pair with them: 0, 1, 2, 3 or more. Triangulation needs 2.
  std::array<long, 4> persons_by_detecting_views{};
  long persons_in_any_view = 0;
  double ShareDetectedInViews(int k) const {  // k = 0..3 (3: 3 or more)
    return persons_in_any_view > 0 ? static_cast<double>(persons_by_detecting_views[k]) / persons_in_any_view : 0;
  }

  // Relative joint errors.
  ErrorSummary all;
  std::array<VisibilityStats, kNumVisibilities> by_visibility;  // indexed by Visibility
  ErrorSummary hidden;           // occluded or not labelled
  double hidden_share = 0;       // (occluded + not labelled) / labelled-view joints, persons in view
  ErrorSummary clear_persons;    // persons neither truncated nor with a hidden statistic joint
  ErrorSummary hidden_persons;   // the others: truncated or partly hidden
  ErrorSummary confidence_low, confidence_mid, confidence_high;  // score <= 0.5, (0.5, 0.9), >= 0.9

  long joints_in_image = 0, joints_missing = 0;  // GT joints in the image of paired persons
  double missing_rate = 0;
  long reported_outside = 0;   // reported joints whose GT joint is outside the image (not in the errors)

  std::array<long, 10> confidence_histogram{};  // reported joints, bins of 0.1 (1.0 in the last)
  double confidence_mean = 0, confidence_median = 0;
  double false_positive_confidence_mean = 0;   // mean score of the reported statistic joints of false positives
  double false_positive_joints_mean = 0;       // mean number of reported statistic joints of false positives
  double detected_joints_mean = 0;             // the same for detections paired with a GT person in view

  long swap_candidates = 0, swaps = 0;  // reported left/right joints whose partner is in the image
  double swap_rate = 0;                 // closer to the mirrored GT joint than to its own

  std::vector<JointStats> per_joint;    // in `joints` order
};

class StatsAccumulator {
 public:
  explicit StatsAccumulator(StatsOptions options);
  // Adds every frame with detections. Throws InputError when the sequence's GT and detections
  // share none of the requested joints.
  void Add(const Sequence& sequence);
  DetectorStats Finalize() const;

 private:
  struct JointSamples {
    std::vector<double> error;
    std::vector<double> down, out;
    long in_image = 0, missing = 0, hidden = 0, hidden_missing = 0;
    double confidence_sum = 0;
  };
  struct VisibilitySamples {
    long joints = 0, of_detected = 0, missing = 0;
    std::vector<double> error;
    double confidence_sum = 0;
    std::array<long, 10> histogram{};
  };
  StatsOptions options_;
  JointNames joints_;
  std::vector<JointSamples> per_joint_;
  std::vector<ViewStats> views_;
  std::array<VisibilitySamples, kNumVisibilities> by_visibility_;
  std::vector<double> all_, clear_, hidden_persons_, low_, mid_, high_;
  std::vector<double> diagonals_, diagonals_truncated_;
  std::vector<double> confidences_;
  long persons_in_view_ = 0, persons_truncated_ = 0;
  long joints_in_image_ = 0, joints_missing_ = 0, reported_outside_ = 0;
  long swap_candidates_ = 0, swaps_ = 0;
  double fp_confidence_sum_ = 0;
  long fp_confidence_count_ = 0, detected_joint_count_ = 0, detected_count_ = 0;
  std::array<long, 3> persons_by_label_{}, detected_by_label_{};
  std::array<long, 4> persons_by_detecting_views_{};
  std::array<long, 10> histogram_{};
};

// Linear interpolation between order statistics (numpy's default): q in [0, 1]; 0 for none.
double Percentile(std::vector<double> values, double q);
ErrorSummary Summarize(const std::vector<double>& values);

}  // namespace rpt::detector_stats

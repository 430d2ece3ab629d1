// SPDX-License-Identifier: MIT
// Where the ground-truth persons are lost (`rpt eval --loss-table`, docs/diagnostics.md): each
// kept GT person of each frame (the persons Recall@500 counts) is followed through the
// triangulator's association steps (core/pipeline/frame_trace.h) and put in one category, the
// first that applies:
//
//   found              the metrics match it within 500 mm (it counts in Recall@500)
//   fewer_than_2_views its detections (below) are in fewer than two views: nothing to triangulate
//   pair_filtered      no pair of two of its own detections survives filter
//   grouped_wrongly    such pairs survive, but grouping drops them all or puts them only into
//                      groups that are not its own: a group is a person's own when that person
//                      has more true pairs in it than anybody else
//   merged_wrongly     it has groups of its own, but every one merges into a person >= 500 mm off
//   rejected           such a person (< 500 mm) exists, but verify or postprocess drops it
//   placed_off         such a person is output, yet the final matching does not count it within
//                      500 mm (tracking or post-processing moved it, or it went to another person)
//
// Its detections: per camera, the GT persons (projected with the camera) and the 2D detections
// are paired one-to-one as `rpt detector-stats` pairs them (datasets/detector_stats/association.h,
// on the evaluated joints): a GT person counts as detected in a view when it is in view (at least
// min_joints_in_image joints in the image) and paired with a detection there. Exact copies of a
// detection belong to the person of the original. A pair of two of its detections in different
// views is a *true pair* of the person; a group's pairs are counted per person by their true pairs.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/joints.h"
#include "core/pipeline/frame_trace.h"
#include "datasets/detector_stats/association.h"
#include "datasets/sequence.h"
#include "metrics/eval_options.h"
#include "metrics/eval_records.h"
#include "metrics/pcp.h"

namespace rpt::engine {

enum class Loss : int {
  kFound = 0,
  kFewerThanTwoViews,
  kPairFiltered,
  kGroupedWrongly,
  kMergedWrongly,
  kRejected,
  kPlacedOff,
};
inline constexpr int kNumLosses = 7;
// "found", "fewer_than_2_views", "pair_filtered", ... (the keys of the JSON and CSV).
const char* LossKey(Loss loss);

// The unmatched predictions (those Invalid counts: no match within metrics.match_threshold_mm, in
// frames Invalid counts) of frames that carry 2D person labels (SequenceFrame::labels_2d; MVOR
// labels people in 2D that have no 3D pose), by what they show in the images. A prediction merged
// from pose pairs is judged by the detections it was triangulated from; any other (placed from one
// view, or carried by tracking) by its projection into each camera where at least two of its joints
// land in the image. A detection or projection shows a 3D-labelled person when its joints' box
// overlaps (IoU >= LossTableOptions::label_min_iou) such a person's 2D label best, or, for a
// detection, when it is paired with one (above); it shows a person labelled in 2D only when the
// label it overlaps best has no 3D pose. First that applies:
//
//   labelled_3d         one of them shows a 3D-labelled person (a misplaced or mixed person, or a
//                       ghost made with a labelled person's detection)
//   labelled_2d_only    each shows a person labelled in 2D only: by all appearance a real person
//                       the 3D labels leave out
//   partly_2d_only      some show a person labelled in 2D only, the others nobody labelled
//   unlabelled          none shows a labelled person (false detections, or people nobody labelled)
enum class UnmatchedSource : int {
  kLabelled3d = 0,
  kLabelled2dOnly,
  kPartly2dOnly,
  kUnlabelled,
};
inline constexpr int kNumUnmatchedSources = 4;
// "labelled_3d", "labelled_2d_only", ... (the keys of the JSON).
const char* UnmatchedSourceKey(UnmatchedSource source);

// The steps that can drop a person's last true pair, in pipeline order.
inline constexpr std::array<const char*, 5> kPairDroppers = {"undistort", "prefilter", "triangulate_core",
                                                             "room_check", "filter"};

// The PCP parts (metrics/pcp.h GenericPcpParts(): each part of each kept GT person that PCP
// evaluates) and how far the person's own detections (above) could take them. For each endpoint,
// every pair of two of its detections (two views, both holding the endpoint's joints) is
// triangulated (core/triangulation.h TriangulateDlt on the undistorted coordinates) and the point
// nearest the GT endpoint is taken; a part is *beyond its best pair* when even these nearest points
// miss PCP's gate. Where the detections agree with each other but not with the dataset's joint (an
// elbow every view places 0.2 m from its label), no pair of them reaches the part; a mean of
// several pairs erring in opposite directions can, so it is a reference, not a strict bound.
struct PartLosses {
  long evaluated = 0;               // PCP's denominator
  long wrong = 0;                   // wrong in the output (against the nearest prediction, as PCP)
  long beyond_best_pair = 0;        // no pair of the person's detections reaches it
  long wrong_beyond_best_pair = 0;  // both
  void Merge(const PartLosses& other);
};
inline constexpr int kNumPcpParts = 10;  // GenericPcpParts().size()

// The joint errors of the matched GT persons (matched at metrics.match_threshold_mm) against two
// references made from their own detections, over the same joints: each evaluated joint with a
// valid GT position, a predicted one, and a detection in two or more of the person's views.
//   all_views: the point nearest the rays of all those views, each weighted by its 2D confidence
//              (least squares): plain triangulation that is told the association.
//   best_pair: the pair of two of those views whose triangulation lands nearest the GT joint,
//              chosen with the GT: optimistic for one pair (a mean of several can come closer).
struct JointReferences {
  long joints = 0;
  double output_mm = 0;     // sums over the joints (mm); divide by `joints` for the mean
  double all_views_mm = 0;
  double best_pair_mm = 0;
  void Merge(const JointReferences& other);
};

// The counts over a run (or one sequence). Every kept GT person is in exactly one category, so the
// categories sum to gt_persons; the details split some categories further.
struct LossTable {
  long gt_persons = 0;    // kept GT persons (Recall's denominator)
  long triangulable = 0;  // of those, detected in two or more views
  std::array<long, kNumLosses> count{};
  // Details.
  long found_fewer_than_2_views = 0;  // found, though detected in fewer than two views (coasting, single_view)
  long in_no_view = 0;                // fewer_than_2_views: detected in no view
  long in_one_view = 0;               // fewer_than_2_views: detected in exactly one view
  // pair_filtered: the step that dropped the last true pair, kPairDroppers order (undistort: no
  // pair was made, it dropped the person's poses in all views but one for too few core joints).
  std::array<long, 5> pairs_dropped_by{};
  long grouped_dropped = 0;   // grouped_wrongly: grouping dropped every true pair
  long grouped_absorbed = 0;  // grouped_wrongly: true pairs kept only in groups of other persons
  // merged_wrongly: one of its groups also holds other pairs (cross-person pairs, other persons'
  // pairs), or all hold only its true pairs (the detections themselves triangulate that far off).
  long merged_mixed = 0, merged_own_pairs_only = 0;
  long rejected_by_verify = 0, rejected_by_postprocess = 0;
  // The unmatched predictions of the frames with 2D labels, by UnmatchedSource (they sum to
  // unmatched_with_2d_labels; no frame with 2D labels: all 0).
  long unmatched_with_2d_labels = 0;
  std::array<long, kNumUnmatchedSources> unmatched_by_source{};
  long unmatched_by_projection = 0;  // of those, judged by their projection (not merged from pairs)
  std::array<PartLosses, kNumPcpParts> parts{};  // GenericPcpParts() order
  PartLosses AllParts() const;                    // the sum over the parts
  JointReferences joints;

  long& operator[](Loss loss) { return count[static_cast<int>(loss)]; }
  long operator[](Loss loss) const { return count[static_cast<int>(loss)]; }
  void Merge(const LossTable& other);
};

struct LossTableOptions {
  detector_stats::AssociationOptions association;  // as `rpt detector-stats` (--gate)
  int min_joints_in_image = 2;                      // as `rpt detector-stats --min-joints-in-image`
  double label_min_iou = 0.3;  // a detection shows a labelled person from this box IoU with its 2D label
};

// Follows the GT persons of one sequence, frame by frame.
class LossAccumulator {
 public:
  // `eval` with its evaluated joints resolved (run.h EvalOptionsFor); `output_joints` are the
  // triangulator's.
  LossAccumulator(const SequenceHeader& header, const JointNames& output_joints, const metrics::EvalOptions& eval,
                  const LossTableOptions& options = {});

  // One frame: its input, what the triangulator did (`trace`), its output (`predictions`) and the
  // metrics' records of that output (MetricsAccumulator::LastFrame()).
  void Add(const SequenceFrame& frame, const FrameTrace& trace, const Poses3D& predictions,
           const metrics::FrameRecords& records);

  const LossTable& table() const { return table_; }

  // The category of each kept GT person of the frame added last (records.kept_gt_idx order).
  const std::vector<Loss>& last_frame() const { return last_; }

 private:
  // Per view, the GT person (frame index) of each detection, -1 for none.
  void LabelDetections(const SequenceFrame& frame);
  // The unmatched predictions of a frame with 2D labels into table_.unmatched_by_source;
  // `owner` is the GT person of each traced pose (-1: none).
  void CountUnmatched(const SequenceFrame& frame, const FrameTrace& trace, const Poses3D& predictions,
                      const metrics::FrameRecords& records, const std::vector<int>& owner);
  // The PCP parts of the frame's kept GT persons into table_.parts (after LabelDetections).
  void CountParts(const SequenceFrame& frame, const metrics::FrameRecords& records);
  // The joints of kept GT person k into table_.joints (CountParts' detections and pairs).
  void AddJointReferences(const metrics::FrameRecords& records, int k, size_t num_pairs);

  std::vector<Camera> cameras_;
  LossTableOptions options_;
  std::vector<int> gt_index_, det_index_;  // per association joint: GT / detection joint index
  std::vector<int> pred_eval_;             // per evaluated joint: output joint index (-1: none)
  std::vector<int> det_eval_;              // per evaluated joint: detection joint index (-1: none)
  std::vector<Eigen::Matrix<double, 3, 4>> world_to_camera_;  // per camera: [R | t]
  metrics::GenericPcpLayout pcp_layout_;   // on the evaluated joints
  double pcp_alpha_ = 0.5;
  double min_pred_score_ = 0;
  LossTable table_;
  std::vector<Loss> last_;
  // Per frame scratch.
  std::vector<std::vector<int>> label_;  // [view][detection]
  std::vector<int> detecting_views_;     // per GT person of the frame
  std::vector<int> own_views_;           // CountParts: the views with a detection of the person
  std::vector<Eigen::Vector2d> own_xy_;  // CountParts: [view][evaluated joint], undistorted (NaN: none)
  std::vector<double> own_confidence_;   // CountParts: [view][evaluated joint], 2D confidence (0: none)
  std::vector<Eigen::Vector3d> pair_points_mm_;  // CountParts: [pair][evaluated joint] (NaN: none)
};

}  // namespace rpt::engine

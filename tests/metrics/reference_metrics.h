// SPDX-License-Identifier: MIT
// The oracle of streaming_equivalence_test.cc: MetricsAccumulator as it was before it streamed
// (commit 826ae86), frozen. It keeps one record per candidate (prediction, GT) pair for the whole
// run, runs greedy matching over all of them with dataset-wide GT ids, and reduces every metric
// family over all records in Finalize(). Built on the same primitives (person_error, matching, pcp,
// average_precision) as the library, so its numbers are comparable bit for bit on any build.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "core/joints.h"
#include "core/poses.h"
#include "metrics/eval_options.h"
#include "metrics/metrics_result.h"

namespace rpt::metrics::reference {

class ReferenceAccumulator {
 public:
  explicit ReferenceAccumulator(const EvalOptions& options);
  ~ReferenceAccumulator();
  void Add(std::string_view frame_id, const Poses3D& gt, const JointNames& gt_names, const Poses3D& predictions,
           const JointNames& pred_names, std::span<const double> pred_scores = {});
  MetricsResult Finalize() const;

  // Per frame (in Add order), per prediction: matched at the gate, and the MPJPE to its nearest GT.
  struct FrameMatches {
    std::vector<bool> pred_matched;
    std::vector<int> pred_matched_gt;  // kept-GT index of the match, -1
    std::vector<double> pred_error_mm;
  };
  std::vector<FrameMatches> PerFrameMatches() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rpt::metrics::reference

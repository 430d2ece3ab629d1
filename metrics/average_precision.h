// SPDX-License-Identifier: MIT
// Average precision at an MPJPE threshold (VoxelPose lib/dataset/panoptic.py _eval_list_to_ap).
#pragma once

#include <span>
#include <vector>

#include "metrics/matching.h"

namespace rpt::metrics {

// AP@t in [0, 1] over the nearest-GT records of a whole dataset.
//
// Records are visited in RankRecords() order (score descending); record i is a TP iff
// error_mm < threshold_mm and its GT is not yet detected (GreedyMatch), else a FP. With cumulative
// counts, recall_i = TP_i / num_gt and precision_i = TP_i / (TP_i + FP_i); precision is made monotone
// from the right, and AP = sum_i (recall_i - recall_{i-1}) * precision_i (recall_0 = 0), i.e. the
// area under the step curve. VoxelPose adds 1e-5 to both denominators; we do not (exact values).
// Returns NaN when num_gt == 0 and 0 when there are no records.
double AveragePrecision(std::span<const MatchRecord> records, int num_gt, double threshold_mm);

// The same AP from the records' true-positive flags, already in RankRecords() order.
double RankedAveragePrecision(const std::vector<bool>& ranked_is_tp, int num_gt);

}  // namespace rpt::metrics

// SPDX-License-Identifier: MIT
// Fitting a joint-definition adapter (engine/joint_adapter.h, docs/joint_adapter.md): the input
// is triangulated as `rpt eval` would, each frame's predictions are matched to its GT persons by
// the metrics' own matching (metrics.matching at metrics.match_threshold_mm, the pairs counted as
// matches), and per prediction joint the GT-minus-prediction residuals of the matched persons,
// expressed in the predicted person's body frame (core/body_frame.h), give its offset
// (core/joint_offsets.h). Joints without a GT joint of the same name get none.
#pragma once

#include <memory>
#include <vector>

#include "core/joint_offsets.h"
#include "datasets/frame_source.h"
#include "engine/joint_adapter.h"
#include "engine/run.h"

namespace rpt::engine {

struct JointAdapterFitOptions {
  OffsetStatistic statistic = OffsetStatistic::kMedian;
  long min_samples = 20;  // joints with fewer residuals get no offset
};

// Fits an adapter on every frame of `input` under `options` (its triangulator, its metrics for
// the matching; options.adapter must be null, options.eval set). The result's fit info holds the
// sequences, the frame ids and the counts; the caller fills in dataset, root, params and command.
// Throws ConfigError when the input has no GT or the predictions lack a body frame's joints.
JointAdapter FitJointAdapter(Input& input, const RunOptions& options, const JointAdapterFitOptions& fit);
// The same on sources that are not an opened input (generated scenes, in-memory sequences).
JointAdapter FitJointAdapter(std::span<const Sequence> sequences, const RunOptions& options,
                             const JointAdapterFitOptions& fit);

}  // namespace rpt::engine

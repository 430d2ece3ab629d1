// SPDX-License-Identifier: MIT
// The metric families, each a pure function of the collected records and the match sets that
// fills its fields of MetricsResult (one file each in metrics/reducers/). To add a metric: add its
// field to MetricsResult, write Reduce<Metric>() in a new file here, declare it below, list it in
// MetricReducers() (reducers.cc) and add the file to metrics/CMakeLists.txt.
#pragma once

#include <cmath>
#include <limits>
#include <span>

#include "metrics/eval_options.h"
#include "metrics/eval_records.h"
#include "metrics/metrics_result.h"

namespace rpt::metrics {

using MetricReducer = void (*)(const EvalRecords& records, const MatchSets& matches, const EvalOptions& options,
                               MetricsResult* result);

void ReduceCounts(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);     // num_*
void ReduceRecall(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);     // recall_100/500
void ReduceInvalid(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);    // invalid
void ReduceF1(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);         // f1
void ReduceMpjpe(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);      // mpjpe_mm
void ReducePck(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);        // pck_100/500
void ReducePerJoint(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);   // joints
void ReduceAp(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);         // ap
void ReducePcp(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);        // pcp, pcp_parts
void ReduceLegacyPcp(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);  // legacy_pcp
void ReduceWholeBody(const EvalRecords&, const MatchSets&, const EvalOptions&, MetricsResult*);  // wholebody

// Every reducer, in the order Finalize() runs them (each writes its own fields only).
std::span<const MetricReducer> MetricReducers();

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// 100 * numerator / denominator, NaN when the denominator is zero.
inline double Percent(double numerator, double denominator) {
  return denominator > 0 ? 100.0 * numerator / denominator : kNaN;
}

}  // namespace rpt::metrics

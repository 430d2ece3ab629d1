// SPDX-License-Identifier: MIT
#include "metrics/reducers/reducers.h"

namespace rpt::metrics {

std::span<const MetricReducer> MetricReducers() {
  static constexpr MetricReducer kReducers[] = {
      ReduceCounts, ReduceRecall,  ReduceInvalid, ReduceF1,        ReduceMpjpe,     ReducePck,
      ReducePerJoint, ReduceAp,    ReducePcp,     ReduceLegacyPcp, ReduceWholeBody,
  };
  return kReducers;
}

}  // namespace rpt::metrics

// SPDX-License-Identifier: MIT
// When a ground-truth joint exists: the datasets store absent joints with a low score (Panoptic
// writes its confidences, the others 0), so a GT joint counts only with a score above this.
#pragma once

namespace rpt {

inline constexpr double kGtPresentScore = 0.1;

}  // namespace rpt

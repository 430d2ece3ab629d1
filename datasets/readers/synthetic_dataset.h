// SPDX-License-Identifier: MIT
// "synthetic": a generated scene with simulated detections, as a dataset (no files needed).
#pragma once

#include <vector>

#include "datasets/dataset_request.h"
#include "datasets/sequence.h"

namespace rpt {

DatasetInfo SyntheticInfo();
std::vector<Sequence> ReadSynthetic(const DatasetRequest& request);

}  // namespace rpt

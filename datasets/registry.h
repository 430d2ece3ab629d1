// SPDX-License-Identifier: MIT
// The dataset readers by name (one line per reader in registry.cc).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "datasets/dataset_request.h"
#include "datasets/sequence.h"

namespace rpt {

struct DatasetEntry {
  DatasetInfo info;
  std::function<std::vector<Sequence>(const DatasetRequest&)> read;
};

const std::vector<DatasetEntry>& DatasetRegistry();

// Reads request.dataset; throws ConfigError for an unknown dataset (listing the known ones).
std::vector<Sequence> ReadDataset(const DatasetRequest& request);

}  // namespace rpt

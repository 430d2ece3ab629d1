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

// The parameters of every reader as Markdown: one "### <name>" heading and one table (parameter,
// default, type, meaning) per dataset, as docs/datasets.md shows them between its
// "<!-- dataset-params:begin -->" and "<!-- dataset-params:end -->" markers.
std::string DatasetParamsMarkdown();

// Reads request.dataset; throws ConfigError for an unknown dataset (listing the known ones).
std::vector<Sequence> ReadDataset(const DatasetRequest& request);

}  // namespace rpt

// SPDX-License-Identifier: MIT
// The dataset readers by name (one line per reader in registry.cc).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_request.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt::engine {

struct DatasetEntry {
  DatasetInfo info;
  std::function<std::vector<Sequence>(const DatasetRequest&)> read;
  // Readers that stream frame by frame (datasets/frame_source.h); empty: the reader loads whole.
  std::function<std::vector<std::unique_ptr<FrameSource>>(const DatasetRequest&)> stream = {};
};

const std::vector<DatasetEntry>& DatasetRegistry();

// The parameters of every reader as Markdown: one "### <name>" heading and one table (parameter,
// default, type, meaning) per dataset, as docs/datasets.md shows them between its
// "<!-- dataset-params:begin -->" and "<!-- dataset-params:end -->" markers.
std::string DatasetParamsMarkdown();

// The sequences of request.dataset as frame sources (one per sequence). Throws ConfigError for an
// unknown dataset (listing the known ones) and what the reader throws.
std::vector<std::unique_ptr<FrameSource>> OpenDataset(const DatasetRequest& request);
// The same sequences read whole (every source materialised; not validated: OpenInput validates).
std::vector<Sequence> ReadDataset(const DatasetRequest& request);

}  // namespace rpt::engine

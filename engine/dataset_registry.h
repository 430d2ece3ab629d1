// SPDX-License-Identifier: MIT
// The dataset readers by name (one line per reader in registry.cc), and the one place a dataset
// request is dispatched to its reader.
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
  // Open<Name> (datasets/dataset_request.h): one frame source per sequence.
  std::function<std::vector<std::unique_ptr<FrameSource>>(const DatasetRequest&)> open;
};

const std::vector<DatasetEntry>& DatasetRegistry();

// The parameters of every reader as Markdown: one "### <name>" heading and one table (parameter,
// default, type, meaning) per dataset, as docs/datasets.md shows them between its
// "<!-- dataset-params:begin -->" and "<!-- dataset-params:end -->" markers.
std::string DatasetParamsMarkdown();

// The sequences of request.dataset as frame sources, one per sequence, from its reader. Throws
// ConfigError for an unknown dataset (listing the known ones) and what the reader throws before
// the first frame (missing files, unknown cameras, bad parameters).
std::vector<std::unique_ptr<FrameSource>> OpenDataset(const DatasetRequest& request);
// OpenDataset's sources materialised (MaterializeAll): every frame of every sequence in memory.
// Frames are not validated here (the consumer validates: datasets/sequence.h).
std::vector<Sequence> ReadDataset(const DatasetRequest& request);
// Throws ConfigError for an unknown dataset name, listing the known ones (as OpenDataset does).
void CheckDatasetName(const std::string& dataset);
// The reader called `dataset`'s description, or nullptr for an unknown name.
const DatasetInfo* FindDatasetInfo(const std::string& dataset);

}  // namespace rpt::engine

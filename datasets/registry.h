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

namespace rpt {

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

// Reads request.dataset; throws ConfigError for an unknown dataset (listing the known ones).
std::vector<Sequence> ReadDataset(const DatasetRequest& request);
// The sequences of request.dataset as frame sources: streamed where the reader streams
// (DatasetEntry::stream), else the loaded sequences behind SequenceSource. Same errors.
std::vector<std::unique_ptr<FrameSource>> StreamDataset(const DatasetRequest& request);
// Whether the reader of `dataset` streams frame by frame (false for unknown names).
bool DatasetStreams(const std::string& dataset);

}  // namespace rpt

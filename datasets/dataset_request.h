// SPDX-License-Identifier: MIT
// What a dataset reader is asked for, and how it describes itself.
//
// Every reader is a pair of functions (datasets/readers/<name>.h):
//   DatasetInfo <Name>Info();
//   std::vector<Sequence> Read<Name>(const DatasetRequest& request);
// and, where the format can be walked frame by frame, a third:
//   std::vector<std::unique_ptr<FrameSource>> Stream<Name>Dataset(const DatasetRequest& request);
// registered beside the other two (engine/dataset_registry.cc). A FrameSource (datasets/frame_source.h)
// announces the SequenceHeader (name, cameras, joint names, room, fps) and then hands out one
// frame per Next() into the caller's buffer: memory flat in the number of frames. Read<Name> of a
// streaming reader is the same frames materialised (Materialize), so both give the same numbers.
// StreamDataset (registry.h) gives every dataset as sources: the loaded sequences of readers that
// do not stream go behind SequenceSource. Which readers stream and why the others load whole:
// docs/datasets.md, "Streaming".
// and a <Name>Params struct with VisitFields: the reader parses request.params into it once
// (ParseDatasetParams, datasets/dataset_params.h) and <Name>Info() lists it (DescribeDatasetParams).
// Read<Name> walks the data once and returns the sequences with their ground truth and, when a
// detections parameter asks for the dataset's own 2D (e.g. detections=voxelpose, =cache,
// =annotations), the frames' views filled in the same walk.
// Readers convert everything to metres in a z-up world frame where the dataset allows it, name
// joints like core/joints.h (nose, shoulder_left, ...; dataset-specific extras such as
// head_top), and set frame ids "<dataset>[_<sequence>]_<frame number, 6 digits>".
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rpt {

struct DatasetParam {
  std::string name;           // e.g. "frames"
  std::string default_value;  // as text; empty = none
  std::string help;           // one line
  std::string type;           // what the value must be, e.g. "integer in [2, 64]", "none | voxelpose"
};

struct DatasetInfo {
  std::string name;                 // registry name, e.g. "shelf"
  std::string description;          // one line
  std::string layout;               // what must be on disk under --root (multi-line ok)
  std::vector<DatasetParam> params;  // accepted --param key=value options
};

struct DatasetRequest {
  std::string dataset;
  std::filesystem::path root;
  std::map<std::string, std::string> params;  // key=value from the command line (parsed by the reader)
};

// Parses frame selections like "300-600", "350-470,650-750", "0-3199:12" (every 12th) into a
// sorted list of frame numbers. Throws ConfigError naming `what` on malformed text.
std::vector<int> ParseFrameRanges(const std::string& text, const std::string& what);

}  // namespace rpt

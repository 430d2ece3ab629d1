// SPDX-License-Identifier: MIT
// What a dataset reader is asked for, and how it describes itself.
//
// Every reader is a pair of functions (datasets/readers/<name>.h):
//   DatasetInfo <Name>Info();
//   std::vector<std::unique_ptr<FrameSource>> Open<Name>(const DatasetRequest& request);
// registered together (engine/dataset_registry.cc), and a <Name>Params struct with VisitFields: the
// reader parses request.params into it once (ParseDatasetParams, datasets/dataset_params.h) and
// <Name>Info() lists it (DescribeDatasetParams).
// Open<Name> returns one FrameSource (datasets/frame_source.h) per sequence. Everything that is
// wrong before the first frame is thrown by Open<Name> itself: bad parameters (ConfigError), a
// missing root, calibration or annotation file, unknown cameras, subjects or sequences, malformed
// headers (InputError naming the file and the place). Each source then announces the
// SequenceHeader (name, cameras, joint names, room, fps) and converts one frame at a time into the
// caller's buffer (Pull, then Complete for the part that may run on several frames at once), so
// memory stays flat in the number of frames: formats with a file per frame read it when the frame
// is pulled; formats with every frame in one file (a .mat, JSON, NumPy or text file) keep that
// file parsed and convert frame i from it (IndexedFrameSource), never holding the converted frames
// of a sequence. Reading a whole dataset is its sources materialised
// (ReadDataset, MaterializeAll). How each reader yields its frames: docs/datasets.md, "Streaming".
// Readers do not validate (ValidateFrame, datasets/sequence.h): the consumer validates every frame
// once. They still throw InputError for what they cannot parse and accept, correct and count
// real-world imprecision (the source's warnings(), datasets/input_warnings.h).
// When a detections parameter asks for the dataset's own 2D (e.g. detections=voxelpose, =openpose,
// =cache, =annotations) each frame's views are attached by its source as the frame is converted.
// With request.ground_truth false a reader that can give frames without its ground-truth files
// (the frames of its detections or of its `frames` parameter) does so, with no persons and empty
// gt_joints; one that cannot throws ConfigError saying why.
// Readers convert everything to metres in a z-up world frame where the dataset allows it, name
// joints like core/joints.h (nose, shoulder_left, ...; dataset-specific extras such as
// head_top), set frame ids "<dataset>[_<sequence>]_<frame number, 6 digits>", and give frame
// times in seconds from the data (its clock or its frame rate), kUnknownTime (NaN) where the data
// has none.
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
  // Every frame id the reader gives starts with this and ends in the frame's number
  // ("panoptic_" for panoptic_160906_band1_000180); empty: ids of no such form. A detections file's
  // frame of this form that no selected frame uses is one the selection (frames=, every=, days=,
  // sequences=) left out, not unused input.
  std::string frame_id_prefix;
};

struct DatasetRequest {
  std::string dataset;
  std::filesystem::path root;
  std::map<std::string, std::string> params;  // key=value from the command line (parsed by the reader)
  // false: only the detections are wanted; the reader runs without its ground-truth files where it
  // can (frames without persons), else throws ConfigError.
  bool ground_truth = true;
};

// Parses frame selections like "300-600", "350-470,650-750", "0-3199:12" (every 12th) into a
// sorted list of frame numbers. Throws ConfigError naming `what` on malformed text.
std::vector<int> ParseFrameRanges(const std::string& text, const std::string& what);

}  // namespace rpt

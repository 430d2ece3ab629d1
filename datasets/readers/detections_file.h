// SPDX-License-Identifier: MIT
// Entry points for the files a user names on the command line: 2D detections of any supported
// format, and generic labels (JSON or the HDF5 cache).
#pragma once

#include <filesystem>
#include <vector>

#include "datasets/detections.h"
#include "datasets/readers/coco_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/openpose_json.h"

namespace rpt {

struct DetectionsFileOptions {
  OpenPoseFolderOptions openpose;  // used for folders
  CocoDetectionsOptions coco;      // used for JSON result lists
};

// Dispatches on what `path` is:
//   folder                 -> OpenPose JSON folder (ReadOpenPoseFolder)
//   *.h5, *.hdf5           -> HDF5 cache (ReadDetectionsHdf5)
//   *.json, an object      -> generic detections {"joints", "frames"} (ReadGenericDetections)
//   *.json, a list         -> COCO-style result list (ReadCocoDetections)
//   *.pkl                  -> VoxelPose 2D caches: not read here (InputError saying so)
// Throws InputError for a missing path and for anything else, listing the supported formats.
Detections ReadDetectionsFile(const std::filesystem::path& path, const DetectionsFileOptions& options = {});

// Labels: *.h5 / *.hdf5 -> ReadSequencesHdf5 (options.split must be empty: the cache keeps no
// splits; options.fps is unused, timestamps are stored), anything else -> ReadLabels (JSON).
std::vector<Sequence> ReadLabelsFile(const std::filesystem::path& path, const LabelsOptions& options = {});

// One line per supported format, for help texts and error messages.
const char* SupportedDetectionFormats();

}  // namespace rpt

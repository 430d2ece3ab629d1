// SPDX-License-Identifier: MIT
// Entry points for the files a user names on the command line: 2D detections of any supported
// format, and generic labels (JSON or the HDF5 cache).
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/readers/coco_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/openpose_json.h"
#include "datasets/readers/voxelpose_detections.h"

namespace rpt {

struct DetectionsFileOptions {
  OpenPoseFolderOptions openpose;  // used for folders
  CocoDetectionsOptions coco;      // used for JSON result lists
  // Used for VoxelPose caches, whose keys "<camera>_<frame>" name neither the sequence nor its
  // frame ids: the frame-id prefix of the sequence (required) and its camera names.
  VoxelPoseDetectionsOptions voxelpose;
};

// The formats ReadDetectionsFile reads.
enum class DetectionsFormat { kOpenPoseFolder, kHdf5Cache, kGenericJson, kCocoResults, kVoxelPosePickle };

// What `path` is (the dispatch below): a folder, then the extension, then for .json the first
// significant character. Throws InputError for a missing path, an unknown extension, and a .json
// file that is neither an object nor a list.
DetectionsFormat DetectionsFormatOf(const std::filesystem::path& path);
// "an OpenPose folder", "an HDF5 cache", "generic detections JSON", "a COCO result list",
// "a VoxelPose .pkl cache": for messages.
const char* DetectionsFormatName(DetectionsFormat format);

// Dispatches on what `path` is (DetectionsFormatOf):
//   folder                 -> OpenPose JSON folder (ReadOpenPoseFolder)
//   *.h5, *.hdf5           -> HDF5 cache (ReadDetectionsHdf5)
//   *.json, an object      -> generic detections {"joints", "frames"} (ReadGenericDetections)
//   *.json, a list         -> COCO-style result list (ReadCocoDetections)
//   *.pkl, *.pickle        -> VoxelPose 2D cache (ReadVoxelPoseDetections with options.voxelpose;
//                             ConfigError when it has no frame-id prefix)
// Throws InputError for a missing path and for anything else, listing the supported formats.
Detections ReadDetectionsFile(const std::filesystem::path& path, const DetectionsFileOptions& options = {});

// Labels, one source per sequence: *.h5 / *.hdf5 -> OpenSequencesHdf5 (options.split must be empty:
// the cache keeps no splits; options.fps is unused, timestamps are stored), anything else ->
// OpenLabels (JSON; without `ground_truth` its persons are not read). The cache's sequences always
// carry their GT.
std::vector<std::unique_ptr<FrameSource>> OpenLabelsFile(const std::filesystem::path& path,
                                                         const LabelsOptions& options = {}, bool ground_truth = true);

// One line per supported format, for help texts and error messages.
const char* SupportedDetectionFormats();

}  // namespace rpt

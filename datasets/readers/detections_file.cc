// SPDX-License-Identifier: MIT
#include "datasets/readers/detections_file.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/detections.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_internal.h"
#include "datasets/readers/hdf5_cache.h"

namespace rpt {

const char* SupportedDetectionFormats() {
  return "  a folder of OpenPose JSON files (<camera>/<video>_<frame>_keypoints.json)\n"
         "  .json with {\"joints\": [...], \"frames\": [...]} (generic detections)\n"
         "  .json with a list of COCO results [{\"image_id\", \"keypoints\", ...}]\n"
         "  .h5 / .hdf5 detection cache (rpt convert)\n"
         "  .pkl VoxelPose 2D cache {\"<camera>_<frame>\": [{\"pred\": 17x3}]} (Shelf, Campus)";
}

namespace {

std::string LowerExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

bool IsHdf5Extension(const std::filesystem::path& path) {
  const std::string extension = LowerExtension(path);
  return extension == ".h5" || extension == ".hdf5";
}

}  // namespace

std::vector<std::unique_ptr<FrameSource>> OpenLabelsFile(const std::filesystem::path& path,
                                                         const LabelsOptions& options, bool ground_truth) {
  if (!IsHdf5Extension(path)) return OpenLabels(path, options, ground_truth);
  if (!options.split.empty()) {
    throw ConfigError(path.string() + ": an HDF5 cache keeps no splits; select the split when converting (split '" +
                      options.split + "' requested)");
  }
  return OpenSequencesHdf5(path);
}

DetectionsFormat DetectionsFormatOf(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(source + ": file not found");
  if (std::filesystem::is_directory(path, ec)) return DetectionsFormat::kOpenPoseFolder;
  // A FIFO, a device or a socket: never read (it may block or never end), whatever its name.
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(source + ": not a regular file");
  if (IsHdf5Extension(path)) return DetectionsFormat::kHdf5Cache;
  const std::string extension = LowerExtension(path);
  if (extension == ".json") {
    const char first = generic_internal::FirstSignificantChar(path);
    if (first == '[') return DetectionsFormat::kCocoResults;
    if (first == '{') return DetectionsFormat::kGenericJson;
    throw InputError(source + ":1:1: expected a JSON object (generic detections) or a list (COCO results); supported:\n" +
                     SupportedDetectionFormats());
  }
  if (extension == ".pkl" || extension == ".pickle") return DetectionsFormat::kVoxelPosePickle;
  throw InputError(source + ": unknown detection format " + QuoteName(extension) + "; supported:\n" + SupportedDetectionFormats());
}

const char* DetectionsFormatName(DetectionsFormat format) {
  switch (format) {
    case DetectionsFormat::kOpenPoseFolder:
      return "an OpenPose folder";
    case DetectionsFormat::kHdf5Cache:
      return "an HDF5 cache";
    case DetectionsFormat::kGenericJson:
      return "generic detections JSON";
    case DetectionsFormat::kCocoResults:
      return "a COCO result list";
    case DetectionsFormat::kVoxelPosePickle:
      return "a VoxelPose .pkl cache";
  }
  return "?";
}

namespace {

Detections ReadDetectionsFormat(const std::filesystem::path& path, const DetectionsFileOptions& options) {
  switch (DetectionsFormatOf(path)) {
    case DetectionsFormat::kOpenPoseFolder:
      return ReadOpenPoseFolder(path, options.openpose);
    case DetectionsFormat::kHdf5Cache:
      return ReadDetectionsHdf5(path);
    case DetectionsFormat::kGenericJson:
      return ReadGenericDetections(path);
    case DetectionsFormat::kCocoResults:
      return ReadCocoDetections(path, options.coco);
    case DetectionsFormat::kVoxelPosePickle:
      return ReadVoxelPoseDetections(path, options.voxelpose);
  }
  throw InputError(path.string() + ": unknown detection format");
}

}  // namespace

Detections ReadDetectionsFile(const std::filesystem::path& path, const DetectionsFileOptions& options) {
  Detections detections = ReadDetectionsFormat(path, options);
  long origin = 0;
  for (FrameDetections& frame : detections.frames) {
    for (Poses2D& view : frame.views) origin += ReadOriginJointsAsMissing(&view);
  }
  detections.warnings.Add(path.string(), kOriginJointsRead, "", 0, origin);
  return detections;
}

}  // namespace rpt

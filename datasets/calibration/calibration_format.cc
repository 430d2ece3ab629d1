// SPDX-License-Identifier: MIT
// Which calibration format a path holds (DetectCalibrationFormat) or is written in
// (CalibrationFormatForOutput), and the length units.
#include <algorithm>
#include <cctype>

#include "core/errors.h"
#include "datasets/calibration/calibration.h"
#include "datasets/calibration/opencv_yml.h"
#include "datasets/calibration/file_storage.h"
#include "datasets/io/json_file.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool IsStorageExtension(const std::string& extension) {
  return extension == ".yml" || extension == ".yaml" || extension == ".xml";
}

// The JSON calibrations, told apart by their first camera's keys.
CalibrationFormat DetectJson(const fs::path& path) {
  const nlohmann::json root = io::LoadJsonFile(path);
  if (root.is_array()) return CalibrationFormat::kJson;  // a labels file
  if (!root.is_object() || root.empty()) {
    throw InputError(path.string() + ": /: expected a JSON object of cameras (or a list of labels)");
  }
  if (const auto cameras = root.find("cameras"); cameras != root.end()) {
    if (cameras->is_array() && !cameras->empty() && (*cameras)[0].is_object()) {
      const nlohmann::json& first = (*cameras)[0];
      if (first.contains("resolution") || first.contains("distCoef") || first.contains("t"))
        return CalibrationFormat::kPanoptic;
    }
    return CalibrationFormat::kJson;
  }
  // OpenCV FileStorage written as JSON (cv::FileStorage("x.json", WRITE)): matrices are objects
  // tagged "type_id": "opencv-matrix".
  for (const auto& [key, value] : root.items()) {
    if (value.is_object() && value.value("type_id", nlohmann::json()) == "opencv-matrix") return CalibrationFormat::kOpenCV;
  }
  const nlohmann::json& first = root.begin().value();
  if (first.is_object() && first.contains("fx")) return CalibrationFormat::kVoxelPose;
  if (first.is_object() && (first.contains("imgSize") || first.contains("RT"))) return CalibrationFormat::kFourDa;
  throw InputError(
      path.string() +
      ": cannot tell which calibration JSON this is: expected \"cameras\" (ours, Panoptic), "
      "cameras keyed by id with \"fx\" (VoxelPose) or \"imgSize\" / \"RT\" (4D-Association), or OpenCV "
      "FileStorage matrices (\"type_id\": \"opencv-matrix\"); set the format (e.g. --format opencv)");
}

}  // namespace

double MetresPerUnit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kCentimetres:
      return 0.01;
    case LengthUnit::kMillimetres:
      return 0.001;
    case LengthUnit::kDefault:
    case LengthUnit::kMetres:
      break;
  }
  return 1.0;
}

const char* LengthUnitWord(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kCentimetres:
      return "centimetres";
    case LengthUnit::kMillimetres:
      return "millimetres";
    case LengthUnit::kDefault:
    case LengthUnit::kMetres:
      break;
  }
  return "metres";
}

CalibrationFormat DetectCalibrationFormat(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (IsRegularFile(path / "cameras.txt") && IsRegularFile(path / "images.txt")) return CalibrationFormat::kColmap;
    if (IsRegularFile(path / "intri.yml") && IsRegularFile(path / "extri.yml")) return CalibrationFormat::kEasyMocap;
    if (!OpenCVFilesIn(path).empty()) return CalibrationFormat::kOpenCV;
    throw InputError(path.string() +
                     ": a folder, but it holds neither cameras.txt + images.txt (COLMAP), intri.yml + "
                     "extri.yml (EasyMocap) nor OpenCV files, one per camera (*.yml, *.yaml, *.xml)");
  }
  if (!fs::exists(path, ec)) throw InputError(path.string() + ": file not found");
  // A FIFO, a device or a socket: never read (it may block or never end).
  if (!IsRegularFile(path)) throw InputError(path.string() + ": not a regular file");
  const std::string name = Lower(path.filename().string());
  const std::string extension = Lower(path.extension().string());
  const std::string stem = Lower(path.stem().string());
  if (name == "cameras.txt" || name == "images.txt") return CalibrationFormat::kColmap;
  if ((stem == "intri" || stem == "extri") && IsStorageExtension(extension)) return CalibrationFormat::kEasyMocap;
  if (extension == ".toml") return CalibrationFormat::kToml;
  if (extension == ".json") return DetectJson(path);
  if (IsStorageExtension(extension)) {
    const file_storage::File file = file_storage::ReadFile(path);
    return file.Find("names") != nullptr ? CalibrationFormat::kEasyMocap : CalibrationFormat::kOpenCV;
  }
  // A pickle is none of the calibration formats: Human3.6M's cameras.pkl holds cameras per subject,
  // which only its dataset reader knows how to pick ("set the format" would send the user nowhere).
  if (extension == ".pkl" || extension == ".pickle") {
    throw InputError(path.string() +
                     ": a Python pickle, which is no calibration format rpt reads as a file (Human3.6M's "
                     "cameras.pkl is read with its dataset: --dataset human36m --root DIR; convert other cameras to "
                     "*.json, *.toml or *.yml)");
  }
  throw InputError(path.string() +
                   ": cannot tell the calibration format from the name (expected *.json, *.toml, "
                   "*.yml, *.yaml, *.xml, cameras.txt / images.txt or a folder); set the format");
}

CalibrationWriteFormat CalibrationFormatForOutput(const fs::path& path) {
  const std::string extension = Lower(path.extension().string());
  const std::string stem = Lower(path.stem().string());
  if (extension == ".json") return CalibrationWriteFormat::kJson;
  if (extension == ".toml") return CalibrationWriteFormat::kToml;
  if ((stem == "intri" || stem == "extri") && IsStorageExtension(extension)) return CalibrationWriteFormat::kEasyMocap;
  if (IsStorageExtension(extension)) return CalibrationWriteFormat::kOpenCV;
  throw ConfigError(path.string() +
                    ": cannot tell the format to write from the name (expected *.json, *.toml, "
                    "*.yml, *.yaml, *.xml or intri.yml); set the format");
}

bool IsRegularFile(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
// ReadCalibration and WriteCalibration: the dispatch to the format readers and writers, the
// description of the reused dataset readers' conventions, and the checks every format shares
// (unique names, implausible rigs, cameras a writer can hold).
#include "datasets/calibration/calibration.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <set>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/utf8.h"
#include "datasets/calibration/camera_group_toml.h"
#include "datasets/calibration/cameras_json.h"
#include "datasets/calibration/colmap_calibration.h"
#include "datasets/calibration/easymocap_yml.h"
#include "datasets/calibration/file_storage.h"
#include "datasets/calibration/opencv_yml.h"
#include "datasets/camera_plausibility.h"
#include "datasets/readers/fourda_calibration.h"
#include "datasets/readers/panoptic.h"
#include "datasets/readers/voxelpose_calibration.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

std::string FormatName(CalibrationFormat format) { return std::string(EnumName(format)); }

const char* FormatTitle(CalibrationFormat format) {
  switch (format) {
    case CalibrationFormat::kJson:
      return "rpt cameras JSON (the camera schema of the generic labels)";
    case CalibrationFormat::kOpenCV:
      return "OpenCV FileStorage (calibrateCamera / stereoCalibrate / ROS camera_info keys)";
    case CalibrationFormat::kEasyMocap:
      return "EasyMocap intri.yml + extri.yml (OpenCV FileStorage)";
    case CalibrationFormat::kToml:
      return "Pose2Sim / anipose camera group (TOML)";
    case CalibrationFormat::kColmap:
      return "COLMAP text model (cameras.txt + images.txt)";
    case CalibrationFormat::kVoxelPose:
      return "VoxelPose calibration JSON";
    case CalibrationFormat::kPanoptic:
      return "CMU Panoptic calibration JSON";
    case CalibrationFormat::kFourDa:
      return "4D-Association calibration JSON";
    case CalibrationFormat::kAuto:
      break;
  }
  return "unknown";
}

// The unit a format fixes, or kDefault when the file's unit is the user's choice.
LengthUnit FixedUnit(CalibrationFormat format) {
  switch (format) {
    case CalibrationFormat::kJson:
    case CalibrationFormat::kFourDa:
      return LengthUnit::kMetres;
    case CalibrationFormat::kVoxelPose:
      return LengthUnit::kMillimetres;
    case CalibrationFormat::kPanoptic:
      return LengthUnit::kCentimetres;
    default:
      return LengthUnit::kDefault;
  }
}

// The descriptions of the dataset readers reused here.
CalibrationDescription DatasetReaderDescription(CalibrationFormat format, const fs::path& path) {
  CalibrationDescription d;
  d.format = format;
  d.files = {path};
  d.units = FixedUnit(format);
  d.rotation = "3x3 matrix";
  if (format == CalibrationFormat::kVoxelPose) {
    d.extrinsics = "world to camera with the camera centre T: x_cam = R (X - T)";
    d.distortion = "radial k (k1 k2 k3) and tangential p (p1 p2), OpenCV's model";
    d.notes.emplace_back(
        "image sizes are not in the file: --image-width / --image-height (with --cameras: --cameras-image-width / "
        "--cameras-image-height; Python: image_width= / image_height=), else twice the principal point");
  } else if (format == CalibrationFormat::kPanoptic) {
    d.extrinsics = "world to camera: x_cam = R X + t";
    d.distortion = "distCoef: OpenCV radial-tangential k1 k2 p1 p2 k3";
    d.notes.emplace_back("Panoptic world (y down) turned to rpt's (z up): (x, y, z) -> (x, z, -y)");
    d.notes.emplace_back("every camera of the file (HD, VGA, Kinect)");
  } else {
    d.extrinsics = "world to camera: x_cam = R X + t (\"RT\" 3x4, or \"R\" and \"T\")";
    d.rotation = "3x3 matrix (\"RT\", or \"R\" as 9 numbers), or Rodrigues vector (\"R\" as 3 numbers)";
    d.distortion = "none (distCoeff must be zero)";
  }
  return d;
}

// Rotations accepted as round-off (max |R^T R - I| <= kRotationRoundOff, uncounted) are made
// exact: a rotation orthonormal to only 1e-9 changes projections by ~1e-6 px once written as a
// Rodrigues vector or with the camera centre, so every format would hold a slightly different
// camera. Beyond round-off the readers have already replaced R (AcceptRotation, counted).
void MakeRotationsExact(std::vector<Camera>* cameras) {
  constexpr double kExact = 1e-15;
  for (Camera& camera : *cameras) {
    if ((camera.R.transpose() * camera.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= kExact) continue;
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(camera.R, Eigen::ComputeFullU | Eigen::ComputeFullV);
    camera.R = svd.matrixU() * svd.matrixV().transpose();
  }
}

void CheckUniqueNames(const std::vector<Camera>& cameras, const std::string& source) {
  std::set<std::string> names;
  for (const Camera& camera : cameras) {
    if (!names.insert(camera.name).second)
      throw InputError(source + ": camera name " + QuoteName(camera.name) + " appears twice");
  }
}

// An existing folder gets intri.yml and extri.yml; intri.* / extri.* name the pair.
std::pair<fs::path, fs::path> EasyMocapOutput(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return {path / "intri.yml", path / "extri.yml"};
  const std::string stem = path.stem().string();
  if (stem != "intri" && stem != "extri") {
    throw ConfigError(path.string() +
                      ": the EasyMocap layout is two files: give intri.yml (extri.yml is written beside "
                      "it) or a folder");
  }
  const std::string extension = path.extension().string();
  return {path.parent_path() / ("intri" + extension), path.parent_path() / ("extri" + extension)};
}

}  // namespace

std::vector<std::string> CalibrationDescription::Lines() const {
  std::vector<std::string> lines;
  lines.push_back("format: " + FormatName(format) + ", " + FormatTitle(format));
  std::string list;
  for (const fs::path& file : files) list += (list.empty() ? "" : ", ") + file.string();
  lines.push_back("files: " + list);
  lines.push_back("extrinsics: " + extrinsics);
  lines.push_back("rotation: " + rotation);
  std::string unit_line = "units: " + std::string(LengthUnitWord(units));
  if (units_assumed) {
    unit_line += " (assumed: the format leaves the unit open; set units if the file is in mm or cm)";
  } else if (units != LengthUnit::kMetres) {
    unit_line += ", converted to metres";
  }
  lines.push_back(unit_line);
  lines.push_back("distortion: " + distortion);
  for (const std::string& note : notes) lines.push_back("note: " + note);
  return lines;
}

Calibration ReadCalibration(const fs::path& path, const CalibrationReadOptions& options, InputWarnings* warnings) {
  if (options.image_width < 0 || options.image_height < 0) {
    throw ConfigError("image_width / image_height: must be >= 0 (0 = twice the principal point)");
  }
  const CalibrationFormat format =
      options.format == CalibrationFormat::kAuto ? DetectCalibrationFormat(path) : options.format;
  const LengthUnit fixed = FixedUnit(format);
  if (fixed != LengthUnit::kDefault && options.units != LengthUnit::kDefault && options.units != fixed) {
    throw ConfigError("units: " + FormatName(format) + " files are in " + LengthUnitWord(fixed) +
                      "; the option applies to opencv, easymocap, toml and colmap files");
  }
  const std::string source = path.string();
  Calibration calibration;
  switch (format) {
    case CalibrationFormat::kJson:
      calibration = ReadCamerasJson(path, warnings);
      break;
    case CalibrationFormat::kOpenCV: {
      // A FileStorage file with a `names` list is the several cameras an opencv write of a rig
      // gives (the EasyMocap layout in one file): read as such, so format opencv reads back.
      std::error_code ec;
      calibration = !fs::is_directory(path, ec) && file_storage::ReadFile(path).Find("names") != nullptr
                        ? ReadEasyMocapCalibration(path, options, warnings)
                        : ReadOpenCVCalibration(path, options, warnings);
      break;
    }
    case CalibrationFormat::kEasyMocap:
      calibration = ReadEasyMocapCalibration(path, options, warnings);
      break;
    case CalibrationFormat::kToml:
      calibration = ReadCameraGroupToml(path, options, warnings);
      break;
    case CalibrationFormat::kColmap:
      calibration = ReadColmapCalibration(path, options, warnings);
      break;
    case CalibrationFormat::kVoxelPose:
      calibration.cameras = ReadVoxelPoseCalibration(path, options.image_width, options.image_height, warnings);
      calibration.description = DatasetReaderDescription(format, path);
      break;
    case CalibrationFormat::kPanoptic:
      try {
        calibration.cameras = ReadPanopticCameras(path, "", warnings);
      } catch (const InputError& e) {
        if (options.format != CalibrationFormat::kAuto) throw;
        // Told from the content: a JSON of rpt's own layout with a 't' or 'distCoef' key is taken
        // for Panoptic, and the error did not say so.
        throw InputError(std::string(e.what()) +
                         " (the file was read as a CMU Panoptic calibration, told by its cameras' 't', "
                         "'distCoef' or 'resolution' keys; if it is rpt's JSON, give the format json)");
      }
      calibration.description = DatasetReaderDescription(format, path);
      break;
    case CalibrationFormat::kFourDa:
      calibration.cameras = ReadFourDaCalibration(path, warnings);
      calibration.description = DatasetReaderDescription(format, path);
      break;
    case CalibrationFormat::kAuto:
      break;
  }
  CheckUniqueNames(calibration.cameras, source);
  MakeRotationsExact(&calibration.cameras);
  CountImplausibleRig(calibration.cameras, source, warnings);
  return calibration;
}

void WriteCalibration(const fs::path& path, const std::vector<Camera>& cameras, const CalibrationWriteOptions& options,
                      InputWarnings* warnings) {
  const CalibrationWriteFormat format =
      options.format == CalibrationWriteFormat::kAuto ? CalibrationFormatForOutput(path) : options.format;
  const std::string source = path.string();
  if (cameras.empty()) throw InputError(source + ": no cameras to write");
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    const Camera& camera = cameras[c];
    const std::string where = source + ": cannot write camera " + std::to_string(c) + " (" + QuoteName(camera.name) + ")";
    if (camera.name.empty()) throw InputError(where + ": the name is empty");
    if (!IsValidUtf8(camera.name)) throw InputError(where + ": the name is not valid UTF-8");
    if (const std::string error = camera.Validate(); !error.empty())
      throw InputError(source + ": cannot write " + error);
  }
  CheckUniqueNames(cameras, source + ": cannot write");
  if (warnings != nullptr && format != CalibrationWriteFormat::kJson) {
    long skewed = 0;
    double largest = 0;
    for (const Camera& camera : cameras) {
      if (camera.K(0, 1) == 0) continue;
      ++skewed;
      largest = std::max(largest, std::abs(camera.K(0, 1)));
    }
    warnings->Add(source,
                  "cameras with a skew (K[0][1]) written, which OpenCV's projectPoints and anipose ignore: they project "
                  "these cameras differently from rpt (our JSON keeps it exactly)",
                  "largest |skew| in px", largest, skewed);
  }
  switch (format) {
    case CalibrationWriteFormat::kJson:
      if (options.units != LengthUnit::kDefault && options.units != LengthUnit::kMetres) {
        throw ConfigError("units: our cameras JSON is always in metres");
      }
      WriteCamerasJson(path, cameras);
      return;
    case CalibrationWriteFormat::kOpenCV:
      if (cameras.size() == 1) {
        WriteOpenCVCamera(path, cameras[0], options.units);
      } else {
        WriteEasyMocapCameras(path, path, cameras, options.units);
      }
      return;
    case CalibrationWriteFormat::kEasyMocap: {
      const auto [intri, extri] = EasyMocapOutput(path);
      WriteEasyMocapCameras(intri, extri, cameras, options.units);
      return;
    }
    case CalibrationWriteFormat::kToml:
      WriteCameraGroupToml(path, cameras, options.units);
      return;
    case CalibrationWriteFormat::kAuto:  // resolved above
      break;
  }
}

}  // namespace rpt

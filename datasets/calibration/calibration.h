// SPDX-License-Identifier: MIT
// Calibration files of other tools read into rpt cameras and written back: the API behind
// `rpt cameras show FILE` and `rpt cameras convert IN OUT`, and the way every command that reads
// cameras accepts these formats. User documentation with an example of each format:
// docs/cameras.md.
//
// Formats read (CalibrationFormat):
//   json       our cameras JSON: {"cameras": [camera, ...]} in the camera schema of the generic
//              labels (R world->camera, T = camera centre in metres), or a labels file (the
//              cameras of its first label).
//   opencv     one cv::FileStorage file (.yml, .yaml, .xml) as calibrateCamera / stereoCalibrate
//              users save it: camera_matrix (K, M, cameraMatrix), distortion_coefficients (D,
//              dist_coeffs, distCoeffs), optional R (matrix or Rodrigues vector) or rvec and T or
//              tvec, image_width / image_height; stereo files with M1/D1, M2/D2 (or K1/K2) and
//              R, T; ROS camera_info YAML. A file that holds a `names` list is the EasyMocap
//              layout in one file.
//   easymocap  EasyMocap's intri.yml + extri.yml pair: names, K_<cam>, dist_<cam>, H_/W_<cam>,
//              R_<cam> (Rodrigues) or Rot_<cam> (matrix), T_<cam>.
//   toml       Pose2Sim / anipose camera groups: [cam_1] name, size, matrix, distortions,
//              rotation (Rodrigues), translation, fisheye.
//   colmap     COLMAP text model cameras.txt + images.txt: one camera per image.
//   voxelpose  VoxelPose calibration_<dataset>.json (datasets/readers/voxelpose_calibration.h).
//   panoptic   CMU Panoptic calibration_<seq>.json, every camera (datasets/readers/panoptic.h).
//   4da        4D-Association calibration.json (datasets/readers/fourda_calibration.h).
// Written (WriteCalibration): json (the canonical form), opencv, easymocap and toml.
//
// Every camera comes out in rpt's convention (core/camera.h: x_cam = R X + t, metres). Each
// reader states the convention it read in CalibrationDescription. Bad files throw InputError
// naming the file and the place (line, YAML/XML node, TOML key, JSON pointer); bad options throw
// ConfigError. Accepted imprecision (rotations stored with few digits) and implausible values
// (camera_plausibility.h) are counted in `warnings`.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/camera.h"
#include "core/option_spec.h"
#include "datasets/input_warnings.h"

namespace rpt {

enum class CalibrationFormat { kAuto, kJson, kOpenCV, kEasyMocap, kToml, kColmap, kVoxelPose, kPanoptic, kFourDa };

template <>
struct EnumNames<CalibrationFormat> {
  static constexpr std::array<std::pair<CalibrationFormat, std::string_view>, 9> values = {{
      {CalibrationFormat::kAuto, "auto"},
      {CalibrationFormat::kJson, "json"},
      {CalibrationFormat::kOpenCV, "opencv"},
      {CalibrationFormat::kEasyMocap, "easymocap"},
      {CalibrationFormat::kToml, "toml"},
      {CalibrationFormat::kColmap, "colmap"},
      {CalibrationFormat::kVoxelPose, "voxelpose"},
      {CalibrationFormat::kPanoptic, "panoptic"},
      {CalibrationFormat::kFourDa, "4da"},
  }};
};

// The unit of the translations in a file. kDefault: the format's own unit (VoxelPose mm,
// Panoptic cm, our JSON and 4D-Association m) and metres for the formats that leave it to the
// user (OpenCV, EasyMocap, toml, COLMAP), then warned when the cameras look like millimetres.
enum class LengthUnit { kDefault, kMetres, kCentimetres, kMillimetres };

template <>
struct EnumNames<LengthUnit> {
  static constexpr std::array<std::pair<LengthUnit, std::string_view>, 4> values = {{
      {LengthUnit::kDefault, "default"},
      {LengthUnit::kMetres, "m"},
      {LengthUnit::kCentimetres, "cm"},
      {LengthUnit::kMillimetres, "mm"},
  }};
};

// Metres per unit (1, 0.01, 0.001); kDefault counts as metres.
double MetresPerUnit(LengthUnit unit);
// "metres", "centimetres", "millimetres" (kDefault: "metres").
const char* LengthUnitWord(LengthUnit unit);

struct CalibrationReadOptions {
  CalibrationFormat format = CalibrationFormat::kAuto;
  LengthUnit units = LengthUnit::kDefault;
  // The image size of cameras whose file stores none (VoxelPose; OpenCV files without
  // image_width; EasyMocap without H_/W_). 0 = twice the principal point, counted as a warning.
  int image_width = 0;
  int image_height = 0;
};

template <class Visitor, OptionsOf<CalibrationReadOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("format", o.format, OptionSpec{.help = "calibration format; auto = from the file name and content"});
  v("units", o.units,
    OptionSpec{.help = "unit of the file's translations; default = the format's (VoxelPose mm, Panoptic cm, else m)"});
  v("image_width", o.image_width,
    OptionSpec{
        .help = "image width for files without image sizes (0 = twice the principal point)", .unit = "px", .min = 0});
  v("image_height", o.image_height,
    OptionSpec{
        .help = "image height for files without image sizes (0 = twice the principal point)", .unit = "px", .min = 0});
}

// The calibration formats rpt writes (the others are read only).
enum class CalibrationWriteFormat { kAuto, kJson, kOpenCV, kEasyMocap, kToml };
template <>
struct EnumNames<CalibrationWriteFormat> {
  static constexpr std::array<std::pair<CalibrationWriteFormat, std::string_view>, 5> values = {{
      {CalibrationWriteFormat::kAuto, "auto"},
      {CalibrationWriteFormat::kJson, "json"},
      {CalibrationWriteFormat::kOpenCV, "opencv"},
      {CalibrationWriteFormat::kEasyMocap, "easymocap"},
      {CalibrationWriteFormat::kToml, "toml"},
  }};
};

struct CalibrationWriteOptions {
  // auto: from the file name (*.json json, *.toml toml, intri.yml easymocap, *.yml / *.yaml /
  // *.xml opencv).
  CalibrationWriteFormat format = CalibrationWriteFormat::kAuto;
  // Unit of the translations written (opencv, easymocap, toml); default = metres. Our JSON is
  // always in metres.
  LengthUnit units = LengthUnit::kDefault;
};

template <class Visitor, OptionsOf<CalibrationWriteOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("format", o.format, OptionSpec{.help = "calibration format written; auto = from the file name"});
  v("units", o.units, OptionSpec{.help = "unit of the translations written (opencv, easymocap, toml); default = m"});
}

// What a reader found in the file: the conventions it converted from, in words, for `rpt
// cameras show`.
struct CalibrationDescription {
  CalibrationFormat format = CalibrationFormat::kAuto;
  std::vector<std::filesystem::path> files;  // every file read
  std::string extrinsics;                    // e.g. "world to camera: x_cam = R X + T"
  std::string rotation;                      // e.g. "3x3 matrix", "Rodrigues vector (axis * angle, radians)"
  LengthUnit units = LengthUnit::kMetres;    // of the file's translations (converted to metres)
  bool units_assumed = false;                // the format leaves the unit open and no option set it: metres assumed
  std::string distortion;                    // the file's lens model, e.g. "OpenCV radial-tangential k1 k2 p1 p2 k3"
  std::vector<std::string> notes;            // anything else converted (world axes, image sizes, layouts)

  // "format: ...", "files: ...", "extrinsics: ...", "rotation: ...", "units: ...",
  // "distortion: ...", then "note: ..." lines.
  std::vector<std::string> Lines() const;
};

struct Calibration {
  std::vector<Camera> cameras;
  CalibrationDescription description;
};

// The format of `path` read as a calibration: a folder holding cameras.txt + images.txt
// (colmap) or intri.yml + extri.yml (easymocap); cameras.txt / images.txt; intri.* / extri.*;
// *.toml; *.yml / *.yaml / *.xml (opencv, or easymocap when it holds a `names` list); *.json by
// its content (our JSON, VoxelPose, Panoptic, 4D-Association). Throws InputError naming the
// file when it is missing or its format cannot be told.
CalibrationFormat DetectCalibrationFormat(const std::filesystem::path& path);

// True for an existing regular file (or a link to one); false, never an error, for anything else.
bool IsRegularFile(const std::filesystem::path& path);

// The format a file of this name is written in (CalibrationWriteOptions::format auto). Throws
// ConfigError for a name whose format cannot be told.
CalibrationWriteFormat CalibrationFormatForOutput(const std::filesystem::path& path);

// Reads the cameras of a calibration file (or folder, for COLMAP and EasyMocap), in rpt's
// convention, with the description of what was read. Camera names are unique; rotations are exact
// to double round-off (the readers re-orthonormalise and count what is beyond 1e-9, this makes the
// round-off itself exact, so that every format holds the same camera to 1e-9 px). Besides the
// readers' own counts, implausible cameras and rigs (camera_plausibility.h) are counted in
// `warnings` under the file.
Calibration ReadCalibration(const std::filesystem::path& path, const CalibrationReadOptions& options = {},
                            InputWarnings* warnings = nullptr);

// Writes `cameras` in the format of `options` (json, opencv, easymocap, toml); easymocap writes
// intri.yml and extri.yml into the folder of `path` (or into `path` when it is a folder). Throws
// ConfigError for a format that cannot be written, InputError naming the file and the camera for
// cameras the format cannot hold (the Human3.6M lens model outside our JSON; fisheye cameras in
// the EasyMocap layout; non-finite values) and when the file cannot be written.
// `warnings` (may be null): cameras with a skew (K(0, 1) != 0) written to opencv, easymocap or toml,
// whose readers (OpenCV's projectPoints, anipose) ignore it and project such a camera differently.
void WriteCalibration(const std::filesystem::path& path, const std::vector<Camera>& cameras,
                      const CalibrationWriteOptions& options = {}, InputWarnings* warnings = nullptr);

}  // namespace rpt

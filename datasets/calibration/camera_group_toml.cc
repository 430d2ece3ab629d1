// SPDX-License-Identifier: MIT
#include "datasets/calibration/camera_group_toml.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/calibration/opencv_yml.h"
#include "datasets/calibration/rodrigues.h"
#include "datasets/camera_plausibility.h"
#include "datasets/io/text_file.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

// Tables that hold no camera (Pose2Sim skips these too).
const std::set<std::string> kNotCameras = {"metadata", "capture_volume", "charuco", "checkerboard"};

std::string TypeName(const toml::node& node) {
  if (node.is_string()) return "a string";
  if (node.is_boolean()) return "a boolean";
  if (node.is_table()) return "a table";
  if (node.is_array()) return "an array";
  return "a date or time";
}

// One camera table, with messages "<file>:<line>: [<table>].<key>: ...".
class CameraTable {
 public:
  CameraTable(const toml::table& table, const std::string& key, const std::string& source)
      : table_(table), key_(key), source_(source) {}

  std::string Where(const std::string& key) const {
    const toml::node* node = table_.get(key);
    const auto line = (node != nullptr ? node->source() : table_.source()).begin.line;
    return source_ + ":" + std::to_string(line) + ": [" + key_ + "]" + (key.empty() ? "" : "." + key);
  }
  bool Has(const std::string& key) const { return table_.get(key) != nullptr; }

  // The numbers of an array (nested arrays flattened one level: a matrix's rows).
  std::vector<double> Numbers(const std::string& key) const {
    const toml::node* node = table_.get(key);
    if (node == nullptr) throw InputError(Where("") + ": " + key + " missing");
    std::vector<double> out;
    auto append = [&](const toml::node& item) {
      const std::optional<double> v =
          item.is_integer() || item.is_floating_point() ? item.value<double>() : std::nullopt;
      if (!v) throw InputError(Where(key) + ": expected numbers (or rows of numbers), found " + TypeName(item));
      if (!std::isfinite(*v)) throw InputError(Where(key) + ": a value is NaN or infinite");
      out.push_back(*v);
    };
    const toml::array* array = node->as_array();
    if (array == nullptr) throw InputError(Where(key) + ": expected an array of numbers");
    for (const toml::node& item : *array) {
      if (const toml::array* row = item.as_array()) {
        for (const toml::node& value : *row) append(value);
      } else {
        append(item);
      }
    }
    return out;
  }
  std::vector<double> Numbers(const std::string& key, std::size_t count, const std::string& shape) const {
    std::vector<double> out = Numbers(key);
    if (out.size() != count) {
      throw InputError(Where(key) + ": expected " + shape + " numbers, got " + std::to_string(out.size()));
    }
    return out;
  }
  std::optional<std::string> String(const std::string& key) const {
    const toml::node* node = table_.get(key);
    if (node == nullptr) return std::nullopt;
    if (!node->is_string()) throw InputError(Where(key) + ": expected a string");
    return node->value<std::string>();
  }
  bool Bool(const std::string& key) const {
    const toml::node* node = table_.get(key);
    if (node == nullptr) return false;
    if (!node->is_boolean()) throw InputError(Where(key) + ": expected true or false");
    return *node->value<bool>();
  }

 private:
  const toml::table& table_;
  std::string key_;
  std::string source_;
};

int ImageSide(double value, const std::string& where) {
  if (!(value >= 1.0 && value <= 1e6) || value != std::floor(value)) {
    throw InputError(where + ": image size " + std::to_string(value) + " is not an integer in [1, 1000000]");
  }
  return static_cast<int>(value);
}

Camera ReadCamera(const CameraTable& table, const std::string& key, double metres_per_unit, const std::string& source,
                  InputWarnings* warnings) {
  Camera camera;
  camera.name = table.String("name").value_or(key);
  const std::vector<double> size = table.Numbers("size", 2, "2 (width, height)");
  camera.width = ImageSide(size[0], table.Where("size"));
  camera.height = ImageSide(size[1], table.Where("size"));
  camera.K = opencv_conventions::Matrix3(table.Numbers("matrix", 9, "3x3"));
  const bool fisheye = table.Bool("fisheye");
  if (table.Has("distortions")) {
    opencv_conventions::SetDistortion(table.Numbers("distortions"), fisheye, table.Where("distortions"), &camera);
  } else if (fisheye) {
    throw InputError(table.Where("") + ": distortions missing (a fisheye camera has 4 coefficients)");
  }
  camera.R = opencv_conventions::Rotation(table.Numbers("rotation"), source, table.Where("rotation"), warnings);
  const std::vector<double> t = table.Numbers("translation", 3, "3");
  camera.t = Eigen::Vector3d(t[0], t[1], t[2]) * metres_per_unit;
  if (const std::string error = camera.Validate(); !error.empty()) throw InputError(table.Where("") + ": " + error);
  CountImplausibleCamera(camera, source, warnings);
  return camera;
}

// The shortest text that reads back as `value`, always a TOML float ("1920.0", "1e-05").
std::string Float(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  std::string text(buffer, result.ptr);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string Floats(const std::vector<double>& values) {
  std::string out = "[ ";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + Float(values[i]);
  return out + "]";
}

// A TOML basic string.
std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || byte == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof(escape), "\\u%04X", byte);
      out += escape;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

Calibration ReadCameraGroupToml(const fs::path& path, const CalibrationReadOptions& options, InputWarnings* warnings) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  if (!in || fs::is_directory(path, ec)) throw InputError(source + ": file not found or unreadable");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) + ": TOML parse error: " + std::string(e.description()));
  }

  Calibration calibration;
  CalibrationDescription& d = calibration.description;
  d.format = CalibrationFormat::kToml;
  d.files = {path};
  d.extrinsics = "world to camera: x_cam = R(rotation) X + translation";
  d.rotation = "Rodrigues vector (axis * angle, radians)";
  d.units = options.units == LengthUnit::kDefault ? LengthUnit::kMetres : options.units;
  d.units_assumed = options.units == LengthUnit::kDefault;
  d.distortion = "OpenCV radial-tangential k1 k2 p1 p2 [k3]; fisheye = true: OpenCV fisheye k1 k2 k3 k4";

  // toml++ keeps keys sorted: the cameras are put back in file order.
  std::vector<std::pair<std::string, const toml::table*>> tables;
  long others = 0;
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (kNotCameras.count(name)) continue;
    if (const toml::table* table = node.as_table()) {
      tables.emplace_back(name, table);
    } else {
      ++others;
    }
  }
  if (warnings != nullptr) warnings->AddUnused(source, "top-level values outside camera tables ignored", others);
  std::sort(tables.begin(), tables.end(),
            [](const auto& a, const auto& b) { return a.second->source().begin.line < b.second->source().begin.line; });
  if (tables.empty()) throw InputError(source + ": no camera table (expected [cam_1] with name, size, matrix, ...)");
  std::set<std::string> names;
  bool any_fisheye = false;
  int rotation_vectors = 0, rotation_matrices = 0;
  // Keys of a camera table rpt does not read: a misspelt one (fish_eye = true) changed the lens
  // without a word, so they are counted, the first named with the key it may mean.
  static const std::vector<std::string> kCameraKeys = {"name",     "size",        "matrix", "distortions",
                                                       "rotation", "translation", "fisheye"};
  long unknown_keys = 0;
  std::string first_unknown;
  for (const auto& [key, table] : tables) {
    for (const auto& [item, node] : *table) {
      const std::string item_key(item.str());
      if (std::find(kCameraKeys.begin(), kCameraKeys.end(), item_key) != kCameraKeys.end()) continue;
      if (unknown_keys++ == 0) {
        first_unknown = QuoteName(item_key) + " in [" + PrintableText(key, LineBreaks::kEscape) + "]" +
                        DidYouMeanKey(item_key, kCameraKeys);
      }
    }
    const CameraTable camera_table(*table, key, source);
    Camera camera = ReadCamera(camera_table, key, MetresPerUnit(options.units), source, warnings);
    (camera_table.Numbers("rotation").size() == 9 ? rotation_matrices : rotation_vectors) += 1;
    if (!names.insert(camera.name).second) {
      throw InputError(camera_table.Where("name") + ": camera name " + QuoteName(camera.name) + " appears twice");
    }
    any_fisheye |= camera.model == DistortionModel::kFisheye;
    calibration.cameras.push_back(std::move(camera));
  }
  if (warnings != nullptr) {
    warnings->AddUnused(source, "keys in camera tables rpt does not read, ignored (the first: " + first_unknown + ")",
                        unknown_keys);
  }
  if (any_fisheye) d.notes.emplace_back("fisheye cameras (fisheye = true)");
  const std::string matrix = "3x3 matrix (9 numbers, row by row)";
  if (rotation_matrices > 0) d.rotation = rotation_vectors > 0 ? d.rotation + " or " + matrix : matrix;
  return calibration;
}

void WriteCameraGroupToml(const fs::path& path, const std::vector<Camera>& cameras, LengthUnit units) {
  const std::string source = path.string();
  std::string text;
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    const Camera& camera = cameras[c];
    const std::vector<double> dist =
        opencv_conventions::DistortionCoefficients(camera, source + ": camera " + QuoteName(camera.name));
    const Eigen::Vector3d r = RodriguesFromRotation(camera.R);
    const Eigen::Vector3d t = camera.t / MetresPerUnit(units);
    text += "[cam_" + std::to_string(c + 1) + "]\n";
    text += "name = " + Quoted(camera.name) + "\n";
    text += "size = " + Floats({static_cast<double>(camera.width), static_cast<double>(camera.height)}) + "\n";
    text += "matrix = [ " + Floats({camera.K(0, 0), camera.K(0, 1), camera.K(0, 2)}) + ", " +
            Floats({camera.K(1, 0), camera.K(1, 1), camera.K(1, 2)}) + ", " +
            Floats({camera.K(2, 0), camera.K(2, 1), camera.K(2, 2)}) + "]\n";
    text += "distortions = " + Floats(dist) + "\n";
    text += "rotation = " + Floats({r.x(), r.y(), r.z()}) + "\n";
    text += "translation = " + Floats({t.x(), t.y(), t.z()}) + "\n";
    text += std::string("fisheye = ") + (camera.model == DistortionModel::kFisheye ? "true" : "false") + "\n\n";
  }
  text += "[metadata]\nadjusted = false\nerror = 0.0\n";
  io::WriteTextFile(path, io::NamedBy::kUser, text);
}

}  // namespace rpt

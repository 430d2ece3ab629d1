// SPDX-License-Identifier: MIT
#include "datasets/calibration/opencv_yml.h"

#include <algorithm>
#include <map>
#include <cctype>
#include <cmath>
#include <system_error>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/calibration/file_storage.h"
#include "datasets/calibration/image_size.h"
#include "datasets/calibration/rodrigues.h"
#include "datasets/camera_plausibility.h"
#include "datasets/io/text_file.h"

namespace rpt {

namespace opencv_conventions {

void SetDistortion(const std::vector<double>& coefficients, bool fisheye, const std::string& where, Camera* camera) {
  camera->dist = {0, 0, 0, 0, 0};
  const std::size_t n = coefficients.size();
  if (fisheye) {
    if (n != 4)
      throw InputError(where + ": the fisheye model has 4 coefficients (k1 k2 k3 k4), got " + std::to_string(n));
    camera->model = DistortionModel::kFisheye;
    std::copy(coefficients.begin(), coefficients.end(), camera->dist.begin());
    return;
  }
  if (n == 0) {
    camera->model = DistortionModel::kNone;
    return;
  }
  if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14) {
    throw InputError(where + ": expected 4, 5, 8, 12 or 14 OpenCV distortion coefficients, got " + std::to_string(n));
  }
  if (std::any_of(coefficients.begin() + std::min<std::ptrdiff_t>(5, static_cast<std::ptrdiff_t>(n)),
                  coefficients.end(), [](double c) { return c != 0.0; })) {
    throw InputError(
        where + ": coefficients past k3 (rational, thin prism or tilted model) are not supported; only 0 is accepted");
  }
  std::copy(coefficients.begin(), coefficients.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(5, n)),
            camera->dist.begin());
  const bool distorted = std::any_of(camera->dist.begin(), camera->dist.end(), [](double c) { return c != 0.0; });
  camera->model = distorted ? DistortionModel::kOpenCV : DistortionModel::kNone;
}

std::vector<double> DistortionCoefficients(const Camera& camera, const std::string& where) {
  switch (camera.model) {
    case DistortionModel::kNone:
      return {0, 0, 0, 0, 0};
    case DistortionModel::kOpenCV:
      return {camera.dist.begin(), camera.dist.end()};
    case DistortionModel::kFisheye:
      return {camera.dist[0], camera.dist[1], camera.dist[2], camera.dist[3]};
    case DistortionModel::kH36M:
      break;
  }
  throw InputError(where + ": the Human3.6M lens model has no OpenCV equivalent; write our JSON instead");
}

Eigen::Matrix3d Rotation(const std::vector<double>& numbers, const std::string& source, const std::string& where,
                         InputWarnings* warnings) {
  if (numbers.size() == 3) return RotationFromStoredRodrigues(Eigen::Vector3d(numbers[0], numbers[1], numbers[2]), where);
  if (numbers.size() != 9) {
    throw InputError(where + ": expected a 3x3 rotation matrix or a 3x1 Rodrigues vector, got " +
                     std::to_string(numbers.size()) + " numbers");
  }
  return AcceptRotation(Matrix3(numbers), source, where, warnings);
}

std::vector<double> RowMajor(const Eigen::Matrix3d& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}

Eigen::Matrix3d Matrix3(const std::vector<double>& v) {
  Eigen::Matrix3d m;
  m << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
  return m;
}

}  // namespace opencv_conventions

std::vector<std::filesystem::path> OpenCVFilesIn(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (auto it = fs::directory_iterator(dir, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::string extension = it->path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if ((extension == ".yml" || extension == ".yaml" || extension == ".xml") && it->is_regular_file(ec)) {
      files.push_back(it->path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

namespace {

namespace fs = std::filesystem;
using file_storage::File;
using namespace opencv_conventions;

// Key spellings, most common first.
const std::vector<std::string> kIntrinsicsKeys = {"camera_matrix", "K", "M", "cameraMatrix", "intrinsic_matrix"};
const std::vector<std::string> kDistortionKeys = {
    "distortion_coefficients", "D", "dist", "dist_coeffs", "distCoeffs", "distortion"};
const std::vector<std::string> kRotationKeys = {"R", "rvec", "rotation"};
const std::vector<std::string> kTranslationKeys = {"T", "tvec", "t", "translation"};
const std::vector<std::string> kImageSizeKeys = {"image_size", "imageSize"};

// The nodes of one file, or of the stereo_calib pair intrinsics.yml + extrinsics.yml; each
// lookup names the file that holds the node.
class Nodes {
 public:
  explicit Nodes(std::vector<File> files) : files_(std::move(files)) {}

  // The file holding the first of `keys` found (its name in *key), or nullptr.
  const File* Find(const std::vector<std::string>& keys, std::string* key) const {
    for (const std::string& k : keys) {
      for (const File& file : files_) {
        if (file.Find(k) != nullptr) {
          *key = k;
          return &file;
        }
      }
    }
    return nullptr;
  }
  const File& first() const { return files_.front(); }

 private:
  std::vector<File> files_;
};

// `keys` with `suffix` appended ("M" -> "M1").
std::vector<std::string> Suffixed(const std::vector<std::string>& keys, const std::string& suffix) {
  std::vector<std::string> out;
  for (const std::string& key : keys) out.push_back(key + suffix);
  return out;
}

// ROS camera_info's (and other tools') lens names, in lower case: OpenCV's fisheye model (the
// equidistant Kannala-Brandt model with k1..k4) or its radial-tangential one. Another name is an
// error: read as radial-tangential, a fisheye lens projected up to 17.6 px off, silently.
bool IsFisheye(const Nodes& nodes) {
  std::string key;
  if (const File* file = nodes.Find({"fisheye_model"}, &key)) return file->Number(key) != 0.0;
  if (const File* file = nodes.Find({"distortion_model"}, &key)) {
    std::string model = file->String(key);
    for (char& c : model) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* name : {"fisheye", "equidistant", "kannala_brandt", "kannala-brandt"}) {
      if (model == name) return true;
    }
    for (const char* name : {"plumb_bob", "radtan", "radial_tangential", "radial-tangential", "rational_polynomial"}) {
      if (model == name) return false;
    }
    throw InputError(file->source + ": " + key + ": " + QuoteName(file->String(key)) +
                     " is not a lens model rpt reads (plumb_bob, radtan, rational_polynomial: OpenCV's "
                     "radial-tangential; fisheye, equidistant, kannala_brandt: OpenCV's fisheye)");
  }
  return false;
}

// Intrinsics and lens of the camera whose keys end in `suffix` ("" or "1", "2").
Camera ReadIntrinsics(const Nodes& nodes, const std::string& suffix, bool fisheye) {
  Camera camera;
  std::string key;
  const File* file = nodes.Find(Suffixed(kIntrinsicsKeys, suffix), &key);
  if (file == nullptr) {
    std::string keys;
    for (const std::string& k : kIntrinsicsKeys) keys += (keys.empty() ? "" : ", ") + k;
    throw InputError(nodes.first().source + ": no camera matrix (expected one of " + keys +
                     (suffix.empty() ? std::string() : " with the suffix " + suffix) + ")");
  }
  camera.K = Matrix3(file->Numbers(key, 9, "3x3"));
  if (file = nodes.Find(Suffixed(kDistortionKeys, suffix), &key); file != nullptr) {
    SetDistortion(file->AnyNumbers(key), fisheye, file->source + ": " + key, &camera);
  }
  return camera;
}

void ReadImageSize(const Nodes& nodes, Camera* camera) {
  std::string key;
  if (const File* file = nodes.Find({"image_width"}, &key)) camera->width = file->Integer(key, 1, 1'000'000);
  if (const File* file = nodes.Find({"image_height"}, &key)) camera->height = file->Integer(key, 1, 1'000'000);
  if (const File* file = nodes.Find(kImageSizeKeys, &key); file != nullptr && camera->width == 0) {
    const std::vector<double> size = file->Numbers(key, 2, "2 (width, height)");
    for (const double side : size) {
      if (!(side >= 1 && side <= 1e6) || side != std::floor(side)) {
        throw InputError(file->source + ": " + key + ": expected integers in [1, 1000000]");
      }
    }
    camera->width = static_cast<int>(size[0]);
    camera->height = static_cast<int>(size[1]);
  }
}

// R and T: world -> camera (or camera 2 from camera 1 in a stereo file). False when neither is
// there; an error when only one is.
bool ReadPose(const Nodes& nodes, double metres_per_unit, InputWarnings* warnings, Camera* camera,
              std::string* rotation_key) {
  std::string r_key, t_key;
  const File* r_file = nodes.Find(kRotationKeys, &r_key);
  const File* t_file = nodes.Find(kTranslationKeys, &t_key);
  if (r_file == nullptr && t_file == nullptr) return false;
  if (r_file == nullptr || t_file == nullptr) {
    throw InputError(nodes.first().source + ": " +
                     (r_file ? r_key + " without a translation (T, tvec)" : t_key + " without a rotation (R, rvec)"));
  }
  const std::vector<double> r = r_file->AnyNumbers(r_key);
  camera->R = Rotation(r, r_file->source, r_file->source + ": " + r_key, warnings);
  *rotation_key = r_key + (r.size() == 3 ? " (Rodrigues vector)" : " (3x3 matrix)");
  const std::vector<double> t = t_file->Numbers(t_key, 3, "3x1");
  camera->t = Eigen::Vector3d(t[0], t[1], t[2]) * metres_per_unit;
  return true;
}

void Finish(Camera* camera, const std::string& where, const CalibrationReadOptions& options, const std::string& source,
            InputWarnings* warnings) {
  CompleteImageSize(camera, options.image_width, options.image_height, source, where, warnings);
  if (const std::string error = camera->Validate(); !error.empty()) throw InputError(where + ": " + error);
  CountImplausibleCamera(*camera, source, warnings);
}

// `path`, and intrinsics.yml <-> extrinsics.yml beside it (the stereo_calib sample) when it
// exists; the paths read are appended to `paths`.
std::vector<File> ReadFileAndPartner(const fs::path& path, std::vector<fs::path>* paths) {
  std::vector<File> files = {file_storage::ReadFile(path)};
  paths->push_back(path);
  const std::string stem = path.stem().string();
  const std::string partner = stem == "intrinsics" ? "extrinsics" : stem == "extrinsics" ? "intrinsics" : "";
  const fs::path other = path.parent_path() / (partner + path.extension().string());
  std::error_code ec;
  if (!partner.empty() && fs::is_regular_file(other, ec)) {
    files.push_back(file_storage::ReadFile(other));
    paths->push_back(other);
  }
  return files;
}

}  // namespace

Calibration ReadOpenCVCalibration(const fs::path& path, const CalibrationReadOptions& options,
                                  InputWarnings* warnings) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    // One file per camera (what calibrateCamera users save), read in name order.
    const std::vector<fs::path> files = OpenCVFilesIn(path);
    if (files.empty()) throw InputError(path.string() + ": a folder without OpenCV files (*.yml, *.yaml, *.xml)");
    // Each file's corrections and doubts (a camera 4 km away: millimetres read as metres) are counted
    // once for the folder, not once per file ("1 cameras ..." three times); what a file leaves unused
    // stays under its name.
    const auto read = [&](const fs::path& file) {
      InputWarnings own;
      Calibration calibration = ReadOpenCVCalibration(file, options, warnings != nullptr ? &own : nullptr);
      if (warnings == nullptr) return calibration;
      for (const InputWarning& w : own.items()) {
        switch (w.kind) {
          case InputWarningKind::kCorrected:
            warnings->Add(w.source == file.string() ? path.string() : w.source, w.what, w.measure, w.worst, w.count);
            break;
          case InputWarningKind::kUnused:
            warnings->AddUnused(w.source, w.what, w.count);
            break;
          case InputWarningKind::kMissing:
            warnings->AddMissing(w.source, w.what, w.count);
            break;
        }
      }
      return calibration;
    };
    Calibration all = read(files.front());
    std::map<std::string, fs::path> file_of;  // camera name -> the file that named it first
    for (const Camera& camera : all.cameras) file_of.emplace(camera.name, files.front());
    for (size_t i = 1; i < files.size(); ++i) {
      Calibration one = read(files[i]);
      for (Camera& camera : one.cameras) {
        const auto [it, fresh] = file_of.emplace(camera.name, files[i]);
        if (!fresh) {
          throw InputError(files[i].string() + ": camera name " + QuoteName(camera.name) + " appears twice (also in " +
                           it->second.string() + "); name each file's camera with camera_name");
        }
        all.cameras.push_back(std::move(camera));
      }
      all.description.files.insert(all.description.files.end(), one.description.files.begin(),
                                   one.description.files.end());
      if (one.description.distortion != all.description.distortion) {
        all.description.distortion = "per file: OpenCV radial-tangential or fisheye";
      }
    }
    all.description.notes.emplace_back("one file per camera in the folder " + path.string());
    return all;
  }
  Calibration calibration;
  CalibrationDescription& d = calibration.description;
  const Nodes nodes(ReadFileAndPartner(path, &d.files));
  const std::string source = path.string();
  const double metres_per_unit = MetresPerUnit(options.units);
  d.format = CalibrationFormat::kOpenCV;
  d.units = options.units == LengthUnit::kDefault ? LengthUnit::kMetres : options.units;
  d.units_assumed = options.units == LengthUnit::kDefault;
  const bool fisheye = IsFisheye(nodes);
  d.distortion = fisheye ? "OpenCV fisheye k1 k2 k3 k4" : "OpenCV radial-tangential k1 k2 p1 p2 [k3]";

  std::string key;
  const bool stereo =
      nodes.Find(kIntrinsicsKeys, &key) == nullptr && nodes.Find(Suffixed(kIntrinsicsKeys, "1"), &key) != nullptr;
  std::string rotation_key;
  if (!stereo) {
    Camera camera = ReadIntrinsics(nodes, "", fisheye);
    camera.name = path.stem().string();
    if (const File* file = nodes.Find({"camera_name"}, &key)) camera.name = file->String(key);
    ReadImageSize(nodes, &camera);
    if (ReadPose(nodes, metres_per_unit, warnings, &camera, &rotation_key)) {
      d.extrinsics = "world to camera: x_cam = R X + T";
      d.rotation = rotation_key;
    } else {
      // Keys that look like a pose under another name (rotation_matrix, translation_vector): the
      // camera would sit at the world origin without a word.
      std::string posed;
      for (const auto& [name, value] : nodes.first().nodes) {
        std::string lower = name;
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower.find("rot") != std::string::npos || lower.find("trans") != std::string::npos) {
          posed += (posed.empty() ? "" : ", ") + QuoteName(name);
        }
      }
      if (!posed.empty()) {
        throw InputError(source + ": no pose rpt reads (R, rvec or rotation with T, tvec, t or translation), but " +
                         posed + ": rename them, or the camera would be the world origin");
      }
      d.extrinsics = "none: the camera is the world origin (R = I, T = 0)";
      d.rotation = "none";
    }
    Finish(&camera, source, options, source, warnings);
    calibration.cameras.push_back(std::move(camera));
  } else {
    Camera first = ReadIntrinsics(nodes, "1", fisheye);
    Camera second = ReadIntrinsics(nodes, "2", fisheye);
    first.name = "1";
    second.name = "2";
    ReadImageSize(nodes, &first);
    ReadImageSize(nodes, &second);
    if (!ReadPose(nodes, metres_per_unit, warnings, &second, &rotation_key)) {
      throw InputError(source + ": a stereo file (M1, M2) needs R and T (camera 2 from camera 1)");
    }
    d.extrinsics = "stereo: camera 1 is the world origin, camera 2 from camera 1: x_2 = R x_1 + T";
    d.rotation = rotation_key;
    d.notes.emplace_back("stereo layout: cameras \"1\" and \"2\" from the keys ending in 1 and 2");
    Finish(&first, source + ": camera 1", options, source, warnings);
    Finish(&second, source + ": camera 2", options, source, warnings);
    calibration.cameras = {std::move(first), std::move(second)};
  }
  if (d.files.size() == 2) d.notes.emplace_back("the stereo_calib pair intrinsics + extrinsics");
  return calibration;
}

void WriteOpenCVCamera(const fs::path& path, const Camera& camera, LengthUnit units) {
  const std::string source = path.string();
  const std::string where = source + ": camera " + QuoteName(camera.name);
  const std::vector<double> dist = DistortionCoefficients(camera, where);
  file_storage::Writer out(path.extension() == ".xml", source);
  out.String("camera_name", camera.name);
  out.Integer("image_width", camera.width);
  out.Integer("image_height", camera.height);
  out.Matrix("camera_matrix", 3, 3, RowMajor(camera.K));
  out.Matrix("distortion_coefficients", 1, static_cast<int>(dist.size()), dist);
  if (camera.model == DistortionModel::kFisheye) out.Integer("fisheye_model", 1);
  out.Matrix("R", 3, 3, RowMajor(camera.R));
  const Eigen::Vector3d t = camera.t / MetresPerUnit(units);
  out.Matrix("T", 3, 1, {t.x(), t.y(), t.z()});
  io::WriteTextFile(path, io::NamedBy::kUser, out.Finish());
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
// Human3.6M camera files: metadata.xml (<w0> block), mmpose cameras.pkl, learnable-triangulation
// labels npy. Each file's own convention is converted to Camera (world->camera R, t in metres).
#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/npy.h"
#include "datasets/io/pickle.h"
#include "datasets/readers/h36m_ego_common.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/human36m_internal.h"
#include "core/printable_text.h"

namespace rpt {
namespace h36m_ego {

Camera MakeH36mCamera(const std::string& id, const Eigen::Matrix3d& R_cam_from_world, const Eigen::Vector3d& center_m,
                      double fx, double fy, double cx, double cy, double k1, double k2, double k3, double p1, double p2,
                      DistortionModel model) {
  Camera camera = Camera::FromCenter(R_cam_from_world, center_m);
  camera.name = id;
  const int index = H36mCameraIndex(id);
  if (index >= 0) H36mImageSize(index, &camera.width, &camera.height);
  camera.K << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  camera.model = model;
  if (model != DistortionModel::kNone) camera.dist = {k1, k2, p1, p2, k3};
  return camera;
}

std::vector<Camera> LearnableTriCameras(const io::PyView& labels, const std::string& subject, DistortionModel model,
                                        InputWarnings* warnings) {
  const io::PyView subjects = labels.Key("subject_names");
  std::size_t subject_idx = subjects.Size();
  std::string known;
  for (std::size_t i = 0; i < subjects.Size(); ++i) {
    const std::string& name = subjects.At(i).AsStr();
    known += (i ? ", " : "") + name;
    if (name == subject) subject_idx = i;
  }
  if (subject_idx == subjects.Size()) subjects.Fail("unknown subject " + QuoteName(subject) + " (file has " + known + ")");
  const io::PyView camera_names = labels.Key("camera_names");
  const std::size_t num_cameras = camera_names.Size();
  const io::PyView cameras = labels.Key("cameras");
  const auto shape = cameras.Shape();
  if (shape.size() != 2 || shape[0] != static_cast<std::int64_t>(subjects.Size()) ||
      shape[1] != static_cast<std::int64_t>(num_cameras)) {
    cameras.Fail("expected shape (" + std::to_string(subjects.Size()) + ", " + std::to_string(num_cameras) +
                 ") = (subjects, cameras)");
  }
  const std::size_t n = subjects.Size() * num_cameras;
  const auto R_all = FiniteNumbers(cameras.Field("R"), n * 9);
  const auto t_all = FiniteNumbers(cameras.Field("t"), n * 3);
  const auto K_all = FiniteNumbers(cameras.Field("K"), n * 9);
  const auto d_all = FiniteNumbers(cameras.Field("dist"), n * 5);
  std::vector<Camera> out;
  for (std::size_t c = 0; c < num_cameras; ++c) {
    const std::string& id = camera_names.At(c).AsStr();
    if (H36mCameraIndex(id) < 0) camera_names.At(c).Fail("unknown Human3.6M camera id " + QuoteName(id));
    const std::size_t k = subject_idx * num_cameras + c;
    // File convention: R world->camera (float32), t = -R C in millimetres, K 3x3, dist (k1 k2 p1 p2 k3).
    const Eigen::Matrix3d R =
        AcceptRotation(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(&R_all[9 * k]), labels.source(),
                       cameras.Where() + " [" + subject + ", " + id + "]", warnings);
    const Eigen::Vector3d t_mm(t_all[3 * k], t_all[3 * k + 1], t_all[3 * k + 2]);
    const Eigen::Vector3d center_m = -R.transpose() * t_mm / 1000.0;
    const double* K = &K_all[9 * k];
    const double* d = &d_all[5 * k];
    Camera camera = MakeH36mCamera(id, R, center_m, K[0], K[4], K[2], K[5], d[0], d[1], d[4], d[2], d[3], model);
    CheckCamera(camera, cameras.Where() + " [" + subject + ", " + id + "]");
    out.push_back(camera);
  }
  return out;
}

namespace {

std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(PathName(path) + ": file not found or unreadable");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int SubjectNumber(const std::string& subject) {
  if (subject.size() < 2 || subject[0] != 'S') return -1;
  int n = 0;
  return io::ParseInteger(std::string_view(subject).substr(1), &n) ? n : -1;
}

Eigen::Matrix3d RotationXYZ(double rx, double ry, double rz) {
  return (Eigen::AngleAxisd(rx, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(ry, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rz, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

// metadata.xml: <w0>[ 300 numbers ]</w0>. Camera c (0-based, order of Human36mCameraIds()) and
// subject s (1..11): extrinsics rx ry rz Cx Cy Cz (rad, mm) at 6 (c 11 + s - 1); intrinsics
// fx fy cx cy k1 k2 k3 p1 p2 at 264 + 9 c. R = Rx(rx) Ry(ry) Rz(rz) maps world to camera.
std::vector<Camera> MetadataXmlCameras(const std::filesystem::path& path, const std::string& subject,
                                       DistortionModel model) {
  const std::string source = PathName(path);
  const std::string text = ReadText(path);
  const std::size_t open = text.find("<w0>");
  if (open == std::string::npos) throw InputError(source + ": no <w0> element (expected the Human3.6M metadata.xml)");
  const std::size_t close = text.find("</w0>", open);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(open), '\n'));
  const std::string where = source + ":" + std::to_string(line) + ": <w0>";
  if (close == std::string::npos) throw InputError(where + ": missing </w0>");
  std::vector<double> w0;
  std::size_t i = open + 4;
  while (i < close) {
    const char ch = text[i];
    if (ch == '[' || ch == ']' || ch == ',' || ch == ';' || std::isspace(static_cast<unsigned char>(ch))) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < close && text[end] != ',' && text[end] != ';' && text[end] != ']' &&
           !std::isspace(static_cast<unsigned char>(text[end]))) {
      ++end;
    }
    double value = 0;
    if (!io::ParseFiniteNumber(std::string_view(text).substr(i, end - i), &value)) {
      throw InputError(where + ": value " + std::to_string(w0.size()) + " (" + QuoteName(text.substr(i, std::min<std::size_t>(end - i, 40))) +
                       ") is not a finite number");
    }
    w0.push_back(value);
    i = end;
  }
  if (w0.size() != 300) throw InputError(where + ": expected 300 numbers, got " + std::to_string(w0.size()));
  const int s = SubjectNumber(subject);
  if (s < 1 || s > 11) throw InputError(where + ": unknown subject " + QuoteName(subject) + " (the block holds S1..S11)");
  std::vector<Camera> out;
  for (int c = 0; c < 4; ++c) {
    const double* e = &w0[static_cast<std::size_t>(6 * (c * 11 + (s - 1)))];
    const double* k = &w0[static_cast<std::size_t>(264 + 9 * c)];
    const Eigen::Matrix3d R = RotationXYZ(e[0], e[1], e[2]);
    const Eigen::Vector3d center_m = Eigen::Vector3d(e[3], e[4], e[5]) / 1000.0;
    Camera camera = MakeH36mCamera(Human36mCameraIds()[static_cast<std::size_t>(c)], R, center_m, k[0], k[1], k[2], k[3],
                                   k[4], k[5], k[6], k[7], k[8], model);
    CheckCamera(camera, where + " [" + subject + ", " + camera.name + "]");
    out.push_back(camera);
  }
  return out;
}

// mmpose cameras.pkl: {(subject, camera_id): {R: camera->world 3x3, T: centre (m) 3x1, f, c, k (3),
// p (2), w, h, name, id}}.
std::vector<Camera> MmposeCameras(const std::filesystem::path& path, const std::string& subject, DistortionModel model,
                                  InputWarnings* warnings) {
  const io::PyView root = io::ReadPickle(path);
  std::vector<Camera> out;
  for (const std::string& id : Human36mCameraIds()) {
    const auto key = io::MakeStrTuple({subject, id});
    const std::optional<io::PyView> entry = root.Find(*key);
    if (!entry) {
      std::string subjects;
      if (root.IsDict()) {
        for (const auto& [k, v] : root.Items()) {
          if (k.IsTuple() && k.Size() == 2 && k.At(0).IsStr() && k.At(1).IsStr() && k.At(1).AsStr() == id) {
            subjects += (subjects.empty() ? "" : ", ") + k.At(0).AsStr();
          }
        }
      }
      root.Fail("unknown subject/camera " + io::Repr(*key) + " (subjects in file: " + (subjects.empty() ? "none" : subjects) + ")");
    }
    const auto R_c2w = FiniteNumbers(entry->Key("R"), 9);
    const auto T = FiniteNumbers(entry->Key("T"), 3);
    const auto f = FiniteNumbers(entry->Key("f"), 2);
    const auto c = FiniteNumbers(entry->Key("c"), 2);
    const auto k = FiniteNumbers(entry->Key("k"), 3);
    const auto p = FiniteNumbers(entry->Key("p"), 2);
    const Eigen::Matrix3d R_world_from_cam =
        AcceptRotation(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R_c2w.data()), root.source(),
                       entry->Key("R").Where(), warnings);
    Camera camera = MakeH36mCamera(id, R_world_from_cam.transpose(), Eigen::Vector3d(T[0], T[1], T[2]), f[0], f[1], c[0],
                                   c[1], k[0], k[1], k[2], p[0], p[1], model);
    if (entry->Has("w")) camera.width = static_cast<int>(entry->Key("w").AsInt());
    if (entry->Has("h")) camera.height = static_cast<int>(entry->Key("h").AsInt());
    CheckCamera(camera, entry->Where());
    out.push_back(camera);
  }
  return out;
}

}  // namespace
}  // namespace h36m_ego

const std::vector<std::string>& Human36mCameraIds() {
  static const std::vector<std::string> ids = {"54138969", "55011271", "58860488", "60457274"};
  return ids;
}

std::vector<Camera> ReadHuman36mCameras(const std::filesystem::path& path, const std::string& subject,
                                        DistortionModel model, InputWarnings* warnings) {
  const std::string ext = path.extension().string();
  // metadata.xml stores angles: its rotations are exact and need no check.
  if (ext == ".xml") return h36m_ego::MetadataXmlCameras(path, subject, model);
  if (ext == ".pkl") return h36m_ego::MmposeCameras(path, subject, model, warnings);
  if (ext == ".npy") return h36m_ego::LearnableTriCameras(io::ReadNpy(path), subject, model, warnings);
  throw InputError(path.string() + ": unknown Human3.6M camera file type (expected metadata.xml, cameras.pkl or a labels .npy)");
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "datasets/readers/colmap_text.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/input_warnings.h"
#include "core/printable_text.h"

namespace rpt {
namespace {

// White space as the tokens are split (std::isspace in the classic locale); the NAME of an image
// line is found after the same characters, so the two cannot disagree on where fields end.
constexpr const char* kSpace = " \t\n\v\f\r";

// Whitespace-separated tokens of a line.
std::vector<std::string> Tokens(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  s.imbue(std::locale::classic());
  std::string token;
  while (s >> token) out.push_back(token);
  return out;
}

std::string Trim(const std::string& line) {
  const std::size_t first = line.find_first_not_of(kSpace);
  if (first == std::string::npos) return {};
  const std::size_t last = line.find_last_not_of(kSpace);
  return line.substr(first, last - first + 1);
}

std::string LineWhere(const std::string& source, int line) { return source + ":" + std::to_string(line); }

// The lines of a COLMAP text file, numbered for error messages; Next() skips blank lines and
// '#' comments.
class NumberedLines {
 public:
  NumberedLines(std::istream& in, const std::string& source) : in_(in), source_(source) {}

  // The next data line, trimmed; false at the end of the input.
  bool Next(std::string* line) {
    std::string raw;
    while (NextRaw(&raw)) {
      *line = Trim(raw);
      if (!line->empty() && (*line)[0] != '#') return true;
    }
    return false;
  }
  // The next line as it is (even when blank); false at the end of the input.
  bool NextRaw(std::string* raw) {
    if (!std::getline(in_, *raw)) return false;
    ++number_;
    return true;
  }
  int number() const { return number_; }
  // "file:line" of the line read last.
  std::string LineWhere() const { return rpt::LineWhere(source_, number_); }

 private:
  std::istream& in_;
  const std::string& source_;
  int number_ = 0;
};

double ParseDouble(const std::string& token, const std::string& what, const std::string& where) {
  double value = 0;
  if (!io::ParseNumber(token, &value)) throw InputError(where + ": " + what + " " + QuoteName(token) + " is not a number");
  if (!std::isfinite(value)) throw InputError(where + ": " + what + " is NaN or infinite");
  return value;
}

int ParseColmapInt(const std::string& token, const std::string& what, const std::string& where) {
  int value = 0;
  if (!io::ParseInteger(token, &value)) throw InputError(where + ": " + what + " " + QuoteName(token) + " is not an integer");
  return value;
}

std::ifstream OpenOrThrow(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": file not found or unreadable");
  return in;
}

}  // namespace

std::vector<ColmapCamera> ParseColmapCamerasText(std::istream& in, const std::string& source) {
  std::vector<ColmapCamera> out;
  std::set<int> ids;
  NumberedLines lines(in, source);
  std::string line;
  while (lines.Next(&line)) {
    const std::string where = lines.LineWhere();
    const auto tokens = Tokens(line);
    if (tokens.size() < 4) throw InputError(where + ": expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS...");
    ColmapCamera camera;
    camera.line = lines.number();
    camera.camera_id = ParseColmapInt(tokens[0], "CAMERA_ID", where);
    camera.model = tokens[1];
    camera.width = ParseColmapInt(tokens[2], "WIDTH", where);
    camera.height = ParseColmapInt(tokens[3], "HEIGHT", where);
    if (camera.width <= 0 || camera.height <= 0) throw InputError(where + ": image size must be positive");
    for (std::size_t i = 4; i < tokens.size(); ++i) {
      camera.params.push_back(ParseDouble(tokens[i], "parameter " + std::to_string(i - 4), where));
    }
    if (!ids.insert(camera.camera_id).second) throw InputError(where + ": duplicate CAMERA_ID " + tokens[0]);
    out.push_back(std::move(camera));
  }
  return out;
}

std::vector<ColmapImage> ParseColmapImagesText(std::istream& in, const std::string& source, InputWarnings* warnings) {
  std::vector<ColmapImage> out;
  std::set<int> ids;
  NumberedLines lines(in, source);
  std::string line;
  while (lines.Next(&line)) {
    const std::string where = lines.LineWhere();
    const auto tokens = Tokens(line);
    if (tokens.size() < 10) throw InputError(where + ": expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME");
    ColmapImage image;
    image.line = lines.number();
    image.image_id = ParseColmapInt(tokens[0], "IMAGE_ID", where);
    for (int i = 0; i < 4; ++i) image.qvec_wxyz[i] = ParseDouble(tokens[1 + static_cast<std::size_t>(i)], "quaternion", where);
    for (int i = 0; i < 3; ++i) image.tvec[i] = ParseDouble(tokens[5 + static_cast<std::size_t>(i)], "translation", where);
    image.camera_id = ParseColmapInt(tokens[8], "CAMERA_ID", where);
    // NAME is the rest of the line (COLMAP allows spaces in image names).
    std::size_t pos = 0;
    for (int i = 0; i < 9; ++i) {
      pos = line.find_first_not_of(kSpace, pos);
      pos = line.find_first_of(kSpace, pos);
    }
    image.name = Trim(line.substr(pos));
    image.qvec_wxyz = AcceptQuaternion(image.qvec_wxyz, source, where, warnings);
    if (!ids.insert(image.image_id).second) throw InputError(where + ": duplicate IMAGE_ID " + tokens[0]);
    out.push_back(std::move(image));
    // The POINTS2D line always follows (possibly empty): (X, Y, POINT3D_ID) triples.
    if (std::string raw; lines.NextRaw(&raw)) {
      if (Tokens(raw).size() % 3 != 0) {
        throw InputError(lines.LineWhere() + ": expected the POINTS2D line of image " + tokens[0] +
                         " (X Y POINT3D_ID triples)");
      }
    }
  }
  return out;
}

std::vector<ColmapCamera> ReadColmapCamerasText(const std::filesystem::path& path) {
  std::ifstream in = OpenOrThrow(path);
  return ParseColmapCamerasText(in, path.string());
}

std::vector<ColmapImage> ReadColmapImagesText(const std::filesystem::path& path, InputWarnings* warnings) {
  std::ifstream in = OpenOrThrow(path);
  return ParseColmapImagesText(in, path.string(), warnings);
}

Eigen::Matrix3d ColmapQuaternionToRotation(const Eigen::Vector4d& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

Camera ColmapCameraToCamera(const ColmapCamera& colmap, const std::string& source) {
  const std::string where =
      LineWhere(source, colmap.line) + ": camera " + std::to_string(colmap.camera_id) + " (" + colmap.model + ")";
  const std::vector<double>& p = colmap.params;
  auto expect = [&](std::size_t n) {
    if (p.size() != n) {
      throw InputError(where + ": expected " + std::to_string(n) + " parameters, got " + std::to_string(p.size()));
    }
  };
  Camera camera;
  camera.width = colmap.width;
  camera.height = colmap.height;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  if (colmap.model == "SIMPLE_PINHOLE") {
    expect(3);
    fx = fy = p[0], cx = p[1], cy = p[2];
  } else if (colmap.model == "PINHOLE") {
    expect(4);
    fx = p[0], fy = p[1], cx = p[2], cy = p[3];
  } else if (colmap.model == "SIMPLE_RADIAL" || colmap.model == "RADIAL") {
    expect(colmap.model == "RADIAL" ? 5 : 4);
    fx = fy = p[0], cx = p[1], cy = p[2];
    camera.model = DistortionModel::kOpenCV;
    camera.dist = {p[3], colmap.model == "RADIAL" ? p[4] : 0.0, 0, 0, 0};
  } else if (colmap.model == "OPENCV" || colmap.model == "FULL_OPENCV") {
    expect(colmap.model == "OPENCV" ? 8 : 12);
    if (colmap.model == "FULL_OPENCV" && (p[9] != 0 || p[10] != 0 || p[11] != 0)) {
      throw InputError(where + ": rational distortion (k4..k6 != 0) is not supported");
    }
    fx = p[0], fy = p[1], cx = p[2], cy = p[3];
    camera.model = DistortionModel::kOpenCV;
    camera.dist = {p[4], p[5], p[6], p[7], colmap.model == "FULL_OPENCV" ? p[8] : 0.0};
  } else if (colmap.model == "OPENCV_FISHEYE") {
    expect(8);
    fx = p[0], fy = p[1], cx = p[2], cy = p[3];
    camera.model = DistortionModel::kFisheye;
    camera.dist = {p[4], p[5], p[6], p[7], 0.0};
  } else {
    throw InputError(where + ": unsupported camera model");
  }
  camera.K << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  return camera;
}

}  // namespace rpt

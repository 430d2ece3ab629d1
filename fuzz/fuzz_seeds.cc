// SPDX-License-Identifier: MIT
#include "fuzz/fuzz_seeds.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/joints.h"
#include "datasets/calibration/calibration.h"
#include "datasets/io/binary.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/readers/human36m.h"
#include "fuzz/fuzz_targets.h"
#include "tests/datasets/calibration_test_util.h"
#include "tests/datasets/io_test_util.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/datasets/readers_h36m_ego_test_util.h"

namespace rpt::fuzz {
namespace {

namespace fs = std::filesystem;
using test::ByteVec;

Bytes Of(const std::string& text) { return Bytes(text.begin(), text.end()); }

// `detections` as the live input's stream (datasets/readers/detection_lines.h): the joints line,
// then one frame a line with its time; a missing joint as null, a blank line in between.
Bytes DetectionLines(const Detections& detections) {
  std::string text = "{\"joints\": [";
  for (size_t j = 0; j < detections.joints.size(); ++j) text += (j ? ", \"" : "\"") + detections.joints[j] + "\"";
  text += "]}\n\n";
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    text += "{\"id\": \"" + frame.frame_id + "\", \"time\": " + std::to_string(0.04 * static_cast<double>(f)) +
            ", \"views\": [";
    for (size_t v = 0; v < frame.views.size(); ++v) {
      text += std::string(v ? ", " : "") + "{\"camera\": \"" + frame.cameras[v] + "\", \"poses\": [";
      for (int p = 0; p < frame.views[v].num_persons(); ++p) {
        text += p ? ", [" : "[";
        const auto person = frame.views[v].Person(p);
        for (int j = 0; j < frame.views[v].num_joints; ++j) {
          if (j) text += ", ";
          if (person(2, j) > 0) {  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "[" + string
            text += "[";
            text += std::to_string(person(0, j));
            text += ", ";
            text += std::to_string(person(1, j));
            text += ", ";
            text += std::to_string(person(2, j));
            text += "]";
          } else {
            text += "null";
          }
        }
        text += "]";
      }
      text += "]}";
    }
    text += "]}\n";
  }
  return Of(text);
}

// What a project writer puts into a file, read back as bytes.
template <class Write>
Bytes Written(const std::string& name, Write&& write) {
  test::TempDir dir;
  const fs::path path = dir.path() / name;
  write(path);
  return io::detail::ReadFileBytes(path);
}

// `count` numbers first, first + step, ... separated by spaces (4D-Association text).
std::string Numbers(int count, double first, double step) {
  std::string out;
  for (int i = 0; i < count; ++i) {
    if (i > 0) out += ' ';
    out += std::to_string(first + step * i);
  }
  return out;
}

// x, y, score triples of `joints` points.
std::string Keypoints(int joints, double x0) {
  std::string out;
  for (int j = 0; j < joints; ++j) {
    out += (j ? ", " : "") + std::to_string(x0 + 10 * j) + ", " + std::to_string(200 + 5 * j) + ", " + (j % 4 ? "0.8" : "0.0");
  }
  return out;
}

// A VoxelPose cache: defaultdict {"<camera>_<frame>": [{"pred": 17x3 float64}]}.
ByteVec VoxelPosePickle() {
  test::PickleWriter w;
  w.Proto(3).Global("collections", "defaultdict").None().Tuple1().Reduce().Mark();
  for (const char* key : {"0_0", "1_0", "0_2"}) {
    w.Str(key).EmptyList().Mark();
    std::vector<double> pred;
    for (int j = 0; j < 17; ++j) {
      for (double v : {100.0 + 3 * j, 50.0 + 2 * j, 0.5 + 0.02 * j}) pred.push_back(v);
    }
    w.EmptyDict().Str("pred").Array({17, 3}, "f8", "<", false, test::RawOf(pred)).SetItem();
    w.Appends();
  }
  w.SetItems().Stop();
  return w.bytes;
}

ByteVec Npy2x3() {
  return test::NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }", test::RawOf(std::vector<double>{1, 2, 3, 4, 5, 6}));
}

ByteVec MatFile() {
  using namespace test::mat;
  ByteVec out = Header();
  test::Append(out, Matrix(kDoubleClass, {2, 2}, "a", Doubles({1, 2, 3, 4})));
  test::Append(out, Compressed(Matrix(kDoubleClass, {1, 3}, "b", Doubles({5, 6, 7}))));
  const std::string text = "hi";
  ByteVec chars;
  for (char c : text) test::AppendLE(chars, static_cast<std::uint8_t>(c), 2);
  test::Append(out, Matrix(kCharClass, {1, 2}, "s", Element(kUInt16, chars)));
  return out;
}

// A 4D-Association detection file: BODY25, `frames` frames of one candidate per joint.
std::string FourDaDetections(int frames) {
  std::string out = "4 " + std::to_string(frames) + "\n";
  for (int f = 0; f < frames; ++f) {
    for (int j = 0; j < 25; ++j) out += "1\n" + std::to_string(0.3 + 0.01 * j) + "\n" + std::to_string(0.2 + 0.02 * j) + "\n0.9\n";
    for (int k = 0; k < 26; ++k) out += "0.7\n";
  }
  return out;
}

std::string FourDaSkeletons() {
  std::string out = "19 2\n";
  for (int f = 0; f < 2; ++f) {
    out += "1\n5\n";
    for (int row = 0; row < 4; ++row) {
      out += Numbers(19, row == 3 ? 1 : 0.1 * row + f, row == 3 ? 0 : 0.05);
      out += '\n';
    }
  }
  return out;
}

// A small MVOR annotation file of day 1: three cameras, one multi-view frame, one 3D person.
std::string MvorAnnotations() {
  std::string intrinsics;
  for (int c = 0; c < 3; ++c) {
    intrinsics += std::string(c ? ", " : "") +
                  R"({"focallength": [500, 500], "principalpoint": [320, 240], "distortion": [0.1, 0, 0, 0, 0], "skew_value": 0, "imagesize": [640, 480]})";
  }
  auto rigid = [](double tx) { return "[1, 0, 0, " + std::to_string(tx) + ", 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]"; };
  std::string images;
  for (int c = 1; c <= 3; ++c) {
    images += std::string(c > 1 ? ", " : "") + R"({"id": )" + std::to_string(10000000000LL + c * 10000000LL + 5) +
              R"(, "file_name": "day1/cam)" + std::to_string(c) + R"(/color/000005.png", "cam_id": )" + std::to_string(c) +
              R"(, "day_id": 1, "width": 640, "height": 480, "date_captured": "2015-04-01 06:47:08.500000"})";
  }
  std::string points;
  for (int j = 0; j < 12; ++j) points += (j ? ", " : "") + std::to_string(100 * j) + ", 0, 3000, 2";
  return R"({"cameras_info": {"camParams": {"intrinsics": [)" + intrinsics + R"(], "extrinsics": [)" + rigid(0) + ", " +
         rigid(1000) + ", " + rigid(-500) + R"(], "firstCamToRoomRef": [1, 0, 0, 1000, 0, 0, 1, 0, 0, -1, 0, 1000, 0, 0, 0, 1]}},
 "images": [)" + images + R"(], "multiview_images": [{"id": "x", "images": [)" + images + R"(]}],
 "annotations3D": [{"image_ids": "10010000005_10020000005_10030000005", "person_id": 4, "ref_camera": 2, "keypoints3D": [)" +
         points + R"(], "id": "1"}],
 "annotations": [{"image_id": 10010000005, "person_id": 4, "bbox": [10, 20, 100, 200], "keypoints": [)" + Keypoints(10, 50) + "]}]}";
}

// ---------------------------------------------------------------------------------------
// H3WB

// 133 whole-body joints (metres, Human3.6M world, z up) of a person standing near the origin.
Eigen::Matrix3Xd WholeBody() {
  Eigen::Matrix3Xd X(3, 133);
  for (int j = 0; j < 133; ++j) X.col(j) << 0.3 * std::sin(0.37 * j), 0.2 * std::cos(0.11 * j), 0.012 * j + 0.05;
  return X;
}

std::string Rounded(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.0f", v);
  return std::string(buf) == "-0" ? "0" : buf;
}

// One H3WB json sample seen by `camera`: keypoints_3d in camera coordinates (whole mm, so two views
// still agree within the reader's 1 cm), optionally keypoints_2d (whole pixels) and image_path.
std::string H3wbJsonSample(const Camera& camera, bool with_2d, const std::string& image_path) {
  const Eigen::Matrix3Xd X = WholeBody();
  std::string kp3, kp2;
  for (int j = 0; j < 133; ++j) {
    const Eigen::Vector3d x_mm = (camera.R * X.col(j) + camera.t) * 1000.0;
    Eigen::Vector2d uv;
    camera.Project(X.col(j), &uv);
    const std::string key = (j ? ",\"" : "\"") + std::to_string(j) + "\":";
    kp3 += key + "{\"x\":" + Rounded(x_mm.x()) + ",\"y\":" + Rounded(x_mm.y()) + ",\"z\":" + Rounded(x_mm.z()) + "}";
    kp2 += key + "{\"x\":" + Rounded(uv.x()) + ",\"y\":" + Rounded(uv.y()) + "}";
  }
  std::string out = "{";
  if (!image_path.empty()) out += "\"image_path\":\"" + image_path + "\",";
  if (with_2d) out += "\"keypoints_2d\":{" + kp2 + "},";
  return out + "\"keypoints_3d\":{" + kp3 + "}}";
}

// The cameras of S8 in the h3wb_json target's fixed metadata.xml.
std::vector<Camera> H3wbJsonCameras() {
  test::TempDir dir;
  test::WriteText(dir.path() / "metadata.xml", H36mMetadataXmlText());
  return ReadHuman36mCameras(dir.path() / "metadata.xml", "S8");
}

// The two members of a small h3wb_train.npz, train_data.npy then metadata.npy (the h3wb_npz
// target's input): S8 "Directions 1", one frame (frame_id 7) seen by camera 54138969, float32 as
// in the real file.
Bytes H3wbNpzMembers() {
  const test::H36mCalib k = test::SyntheticH36mCalibs(8)[0];
  const Eigen::Matrix3d R = k.R();
  const Eigen::Vector3d center_m = k.center_mm / 1000.0;
  const Eigen::Matrix3Xd X = WholeBody();
  std::vector<double> global, camera_3d, pose_2d;
  Camera camera = Camera::FromCenter(R, center_m);
  camera.K << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1;
  for (int j = 0; j < 133; ++j) {
    for (int d = 0; d < 3; ++d) global.push_back(1000.0 * X(d, j));
    const Eigen::Vector3d x_mm = 1000.0 * R * (X.col(j) - center_m);
    camera_3d.insert(camera_3d.end(), {x_mm.x(), x_mm.y(), x_mm.z()});
    Eigen::Vector2d uv;
    camera.Project(X.col(j), &uv);
    pose_2d.insert(pose_2d.end(), {uv.x(), uv.y()});
  }
  const std::string id = Human36mCameraIds()[0];
  const test::Obj action = test::PyDict({
      {test::PyStr("global_3d"), test::PyArray({1, 133, 3}, global, "f4")},
      {test::PyStr("frame_id"), test::PyArray({1}, {7}, "i8")},
      {test::PyStr(id), test::PyDict({{test::PyStr("camera_3d"), test::PyArray({1, 133, 3}, camera_3d, "f4")},
                                      {test::PyStr("pose_2d"), test::PyArray({1, 133, 2}, pose_2d, "f4")}})},
  });
  const test::Obj train = test::PyDict({{test::PyStr("S8"), test::PyDict({{test::PyStr("Directions 1"), action}})}});
  // K divided by 1000, R world -> camera, T = -R C in metres, Distortion k1 k2 p1 p2 k3.
  const Eigen::Matrix3d Rt = R.transpose();  // column-major storage of R^T = row-major values of R
  const Eigen::Vector3d T = -R * center_m;
  const test::Obj metadata = test::PyDict({{test::PyStr("S8"), test::PyDict({{test::PyStr(id), test::PyDict({
      {test::PyStr("K"), test::PyArray({1, 3, 3}, {k.fx / 1000, 0, k.cx / 1000, 0, k.fy / 1000, k.cy / 1000, 0, 0, 0.001}, "f4")},
      {test::PyStr("R"), test::PyArray({1, 3, 3}, std::vector<double>(Rt.data(), Rt.data() + 9), "f4")},
      {test::PyStr("T"), test::PyArray({1, 1, 3}, {T.x(), T.y(), T.z()}, "f4")},
      {test::PyStr("Distortion"), test::PyArray({1, 5}, {k.k1, k.k2, k.p1, k.p2, k.k3}, "f4")}})}})}});
  Bytes out = test::NpyOfObject(train);
  test::Append(out, test::NpyOfObject(metadata));
  return out;
}

// ---------------------------------------------------------------------------------------
// EgoHumans

std::vector<double> Flat(const Eigen::Matrix4d& m) {
  std::vector<double> values;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values.push_back(m(r, c));
  }
  return values;
}

// colmap_from_aria_transforms.pkl as EgoHumans writes it: aria name -> 4x4 float64 ndarray
// (aria01 a similarity with scale 1.7).
Bytes EgohumansTransforms() {
  Eigen::Matrix4d anchor = Eigen::Matrix4d::Identity();
  anchor.topLeftCorner<3, 3>() = 1.7 * Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  anchor.topRightCorner<3, 1>() << 0.3, -0.2, 1.1;
  Eigen::Matrix4d other = Eigen::Matrix4d::Identity();
  other.topRightCorner<3, 1>() << 5, 5, 5;
  return test::PickleOf(test::PyDict({{test::PyStr("aria01"), test::PyArray({4, 4}, Flat(anchor))},
                                      {test::PyStr("aria02"), test::PyArray({4, 4}, Flat(other))}}));
}

// A manual exo calibration camXX.npy: 4x4 float64, COLMAP -> camera (rigid).
Bytes EgohumansManualCamera() {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(-1.2, Eigen::Vector3d(1, 0.2, 0).normalized()).toRotationMatrix();
  m.topRightCorner<3, 1>() << 0.4, 1.2, 3.9;
  return test::NpyBytes("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }", test::RawOf(Flat(m)));
}

// processed_data/poses3d/00001.npy: {aria01: (17, 4), aria02: (17, 4) with joints 5 and 6 not valid}.
Bytes EgohumansGt() {
  std::vector<std::pair<test::Obj, test::Obj>> people;
  for (int p = 0; p < 2; ++p) {
    std::vector<double> values;
    for (int j = 0; j < 17; ++j) {
      const bool valid = !(p == 1 && (j == 5 || j == 6));
      for (double v : {0.8 * p - 0.4 + 0.1 * std::sin(j), 0.5 * p + 0.08 * std::cos(1.3 * j), 1.7 - 0.09 * j}) values.push_back(valid ? v : 0.0);
      values.push_back(valid ? 1.0 : 0.0);
    }
    people.emplace_back(test::PyStr("aria0" + std::to_string(p + 1)), test::PyArray({17, 4}, values));
  }
  return test::NpyOfObject(test::PyDict(people));
}

// processed_data/poses2d/cam01/rgb/00001.npy: one detected person (keypoints (133, 3) float32,
// the face and hands with score 0).
Bytes EgohumansPoses2d() {
  std::vector<double> keypoints;
  for (int j = 0; j < 133; ++j) keypoints.insert(keypoints.end(), {1800.0 + 7 * j, 900.0 + 3 * (j % 17), j < 23 ? 0.9 : 0.0});
  return test::NpyOfObjectList({test::PyDict({{test::PyStr("human_name"), test::PyStr("aria01")},
                                              {test::PyStr("bbox"), test::PyArray({5}, {1700, 850, 2800, 1400, 0.99})},
                                              {test::PyStr("keypoints"), test::PyArray({133, 3}, keypoints, "f4")}})});
}

// ---------------------------------------------------------------------------------------
// Calibrations: files of the project's writers and hand-written files of the other tools.

void AddCalibrationSeeds(std::map<std::string, std::vector<std::pair<std::string, Bytes>>>* seeds) {
  const std::vector<Camera> rig = test::MakeRig(/*with_fisheye=*/false);
  const std::vector<Camera> fisheye_rig = test::MakeRig(/*with_fisheye=*/true);
  auto written = [](const std::string& name, const std::vector<Camera>& cameras) {
    return Written(name, [&](const fs::path& p) { WriteCalibration(p, cameras); });
  };
  (*seeds)["calibration_json"] = {{"rig.json", written("rig.json", fisheye_rig)}};
  (*seeds)["calibration_opencv"] = {
      {"fisheye.yml", written("c.yml", {fisheye_rig[3]})},
      {"camera.xml", written("c.xml", {rig[1]})},
      {"ros.yaml", Of("image_width: 1280\nimage_height: 720\ncamera_name: left\ncamera_matrix:\n  rows: 3\n  cols: 3\n"
                      "  data: [1000, 0, 640, 0, 1000, 360, 0, 0, 1]\ndistortion_model: plumb_bob\n"
                      "distortion_coefficients:\n  rows: 1\n  cols: 5\n  data: [-0.1, 0.01, 0.001, 0.002, 0.0]\n")},
      {"storage.json", Of(R"({"camera_matrix": {"type_id": "opencv-matrix", "rows": 3, "cols": 3, "dt": "d",
  "data": [1000.0, 0.0, 960.0, 0.0, 1000.0, 540.0, 0.0, 0.0, 1.0]}, "image_width": 1920, "image_height": 1080,
  "rvec": [1.5707963267948966, 0.0, 0.0], "tvec": [0.0, 1.5, 4.0], "distortion_model": "fisheye", "D": [0.1, 0.0, 0.0, 0.0]})")},
      {"stereo.yml", Of("%YAML:1.0\nM1: [1000, 0, 960, 0, 1000, 540, 0, 0, 1]\nD1: [0.1, 0, 0, 0]\n"
                        "M2: [1000, 0, 960, 0, 1000, 540, 0, 0, 1]\nD2: [0, 0, 0, 0, 0]\nimage_size: [1920, 1080]\n"
                        "R: [0, 0.3, 0]\nT: [-0.5, 0, 0]\n")}};
  (*seeds)["calibration_easymocap"] = {{"cameras.yml", written("c.yml", rig)}};
  (*seeds)["calibration_toml"] = {
      {"rig.toml", written("rig.toml", fisheye_rig)},
      {"anipose.toml",
       Of("[cam_0]\nname = \"A\"\nsize = [ 1920, 1080,]\nmatrix = [ [ 1000.0, 0.0, 960.0,], [ 0.0, 1000.0, 540.0,], "
          "[ 0.0, 0.0, 1.0,],]\ndistortions = [ 0.01, 0.0, 0.0, 0.0, 0.0,]\nrotation = [ 1.5707963267948966, 0.0, "
          "0.0,]\n"
          "translation = [ 0.0, 1500.0, 4000.0,]\n\n[metadata]\n")}};
  (*seeds)["calibration_colmap"] = {
      {"images.txt",
       Of("# Image list\n1 0.70710678118654757 0.70710678118654757 0 0 0 1.5 4 1 cam01/00001.jpg\n\n"
          "2 1 0 0 0 0.5 0 3 2 cam02/00001.jpg\n100 200 -1\n3 0.5 -0.5 0.5 -0.5 -0.3 1.4 4.2 3 cam03.png\n\n")}};
}

}  // namespace

std::map<std::string, std::vector<std::pair<std::string, Bytes>>> MakeFuzzSeeds() {
  std::map<std::string, std::vector<std::pair<std::string, Bytes>>> seeds;
  const Sequence labels = test::MakeLabelSequence("scene", 3, "frame_");
  seeds["labels"] = {
      {"written.json", Written("labels.json", [&](const fs::path& p) { WriteLabels(p, {labels}); })},
      {"skelda.json", Of(R"([{"id": "s_0", "splits": ["test"], "joints": ["nose", "shoulder_left"], "timestamp": 0.5, "bodyids": [1],
  "cameras": [{"name": "c0", "type": "fisheye", "K": [[600, 0, 640], [0, 600, 480], [0, 0, 1]], "DC": [0.1, -0.02, 0.003, -0.0004],
    "R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4], [1.5]], "width": 1280, "height": 960}],
  "bodies3D": [[[0.1, 0.2, 1.7, 1], [0.3, 0.2, 1.5]]], "room_size": [8, 8, 3], "room_center": [[0], [0], [1.5]]}])")}};
  const Detections detections = test::MakeDetections(3, {"cam_a", "cam_b"}, CocoBodyJoints());
  seeds["detections_json"] = {
      {"written.json", Written("detections.json", [&](const fs::path& p) { WriteGenericDetections(p, detections); })}};
  seeds["detection_lines"] = {{"stream.jsonl", DetectionLines(detections)}};
  seeds["coco"] = {{"mvor_results.json", Of(R"([{"image_id": 10010000005, "category_id": 1, "score": 0.9, "keypoints": [)" +
                                                Keypoints(17, 100) + R"(]}, {"image_id": "10020000005", "category_id": 1, "score": 0.4, "keypoints": [)" +
                                                Keypoints(17, 300) + "]}]")}};
  seeds["openpose"] = {{"body25.json", Of(R"({"version": 1.3, "people": [{"person_id": [-1], "pose_keypoints_2d": [)" + Keypoints(25, 40) +
                                          R"(]}, {"pose_keypoints_2d": [)" + Keypoints(25, 400) + "]}]}")}};
  const std::string voxelpose_camera =
      R"({"R": [[1, 0, 0], [0, 0, -1], [0, 1, 0]], "T": [[0], [-4000], [1500]], "fx": 1000, "fy": 1001, "cx": 516, "cy": 388,
  "k": [[-0.2], [0.05], [0.0]], "p": [[0.001], [-0.0005]]})";
  seeds["voxelpose_calibration"] = {{"calibration.json", Of(R"({"0": )" + voxelpose_camera + R"(, "1": )" + voxelpose_camera + "}")}};
  seeds["voxelpose_detections"] = {{"pred.pkl", VoxelPosePickle()}};
  test::PickleWriter dict;
  dict.Proto(2).EmptyDict().Mark().Str("a").Int(5).Str("b").Float(2.5).Str("c").EmptyList().SetItems().Stop();
  seeds["pickle"] = {{"cache.pkl", VoxelPosePickle()}, {"dict.pkl", dict.bytes}};
  seeds["npy"] = {{"a.npy", Npy2x3()}};
  seeds["npz"] = {{"stored.npz", test::ZipBytes({{"a.npy", Npy2x3()}, {"b.npy", Npy2x3(), true}})},
                  {"numpy.npz", test::ZipBytes({{"x.npy", Npy2x3(), true, true}})}};
  seeds["mat"] = {{"a.mat", MatFile()}};
  seeds["hdf5"] = {
      {"sequences.h5", Written("s.h5", [&](const fs::path& p) { WriteSequencesHdf5(p, {labels}); })},
      {"detections.h5", Written("d.h5", [&](const fs::path& p) { WriteDetectionsHdf5(p, detections); })}};
  seeds["colmap_cameras"] = {{"cameras.txt", Of("# Camera list\n1 PINHOLE 640 480 500 500 320 240\n2 OPENCV 640 480 500 501 320 240 0.1 -0.01 0.001 0.002\n"
                                                "3 SIMPLE_RADIAL 800 600 700 400 300 0.05\n")}};
  seeds["colmap_images"] = {{"images.txt", Of("# Image list\n1 1 0 0 0 0.1 0.2 3 1 cam1/000001.jpg\n100 200 -1\n"
                                              "2 0.7071068 0 0.7071068 0 -1 0 4 2 cam2/000001.jpg\n\n")}};
  seeds["fourda_detections"] = {{"detection.txt", Of(FourDaDetections(2))}};
  seeds["fourda_skeletons"] = {{"gt.txt", Of(FourDaSkeletons())}};
  seeds["fourda_calibration"] = {{"calibration.json", Of(R"({"0": {"K": [1000, 0, 480, 0, 1000, 270, 0, 0, 1], "imgSize": [960, 540],
  "RT": [1, 0, 0, 0.1, 0, 1, 0, 0.2, 0, 0, 1, 3], "distCoeff": [0, 0, 0, 0, 0]},
 "1": {"K": [1000, 0, 480, 0, 1000, 270, 0, 0, 1], "imgSize": [960, 540], "R": [0, 0.3, 0], "T": [0.5, 0, 3]}})")}};
  seeds["panoptic_calibration"] = {{"calibration.json", Of(PanopticCalibrationText())}};
  seeds["panoptic_bodies"] = {{"body3DScene.json", Of(PanopticBodiesText())}};
  seeds["mvor"] = {{"camma_mvor_2018.json", Of(MvorAnnotations())}};
  seeds["h36m_metadata_xml"] = {{"metadata.xml", Of(test::MetadataXml(test::W0(test::SyntheticH36mCalibs)))}};
  const std::vector<Camera> h3wb_cameras = H3wbJsonCameras();
  // Two views (ids 0 and 1 = cameras 54138969, 55011271) of one frame: the reader finds the subject
  // whose cameras make them agree. One view found by its image path, with its 2D keypoints.
  seeds["h3wb_json"] = {
      {"2Dto3D_two_views.json", Of("{\"0\":" + H3wbJsonSample(h3wb_cameras[0], false, "") + ",\n\"1\":" +
                                   H3wbJsonSample(h3wb_cameras[1], false, "") + "}\n")},
      {"RGBto3D_image_path.json",
       Of("{\"12\":" + H3wbJsonSample(h3wb_cameras[2], true, "Human36m/S8/Images/Directions 1.58860488/frame_0005.jpg") + "}\n")}};
  seeds["h3wb_npz"] = {{"train_data_metadata.npy", H3wbNpzMembers()}};
  seeds["egohumans_cameras"] = {
      {"cameras.txt", Of(EgohumansCamerasText())},
      {"radial.txt", Of("1 OPENCV 3840 2160 1750 1752 1920 1080 0.05 -0.01 0.001 0.002\n2 SIMPLE_RADIAL 1920 1080 1000 960 540 0.01\n")}};
  seeds["egohumans_images"] = {{"images.txt", Of(EgohumansImagesText())}};
  seeds["egohumans_transforms"] = {{"colmap_from_aria_transforms.pkl", EgohumansTransforms()}};
  seeds["egohumans_camera_npy"] = {{"cam02.npy", EgohumansManualCamera()}};
  seeds["egohumans_gt"] = {{"00001.npy", EgohumansGt()}};
  seeds["egohumans_poses2d"] = {{"00001.npy", EgohumansPoses2d()}, {"nobody.npy", test::NpyOfObjectList({})}};
  AddCalibrationSeeds(&seeds);
  seeds["config"] = {{"config.json", Of(R"({"filter": {"min_match_score": 0.9}, "triangulate": {"core_joints": ["nose", "hip_left", "hip_right"]},
  "room_check": {"size_m": [8, 8, 3]}})")}};
  seeds["thresholds"] = {{"thresholds.json", Of(R"({"description": "fuzz", "evaluations": [{"name": "synthetic",
  "dataset": "synthetic", "params": {"frames": 2}, "min": {"recall500": 50}, "max": {"mpjpe_mm": 100}}]})")}};
  seeds["sweep_list"] = {{"list.json", Of(R"([{"name": "no prefilter", "set": {"prefilter.enabled": false}},
  {"set": {"filter.min_match_score": 0.9, "triangulate.core_joints": ["nose", "hip_left", "hip_right"]}}, {"name": "default"}])")},
                         {"object.json", Of(R"({"configurations": [{"name": "a", "set": {"merge.top_k": 0}}]})")}};
  seeds["sweep_shard"] = {{"sweep-shard-1-of-1.json", Of(R"({"total": 2, "shard": "1/1", "base": {"filter.min_match_score": "0.9"},
  "sweep": {"configurations": [{"name": "a", "set": {"merge.top_k": "0"}}, {"name": "b", "set": {}}], "base_config": "crc32:00000000",
            "input": {"dataset": "synthetic", "params": ["frames=2"]}},
  "rows": [{"index": 0, "name": "a", "set": {"merge.top_k": "0"}, "default": true, "summary": {"mpjpe_mm": 50.5, "recall500": null}},
           {"index": 1, "name": "b", "summary": {"mpjpe_mm": 51}}]})")}};
  seeds["run_folder"] = {{"summary.json", Of(std::string(1, '\0') + R"({"mpjpe_mm": 50.5, "gt_persons": 2})")},
                         {"run.json", Of(std::string(1, '\2') + R"({"argv": ["rpt", "eval", "--labels", "x.json"], "input_digests": {}})")},
                         {"predictions.json", Of(std::string(1, '\3') + R"({"joints": ["a", "b"], "frames": []})")}};
  return seeds;
}

}  // namespace rpt::fuzz

// SPDX-License-Identifier: MIT
#include "datasets/readers/h3wb.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/errors.h"
#include "datasets/readers/human36m.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/reader_stream_test.h"
#include "tests/datasets/readers_h36m_ego_test_util.h"
#include "tests/datasets/tolerance_test_util.h"

namespace rpt {
using engine::ReadDataset;
using engine::OpenDataset;
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::H36mCalib;
using test::InputErrorOf;
using test::Num;

// 133 whole-body joints (metres, H36M world) of frame f.
Eigen::Matrix3Xd WholeBody(int f) {
  Eigen::Matrix3Xd X(3, 133);
  for (int j = 0; j < 133; ++j) {
    X.col(j) << 0.3 * std::sin(0.37 * j + 0.1 * f) + 0.01 * f, 0.2 * std::cos(0.11 * j), 0.012 * j + 0.05;
  }
  return X;
}

Camera CameraOf(const H36mCalib& k, const std::string& id) {
  Camera camera = Camera::FromCenter(k.R(), k.center_mm / 1000.0);
  camera.name = id;
  camera.width = 1000;
  camera.height = 1000;
  camera.K << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1;
  camera.model = DistortionModel::kH36M;
  camera.dist = {k.k1, k.k2, k.p1, k.p2, k.k3};
  return camera;
}

std::vector<Camera> SubjectCameras(int subject) {
  std::vector<Camera> out;
  const auto calibs = test::SyntheticH36mCalibs(subject);
  for (std::size_t c = 0; c < 4; ++c) out.push_back(CameraOf(calibs[c], Human36mCameraIds()[c]));
  return out;
}

// ---------------------------------------------------------------------------------------
// npz

struct NpzOptions {
  double global_scale = 1000.0;  // metres -> file units of global_3d
  bool nan_in_global = false;
  bool camera_3d_2d = false;     // wrong last extent of camera_3d
  int wrong_rotation_camera = -1;  // this camera of S8 gets a rotation 1e-2 off
};

test::Obj ActionObj(int subject, const std::vector<int>& frames, const NpzOptions& options) {
  const auto cameras = SubjectCameras(subject);
  std::vector<double> global, frame_ids;
  std::vector<std::vector<double>> camera_3d(4), pose_2d(4);
  for (int f : frames) {
    const auto X = WholeBody(f);
    frame_ids.push_back(f);
    for (int j = 0; j < 133; ++j) {
      for (int d = 0; d < 3; ++d) global.push_back(X(d, j) * options.global_scale);
      for (std::size_t c = 0; c < 4; ++c) {
        const Eigen::Vector3d x_mm = (cameras[c].R * X.col(j) + cameras[c].t) * 1000.0;
        camera_3d[c].insert(camera_3d[c].end(), {x_mm.x(), x_mm.y(), options.camera_3d_2d ? 0.0 : x_mm.z()});
        if (options.camera_3d_2d) camera_3d[c].pop_back();
        Eigen::Vector2d uv;
        cameras[c].Project(X.col(j), &uv);
        pose_2d[c].insert(pose_2d[c].end(), {uv.x(), uv.y()});
      }
    }
  }
  if (options.nan_in_global) global[5] = std::nan("");
  const auto n = static_cast<std::int64_t>(frames.size());
  std::vector<std::pair<test::Obj, test::Obj>> entries = {
      {test::PyStr("global_3d"), test::PyArray({n, 133, 3}, global)},
      {test::PyStr("frame_id"), test::PyArray({n}, frame_ids, "i8")},
  };
  for (std::size_t c = 0; c < 4; ++c) {
    // Camera 2 stores camera_3d with a singleton axis, as (N, 1, 133, 3).
    const std::vector<std::int64_t> shape = options.camera_3d_2d ? std::vector<std::int64_t>{n, 133, 2}
                                            : c == 2            ? std::vector<std::int64_t>{n, 1, 133, 3}
                                                                : std::vector<std::int64_t>{n, 133, 3};
    entries.emplace_back(test::PyStr(Human36mCameraIds()[c]),
                         test::PyDict({{test::PyStr("camera_3d"), test::PyArray(shape, camera_3d[c], "f4")},
                                       {test::PyStr("pose_2d"), test::PyArray({n, 133, 2}, pose_2d[c])},
                                       {test::PyStr("sample_id"), test::PyArray({n}, frame_ids, "i8")}}));
  }
  return test::PyDict(entries);
}

// Cameras of `subject` as stored in the npz (float32, as the real file); R of camera
// `wrong_camera` 1e-2 off.
test::Obj MetadataObj(int subject, int wrong_camera = -1) {
  std::vector<std::pair<test::Obj, test::Obj>> cams;
  const auto calibs = test::SyntheticH36mCalibs(subject);
  for (std::size_t c = 0; c < 4; ++c) {
    const H36mCalib& k = calibs[c];
    const Eigen::Matrix3d R = static_cast<int>(c) == wrong_camera ? test::WrongRotation(k.R()) : k.R();
    const Eigen::Vector3d T = -R * k.center_mm / 1000.0;
    const Eigen::Matrix3d Rt = R.transpose();  // column-major storage of R^T = row-major values of R
    const std::vector<double> r(Rt.data(), Rt.data() + 9);
    cams.emplace_back(test::PyStr(Human36mCameraIds()[c]),
                      test::PyDict({{test::PyStr("K"), test::PyArray({1, 3, 3}, {k.fx / 1000, 0, k.cx / 1000, 0, k.fy / 1000, k.cy / 1000, 0, 0, 0.001}, "f4")},
                                    {test::PyStr("R"), test::PyArray({1, 3, 3}, r, "f4")},
                                    {test::PyStr("T"), test::PyArray({1, 1, 3}, {T.x(), T.y(), T.z()}, "f4")},
                                    {test::PyStr("Distortion"), test::PyArray({1, 5}, {k.k1, k.k2, k.p1, k.p2, k.k3}, "f4")}}));
  }
  return test::PyDict(cams);
}

fs::path WriteNpz(const fs::path& dir, const NpzOptions& options = {}, bool with_metadata = true) {
  const test::Obj train = test::PyDict({
      {test::PyStr("S8"), test::PyDict({{test::PyStr("Directions 1"), ActionObj(8, {10, 0, 5}, options)},
                                        {test::PyStr("Eating"), ActionObj(8, {3}, options)}})},
      {test::PyStr("S5"), test::PyDict({{test::PyStr("Walking"), ActionObj(5, {1, 2}, options)}})},
  });
  const test::Obj metadata = test::PyDict({
      {test::PyStr("S8"), MetadataObj(8, options.wrong_rotation_camera)},
      {test::PyStr("S5"), MetadataObj(5)},
      {test::PyStr("left_side"), test::PyList({test::PyInt(1), test::PyInt(3)})},
  });
  std::vector<test::ZipMember> members = {{"train_data.npy", test::NpyOfObject(train), true, true}};
  if (with_metadata) members.push_back({"metadata.npy", test::NpyOfObject(metadata), true, true});
  const fs::path path = dir / "h3wb_train.npz";
  test::WriteBytes(path, test::ZipBytes(members));
  return path;
}

DatasetRequest Request(const fs::path& root, std::map<std::string, std::string> params = {}) {
  DatasetRequest request;
  request.dataset = "h3wb";
  request.root = root;
  request.params = std::move(params);
  return request;
}

TEST(H3wbReader, NpzRoundTrip) {
  test::TempDir dir;
  WriteNpz(dir.path());
  const auto sequences = ReadDataset(Request(dir.path()));  // default subjects: S8
  ASSERT_EQ(sequences.size(), 2u);
  const Sequence& seq = sequences[0];
  EXPECT_EQ(seq.name, "h3wb/S8/Directions-1");
  EXPECT_EQ(seq.gt_joints, CocoWholeBodyJoints());
  ASSERT_EQ(seq.cameras.size(), 4u);
  const auto expected_cameras = SubjectCameras(8);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(seq.cameras[c].name, Human36mCameraIds()[c]);
    EXPECT_LT((seq.cameras[c].R - expected_cameras[c].R).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((seq.cameras[c].Center() - expected_cameras[c].Center()).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_NEAR(seq.cameras[c].K(0, 0), expected_cameras[c].K(0, 0), 1e-3);
    EXPECT_NEAR(seq.cameras[c].K(1, 2), expected_cameras[c].K(1, 2), 1e-3);
    EXPECT_NEAR(seq.cameras[c].dist[2], expected_cameras[c].dist[2], 1e-8);
    EXPECT_EQ(seq.cameras[c].model, DistortionModel::kH36M);
  }
  ASSERT_EQ(seq.frames.size(), 3u);
  EXPECT_EQ(seq.frames[0].id, "h3wb_S8_Directions-1_000000");
  EXPECT_EQ(seq.frames[2].id, "h3wb_S8_Directions-1_000010");
  EXPECT_DOUBLE_EQ(seq.frames[1].timestamp_s, 5 / 50.0);
  for (std::size_t f = 0; f < 3; ++f) {
    const auto X = WholeBody(static_cast<int>(5 * f));
    const auto person = seq.frames[f].gt.Person(0);
    EXPECT_LT((person.topRows<3>() - X).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_EQ(person.row(3).minCoeff(), 1.0);
  }
  EXPECT_EQ(sequences[1].name, "h3wb/S8/Eating");
  // The float32 rotations are re-orthonormalised and counted once per subject (first sequence).
  for (const Camera& camera : seq.cameras) EXPECT_LT(test::OrthonormalityError(camera.R), 1e-12);
  test::ExpectOneWarning(seq.warnings, (dir.path() / "h3wb_train.npz").string() + "[metadata.npy]", test::kRotationsFixed, 4);
  EXPECT_TRUE(sequences[1].warnings.empty());

  // 2D from pose_2d (detections=annotations, read in the same walk as the GT); it matches the
  // projection of the GT with the reader's cameras.
  const auto with_views = ReadDataset(Request(dir.path(), {{"actions", "Directions"}, {"detections", "annotations"}}));
  ASSERT_EQ(with_views.size(), 1u);
  EXPECT_EQ(with_views[0].detection_joints.size(), 133u);
  ASSERT_EQ(with_views[0].frames.size(), 3u);
  EXPECT_EQ(with_views[0].frames[1].id, "h3wb_S8_Directions-1_000005");
  ASSERT_EQ(with_views[0].frames[1].views.size(), 4u);
  double worst = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    const auto person = with_views[0].frames[1].views[c].Person(0);
    for (int j = 0; j < 133; ++j) {
      Eigen::Vector2d uv;
      seq.cameras[c].Project(seq.frames[1].gt.Person(0).col(j).head<3>(), &uv);
      worst = std::max(worst, (uv - person.col(j).head<2>()).norm());
      EXPECT_EQ(person(2, j), 1.0);
    }
  }
  EXPECT_LT(worst, 0.01);  // float32 cameras in the file
  for (std::size_t f = 0; f < 3; ++f) EXPECT_EQ(with_views[0].frames[f].gt.data, seq.frames[f].gt.data);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"detections", "hrnet"}})), ConfigError);

  // Other subject, params.
  const auto s5 = ReadDataset(Request(dir.path() / "h3wb_train.npz", {{"subjects", "S5"}, {"max_frames", "1"}}));
  ASSERT_EQ(s5.size(), 1u);
  EXPECT_EQ(s5[0].frames.size(), 1u);
  EXPECT_EQ(s5[0].frames[0].id, "h3wb_S5_Walking_000001");
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"every", "2"}}))[0].frames.size(), 2u);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"distortion", "opencv"}}))[0].cameras[0].model, DistortionModel::kOpenCV);
}

TEST(H3wbReader, NpzRotationBeyondTheToleranceNamesFileAndCamera) {
  test::TempDir dir;
  WriteNpz(dir.path(), {.wrong_rotation_camera = 3});
  EXPECT_THAT(
      test::InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
      HasSubstr("h3wb_train.npz[metadata.npy]: key 'S8'['60457274'].R: R is not a rotation (max |R^T R - I| = 0.0100"));
}

TEST(H3wbReader, NpzGlobalUnits) {
  test::TempDir dir;
  WriteNpz(dir.path(), {.global_scale = 1.0});
  const auto metres = ReadDataset(Request(dir.path(), {{"global_units", "m"}}));
  EXPECT_LT((metres[0].frames[2].gt.Person(0).topRows<3>() - WholeBody(10)).cwiseAbs().maxCoeff(), 1e-12);
  const std::string msg = InputErrorOf([&] { ReadDataset(Request(dir.path())); });
  EXPECT_THAT(msg, HasSubstr("h3wb_train.npz: S8/Directions 1 frame_id 0: global_3d (read as mm) and camera 54138969's camera_3d differ by"));
  EXPECT_THAT(msg, HasSubstr("global_3d looks like metres: pass --param global_units=m"));
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"global_units", "cm"}})), ConfigError);
}

TEST(H3wbReader, NpzMalformed) {
  test::TempDir dir;
  const fs::path npz = WriteNpz(dir.path());
  std::string msg = InputErrorOf([&] { ReadDataset(Request(dir.path(), {{"subjects", "S9"}})); });
  EXPECT_THAT(msg, HasSubstr("h3wb_train.npz[train_data.npy]: top level: unknown subject 'S9' (file has S8, S5)"));
  WriteNpz(dir.path(), {.nan_in_global = true});
  EXPECT_THAT(
      InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
      HasSubstr(
          "h3wb_train.npz[train_data.npy]: key 'S8'['Directions 1'].global_3d: row 0: NaN or infinite coordinate"));
  WriteNpz(dir.path(), {.camera_3d_2d = true});
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr(".camera_3d: expected shape (N, 133, 3)"));
  WriteNpz(dir.path(), {}, false);
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("h3wb_train.npz: no member 'metadata.npy'"));
  const auto bytes = fs::file_size(npz);
  WriteNpz(dir.path());
  fs::resize_file(npz, bytes / 2);
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("h3wb_train.npz"));
  fs::remove(npz);
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("no H3WB annotation file found"));
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"format", "csv"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"view", "1"}})), ConfigError);
}

// ---------------------------------------------------------------------------------------
// json

std::string Padded4(int v) {
  std::string s = std::to_string(v);
  return std::string(4 - s.size(), '0') + s;
}

struct JsonView {
  std::string key;
  int subject;
  int camera;
  int frame;
  std::string image_path;  // empty = none
};

std::string JsonFile(const std::vector<JsonView>& views, bool with_2d = true) {
  std::string text = "{";
  for (std::size_t v = 0; v < views.size(); ++v) {
    const JsonView& view = views[v];
    const Camera camera = SubjectCameras(view.subject)[static_cast<std::size_t>(view.camera)];
    const auto X = WholeBody(view.frame);
    text += (v ? ",\n" : "\n") + std::string("\"") + view.key + "\": {";
    if (!view.image_path.empty()) text += "\"image_path\": \"" + view.image_path + "\", ";
    text += "\"bbox\": {\"x_min\": 1, \"y_min\": 2, \"x_max\": 300, \"y_max\": 400}, ";
    std::string kp3, kp2;
    for (int j = 0; j < 133; ++j) {
      const Eigen::Vector3d x_mm = (camera.R * X.col(j) + camera.t) * 1000.0;
      Eigen::Vector2d uv;
      camera.Project(X.col(j), &uv);
      kp3 += (j ? ", " : "") + std::string("\"") + std::to_string(j) + "\": {\"x\": " + Num(x_mm.x()) + ", \"y\": " + Num(x_mm.y()) +
             ", \"z\": " + Num(x_mm.z()) + "}";
      kp2 += (j ? ", " : "") + std::string("\"") + std::to_string(j) + "\": {\"x\": " + Num(uv.x()) + ", \"y\": " + Num(uv.y()) + "}";
    }
    if (with_2d) text += "\"keypoints_2d\": {" + kp2 + "}, ";
    text += "\"keypoints_3d\": {" + kp3 + "}}";
  }
  return text + "\n}\n";
}

void WriteMetadata(const fs::path& dir) { test::WriteText(dir / "metadata.xml", test::MetadataXml(test::W0(test::SyntheticH36mCalibs))); }

TEST(H3wbReader, JsonByIdsFindsTheSubject) {
  test::TempDir dir;
  WriteMetadata(dir.path());
  std::vector<JsonView> views;
  // ids 0-3: S8 frame 7, ids 4-7: S5 frame 9, ids 8-11: S8 frame 3 (written in shuffled order).
  for (int c : {2, 0, 3, 1}) views.push_back({std::to_string(c), 8, c, 7, ""});
  for (int c = 0; c < 4; ++c) views.push_back({std::to_string(4 + c), 5, c, 9, ""});
  for (int c : {1, 3}) views.push_back({std::to_string(8 + c), 8, c, 3, ""});  // only two views of this frame
  test::WriteText(dir.path() / "2Dto3D_train.json", JsonFile(views));

  const auto sequences = ReadDataset(Request(dir.path()));
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& seq = sequences[0];
  EXPECT_EQ(seq.name, "h3wb/S8/json");
  ASSERT_EQ(seq.frames.size(), 2u);
  EXPECT_EQ(seq.frames[0].id, "h3wb_S8_sample_000000");
  EXPECT_EQ(seq.frames[1].id, "h3wb_S8_sample_000008");
  EXPECT_LT((seq.frames[0].gt.Person(0).topRows<3>() - WholeBody(7)).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((seq.frames[1].gt.Person(0).topRows<3>() - WholeBody(3)).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((seq.cameras[1].R - SubjectCameras(8)[1].R).cwiseAbs().maxCoeff(), 1e-12);
  // Samples in no known order: no time (and no frame rate), which one warning says.
  EXPECT_TRUE(std::isnan(seq.frames[0].timestamp_s));
  EXPECT_TRUE(std::isnan(seq.frames[1].timestamp_s));
  EXPECT_EQ(seq.fps, 0);
  ASSERT_EQ(seq.warnings.items().size(), 1u);
  EXPECT_EQ(seq.warnings.items()[0].kind, InputWarningKind::kMissing);
  EXPECT_EQ(seq.warnings.items()[0].Line(), (dir.path() / "2Dto3D_train.json").string() +
                                                ": 2 frames grouped by sample id (no image paths): their times are "
                                                "unknown, so nothing is carried from one frame to the next");

  const auto s5 = ReadDataset(Request(dir.path(), {{"subjects", "S5"}}));
  ASSERT_EQ(s5.size(), 1u);
  EXPECT_EQ(s5[0].frames[0].id, "h3wb_S5_sample_000004");
  EXPECT_LT((s5[0].frames[0].gt.Person(0).topRows<3>() - WholeBody(9)).cwiseAbs().maxCoeff(), 1e-9);

  // Frame 3 has two views: the other two cameras get no person.
  const auto with_views = ReadDataset(Request(dir.path(), {{"detections", "annotations"}}));
  ASSERT_EQ(with_views[0].frames.size(), 2u);
  const std::vector<Poses2D>& frame_views = with_views[0].frames[1].views;
  ASSERT_EQ(frame_views.size(), 4u);
  EXPECT_EQ(frame_views[0].num_persons(), 0);
  EXPECT_EQ(frame_views[1].num_persons(), 1);
  EXPECT_EQ(frame_views[2].num_persons(), 0);
  EXPECT_EQ(frame_views[3].num_persons(), 1);
  Eigen::Vector2d uv;
  seq.cameras[3].Project(WholeBody(3).col(40), &uv);
  EXPECT_LT((frame_views[3].Person(0).col(40).head<2>() - uv).norm(), 1e-9);

  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S1"}}));
              }),
              HasSubstr("2Dto3D_train.json: unknown subject 'S1' (file has S5, S8)"));
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"actions", "Walking"}})), ConfigError);
}

TEST(H3wbReader, JsonByImagePath) {
  test::TempDir dir;
  WriteMetadata(dir.path());
  std::vector<JsonView> views;
  int key = 100;
  for (int frame : {12, 4}) {
    for (int c : {3, 1, 0, 2}) {
      views.push_back({std::to_string(key--), 8, c, frame,
                       "Human36m/S8/Images/Directions 1." + Human36mCameraIds()[static_cast<std::size_t>(c)] + "/frame_" +
                           Padded4(frame) + ".jpg"});
    }
  }
  views.push_back({"7", 5, 0, 2, "Human36m/S5/Images/Eating.54138969/frame_0002.jpg"});
  test::WriteText(dir.path() / "RGBto3D_train.json", JsonFile(views, false));
  const auto sequences = ReadDataset(Request(dir.path(), {{"file", "RGBto3D_train.json"}, {"format", "json"}}));
  ASSERT_EQ(sequences.size(), 1u);
  EXPECT_EQ(sequences[0].name, "h3wb/S8/Directions-1");
  ASSERT_EQ(sequences[0].frames.size(), 2u);
  EXPECT_EQ(sequences[0].frames[0].id, "h3wb_S8_Directions-1_000004");
  EXPECT_EQ(sequences[0].frames[1].id, "h3wb_S8_Directions-1_000012");
  EXPECT_LT((sequences[0].frames[1].gt.Person(0).topRows<3>() - WholeBody(12)).cwiseAbs().maxCoeff(), 1e-9);
  const auto rgb = ReadDataset(Request(dir.path(), {{"file", "RGBto3D_train.json"}, {"detections", "annotations"}}));
  for (const Poses2D& view : rgb[0].frames[0].views) EXPECT_EQ(view.num_persons(), 0);  // no keypoints_2d
  const auto s5 =
      ReadDataset(Request(dir.path(), {{"file", "RGBto3D_train.json"}, {"subjects", "S5"}, {"actions", "Eating"}}));
  ASSERT_EQ(s5.size(), 1u);
  EXPECT_EQ(s5[0].frames[0].id, "h3wb_S5_Eating_000002");
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(),
                                    {{"file", "RGBto3D_train.json"}, {"subjects", "S5,S8"}, {"actions", "Eating"}}));
              }),
              HasSubstr("RGBto3D_train.json: no frames of subject S8 with the selected actions"));
}

TEST(H3wbReader, JsonMalformed) {
  test::TempDir dir;
  const fs::path json = dir.path() / "2Dto3D_train.json";
  std::vector<JsonView> views;
  for (int c = 0; c < 4; ++c) views.push_back({std::to_string(c), 8, c, 7, ""});
  test::WriteText(json, JsonFile(views));
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("the json format needs Human3.6M cameras"));
  WriteMetadata(dir.path());
  // Views in the wrong camera order do not agree for any subject.
  std::swap(views[0].camera, views[1].camera);
  test::WriteText(json, JsonFile(views));
  std::swap(views[0].camera, views[1].camera);
  std::string msg = InputErrorOf([&] { ReadDataset(Request(dir.path())); });
  EXPECT_THAT(msg, HasSubstr("2Dto3D_train.json: samples 0, 1, 2, 3: the views do not agree in world coordinates"));
  EXPECT_THAT(msg, HasSubstr("are ids 4k..4k+3 the four views of one frame?"));
  // Path-grouped views that disagree.
  std::vector<JsonView> bad_paths = {{"0", 8, 0, 7, "S8/Images/Eating.54138969/frame_0007.jpg"},
                                     {"1", 8, 1, 8, "S8/Images/Eating.55011271/frame_0007.jpg"}};
  test::WriteText(json, JsonFile(bad_paths));
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("samples 0, 1 (S8 Eating frame 7): the views disagree by"));
  test::WriteText(json, "{\"0\": {\"keypoints_2d\": {}}}");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("2Dto3D_train.json: /0/keypoints_3d: missing or not an object"));
  test::WriteText(json, "{\"0\": {\"keypoints_3d\": {\"0\": {\"x\": 1, \"y\": \"a\", \"z\": 3}}}}");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("2Dto3D_train.json: /0/keypoints_3d/0/y: expected a number"));
  test::WriteText(json, "{\"0\": {\"keypoints_3d\": {\"0\": {\"x\": 1, \"y\": 2, \"z\": 3}}}}");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }), HasSubstr("/0/keypoints_3d/1: missing joint"));
  test::WriteText(json, "{\"abc\": {}}");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("/abc: sample id is not a non-negative integer"));
  test::WriteText(json, "{\"0\": [1, 2]}");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("2Dto3D_train.json: /0: expected an object"));
  test::WriteText(json, "{\n\"0\": {\"keypoints_3d\": {\"0\": {\"x\": 1,,");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("2Dto3D_train.json:2:37: JSON parse error"));
  test::WriteText(json, "[]");
  EXPECT_THAT(InputErrorOf([&] { ReadDataset(Request(dir.path())); }),
              HasSubstr("2Dto3D_train.json: /: expected an object keyed by sample id"));
}

// The reader contract (tests/datasets/reader_stream_test.cc): streamed equals materialised, on the
// npz, the json grouped by image path and the json grouped by sample ids (subjects found by the
// cameras), with the stored 2D.
using test::ReaderStreamTest;
INSTANTIATE_TEST_SUITE_P(
    H3wb, ReaderStreamTest,
    ::testing::Values(
        test::ReaderFixture{"Npz",
                            {},
                            [](const fs::path& dir) {
                              WriteNpz(dir);
                              return OpenDataset(Request(dir, {{"detections", "annotations"}}));
                            }},
        test::ReaderFixture{
            "JsonByImagePath",
            {},
            [](const fs::path& dir) {
              WriteMetadata(dir);
              std::vector<JsonView> views;
              int key = 100;
              for (int frame : {12, 4, 9}) {
                for (int c : {3, 1, 0, 2}) {
                  views.push_back({std::to_string(key--), 8, c, frame,
                                   "Human36m/S8/Images/Directions 1." +
                                       Human36mCameraIds()[static_cast<std::size_t>(c)] + "/frame_" + Padded4(frame) +
                                       ".jpg"});
                }
              }
              test::WriteText(dir / "RGBto3D_train.json", JsonFile(views));
              return OpenDataset(Request(dir, {{"file", "RGBto3D_train.json"}, {"detections", "annotations"}}));
            }},
        test::ReaderFixture{"JsonBySampleIds",
                            {},
                            [](const fs::path& dir) {
                              WriteMetadata(dir);
                              std::vector<JsonView> views;
                              for (int c : {2, 0, 3, 1}) views.push_back({std::to_string(c), 8, c, 7, ""});
                              for (int c = 0; c < 4; ++c) views.push_back({std::to_string(4 + c), 5, c, 9, ""});
                              for (int c : {1, 3}) views.push_back({std::to_string(8 + c), 8, c, 3, ""});
                              test::WriteText(dir / "2Dto3D_train.json", JsonFile(views));
                              return OpenDataset(Request(dir, {{"subjects", "S5,S8"}, {"detections", "annotations"}}));
                            }}),
    test::ReaderFixtureName);

}  // namespace
}  // namespace rpt

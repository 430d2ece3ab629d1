// SPDX-License-Identifier: MIT
// The HDF5 cache: detections and sequences round trips, and errors that name the dataset path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "datasets/readers/detections_file.h"
#include "datasets/readers/hdf5_cache.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/datasets/tolerance_test_util.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;
using test::InputErrorOf;

// Marks an edited cache as written by another tool: format version 1, whose datasets carry no
// checksums (a version-2 cache with a replaced dataset is refused as damaged).
inline void MarkCacheVersion1(hid_t file) {
  for (const char* group : {"/detections", "/sequences"}) {
    if (H5Lexists(file, group, H5P_DEFAULT) <= 0) continue;
    // Replaced, not rewritten: HDF5 1.10 cannot write an attribute opened by name in this file.
    H5Adelete_by_name(file, group, "version", H5P_DEFAULT);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute =
        H5Acreate_by_name(file, group, "version", H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const int one = 1;
    EXPECT_GE(H5Awrite(attribute, H5T_NATIVE_INT, &one), 0) << group;
    H5Aclose(attribute);
    H5Sclose(space);
  }
}

// Edits a cache file in place with the HDF5 C API (to make malformed files, or files as another
// tool writes them: version 1, without checksums).
class Hdf5Editor {
 public:
  explicit Hdf5Editor(const std::filesystem::path& path) {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    EXPECT_GE(file_, 0);
    MarkCacheVersion1(file_);
  }
  ~Hdf5Editor() {
    H5Fclose(file_);
    H5Eset_auto2(H5E_DEFAULT, func_, data_);
  }
  void Delete(const std::string& name) { EXPECT_GE(H5Ldelete(file_, name.c_str(), H5P_DEFAULT), 0) << name; }
  // Replaces `name` by a float64 dataset of the given shape and values.
  void PutDoubles(const std::string& name, const std::vector<hsize_t>& dims, const std::vector<double>& values) {
    if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0) Delete(name);
    const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
    const hid_t dataset = H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (!values.empty()) H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
    H5Sclose(space);
  }
  void PutInt64s(const std::string& name, const std::vector<std::int64_t>& values) {
    if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0) Delete(name);
    const hsize_t n = values.size();
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t dataset = H5Dcreate2(file_, name.c_str(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(dataset, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
    H5Sclose(space);
  }
  // Replaces `name` by variable-length strings (what h5py writes for str lists).
  void PutVariableStrings(const std::string& name, const std::vector<std::string>& values) {
    if (H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0) Delete(name);
    std::vector<const char*> pointers;
    for (const auto& v : values) pointers.push_back(v.c_str());
    const hsize_t n = values.size();
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);  // as h5py writes a list of str
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t dataset = H5Dcreate2(file_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data());
    H5Dclose(dataset);
    H5Sclose(space);
    H5Tclose(type);
  }
  // Replaces attribute `name` of `object` by a variable-length UTF-8 string, as h5py's
  // `group.attrs[name] = "text"` writes it.
  void PutVariableStringAttribute(const std::string& object, const std::string& name, const std::string& value) {
    H5Adelete_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute =
        H5Acreate_by_name(file_, object.c_str(), name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const char* text = value.c_str();
    EXPECT_GE(H5Awrite(attribute, type, &text), 0) << object << " " << name;
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
  }
  // Reads a whole float64-convertible dataset.
  std::vector<double> GetDoubles(const std::string& name) {
    const hid_t dataset = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    std::vector<double> values(static_cast<size_t>(H5Sget_simple_extent_npoints(space)));
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(dataset);
    return values;
  }
  std::vector<hsize_t> Dims(const std::string& name) {
    const hid_t dataset = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    std::vector<hsize_t> dims(static_cast<size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    H5Sclose(space);
    H5Dclose(dataset);
    return dims;
  }

 private:
  hid_t file_ = -1;
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

TEST(Hdf5Cache, DetectionsRoundTripInFloat32AndFloat64) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(7, {"a", "b", "c", "d"}, CocoWholeBodyJoints());
  const auto path32 = dir.path() / "d32.h5";
  WriteDetectionsHdf5(path32, detections);
  test::ExpectDetectionsNear(detections, ReadDetectionsHdf5(path32), 1e-7);
  const auto path64 = dir.path() / "d64.h5";
  WriteDetectionsHdf5(path64, detections, {.add_to_existing = false, .float64 = true});
  const Detections read = ReadDetectionsHdf5(path64);
  test::ExpectDetectionsNear(detections, read, 0);
  EXPECT_EQ(read.frames[0].views[0].num_persons(), 0);
  EXPECT_EQ(read.frames[0].views[0].num_joints, 133);

  Hdf5Editor editor(path32);
  EXPECT_EQ(editor.Dims("/detections/keypoints")[1], 133u);
  EXPECT_EQ(editor.Dims("/detections/view_offsets")[0], 8u);
  for (const FrameDetections& frame : read.frames) EXPECT_TRUE(std::isnan(frame.time_s)) << "no times given, none read";
}

// The frames' times of timed detections (generic JSON's "time") are kept: a cache of them was read
// without times, so triangulating it tracked nobody.
TEST(Hdf5Cache, DetectionTimesAreKept) {
  test::TempDir dir;
  Detections detections = test::MakeDetections(4, {"a", "b"}, CocoBodyJoints());
  for (size_t f = 0; f < detections.frames.size(); ++f) detections.frames[f].time_s = 100.0 + 0.04 * f;
  detections.frames[2].time_s = kUnknownTime;
  const auto path = dir.path() / "timed.h5";
  WriteDetectionsHdf5(path, detections);
  const Detections read = ReadDetectionsHdf5(path);
  ASSERT_EQ(read.frames.size(), 4u);
  EXPECT_EQ(read.frames[0].time_s, 100.0);
  EXPECT_EQ(read.frames[3].time_s, 100.12);
  EXPECT_TRUE(std::isnan(read.frames[2].time_s));
  {
    Hdf5Editor editor(path);  // a cache written by another tool
    editor.PutDoubles("/detections/times", {4}, {0, 0.04, INFINITY, 0.12});
  }
  EXPECT_THAT(test::InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("/detections/times: element 2 is infinite"));
}

TEST(Hdf5Cache, EmptyDetectionsAndFramesWithoutViews) {
  test::TempDir dir;
  Detections detections;
  detections.joints = CocoBodyJoints();
  const auto path = dir.path() / "empty.h5";
  WriteDetectionsHdf5(path, detections);
  const Detections empty = ReadDetectionsHdf5(path);
  EXPECT_EQ(empty.joints, CocoBodyJoints());
  EXPECT_TRUE(empty.frames.empty());

  detections.frames.resize(2);
  detections.frames[0].frame_id = "no_views";
  detections.frames[1].frame_id = "one_empty_view";
  detections.frames[1].cameras = {"c"};
  detections.frames[1].views.resize(1);
  detections.frames[1].views[0].Clear(17);
  detections.unlisted_cameras_unavailable = true;  // frame "no_views": no camera has data
  WriteDetectionsHdf5(path, detections);
  const Detections read = ReadDetectionsHdf5(path);
  EXPECT_TRUE(read.unlisted_cameras_unavailable);
  ASSERT_EQ(read.frames.size(), 2u);
  EXPECT_TRUE(read.frames[0].views.empty());
  ASSERT_EQ(read.frames[1].views.size(), 1u);
  EXPECT_EQ(read.frames[1].views[0].num_persons(), 0);
  // Detections where an unlisted camera saw nobody (a COCO result list) are written with that
  // camera listed, empty, in every frame: read back, it still saw nobody there.
  detections.unlisted_cameras_unavailable = false;
  WriteDetectionsHdf5(path, detections);
  const Detections listed = ReadDetectionsHdf5(path);
  ASSERT_EQ(listed.frames.size(), 2u);
  EXPECT_EQ(listed.frames[0].cameras, std::vector<std::string>{"c"});
  ASSERT_EQ(listed.frames[0].views.size(), 1u);
  EXPECT_EQ(listed.frames[0].views[0].num_persons(), 0);
}

TEST(Hdf5Cache, SequencesAndDetectionsShareOneFile) {
  test::TempDir dir;
  std::vector<Sequence> sequences = {test::MakeLabelSequence("a", 3, "a_"), test::MakeLabelSequence("b", 2, "b_")};
  sequences[1].cameras[1] = test::LookAtCamera("h", {3, 3, 1.8}, DistortionModel::kH36M);
  sequences[1].frames[1].gt.Clear(static_cast<int>(sequences[1].gt_joints.size()));  // a frame without persons
  const Detections detections = test::MakeDetections(3, {"cam_a", "cam_b"}, CocoBodyJoints(), "a_");
  const auto path = dir.path() / "cache.hdf5";

  WriteSequencesHdf5(path, sequences);
  EXPECT_TRUE(ProbeHdf5Cache(path).sequences);
  EXPECT_FALSE(ProbeHdf5Cache(path).detections);
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("cache.hdf5: /detections: missing: no detections in this file (it holds labels only)"));
  WriteDetectionsHdf5(path, detections, {.add_to_existing = true});
  WriteDetectionsHdf5(path, detections, {.add_to_existing = true});  // replacing works too
  const Hdf5CacheContents contents = ProbeHdf5Cache(path);
  EXPECT_TRUE(contents.sequences && contents.detections);

  const std::vector<Sequence> read = MaterializeAll(OpenSequencesHdf5(path));
  ASSERT_EQ(read.size(), 2u);
  for (size_t s = 0; s < 2; ++s) test::ExpectSequencesNear(sequences[s], read[s]);
  EXPECT_EQ(read[1].cameras[1].model, DistortionModel::kH36M);
  EXPECT_EQ(read[1].frames[1].gt.num_persons(), 0);
  test::ExpectDetectionsNear(detections, ReadDetectionsHdf5(path), 1e-7);

  // The command-line entry points dispatch on the extension.
  test::ExpectSequencesNear(sequences[0], MaterializeAll(OpenLabelsFile(path))[0]);
  test::ExpectDetectionsNear(detections, ReadDetectionsFile(path), 1e-7);
  EXPECT_THAT(test::ConfigErrorOf([&] { MaterializeAll(OpenLabelsFile(path, {.split = "test"})); }),
              HasSubstr("keeps no splits"));
  const auto json_path = dir.path() / "labels.json";
  WriteLabels(json_path, sequences);
  test::ExpectSequencesNear(sequences[1], MaterializeAll(OpenLabelsFile(json_path))[1]);

  // The detections attach to the labels by frame id and camera name.
  Sequence sequence = read[0];
  InputWarnings warnings;
  const AttachReport report =
      AttachDetections(ReadDetectionsHdf5(path), path.string(), std::span<Sequence>(&sequence, 1), &warnings);
  EXPECT_EQ(report.frames_with_detections, 3);
  EXPECT_TRUE(warnings.empty());
  ValidateSequence(sequence, "attached");
}

TEST(Hdf5Cache, NotAnHdf5FileNamesFileAndPlace) {
  test::TempDir dir;
  const auto fake = test::WriteText(dir, "fake.h5", "[{\"id\": 1}]");
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(fake); }), HasSubstr("fake.h5: byte 0: not an HDF5 file"));
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(fake)); }),
              HasSubstr("fake.h5: byte 0: not an HDF5 file"));
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(dir.path() / "absent.h5"); }), HasSubstr("absent.h5: file not found"));
  EXPECT_THAT(InputErrorOf([&] { WriteDetectionsHdf5(fake, Detections{CocoBodyJoints(), {}, {}}, {.add_to_existing = true}); }),
              HasSubstr("fake.h5: cannot add to it: not an existing HDF5 file"));
}

TEST(Hdf5Cache, CameraRotationsWithSixDigitsAreReorthonormalisedAndCounted) {
  test::TempDir dir;
  const Sequence sequence = test::MakeLabelSequence("a", 2, "a_");
  const auto path = dir.path() / "cache.h5";
  WriteSequencesHdf5(path, {sequence});
  {
    Hdf5Editor editor(path);  // camera_R as another tool would store it: 6 significant digits
    std::vector<double> R = editor.GetDoubles("/sequences/0/camera_R");
    for (int c = 0; c < 2; ++c) {
      const Eigen::Matrix3d rounded = test::RoundedRotation(sequence.cameras[c].R);
      for (int k = 0; k < 9; ++k) R[9 * c + k] = rounded(k / 3, k % 3);
    }
    editor.PutDoubles("/sequences/0/camera_R", editor.Dims("/sequences/0/camera_R"), R);
  }
  const Sequence read = MaterializeAll(OpenSequencesHdf5(path)).at(0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(test::OrthonormalityError(read.cameras[c].R), 1e-12);
    EXPECT_LT((read.cameras[c].R - sequence.cameras[c].R).cwiseAbs().maxCoeff(), 1e-5);
  }
  EXPECT_EQ(read.cameras[2].R, sequence.cameras[2].R) << "stored exactly: kept as it is";
  test::ExpectOneWarning(read.warnings, path.string(), test::kRotationsFixed, 2);

  {
    Hdf5Editor editor(path);
    std::vector<double> R = editor.GetDoubles("/sequences/0/camera_R");
    for (int k = 9; k < 18; ++k) R[k] *= 1.005;  // camera 1: 1e-2 off
    editor.PutDoubles("/sequences/0/camera_R", editor.Dims("/sequences/0/camera_R"), R);
  }
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(path)); }),
              HasSubstr(path.string() + ": /sequences/0/camera_R: camera 1 ('cam_b'): R is not a rotation"));
}

TEST(Hdf5Cache, DetectionScoresSlightlyAboveOneAreClampedAndCounted) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(4, {"a", "b"}, CocoBodyJoints());
  const auto path = dir.path() / "d.h5";
  WriteDetectionsHdf5(path, detections);
  {
    Hdf5Editor editor(path);  // a cache written by another tool
    std::vector<double> keypoints = editor.GetDoubles("/detections/keypoints");
    keypoints[2] = 1.008;           // person 0, joint 0
    keypoints[3 * 17 + 2] = 1.018;  // person 1, joint 0
    editor.PutDoubles("/detections/keypoints", editor.Dims("/detections/keypoints"), keypoints);
  }
  const Detections read = ReadDetectionsHdf5(path);
  EXPECT_EQ(read.frames[0].views[1].Person(0)(2, 0), 1.0);
  EXPECT_EQ(read.frames[1].views[0].Person(0)(2, 0), 1.0);
  test::ExpectOneWarning(read.warnings, path.string(), test::kScoresClamped, 2);
  EXPECT_DOUBLE_EQ(read.warnings.items()[0].worst, 1.018);
}

TEST(Hdf5Cache, NegativeLargeOrNanScoresNameTheDatasetPath) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(4, {"a", "b"}, CocoBodyJoints());
  const auto path = dir.path() / "d.h5";
  for (const double score : {1.6, -0.1, std::numeric_limits<double>::quiet_NaN()}) {
    WriteDetectionsHdf5(path, detections);
    {
      Hdf5Editor editor(path);
      std::vector<double> keypoints = editor.GetDoubles("/detections/keypoints");
      keypoints[2] = score;
      editor.PutDoubles("/detections/keypoints", editor.Dims("/detections/keypoints"), keypoints);
    }
    const std::string what = std::isnan(score) ? "NaN or infinite value" : score > 1 ? "score 1.6 outside [0, 1]" : "score -0.1 outside [0, 1]";
    EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }),
                HasSubstr(path.string() + ": /detections/keypoints: person 0 (frame 'frame_000000', camera 'b'), joint 'nose': " + what));
  }
}

TEST(Hdf5Cache, MalformedDatasetsNameTheDatasetPath) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(4, {"a", "b"}, CocoBodyJoints());
  const auto path = dir.path() / "d.h5";
  auto fresh = [&] { WriteDetectionsHdf5(path, detections); };

  fresh();
  {
    Hdf5Editor editor(path);
    std::vector<double> keypoints = editor.GetDoubles("/detections/keypoints");
    keypoints[3 * 17 + 3] = std::numeric_limits<double>::quiet_NaN();  // person 1, joint 1, u
    editor.PutDoubles("/detections/keypoints", editor.Dims("/detections/keypoints"), keypoints);
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }),
              HasSubstr("d.h5: /detections/keypoints: person 1 (frame 'frame_000001', camera 'a'), joint 'eye_left': NaN or infinite value"));

  fresh();
  {
    Hdf5Editor editor(path);
    std::vector<hsize_t> dims = editor.Dims("/detections/keypoints");
    dims[1] = 16;
    editor.PutDoubles("/detections/keypoints", dims, std::vector<double>(dims[0] * 16 * 3, 0.0));
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }),
              HasSubstr("d.h5: /detections/keypoints: shape [" ));
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr(", 16, 3], expected [*, 17, 3]"));

  fresh();
  {
    Hdf5Editor editor(path);
    std::vector<double> keypoints = editor.GetDoubles("/detections/keypoints");
    keypoints[2] = 3.0;  // a score of 3
    editor.PutDoubles("/detections/keypoints", editor.Dims("/detections/keypoints"), keypoints);
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("/detections/keypoints: person 0"));
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("joint 'nose': score 3 outside [0, 1]"));

  fresh();
  {
    Hdf5Editor editor(path);
    editor.PutInt64s("/detections/person_offsets", {0, 1, 2, 3, 4, 5, 6, 7, 100});
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }),
              HasSubstr("d.h5: /detections/person_offsets: ends at 100 but /detections/keypoints has"));

  fresh();
  {
    Hdf5Editor editor(path);
    editor.PutInt64s("/detections/view_offsets", {0, 2, 4});
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }),
              HasSubstr("d.h5: /detections/view_offsets: shape [3], expected [5] (frames + 1)"));

  fresh();
  {
    Hdf5Editor editor(path);
    editor.Delete("/detections/frame_ids");
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("d.h5: /detections/frame_ids: missing"));

  fresh();
  {
    Hdf5Editor editor(path);
    editor.PutVariableStrings("/detections/joints", {"nose", "left_eye"});
  }
  EXPECT_THAT(InputErrorOf([&] { ReadDetectionsHdf5(path); }), HasSubstr("d.h5: /detections/joints: unknown joint name 'left_eye'"));
}

TEST(Hdf5Cache, ReadsVariableLengthStrings) {
  test::TempDir dir;
  const Detections detections = test::MakeDetections(2, {"a", "b"}, CocoBodyJoints());
  const auto path = dir.path() / "vlen.h5";
  WriteDetectionsHdf5(path, detections, {.add_to_existing = false, .float64 = true});
  {
    Hdf5Editor editor(path);
    editor.PutVariableStrings("/detections/joints", CocoBodyJoints());
    editor.PutVariableStrings("/detections/frame_ids", {"frame_000000", "frame_000001"});
    // h5py's default for a str attribute; it was "cannot read attribute 'format'".
    editor.PutVariableStringAttribute("/detections", "format", "rpt-detections");
  }
  test::ExpectDetectionsNear(detections, ReadDetectionsHdf5(path), 0);
}

TEST(Hdf5Cache, SequenceErrorsNameTheDatasetPath) {
  test::TempDir dir;
  const auto path = dir.path() / "s.h5";
  WriteSequencesHdf5(path, {test::MakeLabelSequence("a", 2, "a_")});
  {
    Hdf5Editor editor(path);
    std::vector<double> poses = editor.GetDoubles("/sequences/0/gt_poses");
    poses[5] = std::numeric_limits<double>::infinity();
    editor.PutDoubles("/sequences/0/gt_poses", editor.Dims("/sequences/0/gt_poses"), poses);
  }
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(path)); }),
              HasSubstr("s.h5: /sequences/0/gt_poses: element 5 is NaN or infinite"));
  WriteSequencesHdf5(path, {test::MakeLabelSequence("a", 2, "a_")});
  {
    Hdf5Editor editor(path);
    editor.PutDoubles("/sequences/0/camera_K", {2, 3, 3}, std::vector<double>(18, 1.0));
  }
  EXPECT_THAT(InputErrorOf([&] { MaterializeAll(OpenSequencesHdf5(path)); }),
              HasSubstr("s.h5: /sequences/0/camera_K: shape [2, 3, 3], expected [3, 3, 3]"));
}

}  // namespace
}  // namespace rpt

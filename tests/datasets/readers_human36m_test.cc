// SPDX-License-Identifier: MIT
// The Human3.6M reader on small files of each format it reads (annot.h5, labels npy,
// metadata.xml, cameras.pkl). Over 500 lines on purpose: one file for the one reader.
#include "datasets/readers/human36m.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/errors.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/reader_stream_test.h"
#include "tests/datasets/readers_h36m_ego_test_util.h"
#include "tests/datasets/tolerance_test_util.h"
#include "tests/test_data.h"

namespace rpt {
using engine::ReadDataset;
using engine::OpenDataset;
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::H36mCalib;
using test::InputErrorOf;

constexpr double kTol = 1e-9;

// Raw 32-joint world skeleton (metres) of a test frame.
Eigen::Matrix<double, 3, 32> RawSkeleton(int frame) {
  Eigen::Matrix<double, 3, 32> X;
  for (int k = 0; k < 32; ++k) {
    X.col(k) << 0.2 * std::sin(0.7 * k + 0.01 * frame) + 0.001 * frame, 0.15 * std::cos(0.3 * k + frame), 0.05 * k + 0.1;
  }
  return X;
}

constexpr int kRaw[17] = {0, 1, 2, 3, 6, 7, 8, 12, 13, 14, 15, 17, 18, 19, 25, 26, 27};

// Writes processed/<subject>/<action>/annot.h5 as h36m-fetch does: all cameras concatenated,
// pose/3d in camera coordinates (mm), frame 1-based.
void WriteAnnot(const fs::path& root, const std::string& subject, const std::string& action, const std::vector<H36mCalib>& calibs,
                const std::vector<int>& frames, const std::vector<int>& cameras = {0, 1, 2, 3}) {
  std::vector<double> pose, camera, frame, pose2d;
  for (int c : cameras) {
    const H36mCalib& k = calibs[static_cast<std::size_t>(c)];
    for (int f : frames) {
      const auto X = RawSkeleton(f);
      for (int j = 0; j < 32; ++j) {
        const Eigen::Vector3d x = k.R() * (X.col(j) * 1000.0 - k.center_mm);
        pose.insert(pose.end(), {x.x(), x.y(), x.z()});
        pose2d.insert(pose2d.end(), {0.0, 0.0});
      }
      camera.push_back(std::stod(Human36mCameraIds()[static_cast<std::size_t>(c)]));
      frame.push_back(f);
    }
  }
  const hsize_t n = camera.size();
  test::WriteH5(root / "processed" / subject / action / "annot.h5",
                {{"pose/3d", {n, 32, 3}, pose, false},
                 {"pose/2d", {n, 32, 2}, pose2d, false},
                 {"camera", {n}, camera, true},
                 {"frame", {n}, frame, true},
                 {"subject", {n}, std::vector<double>(n, 9), true}});
}

void WriteSyntheticMetadata(const fs::path& root) {
  test::WriteText(root / "metadata.xml", test::MetadataXml(test::W0(test::SyntheticH36mCalibs)));
}

DatasetRequest Request(const fs::path& root, std::map<std::string, std::string> params) {
  DatasetRequest request;
  request.dataset = "human36m";
  request.root = root;
  request.params = std::move(params);
  return request;
}

void ExpectCameraMatches(const Camera& camera, const H36mCalib& k, double tol) {
  EXPECT_LT((camera.R - k.R()).cwiseAbs().maxCoeff(), tol);
  EXPECT_LT((camera.Center() - k.center_mm / 1000.0).cwiseAbs().maxCoeff(), tol);
  EXPECT_NEAR(camera.K(0, 0), k.fx, tol * 1e3);
  EXPECT_NEAR(camera.K(1, 2), k.cy, tol * 1e3);
  EXPECT_NEAR(camera.dist[0], k.k1, tol);
  EXPECT_NEAR(camera.dist[2], k.p1, tol);
  EXPECT_NEAR(camera.dist[3], k.p2, tol);
  EXPECT_NEAR(camera.dist[4], k.k3, tol);
}

// ---------------------------------------------------------------------------------------
// Cameras

TEST(Human36mCameras, MmposePickleGivesKnownS1Camera) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  const auto cameras = ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S1");
  ASSERT_EQ(cameras.size(), 4u);
  const Camera& c = cameras[0];
  EXPECT_EQ(c.name, "54138969");
  EXPECT_EQ(c.width, 1000);
  EXPECT_EQ(c.height, 1002);
  EXPECT_EQ(c.model, DistortionModel::kH36M);
  EXPECT_NEAR(c.K(0, 0), 1145.049405, 1e-5);
  EXPECT_NEAR(c.K(1, 1), 1143.781096, 1e-5);
  EXPECT_NEAR(c.K(0, 2), 512.541505, 1e-5);
  EXPECT_NEAR(c.K(1, 2), 515.451487, 1e-5);
  // (k1, k2, p1, p2, k3)
  EXPECT_NEAR(c.dist[0], -0.207099, 1e-6);
  EXPECT_NEAR(c.dist[1], 0.247775, 1e-6);
  EXPECT_NEAR(c.dist[2], -0.001424, 1e-6);
  EXPECT_NEAR(c.dist[3], -0.000976, 1e-6);
  EXPECT_NEAR(c.dist[4], -0.003075, 1e-6);
  const Eigen::Vector3d center_mm = c.Center() * 1000.0;
  EXPECT_NEAR(center_mm.x(), 1841.107, 1e-3);
  EXPECT_NEAR(center_mm.y(), 4955.285, 1e-3);
  EXPECT_NEAR(center_mm.z(), 1563.445, 1e-3);
  EXPECT_NEAR(c.R(0, 0), -0.915362, 1e-6);
  EXPECT_NEAR(c.R(0, 1), 0.401808, 1e-6);
  EXPECT_NEAR(c.R(0, 2), 0.025748, 1e-6);
  EXPECT_EQ(cameras[3].name, "60457274");

  const auto opencv = ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S1", DistortionModel::kOpenCV);
  EXPECT_EQ(opencv[0].model, DistortionModel::kOpenCV);
  const auto none = ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S1", DistortionModel::kNone);
  EXPECT_EQ(none[0].dist[0], 0.0);
}

TEST(Human36mCameras, MetadataXmlBuiltFromPickleGivesTheSameCameras) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  const fs::path pkl = test::SharedData("human36m/cameras.pkl");
  // Re-encode every subject's pickle cameras as metadata.xml angles (R = Rx Ry Rz) and centres.
  auto calibs = [&](int s) {
    const auto cameras = ReadHuman36mCameras(pkl, "S" + std::to_string(s));
    std::vector<H36mCalib> out;
    for (const Camera& c : cameras) {
      H36mCalib k;
      k.angles = test::AnglesXYZ(c.R);
      k.center_mm = c.Center() * 1000.0;
      k.fx = c.K(0, 0), k.fy = c.K(1, 1), k.cx = c.K(0, 2), k.cy = c.K(1, 2);
      k.k1 = c.dist[0], k.k2 = c.dist[1], k.p1 = c.dist[2], k.p2 = c.dist[3], k.k3 = c.dist[4];
      out.push_back(k);
    }
    return out;
  };
  test::TempDir dir;
  test::WriteText(dir.path() / "metadata.xml", test::MetadataXml(test::W0(calibs)));
  for (const std::string subject : {"S1", "S5", "S9", "S11"}) {
    const auto from_xml = ReadHuman36mCameras(dir.path() / "metadata.xml", subject);
    const auto from_pkl = ReadHuman36mCameras(pkl, subject);
    ASSERT_EQ(from_xml.size(), 4u);
    for (std::size_t c = 0; c < 4; ++c) {
      EXPECT_EQ(from_xml[c].name, from_pkl[c].name);
      EXPECT_EQ(from_xml[c].width, from_pkl[c].width);
      EXPECT_EQ(from_xml[c].height, from_pkl[c].height);
      EXPECT_LT((from_xml[c].R - from_pkl[c].R).cwiseAbs().maxCoeff(), 1e-12) << subject << " " << c;
      EXPECT_LT((from_xml[c].t - from_pkl[c].t).cwiseAbs().maxCoeff(), 1e-12) << subject << " " << c;
      if (subject == "S1") {
        EXPECT_LT((from_xml[c].K - from_pkl[c].K).cwiseAbs().maxCoeff(), 1e-9);
        for (int i = 0; i < 5; ++i) EXPECT_NEAR(from_xml[c].dist[static_cast<std::size_t>(i)], from_pkl[c].dist[static_cast<std::size_t>(i)], 1e-15);
      }
    }
  }
  const auto s1 = ReadHuman36mCameras(dir.path() / "metadata.xml", "S1");
  EXPECT_NEAR(s1[0].R(0, 0), -0.915362, 1e-6);
}

TEST(Human36mCameras, UnknownSubjectInPickleNamesFile) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  const std::string msg = InputErrorOf([] { ReadHuman36mCameras(test::SharedData("human36m/cameras.pkl"), "S12"); });
  EXPECT_THAT(msg, HasSubstr("cameras.pkl"));
  EXPECT_THAT(msg, HasSubstr("'S12'"));
  EXPECT_THAT(msg, HasSubstr("S11"));
}

TEST(Human36mCameras, MalformedMetadataXml) {
  test::TempDir dir;
  const fs::path xml = dir.path() / "metadata.xml";
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("metadata.xml: file not found"));
  test::WriteText(xml, "<metadata></metadata>");
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("metadata.xml: no <w0> element"));
  std::vector<double> w0 = test::W0(test::SyntheticH36mCalibs);
  w0.pop_back();
  test::WriteText(xml, "<metadata>\n\n" + test::MetadataXml(w0));
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("metadata.xml:6: <w0>: expected 300 numbers, got 299"));
  test::WriteText(xml, "<w0>[1 2 abc 4]</w0>");
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("<w0>: value 2 ('abc') is not a finite number"));
  test::WriteText(xml, "<w0>[1 2 nan 4]</w0>");
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("value 2 ('nan') is not a finite number"));
  test::WriteText(xml, "<w0>[1 2 3");
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S1"); }), HasSubstr("missing </w0>"));
  test::WriteText(xml, test::MetadataXml(test::W0(test::SyntheticH36mCalibs)));
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(xml, "S12"); }), HasSubstr("unknown subject 'S12'"));
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(dir.path() / "cams.txt", "S1"); }), HasSubstr("cams.txt: unknown Human3.6M camera file type"));
  // A broken rotation (all angles fine, but a zero focal length) is caught by camera validation.
  std::vector<double> bad = test::W0(test::SyntheticH36mCalibs);
  bad[264] = 0;
  test::WriteText(xml, test::MetadataXml(bad));
  const std::string msg = InputErrorOf([&] { ReadHuman36mCameras(xml, "S9"); });
  EXPECT_THAT(msg, HasSubstr("metadata.xml"));
  EXPECT_THAT(msg, HasSubstr("54138969"));
  EXPECT_THAT(msg, HasSubstr("singular"));
}

// An mmpose-style cameras.pkl of subject S1 (R camera->world, T centre in metres); `R_of(c)`
// gives the stored R of camera c.
test::ByteVec MmposeCamerasPickle(const std::function<Eigen::Matrix3d(std::size_t)>& R_of) {
  std::vector<std::pair<test::Obj, test::Obj>> entries;
  const auto calibs = test::SyntheticH36mCalibs(1);
  for (std::size_t c = 0; c < 4; ++c) {
    const H36mCalib& k = calibs[c];
    const Eigen::Matrix3d R = R_of(c);
    std::vector<double> r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) r.push_back(R(i, j));
    }
    const Eigen::Vector3d T = k.center_mm / 1000.0;
    entries.emplace_back(test::PyTuple({test::PyStr("S1"), test::PyStr(Human36mCameraIds()[c])}),
                         test::PyDict({{test::PyStr("R"), test::PyArray({3, 3}, r)},
                                       {test::PyStr("T"), test::PyArray({3, 1}, {T.x(), T.y(), T.z()})},
                                       {test::PyStr("f"), test::PyArray({2, 1}, {k.fx, k.fy})},
                                       {test::PyStr("c"), test::PyArray({2, 1}, {k.cx, k.cy})},
                                       {test::PyStr("k"), test::PyArray({3, 1}, {k.k1, k.k2, k.k3})},
                                       {test::PyStr("p"), test::PyArray({2, 1}, {k.p1, k.p2})}}));
  }
  return test::PickleOf(test::PyDict(entries));
}

TEST(Human36mCameras, PickleRotationsWithSixDigitsAreReorthonormalisedAndCounted) {
  test::TempDir dir;
  const fs::path pkl = dir.path() / "cameras.pkl";
  const auto calibs = test::SyntheticH36mCalibs(1);
  test::WriteBytes(pkl, MmposeCamerasPickle([&](std::size_t c) { return test::RoundedRotation(calibs[c].R().transpose()); }));
  InputWarnings warnings;
  const auto cameras = ReadHuman36mCameras(pkl, "S1", DistortionModel::kH36M, &warnings);
  ASSERT_EQ(cameras.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_LT(test::OrthonormalityError(cameras[c].R), 1e-12);
    EXPECT_LT((cameras[c].R - calibs[c].R()).cwiseAbs().maxCoeff(), 1e-5);
  }
  test::ExpectOneWarning(warnings, pkl.string(), test::kRotationsFixed, 4);
  // Stored exactly: round-off, nothing to report.
  test::WriteBytes(pkl, MmposeCamerasPickle([&](std::size_t c) { return Eigen::Matrix3d(calibs[c].R().transpose()); }));
  InputWarnings none;
  ReadHuman36mCameras(pkl, "S1", DistortionModel::kH36M, &none);
  EXPECT_TRUE(none.empty());
}

TEST(Human36mCameras, PickleRotationBeyondTheToleranceNamesFileAndCamera) {
  test::TempDir dir;
  const fs::path pkl = dir.path() / "cameras.pkl";
  const auto calibs = test::SyntheticH36mCalibs(1);
  test::WriteBytes(pkl, MmposeCamerasPickle([&](std::size_t c) {
                     const Eigen::Matrix3d R = calibs[c].R().transpose();
                     return c == 2 ? test::WrongRotation(R) : R;
                   }));
  EXPECT_THAT(InputErrorOf([&] { ReadHuman36mCameras(pkl, "S1"); }),
              HasSubstr(pkl.string() + ": key ('S1', '58860488').R: R is not a rotation (max |R^T R - I| = 0.010025"));
}

// ---------------------------------------------------------------------------------------
// annot.h5

TEST(Human36mReader, AnnotH5RecoversWorldSkeleton) {
  test::TempDir dir;
  WriteSyntheticMetadata(dir.path());
  const auto calibs = test::SyntheticH36mCalibs(9);
  WriteAnnot(dir.path(), "S9", "Directions-1", calibs, {1, 65, 129});
  WriteAnnot(dir.path(), "S9", "Walking-2", calibs, {1, 65}, {1, 2, 3});  // camera 54138969 missing
  std::filesystem::create_directories(dir.path() / "processed" / "S9" / "MySegmentsMat");

  const auto sequences = ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
  ASSERT_EQ(sequences.size(), 2u);
  const Sequence& seq = sequences[0];
  EXPECT_EQ(seq.name, "human36m/S9/Directions-1");
  EXPECT_EQ(seq.gt_joints, Human36mJoints());
  EXPECT_EQ(seq.gt_joints.size(), 18u);
  EXPECT_EQ(seq.fps, 50.0);
  ASSERT_EQ(seq.cameras.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(seq.cameras[c].name, Human36mCameraIds()[c]);
    ExpectCameraMatches(seq.cameras[c], calibs[c], 1e-12);
  }
  ASSERT_EQ(seq.frames.size(), 3u);
  EXPECT_EQ(seq.frames[0].id, "human36m_S9_Directions-1_000000");
  EXPECT_EQ(seq.frames[1].id, "human36m_S9_Directions-1_000064");
  EXPECT_DOUBLE_EQ(seq.frames[1].timestamp_s, 64 / 50.0);
  for (std::size_t f = 0; f < 3; ++f) {
    const auto X = RawSkeleton(static_cast<int>(1 + 64 * f));
    const Poses3D& gt = seq.frames[f].gt;
    ASSERT_EQ(gt.num_persons(), 1);
    ASSERT_EQ(gt.num_joints, 18);
    const auto person = gt.Person(0);
    for (int j = 0; j < 17; ++j) {
      EXPECT_LT((person.col(j).head<3>() - X.col(kRaw[j])).norm(), kTol) << j;
      EXPECT_EQ(person(3, j), 1.0);
    }
    EXPECT_LT((person.col(17).head<3>() - X.col(15)).norm(), kTol);  // nose = head (raw 15)
  }
  EXPECT_EQ(sequences[1].name, "human36m/S9/Walking-2");
  EXPECT_EQ(sequences[1].frames.size(), 2u);
  EXPECT_LT((sequences[1].frames[1].gt.Person(0).col(0).head<3>() - RawSkeleton(65).col(0)).norm(), kTol);

  // nose_proxy, actions, every, max_frames.
  const auto other = ReadDataset(Request(dir.path(), {{"subjects", "S9"},
                                                      {"actions", "Directions"},
                                                      {"nose_proxy", "neck_nose"},
                                                      {"every", "2"},
                                                      {"max_frames", "5"}}));
  ASSERT_EQ(other.size(), 1u);
  ASSERT_EQ(other[0].frames.size(), 2u);
  EXPECT_EQ(other[0].frames[1].id, "human36m_S9_Directions-1_000128");
  EXPECT_LT((other[0].frames[0].gt.Person(0).col(17).head<3>() - RawSkeleton(1).col(14)).norm(), kTol);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"max_frames", "1"}}))[0].frames.size(), 1u);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"exclude", "S9/Walking-2"}})).size(), 1u);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"exclude", "Walking"}})).size(), 1u);
  // An entry for another subject belongs to a list for all subjects; a typo or another case, for a
  // selected one, would exclude nothing: refused, naming the entry and the actions there are.
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"exclude", "S11/Walking-2"}})).size(), 2u);
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"exclude", "S9/Walkin-2"}}));
              }),
              HasSubstr("human36m.exclude: 'S9/Walkin-2' matches no action of S9 (actions: Directions-1, Walking-2)"));
  EXPECT_THAT(test::ConfigErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"exclude", "s9/Walking-2"}}));
              }),
              HasSubstr("no subject 's9' (did you mean 'S9'?)"));
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"distortion", "none"}}))[0].cameras[0].model,
            DistortionModel::kNone);
}

TEST(Human36mReader, AnnotH5WithRealPickleCameras) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  const fs::path pkl = test::SharedData("human36m/cameras.pkl");
  const auto cameras = ReadHuman36mCameras(pkl, "S11");
  std::vector<H36mCalib> calibs;
  for (const Camera& c : cameras) {
    H36mCalib k{};
    k.angles = test::AnglesXYZ(c.R);
    k.center_mm = c.Center() * 1000.0;
    calibs.push_back(k);
  }
  test::TempDir dir;
  WriteAnnot(dir.path(), "S11", "Phoning-1", calibs, {1, 65});
  const auto sequences = ReadDataset(Request(dir.path(), {{"subjects", "S11"}, {"cameras_file", pkl.string()}}));
  ASSERT_EQ(sequences.size(), 1u);
  EXPECT_LT((sequences[0].frames[1].gt.Person(0).col(3).head<3>() - RawSkeleton(65).col(3)).norm(), 1e-9);
  // Wrong subject's cameras: the four views no longer agree in world coordinates.
  const std::string msg = InputErrorOf([&] {
    test::TempDir other;
    WriteAnnot(other.path(), "S9", "Phoning-1", calibs, {1});
    ReadDataset(Request(other.path(), {{"subjects", "S9"}, {"cameras_file", pkl.string()}}));
  });
  EXPECT_THAT(msg, HasSubstr("annot.h5: frame 1: camera"));
  EXPECT_THAT(msg, HasSubstr("wrong cameras file or subject"));
}

TEST(Human36mReader, AnnotH5Malformed) {
  test::TempDir dir;
  WriteSyntheticMetadata(dir.path());
  const auto calibs = test::SyntheticH36mCalibs(9);
  const fs::path annot = dir.path() / "processed" / "S9" / "Directions-1" / "annot.h5";
  auto read = [&] { ReadDataset(Request(dir.path(), {{"subjects", "S9"}})); };

  // Wrong shape.
  test::WriteH5(annot, {{"pose/3d", {2, 17, 3}, std::vector<double>(102, 1.0), false},
                        {"camera", {2}, {54138969, 54138969}, true},
                        {"frame", {2}, {1, 2}, true}});
  std::string msg = InputErrorOf(read);
  EXPECT_THAT(msg, HasSubstr("annot.h5: pose/3d: shape [2, 17, 3], expected [*, 32, 3] (rows x 32 raw joints x 3)"));
  // Missing dataset.
  test::WriteH5(annot, {{"pose/3d", {1, 32, 3}, std::vector<double>(96, 1.0), false}, {"camera", {1}, {54138969}, true}});
  EXPECT_THAT(InputErrorOf(read), HasSubstr("annot.h5: frame: missing"));
  // Unknown camera id.
  test::WriteH5(annot, {{"pose/3d", {1, 32, 3}, std::vector<double>(96, 1.0), false},
                        {"camera", {1}, {12345}, true},
                        {"frame", {1}, {1}, true}});
  EXPECT_THAT(InputErrorOf(read), HasSubstr("annot.h5: camera: row 0: unknown camera id 12345"));
  // NaN in a used joint.
  std::vector<double> pose(96, 1000.0);
  pose[3 * 15 + 1] = std::nan("");
  test::WriteH5(annot, {{"pose/3d", {1, 32, 3}, pose, false}, {"camera", {1}, {54138969}, true}, {"frame", {1}, {1}, true}});
  EXPECT_THAT(InputErrorOf(read), HasSubstr("annot.h5: pose/3d: row 0 joint 15: NaN or infinite coordinate"));
  // Truncated / not HDF5.
  WriteAnnot(dir.path(), "S9", "Directions-1", calibs, {1});
  const auto size = fs::file_size(annot);
  fs::resize_file(annot, size / 3);
  EXPECT_THAT(InputErrorOf(read), HasSubstr("annot.h5"));
  test::WriteText(annot, "not hdf5");
  EXPECT_THAT(InputErrorOf(read), HasSubstr("annot.h5: byte 0: not an HDF5 file"));
  // Camera 55011271's poses were made with another rig than metadata.xml describes.
  std::vector<H36mCalib> mixed = calibs;
  mixed[1].center_mm.x() += 300.0;
  WriteAnnot(dir.path(), "S9", "Directions-1", mixed, {1});
  msg = InputErrorOf(read);
  EXPECT_THAT(msg, HasSubstr("annot.h5: frame 1: camera 55011271 puts the pose"));
  // Unknown subject.
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S7"}}));
              }),
              HasSubstr("processed/S7: unknown subject"));
  // No cameras file at all.
  fs::remove(dir.path() / "metadata.xml");
  EXPECT_THAT(InputErrorOf(read), HasSubstr("no camera file found"));
  // Params.
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"subject", "S9"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"every", "0"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"distortion", "fisheye"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"nose_proxy", "ear"}})), ConfigError);
  EXPECT_THROW(ReadDataset(Request(dir.path(), {{"labels", "cdf"}})), ConfigError);
}

// ---------------------------------------------------------------------------------------
// learnable-triangulation labels npy

constexpr int kLearnable[17] = {3, 2, 1, 6, 7, 8, 0, 12, 13, 15, 27, 26, 25, 17, 18, 19, 14};

struct LabelRow {
  int subject_idx, action_idx, frame_idx;
};

// The labels npy; R is stored as float32 (as the real file), camera `wrong_camera` of every
// subject with a rotation 1e-2 off.
test::ByteVec LabelsNpy(const std::vector<std::string>& subjects, const std::vector<std::string>& actions,
                        const std::vector<LabelRow>& rows, double nan_at_row = -1, int wrong_camera = -1) {
  test::ByteVec cams;
  for (const std::string& s : subjects) {
    const int number = std::stoi(s.substr(1));
    int camera = 0;
    for (const H36mCalib& k : test::SyntheticH36mCalibs(number)) {
      const Eigen::Matrix3d R = camera++ == wrong_camera ? test::WrongRotation(k.R()) : k.R();
      const Eigen::Vector3d t = -R * k.center_mm;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) test::AppendAs(cams, "f4", R(r, c));
      }
      for (int r = 0; r < 3; ++r) test::AppendAs(cams, "f4", t[r]);
      const double K[9] = {k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1};
      for (double v : K) test::AppendAs(cams, "f4", v);
      for (double v : {k.k1, k.k2, k.p1, k.p2, k.k3}) test::AppendAs(cams, "f4", v);
    }
  }
  test::ByteVec table;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    test::AppendAs(table, "i1", rows[r].subject_idx);
    test::AppendAs(table, "i1", rows[r].action_idx);
    test::AppendAs(table, "i2", rows[r].frame_idx);
    const auto X = RawSkeleton(rows[r].frame_idx + 1);
    for (int i = 0; i < 17; ++i) {
      for (int d = 0; d < 3; ++d) {
        test::AppendAs(table, "f4", static_cast<double>(r) == nan_at_row && i == 4 ? std::nan("") : X(d, kLearnable[i]) * 1000.0);
      }
    }
    for (int i = 0; i < 16; ++i) test::AppendAs(table, "i2", 10 * i);
  }
  std::vector<test::Obj> subject_objs, action_objs, camera_objs;
  for (const auto& s : subjects) subject_objs.push_back(test::PyStr(s));
  for (const auto& a : actions) action_objs.push_back(test::PyStr(a));
  for (const auto& id : Human36mCameraIds()) camera_objs.push_back(test::PyStr(id));
  const test::Obj labels = test::PyDict({
      {test::PyStr("subject_names"), test::PyList(subject_objs)},
      {test::PyStr("camera_names"), test::PyList(camera_objs)},
      {test::PyStr("action_names"), test::PyList(action_objs)},
      {test::PyStr("cameras"), test::PyStructArray({static_cast<std::int64_t>(subjects.size()), 4},
                                                   {{"R", "f4", {3, 3}}, {"t", "f4", {3, 1}}, {"K", "f4", {3, 3}}, {"dist", "f4", {5}}},
                                                   cams)},
      {test::PyStr("table"), test::PyStructArray({static_cast<std::int64_t>(rows.size())},
                                                 {{"subject_idx", "i1", {}},
                                                  {"action_idx", "i1", {}},
                                                  {"frame_idx", "i2", {}},
                                                  {"keypoints", "f4", {17, 3}},
                                                  {"bbox_by_camera_tlbr", "i2", {4, 4}}},
                                                 table)},
  });
  return test::NpyOfObject(labels);
}

TEST(Human36mReader, LearnableTriangulationLabelsRoundTrip) {
  test::TempDir dir;
  const std::vector<LabelRow> rows = {{1, 0, 10}, {0, 0, 5}, {1, 1, 3}, {1, 0, 2}, {1, 0, 7}};
  const fs::path labels = dir.path() / "extra" / "human36m-multiview-labels-GTbboxes.npy";
  test::WriteBytes(labels, LabelsNpy({"S1", "S9"}, {"Directions-1", "Eating-2"}, rows));
  // Image folders under processed/ without annot.h5 do not hide the labels file.
  fs::create_directories(dir.path() / "processed" / "S9" / "Directions-1" / "imageSequence" / "54138969");
  // No metadata.xml / cameras.pkl: the cameras come from the labels file.
  const auto sequences = ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
  ASSERT_EQ(sequences.size(), 2u);
  const Sequence& seq = sequences[0];
  EXPECT_EQ(seq.name, "human36m/S9/Directions-1");
  ASSERT_EQ(seq.frames.size(), 3u);  // sorted by frame index
  EXPECT_EQ(seq.frames[0].id, "human36m_S9_Directions-1_000002");
  EXPECT_EQ(seq.frames[2].id, "human36m_S9_Directions-1_000010");
  const auto calibs = test::SyntheticH36mCalibs(9);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(seq.cameras[c].name, Human36mCameraIds()[c]);
    EXPECT_LT((seq.cameras[c].R - calibs[c].R()).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_LT((seq.cameras[c].Center() - calibs[c].center_mm / 1000.0).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_NEAR(seq.cameras[c].K(0, 0), calibs[c].fx, 1e-3);
    EXPECT_NEAR(seq.cameras[c].dist[3], calibs[c].p2, 1e-7);
    EXPECT_NEAR(seq.cameras[c].dist[4], calibs[c].k3, 1e-7);
    EXPECT_EQ(seq.cameras[c].width, 1000);
  }
  for (std::size_t f = 0; f < 3; ++f) {
    const int frame_idx = std::vector<int>{2, 7, 10}[f];
    const auto X = RawSkeleton(frame_idx + 1);
    const auto person = seq.frames[f].gt.Person(0);
    for (int j = 0; j < 17; ++j) EXPECT_LT((person.col(j).head<3>() - X.col(kRaw[j])).norm(), 1e-6) << j;
    EXPECT_LT((person.col(17).head<3>() - X.col(15)).norm(), 1e-6);
  }
  EXPECT_EQ(sequences[1].name, "human36m/S9/Eating-2");
  EXPECT_EQ(sequences[1].frames.size(), 1u);
  // The float32 rotations are re-orthonormalised and counted once for the subject's cameras (on
  // its first sequence), not once per sequence.
  for (const Camera& camera : seq.cameras) EXPECT_LT(test::OrthonormalityError(camera.R), 1e-12);
  test::ExpectOneWarning(seq.warnings, labels.string(), test::kRotationsFixed, 4);
  EXPECT_TRUE(sequences[1].warnings.empty());

  // The same cameras through ReadHuman36mCameras, and an explicit cameras file.
  const auto npy_cameras = ReadHuman36mCameras(labels, "S1");
  EXPECT_LT((npy_cameras[2].R - test::SyntheticH36mCalibs(1)[2].R()).cwiseAbs().maxCoeff(), 1e-6);
  test::WriteText(dir.path() / "metadata.xml", test::MetadataXml(test::W0(test::SyntheticH36mCalibs)));
  const auto with_xml = ReadDataset(Request(dir.path(), {{"subjects", "S1,S9"}, {"labels", "npy"}}));
  ASSERT_EQ(with_xml.size(), 3u);
  EXPECT_EQ(with_xml[0].name, "human36m/S1/Directions-1");
  ExpectCameraMatches(with_xml[1].cameras[3], calibs[3], 1e-12);
  EXPECT_EQ(ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"every", "2"}}))[0].frames.size(), 2u);
}

TEST(Human36mReader, LearnableTriangulationLabelsMalformed) {
  test::TempDir dir;
  const fs::path labels = dir.path() / "human36m-multiview-labels-GTbboxes.npy";
  test::WriteBytes(labels, LabelsNpy({"S9"}, {"Directions-1"}, {{0, 0, 1}, {0, 0, 2}}));
  std::string msg = InputErrorOf([&] { ReadDataset(Request(dir.path(), {{"subjects", "S11"}})); });
  EXPECT_THAT(msg, HasSubstr("human36m-multiview-labels-GTbboxes.npy: key 'subject_names': unknown subject 'S11' (file has S9)"));
  test::WriteBytes(labels, LabelsNpy({"S9"}, {"Directions-1"}, {{0, 0, 1}, {0, 0, 2}}, 1));
  msg = InputErrorOf([&] { ReadDataset(Request(dir.path(), {{"subjects", "S9"}})); });
  EXPECT_THAT(msg, HasSubstr("labels-GTbboxes.npy: key 'table'.keypoints: row 1 joint 4: NaN or infinite coordinate"));
  test::WriteBytes(labels, LabelsNpy({"S9"}, {"Directions-1"}, {{0, 3, 1}}));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
              }),
              HasSubstr("key 'table': row 0: action_idx out of range"));
  // Truncated file.
  const test::ByteVec full = LabelsNpy({"S9"}, {"Directions-1"}, {{0, 0, 1}});
  test::WriteBytes(labels, test::ByteVec(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(full.size() / 2)));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
              }),
              HasSubstr("labels-GTbboxes.npy"));
  // A camera rotation 1e-2 off is a wrong matrix, not float32 rounding.
  test::WriteBytes(labels, LabelsNpy({"S9"}, {"Directions-1"}, {{0, 0, 1}}, -1, 1));
  EXPECT_THAT(
      InputErrorOf([&] {
        ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
      }),
      HasSubstr("labels-GTbboxes.npy: key 'cameras' [S9, 55011271]: R is not a rotation (max |R^T R - I| = 0.0100"));
  // Nothing at all under root.
  fs::remove(labels);
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}}));
              }),
              HasSubstr("no Human3.6M labels found"));
  EXPECT_THAT(InputErrorOf([&] {
                ReadDataset(Request(dir.path(), {{"subjects", "S9"}, {"labels", "npy"}}));
              }),
              HasSubstr("labels file not found"));
}

// The reader contract (tests/datasets/reader_stream_test.cc): streamed equals materialised, on
// both label formats.
using test::ReaderStreamTest;
INSTANTIATE_TEST_SUITE_P(
    Human36m, ReaderStreamTest,
    ::testing::Values(test::ReaderFixture{"AnnotH5",
                                          {},
                                          [](const fs::path& dir) {
                                            WriteSyntheticMetadata(dir);
                                            const auto calibs = test::SyntheticH36mCalibs(9);
                                            WriteAnnot(dir, "S9", "Directions-1", calibs, {1, 65, 129});
                                            WriteAnnot(dir, "S9", "Walking-2", calibs, {1, 65}, {1, 2, 3});
                                            return OpenDataset(Request(dir, {{"subjects", "S9"}}));
                                          }},
                      test::ReaderFixture{"LabelsNpy",
                                          {},
                                          [](const fs::path& dir) {
                                            test::WriteBytes(
                                                dir / "extra" / "human36m-multiview-labels-GTbboxes.npy",
                                                LabelsNpy({"S1", "S9"}, {"Directions-1", "Eating-2"},
                                                          {{1, 0, 10}, {0, 0, 5}, {1, 1, 3}, {1, 0, 2}, {1, 0, 7}}));
                                            return OpenDataset(Request(dir, {{"subjects", "S1,S9"}}));
                                          }}),
    test::ReaderFixtureName);

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// Tests of the synthetic rigs, procedural people and scenes.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/joints.h"
#include "datasets/synthetic/camera_rig.h"
#include "datasets/synthetic/person_motion.h"
#include "datasets/synthetic/random.h"
#include "datasets/synthetic/scene.h"
#include "tests/error_message.h"

namespace rpt::synthetic {
namespace {

int J(const JointNames& names, const char* name) {
  const int index = FindJoint(names, name);
  EXPECT_GE(index, 0) << name;
  return index;
}

Eigen::Vector3d HipCenter(const Poses3D& poses, int p, const JointNames& names) {
  const auto person = poses.Person(p);
  return 0.5 * (person.col(J(names, "hip_left")).head<3>() + person.col(J(names, "hip_right")).head<3>());
}

bool SameData(const Scene& a, const Scene& b) {
  if (a.gt.size() != b.gt.size() || a.cameras.size() != b.cameras.size()) return false;
  for (size_t f = 0; f < a.gt.size(); ++f) {
    if (a.gt[f].data != b.gt[f].data || a.gt[f].track_ids != b.gt[f].track_ids) return false;
  }
  for (size_t c = 0; c < a.cameras.size(); ++c) {
    if (a.cameras[c].K != b.cameras[c].K || a.cameras[c].R != b.cameras[c].R || a.cameras[c].t != b.cameras[c].t ||
        a.cameras[c].dist != b.cameras[c].dist) {
      return false;
    }
  }
  return true;
}

TEST(SyntheticRandomTest, DeterministicWithSensibleMoments) {
  Rng a(42), b(42), c(43);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const double x = a.Normal();
    EXPECT_EQ(x, b.Normal());
    differs |= x != c.Normal();
  }
  EXPECT_TRUE(differs);
  Rng rng(7);
  const int n = 200000;
  double sum = 0, sum2 = 0, uniform_sum = 0, poisson_sum = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.Normal();
    sum += x;
    sum2 += x * x;
    const double u = rng.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    uniform_sum += u;
    poisson_sum += rng.Poisson(0.2);
    const int k = rng.UniformInt(5);
    ASSERT_GE(k, 0);
    ASSERT_LT(k, 5);
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum2 / n, 1.0, 0.015);
  EXPECT_NEAR(uniform_sum / n, 0.5, 0.005);
  EXPECT_NEAR(poisson_sum / n, 0.2, 0.005);
  EXPECT_NE(DeriveSeed(1, 2), DeriveSeed(1, 3));
  EXPECT_NE(DeriveSeed(1, 2, 3), DeriveSeed(1, 3, 2));
}

TEST(SyntheticRigTest, CamerasAreValidAndLookAtTheRoom) {
  for (RigLayout layout : {RigLayout::kRing, RigLayout::kRandom}) {
    for (DistortionModel model : {DistortionModel::kNone, DistortionModel::kOpenCV, DistortionModel::kFisheye}) {
      RigOptions options;
      options.layout = layout;
      options.distortion = model;
      options.num_cameras = 6;
      const std::vector<Camera> cameras = MakeCameraRig(options, 11);
      ASSERT_EQ(cameras.size(), 6u);
      for (size_t c = 0; c < cameras.size(); ++c) {
        const Camera& camera = cameras[c];
        SCOPED_TRACE(camera.name + " " + DistortionModelName(model));
        EXPECT_EQ(camera.name, "cam" + std::to_string(c));
        EXPECT_EQ(camera.Validate(), "");
        EXPECT_LT((camera.R * camera.R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
        EXPECT_NEAR(camera.R.determinant(), 1.0, 1e-12);
        EXPECT_EQ(camera.width, 1920);
        EXPECT_EQ(camera.height, 1080);
        EXPECT_EQ(camera.model, model);
        // Horizontal distance and height as configured.
        const Eigen::Vector3d center = camera.Center();
        const double radius = (center - options.look_at_m).head<2>().norm();
        EXPECT_GT(radius, 0.7 * options.radius_m);
        EXPECT_LT(radius, 1.3 * options.radius_m);
        EXPECT_GE(center.z(), 0.5);
        EXPECT_LE(center.z(), options.height_m + 0.85);
        // The look-at point is near the image centre; the camera's y axis points down-ish.
        Eigen::Vector2d uv;
        ASSERT_TRUE(camera.Project(options.look_at_m, &uv));
        EXPECT_NEAR(uv.x(), 960.0, layout == RigLayout::kRing ? 60.0 : 350.0);
        EXPECT_NEAR(uv.y(), 540.0, layout == RigLayout::kRing ? 60.0 : 350.0);
        EXPECT_GT((camera.R.transpose() * Eigen::Vector3d(0, 1, 0)).dot(Eigen::Vector3d(0, 0, -1)), 0.6);
        // A person standing at the room centre (feet and head) is inside the image.
        for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(0, 0, 1.8)}) {
          ASSERT_TRUE(camera.Project(p, &uv));
          EXPECT_TRUE(uv.x() > 0 && uv.x() < 1920 && uv.y() > 0 && uv.y() < 1080) << uv.transpose();
        }
        // The lens model is monotonic well beyond the image corners.
        if (model != DistortionModel::kNone) {
          for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, 0), Eigen::Vector2d(1920, 1080)}) {
            EXPECT_GT(MonotonicRadius(camera), 1.1 * camera.PixelToNormalized(corner).norm());
          }
        } else {
          EXPECT_TRUE(std::isinf(MonotonicRadius(camera)));
        }
      }
    }
  }
}

// Scene, crossing and rig options follow the one Check() convention: "section.key: problem" in the
// option codec's words, thrown by the functions that use them.
TEST(SyntheticOptionsTest, CheckNamesTheKey) {
  EXPECT_EQ(SceneOptions{}.Check(), "");
  EXPECT_EQ(CrossingOptions{}.Check(), "");
  SceneOptions scene;
  scene.num_people = -1;
  EXPECT_EQ(scene.Check(), "scene.num_people: '-1' is not an integer >= 0");
  EXPECT_EQ(test::ConfigErrorOf([&] { GenerateScene(scene); }), "scene.num_people: '-1' is not an integer >= 0");
  scene = {};
  scene.fps = 0;
  EXPECT_EQ(scene.Check(), "scene.fps: '0.0' is not a number > 0");
  scene = {};
  scene.room_size_m = Eigen::Vector3d(1.5, 8, 3);
  EXPECT_EQ(scene.Check(),
            "scene.room_size_m: '1.5,8.0,3.0' is too small (x and y must be above 1.5 m, z at least 2.2 m)");
  scene = {};
  scene.rig.num_cameras = 0;
  EXPECT_EQ(scene.Check(), "rig.num_cameras: '0' is not an integer >= 1");
  CrossingOptions crossing;
  crossing.speed_mps = 0;
  EXPECT_EQ(test::ConfigErrorOf([&] { MakeCrossingScene(crossing); }), "crossing.speed_mps: '0.0' is not a number > 0");
  RigOptions rig;
  rig.horizontal_fov_deg = 170;
  EXPECT_EQ(test::ConfigErrorOf([&] { MakeCameraRig(rig, 1); }),
            "rig.horizontal_fov_deg: '170.0' is too wide for the lens model (it must be below 170)");
  rig.distortion = DistortionModel::kFisheye;
  EXPECT_EQ(rig.Check(), "");
  rig.radius_m = std::nan("");
  EXPECT_EQ(rig.Check(), "rig.radius_m: 'nan' is not a number > 0");
}

TEST(SyntheticRigTest, RingIsEvenlySpacedAndDeterministic) {
  RigOptions options;
  options.num_cameras = 4;
  const std::vector<Camera> a = MakeCameraRig(options, 5);
  const std::vector<Camera> b = MakeCameraRig(options, 5);
  const std::vector<Camera> c = MakeCameraRig(options, 6);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].R, b[i].R);
    EXPECT_EQ(a[i].t, b[i].t);
    EXPECT_EQ(a[i].K, b[i].K);
    EXPECT_NE(a[i].t, c[i].t);
    // Neighbouring cameras ~90 degrees apart.
    const Eigen::Vector2d u = a[i].Center().head<2>().normalized();
    const Eigen::Vector2d v = a[(i + 1) % a.size()].Center().head<2>().normalized();
    EXPECT_NEAR(std::acos(std::clamp(u.dot(v), -1.0, 1.0)), M_PI / 2, 0.15);
  }
}

TEST(SyntheticRigTest, LookAtRotationConvention) {
  const Eigen::Matrix3d r = LookAtRotation(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(5, 0, 1));
  EXPECT_TRUE(r.row(2).transpose().isApprox(Eigen::Vector3d(1, 0, 0)));   // z forward
  EXPECT_TRUE(r.row(0).transpose().isApprox(Eigen::Vector3d(0, -1, 0)));  // x right
  EXPECT_TRUE(r.row(1).transpose().isApprox(Eigen::Vector3d(0, 0, -1)));  // y down
}

TEST(SyntheticMotionTest, StandingPersonHasPlausibleProportions) {
  const BodyShape shape = BodyShapeFromHeight(1.75);
  GaitState state;
  Eigen::Matrix3Xd joints;
  PoseJoints(shape, state, true, &joints);
  ASSERT_EQ(joints.cols(), 133);
  const JointNames& names = CocoWholeBodyJoints();
  const double top = joints.row(2).maxCoeff();
  EXPECT_GT(top, 1.55);  // highest keypoint (brows/eyes) below the top of the head
  EXPECT_LT(top, 1.75);
  EXPECT_NEAR(joints.row(2).minCoeff(), 0.0, 1e-12);
  EXPECT_NEAR(joints(2, J(names, "hip_left")), 0.93, 0.05);
  EXPECT_NEAR(joints(2, J(names, "shoulder_left")), 1.44, 0.06);
  EXPECT_NEAR(joints(2, J(names, "nose")), 1.58, 0.05);
  // Left is +y when facing +x; the face is in front (+x) of the ears.
  EXPECT_GT(joints(1, J(names, "shoulder_left")), joints(1, J(names, "shoulder_right")));
  EXPECT_GT(joints(1, J(names, "eye_left")), joints(1, J(names, "eye_right")));
  EXPECT_GT(joints(0, J(names, "nose")), joints(0, J(names, "ear_left")) + 0.05);
  // iBUG: face_00 is the subject's right jaw end, face_16 the left; face_30 is the nose tip.
  EXPECT_LT(joints(1, J(names, "face_00")), joints(1, J(names, "face_16")));
  EXPECT_LT((joints.col(J(names, "face_30")) - joints.col(J(names, "nose"))).norm(), 1e-9);
  // Thumbs point forward for hanging arms, toes point forward.
  EXPECT_GT(joints(0, J(names, "hand_thumb_4_left")), joints(0, J(names, "hand_pinky_4_left")));
  EXPECT_GT(joints(0, J(names, "foot_big_toe_right")), joints(0, J(names, "foot_heel_right")) + 0.15);
}

TEST(SyntheticMotionTest, WalkingSwingsLegsAndArmsInOpposition) {
  const BodyShape shape = BodyShapeFromHeight(1.75);
  GaitState state;
  state.speed_mps = 1.3;
  state.phase_rad = M_PI / 2;  // left leg forward
  Eigen::Matrix3Xd joints;
  PoseJoints(shape, state, false, &joints);
  const JointNames& names = CocoBodyJoints();
  EXPECT_GT(joints(0, J(names, "ankle_left")) - joints(0, J(names, "ankle_right")), 0.4);
  EXPECT_GT(joints(0, J(names, "wrist_right")) - joints(0, J(names, "wrist_left")), 0.1);
  // Swing phase bends the knee.
  state.phase_rad = 0.6;
  PoseJoints(shape, state, false, &joints);
  const Eigen::Vector3d hip = joints.col(J(names, "hip_left")), knee = joints.col(J(names, "knee_left")),
                        ankle = joints.col(J(names, "ankle_left"));
  const double knee_angle = std::acos((hip - knee).normalized().dot((ankle - knee).normalized()));
  EXPECT_LT(knee_angle, M_PI - 0.6);
  // Body only: the lowest ankle is a few cm above the floor (the foot points touch it).
  EXPECT_GT(joints.row(2).minCoeff(), 0.04);
  EXPECT_LT(joints.row(2).minCoeff(), 0.13);
}

SceneOptions SmallScene(uint64_t seed, bool whole_body = false) {
  SceneOptions options;
  options.seed = seed;
  options.whole_body = whole_body;
  options.num_frames = 300;
  return options;
}

TEST(SyntheticSceneTest, SameSeedSameDataOtherSeedOtherData) {
  const Scene a = GenerateScene(SmallScene(3));
  const Scene b = GenerateScene(SmallScene(3));
  const Scene c = GenerateScene(SmallScene(4));
  EXPECT_TRUE(SameData(a, b));
  EXPECT_FALSE(SameData(a, c));
  ASSERT_EQ(a.gt.size(), 300u);
  EXPECT_EQ(a.cameras.size(), 5u);
  EXPECT_EQ(a.joint_names, CocoBodyJoints());
  EXPECT_EQ(a.fps, 25.0);
  EXPECT_EQ(a.room_size_m, Eigen::Vector3d(8, 8, 3));
  for (const Poses3D& frame : a.gt) {
    ASSERT_EQ(frame.num_joints, 17);
    ASSERT_EQ(frame.track_ids, (std::vector<int>{0, 1, 2, 3}));
    for (int p = 0; p < frame.num_persons(); ++p) {
      EXPECT_TRUE((frame.Person(p).row(3).array() == 1.0).all());
      EXPECT_TRUE(frame.Person(p).allFinite());
    }
  }
}

TEST(SyntheticSceneTest, BoneLengthsAreConstantAndPlausible) {
  const Scene scene = GenerateScene(SmallScene(8, /*whole_body=*/true));
  const JointNames& names = scene.joint_names;
  // COCO skeleton edges (incl. head and torso) plus whole-body attachments.
  std::vector<std::pair<std::string, std::string>> edges = {
      {"nose", "eye_left"}, {"nose", "eye_right"}, {"eye_left", "ear_left"}, {"eye_right", "ear_right"},
      {"ear_left", "shoulder_left"}, {"ear_right", "shoulder_right"}, {"shoulder_left", "hip_left"},
      {"shoulder_right", "hip_right"}, {"hip_left", "hip_right"}, {"shoulder_left", "shoulder_right"},
      {"face_00", "face_16"}, {"face_08", "nose"}, {"ankle_left", "foot_heel_left"},
      {"ankle_right", "foot_big_toe_right"}, {"wrist_left", "hand_middle_4_left"},
      {"hand_root_right", "hand_thumb_4_right"}};
  for (const LimbSpec& limb : BodyLimbs()) edges.emplace_back(limb.a, limb.b);
  for (int p = 0; p < scene.gt[0].num_persons(); ++p) {
    for (const auto& [a, b] : edges) {
      const int ia = J(names, a.c_str()), ib = J(names, b.c_str());
      const double reference = (scene.gt[0].Person(p).col(ia) - scene.gt[0].Person(p).col(ib)).head<3>().norm();
      for (const Poses3D& frame : scene.gt) {
        const double length = (frame.Person(p).col(ia) - frame.Person(p).col(ib)).head<3>().norm();
        ASSERT_NEAR(length, reference, 1e-9) << a << "-" << b << " person " << p;
      }
    }
    for (const LimbSpec& limb : BodyLimbs()) {
      const double length =
          (scene.gt[0].Person(p).col(J(names, limb.a.c_str())) - scene.gt[0].Person(p).col(J(names, limb.b.c_str())))
              .head<3>()
              .norm();
      EXPECT_GE(length, limb.min_length_m) << limb.a << "-" << limb.b;
      EXPECT_LE(length, limb.max_length_m) << limb.a << "-" << limb.b;
    }
    // Tighter human ranges (height 1.5-1.95 m).
    auto length = [&](const char* a, const char* b) {
      return (scene.gt[0].Person(p).col(J(names, a)) - scene.gt[0].Person(p).col(J(names, b))).head<3>().norm();
    };
    EXPECT_GT(length("hip_left", "knee_left"), 0.32);
    EXPECT_LT(length("hip_left", "knee_left"), 0.53);
    EXPECT_GT(length("shoulder_right", "elbow_right"), 0.24);
    EXPECT_LT(length("shoulder_right", "elbow_right"), 0.40);
    EXPECT_GT(length("elbow_left", "wrist_left"), 0.19);
    EXPECT_LT(length("elbow_left", "wrist_left"), 0.32);
    EXPECT_GT(length("shoulder_left", "shoulder_right"), 0.25);
    EXPECT_LT(length("shoulder_left", "shoulder_right"), 0.5);
    // Left and right limbs are equally long.
    EXPECT_NEAR(length("knee_left", "ankle_left"), length("knee_right", "ankle_right"), 1e-9);
  }
}

TEST(SyntheticSceneTest, PeopleStayInsideTheRoomAndApart) {
  for (uint64_t seed : {1, 2, 3}) {
    SceneOptions options = SmallScene(seed);
    options.num_people = seed == 3 ? 8 : 4;
    options.room_size_m = seed == 2 ? Eigen::Vector3d(6, 5, 3) : Eigen::Vector3d(8, 8, 3);
    const Scene scene = GenerateScene(options);
    const Eigen::Vector3d lo = scene.room_center_m - 0.5 * scene.room_size_m;
    const Eigen::Vector3d hi = scene.room_center_m + 0.5 * scene.room_size_m;
    double min_distance = std::numeric_limits<double>::infinity();
    double travelled = 0.0;
    double max_speed = 0.0;
    int moving = 0, facing_motion = 0;
    for (size_t f = 0; f < scene.gt.size(); ++f) {
      const Poses3D& frame = scene.gt[f];
      for (int p = 0; p < frame.num_persons(); ++p) {
        const auto person = frame.Person(p);
        for (int k = 0; k < frame.num_joints; ++k) {
          ASSERT_TRUE((person.col(k).head<3>().array() >= lo.array() - 1e-9).all()) << person.col(k).transpose();
          ASSERT_TRUE((person.col(k).head<3>().array() <= hi.array()).all()) << person.col(k).transpose();
        }
        for (int q = p + 1; q < frame.num_persons(); ++q) {
          min_distance = std::min(min_distance, (HipCenter(frame, p, scene.joint_names) -
                                                 HipCenter(frame, q, scene.joint_names)).head<2>().norm());
        }
        if (f > 0) {
          const Eigen::Vector2d step = (HipCenter(frame, p, scene.joint_names) -
                                        HipCenter(scene.gt[f - 1], p, scene.joint_names)).head<2>();
          travelled += step.norm();
          max_speed = std::max(max_speed, step.norm() * scene.fps);
          if (step.norm() * scene.fps > 0.5) {
            ++moving;
            const Eigen::Vector3d facing = person.col(J(scene.joint_names, "nose")).head<3>() -
                                           0.5 * (person.col(J(scene.joint_names, "ear_left")).head<3>() +
                                                  person.col(J(scene.joint_names, "ear_right")).head<3>());
            facing_motion += facing.head<2>().normalized().dot(step.normalized()) > 0.9;
          }
        }
      }
    }
    EXPECT_GE(min_distance, options.min_separation_m - 1e-9) << "seed " << seed;
    EXPECT_GT(travelled / options.num_people, 3.0) << "people should walk (12 s of footage)";
    EXPECT_LT(max_speed, 1.55);
    ASSERT_GT(moving, 0);
    EXPECT_GT(facing_motion, 0.95 * moving) << "heading follows the velocity";
  }
}

TEST(SyntheticSceneTest, SomebodyStandsStillSometimes) {
  SceneOptions options = SmallScene(21);
  options.num_people = 6;
  options.num_frames = 500;
  const Scene scene = GenerateScene(options);
  int still = 0;
  for (size_t f = 1; f < scene.gt.size(); ++f) {
    for (int p = 0; p < scene.gt[f].num_persons(); ++p) {
      still += (HipCenter(scene.gt[f], p, scene.joint_names) - HipCenter(scene.gt[f - 1], p, scene.joint_names))
                   .head<2>()
                   .norm() < 1e-9;
    }
  }
  EXPECT_GT(still, 0);
}

TEST(SyntheticSceneTest, WholeBodyHandsAtWristsAndFaceAtHead) {
  SceneOptions options = SmallScene(5, /*whole_body=*/true);
  options.num_frames = 60;
  const Scene scene = GenerateScene(options);
  const JointNames& names = scene.joint_names;
  ASSERT_EQ(names, CocoWholeBodyJoints());
  for (const Poses3D& frame : scene.gt) {
    ASSERT_EQ(frame.num_joints, 133);
    for (int p = 0; p < frame.num_persons(); ++p) {
      const auto person = frame.Person(p);
      auto at = [&](const std::string& name) -> Eigen::Vector3d { return person.col(J(names, name.c_str())).head<3>(); };
      for (const std::string side : {"left", "right"}) {
        EXPECT_LT((at("hand_root_" + side) - at("wrist_" + side)).norm(), 0.005);
        for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
          const double reach = (at(std::string("hand_") + finger + "_4_" + side) - at("wrist_" + side)).norm();
          EXPECT_GT(reach, 0.08);
          EXPECT_LT(reach, 0.23);
        }
        for (const char* part : {"foot_big_toe_", "foot_small_toe_", "foot_heel_"}) {
          EXPECT_LT((at(part + side) - at("ankle_" + side)).norm(), 0.25);
          EXPECT_GE(at(part + side).z(), -1e-9);
        }
        // The hand is on the forearm's extension.
        const Eigen::Vector3d forearm = (at("wrist_" + side) - at("elbow_" + side)).normalized();
        EXPECT_GT((at("hand_middle_1_" + side) - at("wrist_" + side)).normalized().dot(forearm), 0.9);
      }
      const Eigen::Vector3d head = 0.5 * (at("ear_left") + at("ear_right"));
      for (int i = 0; i < 68; ++i) {
        const Eigen::Vector3d point = person.col(23 + i).head<3>();
        EXPECT_LT((point - at("nose")).norm(), 0.15);
        EXPECT_LT((point - head).norm(), 0.16);
        EXPECT_GT(point.z(), at("shoulder_left").z());
      }
    }
  }
}

TEST(SyntheticSceneTest, CrossingPeoplePassClosely) {
  for (int num_people : {2, 3}) {
    CrossingOptions options;
    options.num_people = num_people;
    options.seed = 9 + num_people;
    const Scene scene = MakeCrossingScene(options);
    ASSERT_EQ(static_cast<int>(scene.gt.size()), options.num_frames);
    double closest = std::numeric_limits<double>::infinity();
    for (const Poses3D& frame : scene.gt) {
      ASSERT_EQ(frame.num_persons(), num_people);
      for (int p = 0; p + 1 < frame.num_persons(); ++p) {
        closest = std::min(closest, (HipCenter(frame, p, scene.joint_names) -
                                     HipCenter(frame, p + 1, scene.joint_names)).head<2>().norm());
      }
    }
    EXPECT_LT(closest, 0.8);
    EXPECT_GT(closest, 0.5);
    // Persons 0 and 1 walk in opposite directions and swap sides.
    const Eigen::Vector3d d0 = HipCenter(scene.gt.back(), 0, scene.joint_names) - HipCenter(scene.gt[0], 0, scene.joint_names);
    const Eigen::Vector3d d1 = HipCenter(scene.gt.back(), 1, scene.joint_names) - HipCenter(scene.gt[0], 1, scene.joint_names);
    EXPECT_GT(d0.norm(), 3.0);
    EXPECT_LT(d0.normalized().dot(d1.normalized()), -0.99);
    EXPECT_EQ(scene.gt[0].track_ids[1], 1);
  }
}

}  // namespace
}  // namespace rpt::synthetic

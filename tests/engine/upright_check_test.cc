// SPDX-License-Identifier: MIT
// engine::UprightCheck: persons standing on their heads (v flipped, world z down) and mirror images
// (left and right exchanged) are named.
#include "engine/upright_check.h"

#include <gtest/gtest.h>

#include <string>

#include "core/joints.h"
#include "tests/pipeline/test_scene.h"

namespace rpt::engine {
namespace {

// `count` standing persons (COCO-17), mirrored through z = 1 m when `upside_down`.
Poses3D Persons(int count, bool upside_down) {
  Poses3D persons;
  persons.Clear(17);
  for (int p = 0; p < count; ++p) {
    Eigen::Matrix4Xd body = test::StandingPerson(0.5 * p, 0);
    if (upside_down) body.row(2) = (2.0 - body.row(2).array()).matrix();
    persons.AddPerson() = body;
  }
  return persons;
}

TEST(UprightCheck, PersonsOnTheirHeadsAreNamedUprightOnesAreNot) {
  UprightCheck upright(CocoBodyJoints());
  upright.Add(Persons(25, false));
  EXPECT_EQ(upright.count().judged, 25);
  EXPECT_EQ(upright.count().upside_down, 0);
  EXPECT_EQ(UprightWarning("s", upright.count()), "");

  UprightCheck flipped(CocoBodyJoints());
  flipped.Add(Persons(15, true));
  flipped.Add(Persons(5, false));
  EXPECT_EQ(flipped.count().judged, 20);
  EXPECT_EQ(flipped.count().upside_down, 15);
  const std::string line = UprightWarning("take", flipped.count());
  EXPECT_EQ(line.rfind("take: 15 of the 20 persons with a head and both ankles triangulated (75 %) stand on their heads", 0),
            0u)
      << line;
  // Half of them or fewer, or fewer than 20 judged: nothing said.
  UprightCheck half(CocoBodyJoints());
  half.Add(Persons(10, true));
  half.Add(Persons(10, false));
  EXPECT_EQ(UprightWarning("s", half.count()), "");
  UprightCheck few(CocoBodyJoints());
  few.Add(Persons(19, true));
  EXPECT_EQ(UprightWarning("s", few.count()), "");
  // Filled (not triangulated) ankles are not judged.
  Poses3D filled = Persons(1, true);
  filled.PersonProvenance(0)[FindJoint(CocoBodyJoints(), "ankle_left")] = static_cast<uint8_t>(JointProvenance::kFilled);
  UprightCheck unjudged(CocoBodyJoints());
  unjudged.Add(filled);
  EXPECT_EQ(unjudged.count().judged, 0);
}

// A world whose up is y (y down, as OpenCV's camera-like worlds): standing people lie on their sides.
// The axis from the ankles to the head within 30 degrees of the horizontal counts as lying; a person
// bent 45 degrees does not; more than half of at least 20 judged lying is named, as a world axis.
TEST(UprightCheck, PersonsLyingInAWorldWithAnotherUpAreNamed) {
  const auto rotated = [](int count, double tilt_rad) {  // standing persons turned about the x axis
    Poses3D persons = Persons(count, false);
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix();
    for (int p = 0; p < count; ++p) persons.Person(p).topRows<3>() = turn * persons.Person(p).topRows<3>();
    return persons;
  };
  UprightCheck ydown(CocoBodyJoints());
  ydown.Add(rotated(20, -M_PI / 2));  // (x, y, z) -> (x, z, -y): the up axis becomes y
  EXPECT_EQ(ydown.count().judged, 20);
  EXPECT_EQ(ydown.count().upside_down, 0);
  EXPECT_EQ(ydown.count().lying, 20);
  const std::string line = UprightWarning("take", ydown.count());
  EXPECT_EQ(line.rfind("take: 20 of the 20 persons with a head and both ankles triangulated (100 %) lie on their sides "
                       "(ankles to head within 30 degrees of the horizontal; rpt's world has z up): does the "
                       "calibration's world have another axis up",
                       0),
            0u)
      << line;
  EXPECT_EQ(MirroredWarning("take", ydown.count()), "") << "said once, as a world axis";
  // Bent 45 degrees is not lying; 59 degrees from the vertical neither, 61 degrees is.
  UprightCheck bent(CocoBodyJoints());
  bent.Add(rotated(20, M_PI / 4));
  bent.Add(rotated(20, 59.0 * M_PI / 180));
  EXPECT_EQ(bent.count().lying, 0);
  bent.Add(rotated(21, 61.0 * M_PI / 180));
  EXPECT_EQ(bent.count().lying, 21);
  EXPECT_EQ(UprightWarning("s", bent.count()), "") << "21 of 61: not most";
  UprightCheck most(CocoBodyJoints());
  most.Add(rotated(11, 61.0 * M_PI / 180));
  most.Add(rotated(10, 0));
  EXPECT_NE(UprightWarning("s", most.count()), "") << "11 of 21";
}

// `count` standing persons (COCO-17) at yaws 0, 1, 2, ... rad, the first `mirrored` of them with
// every left joint's and right joint's places exchanged (a mirror image).
Poses3D Facing(int count, int mirrored) {
  const JointNames& joints = CocoBodyJoints();
  Poses3D persons;
  persons.Clear(17);
  for (int p = 0; p < count; ++p) {
    Eigen::Matrix4Xd body = test::StandingPerson(0.5 * p, 0, 1.0 * p);
    if (p < mirrored) {
      const Eigen::Matrix4Xd original = body;
      for (size_t j = 0; j < joints.size(); ++j) {
        const std::string& name = joints[j];
        std::string other = name;
        if (const size_t at = name.find("_left"); at != std::string::npos) other.replace(at, 5, "_right");
        if (const size_t at = name.find("_right"); at != std::string::npos) other.replace(at, 6, "_left");
        body.col(static_cast<int>(j)) = original.col(FindJoint(joints, other));
      }
    }
    persons.AddPerson() = body;
  }
  return persons;
}

TEST(UprightCheck, MirrorImagesAreNamedAboveAQuarter) {
  UprightCheck facing(CocoBodyJoints());
  facing.Add(Facing(25, 0));
  EXPECT_EQ(facing.count().facing_judged, 25);
  EXPECT_EQ(facing.count().mirrored, 0) << "every yaw: the nose in front";
  EXPECT_EQ(MirroredWarning("s", facing.count()), "");
  UprightCheck mirrored(CocoBodyJoints());
  mirrored.Add(Facing(25, 7));  // 28 %
  EXPECT_EQ(mirrored.count().mirrored, 7);
  const std::string line = MirroredWarning("take", mirrored.count());
  EXPECT_EQ(line.rfind("take: 7 of the 25 persons with nose, shoulders and hips triangulated (28 %) have the nose "
                       "behind the shoulders, as mirror images have",
                       0),
            0u)
      << line;
  UprightCheck quarter(CocoBodyJoints());
  quarter.Add(Facing(24, 6));  // 25 %: not more than a quarter
  EXPECT_EQ(quarter.count().mirrored, 6);
  EXPECT_EQ(MirroredWarning("s", quarter.count()), "");
  // Persons on their heads are mirror images too: said once, by the upright warning.
  UprightCheck flipped(CocoBodyJoints());
  flipped.Add(Persons(20, true));
  EXPECT_EQ(flipped.count().mirrored, 20);
  EXPECT_NE(UprightWarning("s", flipped.count()), "");
  EXPECT_EQ(MirroredWarning("s", flipped.count()), "");
}

}  // namespace
}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// engine::UprightCheck: persons standing on their heads (v flipped, world z down) are named.
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

}  // namespace
}  // namespace rpt::engine

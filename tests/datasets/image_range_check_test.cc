// SPDX-License-Identifier: MIT
// ImageRangeCheck (datasets/image_range_check.h): which pixel frame the detections of a camera are
// in, from where its joints lie: the camera's own (nothing said), far beyond its image, all in its
// top-left quarter, normalised (within 1.5 px of the origin) or centred (negative coordinates).
#include "datasets/image_range_check.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rpt {
namespace {

Camera CameraOf(const std::string& name) {
  Camera camera;
  camera.name = name;
  camera.width = 1000;
  camera.height = 500;
  return camera;
}

// `count` joints of one person each, at (u, v) with score 0.9; `missing` more of score 0.
Poses2D ViewAt(double u, double v, int count, int missing = 0) {
  Poses2D view;
  view.Clear(count + missing);
  auto person = view.AddPerson();
  for (int j = 0; j < count + missing; ++j) {
    person(0, j) = u;
    person(1, j) = v;
    person(2, j) = j < count ? 0.9 : 0.0;
  }
  return view;
}

std::vector<std::string> Lines(const ImageRangeCheck& check) {
  InputWarnings warnings;
  check.AddWarnings("src", &warnings);
  std::vector<std::string> lines;
  for (const InputWarning& w : warnings.items()) lines.push_back(w.Line());
  return lines;
}

TEST(ImageRangeCheck, JointsInTheImageSayNothing) {
  ImageRangeCheck check({CameraOf("a")});
  check.Add(0, ViewAt(990, 490, 150));
  check.Add(0, ViewAt(10, 10, 150));
  check.Add(0, ViewAt(-99, 549, 10));  // beyond the edge by less than a tenth of the side
  EXPECT_TRUE(Lines(check).empty());
  EXPECT_EQ(check.detected(), 310);
}

TEST(ImageRangeCheck, JointsFarBeyondTheImageAreCountedWithTheFarthest) {
  ImageRangeCheck check({CameraOf("a"), CameraOf("b")});
  check.Add(0, ViewAt(1101, 100, 3, /*missing=*/4));  // 0.101 of the width beyond: counted
  check.Add(0, ViewAt(1099, 100, 5));                 // 0.099: not
  check.Add(1, ViewAt(500, 750, 2));                  // half the height below the image
  const std::vector<std::string> lines = Lines(check);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "src: 3 detected joints beyond the 1000x500 image of camera 'a' by more than a tenth of its side (the "
            "calibration's image size, or the detections' pixel scale, wrong?) (farthest beyond the edge, in image "
            "sides = 0.101)");
  EXPECT_NE(lines[1].find("2 detected joints beyond the 1000x500 image of camera 'b'"), std::string::npos);
  EXPECT_NE(lines[1].find("= 0.5)"), std::string::npos) << lines[1];
}

TEST(ImageRangeCheck, AllInTheTopLeftQuarterIsAHalfSizeImage) {
  ImageRangeCheck check({CameraOf("a")});
  check.Add(0, ViewAt(549, 274, 199));
  EXPECT_TRUE(Lines(check).empty()) << "199 joints: too few to judge";
  check.Add(0, ViewAt(10, 10, 1));
  ASSERT_EQ(Lines(check).size(), 1u);
  EXPECT_EQ(Lines(check)[0],
            "src: 200 detected joints of camera 'a', all in the top-left quarter of its 1000x500 image (detections "
            "from a smaller image, such as a half-size or 1080p proxy video? scale them to the calibration's image "
            "size) (largest u and v, in image sides = 0.549)");
  check.Add(0, ViewAt(551, 10, 1));  // one joint past 0.55 of the width: the image is used
  EXPECT_TRUE(Lines(check).empty());
}

// Normalised coordinates were called "a half-size image", whose advice (scale by 2) does not fix them.
TEST(ImageRangeCheck, CoordinatesWithinAPixelOfTheOriginAreNormalised) {
  ImageRangeCheck check({CameraOf("a")});
  check.Add(0, ViewAt(0.9, 0.4, 100));
  check.Add(0, ViewAt(-1.0, 1.5, 100));  // OpenPose's --keypoint_scale 4: -1 to 1
  const std::vector<std::string> lines = Lines(check);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "src: 200 detected joints of camera 'a', all within 1.5 pixels of the origin (normalised coordinates, 0-1 "
            "or -1-1? give pixels of its 1000x500 image: u times the width, v times the height) (largest |u| or |v|, "
            "in pixels = 1.5)");
  check.Add(0, ViewAt(1.6, 0, 1));
  EXPECT_EQ(Lines(check).size(), 1u);
  EXPECT_NE(Lines(check)[0].find("top-left quarter"), std::string::npos) << "no longer normalised";
}

TEST(ImageRangeCheck, ManyNegativeCoordinatesSayTheOriginIsTheCentre) {
  ImageRangeCheck check({CameraOf("a")});
  check.Add(0, ViewAt(-300, 100, 50));  // 0.3 of the width left of the image
  check.Add(0, ViewAt(300, 100, 150));
  std::vector<std::string> lines = Lines(check);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("50 detected joints beyond the 1000x500 image"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1],
            "src: 50 detected joints of camera 'a' at negative coordinates (is the origin at the image centre? rpt's "
            "pixels count from the top-left corner of the image, u to the right, v down) (share of the camera's "
            "detected joints = 0.25)");
  check.Add(0, ViewAt(300, 100, 801));  // below 5 %: a few joints left of the image are no frame
  lines = Lines(check);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[1].find("top-left quarter"), std::string::npos) << lines[1];
}

}  // namespace
}  // namespace rpt

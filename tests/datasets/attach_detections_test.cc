// SPDX-License-Identifier: MIT
// AttachDetections (datasets/detections.h): one detections file for one or several sequences,
// with the same errors either way and counted warnings for the frames that do not match.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "datasets/detections.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using test::InputErrorOf;
using ::testing::HasSubstr;

// Scenes "a" (ids a_000000..a_000003) and "b" (b_000000..b_000003) and detections for both.
struct TwoScenes {
  std::vector<Sequence> sequences = {test::MakeLabelSequence("a", 4, "a_"), test::MakeLabelSequence("b", 4, "b_")};
  Detections detections;
  TwoScenes() {
    for (const char* prefix : {"a_", "b_"}) {
      Detections d = test::MakeDetections(4, {"cam_a", "cam_b", "cam_c"}, CocoBodyJoints(), prefix);
      detections.joints = d.joints;
      for (FrameDetections& f : d.frames) detections.frames.push_back(std::move(f));
    }
  }
};

TEST(AttachDetections, EachFrameGoesToTheSequenceHoldingItsId) {
  TwoScenes input;
  InputWarnings warnings;
  const AttachReport report = AttachDetections(input.detections, "d.json", input.sequences, &warnings);
  EXPECT_EQ(report.frames_with_detections, 8);
  EXPECT_EQ(report.frames_without, 0);
  EXPECT_EQ(report.unused_frames, 0);
  EXPECT_TRUE(warnings.empty());
  for (const Sequence& s : input.sequences) {
    EXPECT_EQ(s.detection_joints, CocoBodyJoints());
    ValidateSequence(s, "attached");
  }
  // b_000001, camera cam_b: MakeDetections gives (f + c) % 3 = 2 persons.
  EXPECT_EQ(input.sequences[1].frames[1].views[1].num_persons(), 2);
  EXPECT_EQ(input.sequences[1].frames[1].views[1].data, input.detections.frames[5].views[1].data);
}

TEST(AttachDetections, AnUnknownCameraIsAnErrorForSeveralSequencesAsForOne) {
  TwoScenes input;
  input.detections.frames[6].cameras[2] = "cam_typo";  // b_000002
  InputWarnings warnings;
  EXPECT_THAT(InputErrorOf([&] { AttachDetections(input.detections, "d.json", input.sequences, &warnings); }),
              HasSubstr("d.json: frame 'b_000002': camera 'cam_typo' is not a camera of sequence 'b'"));
  Sequence& b = input.sequences[1];
  EXPECT_THAT(
      InputErrorOf([&] { AttachDetections(input.detections, "d.json", std::span<Sequence>(&b, 1), &warnings); }),
      HasSubstr("d.json: frame 'b_000002': camera 'cam_typo' is not a camera of sequence 'b'"));
}

TEST(AttachDetections, UnmatchedFramesAreCountedWithTheFirstId) {
  TwoScenes input;
  input.detections.frames.erase(input.detections.frames.begin() + 1);  // a_000001: absent
  input.detections.frames.erase(input.detections.frames.begin() + 5);  // b_000002: absent
  for (const char* id : {"c_000007", "c_000003"}) {
    input.detections.frames.push_back(input.detections.frames[0]);
    input.detections.frames.back().frame_id = id;
  }
  InputWarnings warnings;
  const AttachReport report = AttachDetections(input.detections, "d.json", input.sequences, &warnings);
  EXPECT_EQ(report.frames_with_detections, 6);
  EXPECT_EQ(report.frames_without, 2);
  EXPECT_EQ(report.unused_frames, 2);
  // The absent frames are attached as frames without persons.
  ASSERT_EQ(input.sequences[0].frames[1].views.size(), 3u);
  EXPECT_EQ(input.sequences[0].frames[1].views[0].num_persons(), 0);
  ASSERT_EQ(warnings.items().size(), 2u);
  EXPECT_EQ(warnings.items()[0].Line(),
            "d.json: 2 detection frames whose id is no frame of the input, ignored (first 'c_000007')");
  EXPECT_EQ(warnings.items()[1].Line(),
            "d.json: 2 frames of the input absent from it, triangulated without detections (first 'a_000001')");
  EXPECT_EQ(warnings.Unused().size(), 2u);
}

TEST(AttachDetections, ASequenceNoneOfWhoseFramesMatchesIsAnError) {
  TwoScenes input;
  input.sequences.push_back(test::MakeLabelSequence("z", 2, "z_"));
  InputWarnings warnings;
  EXPECT_THAT(InputErrorOf([&] { AttachDetections(input.detections, "d.json", input.sequences, &warnings); }),
              HasSubstr("d.json: none of its 8 frame ids (e.g. 'a_000000') matches a frame of sequence 'z' (e.g. "
                        "'z_000000')"));
}

TEST(AttachDetections, JointCountMismatchNamesFrameAndCamera) {
  TwoScenes input;
  input.detections.frames[2].views[2].Clear(5);
  input.detections.frames[2].views[2].AddPerson();
  InputWarnings warnings;
  EXPECT_THAT(InputErrorOf([&] { AttachDetections(input.detections, "d.json", input.sequences, &warnings); }),
              HasSubstr("d.json: frame 'a_000002', camera 'cam_c': 5 joints, expected 17"));
}

}  // namespace
}  // namespace rpt

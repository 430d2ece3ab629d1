// SPDX-License-Identifier: MIT
// The validation of sequences and frames (datasets/sequence.h): what the run checks once per frame
// of every source, now that the readers do not validate what they give.
#include "datasets/sequence.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using ::testing::HasSubstr;
using ::testing::EndsWith;

// A valid sequence: three cameras, two frames of two persons with views and 2D labels.
Sequence ValidSequence() {
  Sequence sequence = test::MakeLabelSequence("s", 2, "s_");
  sequence.detection_joints = {"nose", "eye_left"};
  for (SequenceFrame& frame : sequence.frames) {
    frame.views.resize(sequence.cameras.size());
    for (Poses2D& view : frame.views) {
      view.Clear(2);
      view.AddPerson() << 10, 20, 30, 40, 0.5, 1.0;
    }
    frame.labels_2d.resize(sequence.cameras.size());
    frame.labels_2d[0].push_back(PersonLabel2D{1, Eigen::Vector4d(0, 0, 10, 10), {}});
  }
  return sequence;
}

std::string ErrorOf(const Sequence& sequence) {
  return test::InputErrorOf([&] { ValidateSequence(sequence, "src"); });
}

TEST(SequenceValidation, AValidSequenceAndUnknownTimesPass) {
  Sequence sequence = ValidSequence();
  EXPECT_NO_THROW(ValidateSequence(sequence, "src"));
  sequence.frames[1].timestamp_s = kUnknownTime;  // an unknown time is valid
  EXPECT_NO_THROW(ValidateSequence(sequence, "src"));
  EXPECT_NO_THROW(ValidateFrame(sequence, sequence.frames[1], "src"));
}

TEST(SequenceValidation, HeaderErrorsNameTheSource) {
  Sequence sequence = ValidSequence();
  sequence.cameras.clear();
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: no cameras"));
  sequence = ValidSequence();
  sequence.cameras[1].K(2, 2) = 0;
  EXPECT_THAT(test::InputErrorOf([&] { ValidateSequenceHeader(sequence, "src"); }), HasSubstr("src: "));
}

TEST(SequenceValidation, FrameErrorsNameTheFrameAndCamera) {
  Sequence sequence = ValidSequence();
  sequence.frames[1].id = sequence.frames[0].id;
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000000': duplicate frame id"));

  sequence = ValidSequence();
  sequence.frames[1].gt.num_joints = 3;
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000001': ground truth has 3 joints, expected 20"));

  sequence = ValidSequence();
  sequence.frames[0].gt.data[5] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000000': ground truth contains NaN or infinity"));

  sequence = ValidSequence();
  sequence.frames[1].views.pop_back();
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000001': 2 views for 3 cameras"));

  sequence = ValidSequence();
  sequence.frames[0].views[2].Clear(3);
  sequence.frames[0].views[2].AddPerson();
  EXPECT_THAT(ErrorOf(sequence),
              HasSubstr("src: frame 's_000000', camera 'cam_c': detections have 3 joints, expected 2"));

  sequence = ValidSequence();
  sequence.frames[0].views[1].data[5] = 1.2;
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000000', camera 'cam_b': detection 0, joint 'eye_left': "
                                           "score 1.2 outside [0, 1] (values up to 1.5 are clamped to 1 where "
                                           "detections are read)"));
  sequence.frames[0].views[1].data[5] = -0.25;
  EXPECT_THAT(ErrorOf(sequence), EndsWith("joint 'eye_left': score -0.25 outside [0, 1]"));

  sequence = ValidSequence();
  sequence.frames[0].views[1].data[0] = std::numeric_limits<double>::infinity();
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("camera 'cam_b': detection 0, joint 'nose' contains NaN or infinity"));
  sequence = ValidSequence();
  sequence.frames[0].views[1].data[4] = std::numeric_limits<double>::quiet_NaN();  // v of the second joint
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("camera 'cam_b': detection 0, joint 'eye_left' contains NaN or infinity"));

  sequence = ValidSequence();
  sequence.frames[1].labels_2d.resize(1);
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000001': 2D labels for 1 views, expected 3"));

  sequence = ValidSequence();
  sequence.frames[1].labels_2d[0][0].gt_person = 2;
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("src: frame 's_000001': 2D label of GT person 2, the frame has 2"));

  sequence = ValidSequence();
  sequence.frames[1].labels_2d[0][0].visibility = {kLabelVisible};
  EXPECT_THAT(ErrorOf(sequence), HasSubstr("2D label with 1 joint flags, expected 20"));
}

}  // namespace
}  // namespace rpt

// SPDX-License-Identifier: MIT
// TriangulateSource (cli/run_sequence.h): frames pulled from a FrameSource give the predictions of
// the materialised sequence while one input frame is alive at a time.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "cli/run_sequence.h"
#include "datasets/frame_source.h"
#include "datasets/readers/synthetic_dataset.h"
#include "tests/counting_source.h"

namespace rpt::cli {
namespace {

SyntheticParams Scene(int frames) {
  SyntheticParams params;
  params.cameras = 4;
  params.people = 2;
  params.frames = frames;
  params.seed = 3;
  return params;
}

TEST(TriangulateSourceTest, SamePredictionsAsTheMaterialisedSequence) {
  RunOptions options;
  options.progress = false;
  const std::vector<Sequence> whole = MakeSyntheticDataset(Scene(150));
  const TriangulatedSequence expected = TriangulateSequence(whole[0], options);
  std::unique_ptr<FrameSource> source = StreamSynthetic(Scene(150));
  long visited = 0;
  const TriangulatedSequence streamed =
      TriangulateSource(*source, options, [&](const SequenceFrame& frame, const Poses3D&) {
        EXPECT_EQ(frame.id, whole[0].frames[visited].id);
        ++visited;
      });
  EXPECT_EQ(visited, 150);
  EXPECT_EQ(streamed.output_joints, expected.output_joints);
  ASSERT_EQ(streamed.predictions.size(), expected.predictions.size());
  for (size_t f = 0; f < expected.predictions.size(); ++f) {
    EXPECT_EQ(streamed.predictions[f].data, expected.predictions[f].data) << "frame " << f;
    EXPECT_EQ(streamed.predictions[f].track_ids, expected.predictions[f].track_ids) << "frame " << f;
  }
  EXPECT_EQ(streamed.counts.Finalize().frames, expected.counts.Finalize().frames);
}

TEST(TriangulateSourceTest, HoldsOneInputFrameWhateverTheLength) {
  RunOptions options;
  options.progress = false;
  for (const int frames : {10, 5000}) {
    CountingSource source(StreamSynthetic(Scene(frames)));
    const TriangulatedSequence run = TriangulateSource(source, options);
    EXPECT_EQ(source.delivered(), frames);
    EXPECT_EQ(static_cast<int>(run.predictions.size()), frames);
    EXPECT_EQ(source.frames_alive_peak(), 1u) << frames << " frames";
  }
}

}  // namespace
}  // namespace rpt::cli

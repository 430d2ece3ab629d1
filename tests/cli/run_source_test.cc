// SPDX-License-Identifier: MIT
// TriangulateSource and RunSources (cli/run_sequence.h): frames pulled from a FrameSource give the
// predictions, metrics and input checks of the materialised sequence while one input frame is
// alive at a time.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "cli/run_sequence.h"
#include "datasets/detection_checks.h"
#include "datasets/frame_source.h"
#include "datasets/simulated_source.h"
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
  std::unique_ptr<FrameSource> source = OpenSyntheticSequence(Scene(150));
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
    CountingSource source(OpenSyntheticSequence(Scene(frames)));
    const TriangulatedSequence run = TriangulateSource(source, options);
    EXPECT_EQ(source.delivered(), frames);
    EXPECT_EQ(static_cast<int>(run.predictions.size()), frames);
    EXPECT_EQ(source.frames_alive_peak(), 1u) << frames << " frames";
  }
}


// Everything eval reports from a run, for comparisons.
void ExpectSameRun(const RunResult& a, const RunResult& b) {
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.gt_persons, b.gt_persons);
  EXPECT_EQ(a.output_persons, b.output_persons);
  EXPECT_EQ(a.metrics.mpjpe_mm, b.metrics.mpjpe_mm);
  EXPECT_EQ(a.metrics.pcp, b.metrics.pcp);
  EXPECT_EQ(a.metrics.recall_500, b.metrics.recall_500);
  EXPECT_EQ(a.metrics.num_predictions, b.metrics.num_predictions);
  EXPECT_EQ(a.metrics.ap, b.metrics.ap);
  ASSERT_EQ(a.sequences.size(), b.sequences.size());
  for (size_t i = 0; i < a.sequences.size(); ++i) {
    ASSERT_EQ(a.sequences[i].predictions.size(), b.sequences[i].predictions.size());
    for (size_t f = 0; f < a.sequences[i].predictions.size(); ++f) {
      EXPECT_EQ(a.sequences[i].predictions[f].data, b.sequences[i].predictions[f].data) << "frame " << f;
    }
  }
  ASSERT_EQ(a.per_sequence.size(), b.per_sequence.size());
  for (size_t i = 0; i < a.per_sequence.size(); ++i) {
    EXPECT_EQ(a.per_sequence[i].name, b.per_sequence[i].name);
    EXPECT_EQ(a.per_sequence[i].metrics.mpjpe_mm, b.per_sequence[i].metrics.mpjpe_mm);
  }
}

TEST(RunSourcesTest, SameNumbersAndChecksAsTheMaterialisedSequences) {
  RunOptions options;
  options.progress = false;
  options.threads = 2;
  SyntheticParams other = Scene(60);
  other.seed = 4;
  std::vector<Sequence> whole = MakeSyntheticDataset(Scene(90));
  whole.push_back(MakeSyntheticDataset(other)[0]);
  whole[1].name = "other";
  for (SequenceFrame& frame : whole[1].frames) frame.id = "other_" + frame.id;
  const RunResult expected = RunSequences(whole, options);
  const std::vector<SequenceCheck> expected_checks = CheckDetections(whole);

  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(std::make_unique<CountingSource>(OpenSyntheticSequence(Scene(90))));
  sources.push_back(std::make_unique<SequenceSource>(whole[1]));
  const StreamedRun streamed = RunSources(std::move(sources), options);
  ExpectSameRun(streamed.run, expected);
  ASSERT_EQ(streamed.run.per_sequence.size(), 2u) << "one row per sequence";
  EXPECT_EQ(streamed.run.per_sequence[0].frames, 90);
  EXPECT_EQ(streamed.run.per_sequence[1].name, "other");
  EXPECT_NE(streamed.run.per_sequence[0].metrics.mpjpe_mm, streamed.run.per_sequence[1].metrics.mpjpe_mm);
  ASSERT_EQ(streamed.checks.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(streamed.checks[i].frames, expected_checks[i].frames);
    EXPECT_EQ(streamed.checks[i].measured_frames, expected_checks[i].measured_frames);
    EXPECT_EQ(streamed.checks[i].shift.rel_median, expected_checks[i].shift.rel_median);
    EXPECT_EQ(streamed.checks[i].cameras[0].px_median, expected_checks[i].cameras[0].px_median);
  }
  ASSERT_EQ(streamed.sequences.size(), 2u);
  EXPECT_TRUE(streamed.sequences[0].frames[10].views.empty()) << "detections are dropped once used";
  EXPECT_EQ(streamed.sequences[0].frames[10].gt.data, whole[0].frames[10].gt.data) << "the GT stays for the metrics";
}

TEST(RunSourcesTest, HoldsOneInputFramePerSequenceWhateverTheLength) {
  RunOptions options;
  options.progress = false;
  CountingSource::Counts counts;  // RunSources frees each source once exhausted
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(std::make_unique<CountingSource>(OpenSyntheticSequence(Scene(3000)), &counts));
  const StreamedRun run = RunSources(std::move(sources), options);
  EXPECT_EQ(run.run.frames, 3000);
  EXPECT_EQ(counts.delivered, 3000);
  EXPECT_EQ(counts.frames_alive_peak, 1u) << "one input frame alive";
  EXPECT_EQ(run.checks[0].measured_frames, 200) << "bounded sample of the input checks";
}

TEST(SimulatedDetectionsSourceTest, SameDetectionsAsSimulatingTheWholeSequence) {
  SyntheticParams params = Scene(40);
  params.noise = "perfect";
  std::vector<Sequence> whole = MakeSyntheticDataset(params);
  SimulationOptions simulation;
  simulation.seed = 11;
  simulation.detector = "hard";
  SimulateDetections(simulation, &whole[0]);
  SimulatedDetectionsSource source(OpenSyntheticSequence(params), simulation);
  EXPECT_EQ(source.header().detection_joints, whole[0].detection_joints);
  const Sequence streamed = Materialize(source);
  ASSERT_EQ(streamed.frames.size(), whole[0].frames.size());
  for (size_t f = 0; f < streamed.frames.size(); ++f) {
    ASSERT_EQ(streamed.frames[f].views.size(), whole[0].frames[f].views.size());
    for (size_t c = 0; c < streamed.frames[f].views.size(); ++c) {
      EXPECT_EQ(streamed.frames[f].views[c].data, whole[0].frames[f].views[c].data) << "frame " << f;
    }
    EXPECT_EQ(streamed.frames[f].labels_2d.size(), whole[0].frames[f].labels_2d.size());
  }
}

}  // namespace
}  // namespace rpt::cli

// SPDX-License-Identifier: MIT
// Tests of the streaming reader contract (datasets/frame_source.h): the adapter for materialised
// sequences, the synthetic generator streamed frame by frame with the same numbers, and memory
// flat in the number of frames (one input frame alive at a time).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "datasets/frame_source.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/scene.h"
#include "datasets/synthetic/synthetic_sequence.h"
#include "engine/dataset_registry.h"
#include "tests/counting_source.h"

namespace rpt {
using engine::ReadDataset;
using engine::OpenDataset;
namespace {

synthetic::SceneOptions SmallScene(int frames) {
  synthetic::SceneOptions options;
  options.rig.num_cameras = 3;
  options.num_people = 3;
  options.num_frames = frames;
  options.seed = 7;
  return options;
}

void ExpectSameFrame(const SequenceFrame& a, const SequenceFrame& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.timestamp_s, b.timestamp_s) << a.id;
  EXPECT_EQ(a.gt.data, b.gt.data) << a.id;
  EXPECT_EQ(a.gt.track_ids, b.gt.track_ids) << a.id;
  ASSERT_EQ(a.views.size(), b.views.size()) << a.id;
  for (size_t c = 0; c < a.views.size(); ++c) {
    EXPECT_EQ(a.views[c].num_joints, b.views[c].num_joints) << a.id;
    EXPECT_EQ(a.views[c].data, b.views[c].data) << a.id << " camera " << c;
  }
  ASSERT_EQ(a.labels_2d.size(), b.labels_2d.size()) << a.id;
  for (size_t c = 0; c < a.labels_2d.size(); ++c) {
    ASSERT_EQ(a.labels_2d[c].size(), b.labels_2d[c].size()) << a.id;
    for (size_t p = 0; p < a.labels_2d[c].size(); ++p) {
      EXPECT_EQ(a.labels_2d[c][p].gt_person, b.labels_2d[c][p].gt_person);
      EXPECT_EQ(a.labels_2d[c][p].box_px, b.labels_2d[c][p].box_px);
      EXPECT_EQ(a.labels_2d[c][p].visibility, b.labels_2d[c][p].visibility);
    }
  }
}

TEST(SceneStreamTest, FramesMatchTheWholeScene) {
  for (const int frames : {0, 1, 2, 3, 120}) {
    const synthetic::Scene scene = synthetic::GenerateScene(SmallScene(frames));
    synthetic::SceneStream stream(SmallScene(frames));
    EXPECT_EQ(stream.num_frames(), frames);
    EXPECT_TRUE(stream.shell().gt.empty());
    ASSERT_EQ(stream.shell().cameras.size(), scene.cameras.size());
    EXPECT_EQ(stream.shell().joint_names, scene.joint_names);
    Poses3D gt;
    for (int f = 0; f < frames; ++f) {
      ASSERT_TRUE(stream.Next(&gt)) << f;
      EXPECT_EQ(gt.data, scene.gt[f].data) << "frame " << f << " of " << frames;
      EXPECT_EQ(gt.track_ids, scene.gt[f].track_ids);
    }
    EXPECT_FALSE(stream.Next(&gt));
  }
}

TEST(SyntheticSourceTest, StreamedFramesEqualTheMaterialisedSequence) {
  const synthetic::SceneOptions options = SmallScene(80);
  const synthetic::DetectorOptions detector = synthetic::DetectorProfile("realistic");
  const Sequence whole = synthetic::MakeSyntheticSequence(synthetic::GenerateScene(options), detector, 11, "s");
  synthetic::SyntheticSource source(options, detector, 11, "s");
  EXPECT_EQ(source.num_frames(), 80);
  EXPECT_EQ(source.header().name, "s");
  EXPECT_EQ(source.header().gt_joints, whole.gt_joints);
  EXPECT_EQ(source.header().fps, whole.fps);
  EXPECT_EQ(source.header().room.size_m, whole.room.size_m);
  SequenceFrame frame;  // one buffer for all frames, as a streaming consumer uses it
  size_t count = 0;
  while (source.Next(&frame)) {
    ASSERT_LT(count, whole.frames.size());
    ExpectSameFrame(frame, whole.frames[count]);
    ++count;
  }
  EXPECT_EQ(count, whole.frames.size());
}

TEST(SyntheticSourceTest, DatasetStreamsAndReadsTheSameFrames) {
  DatasetRequest request;
  request.dataset = "synthetic";
  request.params = {{"frames", "40"}, {"people", "2"}, {"cameras", "3"}, {"seed", "5"}};
  const std::vector<Sequence> read = ReadDataset(request);
  std::vector<std::unique_ptr<FrameSource>> sources = OpenDataset(request);
  ASSERT_EQ(read.size(), 1u);
  ASSERT_EQ(sources.size(), 1u);
  const Sequence streamed = Materialize(*sources[0]);
  EXPECT_EQ(streamed.name, read[0].name);
  ASSERT_EQ(streamed.frames.size(), read[0].frames.size());
  for (size_t f = 0; f < streamed.frames.size(); ++f) ExpectSameFrame(streamed.frames[f], read[0].frames[f]);
}

// The source of a format read whole: frame i converted when pulled, into a cleared buffer (nothing
// of the frame before stays), its corrections counted in the source's warnings.
TEST(IndexedFrameSourceTest, ConvertsFrameIWhenPulledIntoAClearedFrame) {
  SequenceHeader header;
  header.name = "seq";
  header.gt_joints = {"nose"};
  InputWarnings opening;
  opening.Add("calibration.json", "rotations re-orthonormalised", "max |R^T R - I|", 1e-6);
  std::vector<size_t> converted;
  IndexedFrameSource source(
      header, 3,
      [&](size_t i, SequenceFrame* frame, InputWarnings* warnings) {
        converted.push_back(i);
        frame->id = "seq_" + std::to_string(i);
        if (i == 0) {  // only the first frame has persons, views and labels
          frame->timestamp_s = 0.5;
          frame->gt.Clear(1);
          frame->gt.AddPerson(4);
          frame->views.resize(2);
          frame->labels_2d.resize(2);
        }
        warnings->Add("frames.json", "scores above 1 clamped to 1", "largest", 1.0 + 0.1 * static_cast<double>(i));
      },
      opening);
  EXPECT_EQ(source.header().name, "seq");
  EXPECT_EQ(source.num_frames(), 3);
  EXPECT_TRUE(converted.empty());  // nothing converted when opened
  SequenceFrame frame;
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_EQ(converted, (std::vector<size_t>{0}));
  EXPECT_EQ(frame.gt.num_persons(), 1);
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_EQ(frame.id, "seq_1");
  EXPECT_EQ(frame.timestamp_s, 0);
  EXPECT_EQ(frame.gt.num_persons(), 0);
  EXPECT_TRUE(frame.views.empty());
  EXPECT_TRUE(frame.labels_2d.empty());
  ASSERT_TRUE(source.Next(&frame));
  EXPECT_FALSE(source.Next(&frame));
  EXPECT_FALSE(source.Next(&frame));
  EXPECT_EQ(converted, (std::vector<size_t>{0, 1, 2}));
  ASSERT_EQ(source.warnings().items().size(), 2u);
  EXPECT_EQ(source.warnings().items()[1].count, 3);
  EXPECT_DOUBLE_EQ(source.warnings().items()[1].worst, 1.2);
}

TEST(SequenceSourceTest, DeliversFramesInOrderAndFreesThem) {
  Sequence sequence;
  sequence.name = "seq";
  sequence.fps = 10;
  for (int f = 0; f < 3; ++f) {
    SequenceFrame& frame = sequence.frames.emplace_back();
    frame.id = "seq_00000" + std::to_string(f);
    frame.gt.Clear(2);
    frame.gt.AddPerson(f);
    frame.views.resize(2);
  }
  sequence.warnings.Add("file.json", "scores clamped to [0, 1]", "max", 1.5);
  SequenceSource source(sequence);
  EXPECT_EQ(source.header().name, "seq");
  EXPECT_EQ(source.num_frames(), 3);
  EXPECT_EQ(source.warnings().items().size(), 1u);
  const Sequence round_trip = Materialize(source);
  ASSERT_EQ(round_trip.frames.size(), 3u);
  for (int f = 0; f < 3; ++f) {
    EXPECT_EQ(round_trip.frames[f].id, sequence.frames[f].id);
    EXPECT_EQ(round_trip.frames[f].gt.track_ids, sequence.frames[f].gt.track_ids);
    EXPECT_EQ(round_trip.frames[f].views.size(), 2u);
  }
  EXPECT_EQ(round_trip.warnings.items().size(), 1u);
  SequenceFrame frame;
  EXPECT_FALSE(source.Next(&frame));
}

TEST(SyntheticSourceTest, HundredThousandFramesWithOneFrameAlive) {
  SyntheticParams params;
  params.cameras = 2;
  params.people = 1;
  params.frames = 100000;
  params.noise = "perfect";
  CountingSource source(OpenSyntheticSequence(params));
  SequenceFrame frame;
  std::string last_id;
  while (source.Next(&frame)) last_id = frame.id;
  EXPECT_EQ(source.delivered(), 100000);
  EXPECT_EQ(last_id, "synthetic_099999");
  EXPECT_EQ(source.frames_alive_peak(), 1u);
}

}  // namespace
}  // namespace rpt

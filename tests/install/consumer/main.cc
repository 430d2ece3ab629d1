// An application of the installed rpt: a generated scene's frames triangulated by the core
// (rpt::Triangulator, frame by frame, as a capture app would), then the same scene run through
// the engine with metrics. Prints what the install test checks; exits 1 when it is wrong.
#include <cstdio>
#include <memory>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "engine/run.h"

int main() {
  rpt::SyntheticParams params;  // 5 cameras around an 8 x 8 m room
  params.frames = 60;
  params.people = 3;
  params.noise = "clean";

  // The core alone: cameras and joint names once, then one Process call per frame.
  std::unique_ptr<rpt::FrameSource> source = rpt::OpenSyntheticSequence(params);
  rpt::Triangulator triangulator(source->header().cameras, source->header().detection_joints, rpt::TriangulatorOptions{});
  rpt::SequenceFrame frame;
  rpt::Poses3D persons;
  rpt::FrameStats stats;
  long frames = 0, found = 0, present = 0;
  while (source->Next(&frame)) {
    triangulator.Process(frame.views, frame.timestamp_s, &persons, &stats);
    ++frames;
    found += persons.num_persons();
    present += frame.gt.num_persons();
  }
  std::printf("core: frames %ld, persons present %ld, found %ld\n", frames, present, found);

  // The engine: the same scene through the triangulator and the metrics.
  std::vector<std::unique_ptr<rpt::FrameSource>> sources;
  sources.push_back(rpt::OpenSyntheticSequence(params));
  const rpt::engine::RunResult run = rpt::engine::Run(std::move(sources), rpt::engine::RunOptions{});
  std::printf("engine: frames %ld, recall500 %.1f, mpjpe_mm %.1f\n", run.frames, run.metrics.recall_500,
              run.metrics.mpjpe_mm);
  const bool ok = frames == 60 && present == 180 && found == present && run.frames == 60 && run.metrics.recall_500 == 100.0;
  return ok ? 0 : 1;
}

// SPDX-License-Identifier: MIT
#include "cli/run_sequence.h"

#include "cli/progress.h"
#include "core/pipeline/triangulator.h"

namespace rpt::cli {

SequenceRun RunSequence(const Sequence& sequence, const RunOptions& options) {
  TriangulatorOptions tri_options = options.triangulator;
  if (!(tri_options.room_check.size_m.array() > 0).any()) {
    tri_options.room_check.center_m = sequence.room.center_m;
    tri_options.room_check.size_m = sequence.room.size_m;
  }
  Triangulator triangulator(sequence.cameras, sequence.detection_joints, tri_options);
  metrics::MetricsAccumulator accumulator(options.eval);
  SequenceRun run;
  run.timing_frames = metrics::TimingAccumulator(options.warmup_frames);
  run.output_joints = triangulator.output_joints();

  Progress progress(sequence.name, static_cast<long>(sequence.frames.size()), options.progress);
  Poses3D persons;
  FrameStats stats;
  std::vector<Poses2D> no_views(sequence.cameras.size());
  for (size_t f = 0; f < sequence.frames.size(); ++f) {
    const SequenceFrame& frame = sequence.frames[f];
    triangulator.Process(frame.views.empty() ? no_views : frame.views, frame.timestamp_s, &persons, &stats);
    run.timing_frames.Add(stats);
    accumulator.Add(frame.id, frame.gt, sequence.gt_joints, persons, run.output_joints);
    run.gt_persons += frame.gt.num_persons();
    run.output_persons += persons.num_persons();
    if (options.keep_predictions) run.predictions.push_back(persons);
    progress.Update(static_cast<long>(f + 1));
  }
  run.metrics = accumulator.Finalize();
  run.timing = run.timing_frames.Finalize();
  return run;
}

}  // namespace rpt::cli

// SPDX-License-Identifier: MIT
#include "cli/run_sequence.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "cli/progress.h"
#include "cli/thread_count.h"
#include "core/errors.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/triangulator.h"
#include "core/smooth_offline.h"

namespace rpt::cli {
namespace {

// Triangulates the frames `next_frame` hands out (nullptr after the last) of a sequence with
// header `header`, keeping only the predictions (and per frame a timestamp and a count for the
// offline smoothing): the frames themselves belong to the caller. `num_frames`: how many frames
// to reserve room for (-1 = unknown).
TriangulatedSequence Triangulate(const SequenceHeader& header, long num_frames,
                                 const std::function<const SequenceFrame*()>& next_frame, const RunOptions& options,
                                 const FrameVisitor& on_frame, std::atomic<long>* frames_done, Progress* progress) {
  TriangulatorOptions tri_options = options.triangulator;
  UseDatasetRoomIfUnset(header.room.center_m, header.room.size_m, &tri_options.room_check);
  Triangulator triangulator(header.cameras, header.detection_joints, tri_options);
  TriangulatedSequence out;
  out.output_joints = triangulator.output_joints();
  out.timing = metrics::TimingAccumulator(options.warmup_frames);
  FrameStats stats;
  const std::vector<Poses2D> no_views(header.cameras.size());
  std::vector<double> timestamps_s;
  std::vector<int> num_detected;
  if (num_frames > 0) {
    out.predictions.reserve(static_cast<size_t>(num_frames));
    timestamps_s.reserve(static_cast<size_t>(num_frames));
    num_detected.reserve(static_cast<size_t>(num_frames));
  }
  while (const SequenceFrame* frame = next_frame()) {
    Poses3D& prediction = out.predictions.emplace_back();
    triangulator.Process(frame->views.empty() ? no_views : frame->views, frame->timestamp_s, &prediction, &stats);
    out.timing.Add(stats);
    out.counts.Add(stats);
    timestamps_s.push_back(frame->timestamp_s);
    num_detected.push_back(prediction.num_persons() - stats.coasting_tracks);
    if (on_frame) on_frame(*frame, prediction);
    const long done = ++*frames_done;
    if (progress != nullptr) progress->Update(done);
  }
  // smooth.mode = offline: two-sided smoothing over the whole sequence (needs tracking).
  if (tri_options.track.enabled) {
    SmoothOffline(tri_options.smooth, tri_options.track.max_gap_s, tri_options.UnobservedScore(), timestamps_s,
                  num_detected, &out.predictions);
  }
  return out;
}

// The frames of a materialised sequence, in place.
TriangulatedSequence Triangulate(const Sequence& sequence, const RunOptions& options, std::atomic<long>* frames_done,
                                 Progress* progress) {
  size_t f = 0;
  const auto next_frame = [&]() -> const SequenceFrame* {
    return f < sequence.frames.size() ? &sequence.frames[f++] : nullptr;
  };
  return Triangulate(sequence, static_cast<long>(sequence.frames.size()), next_frame, options, {}, frames_done,
                     progress);
}

}  // namespace

metrics::EvalOptions EvalOptionsFor(const std::vector<Sequence>& sequences, const metrics::EvalOptions& options) {
  metrics::EvalOptions resolved = options;
  if (!resolved.evaluated_joints.empty() || sequences.empty()) return resolved;
  resolved.evaluated_joints = sequences.front().evaluated_joints;
  for (const Sequence& s : sequences) {
    if (s.evaluated_joints != resolved.evaluated_joints) {
      throw ConfigError("sequences '" + sequences.front().name + "' and '" + s.name +
                        "' evaluate different joints; set metrics.evaluated_joints");
    }
  }
  return resolved;
}

TriangulatedSequence TriangulateSequence(const Sequence& sequence, const RunOptions& options) {
  std::atomic<long> done{0};
  return Triangulate(sequence, options, &done, nullptr);
}

TriangulatedSequence TriangulateSource(FrameSource& source, const RunOptions& options, const FrameVisitor& on_frame) {
  SequenceFrame buffer;  // the one input frame alive: each Next overwrites it
  const auto next_frame = [&]() -> const SequenceFrame* { return source.Next(&buffer) ? &buffer : nullptr; };
  std::atomic<long> done{0};
  return Triangulate(source.header(), source.num_frames(), next_frame, options, on_frame, &done, nullptr);
}

RunResult RunSequences(const std::vector<Sequence>& sequences, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;
  result.sequences.resize(sequences.size());
  long total = 0;
  for (const Sequence& s : sequences) total += static_cast<long>(s.frames.size());
  Progress progress(sequences.size() == 1 ? sequences[0].name : "triangulating", total, options.progress);
  std::atomic<long> frames_done{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const int count = static_cast<int>(sequences.size());
#ifdef _OPENMP
  const int threads = ClampThreads(options.threads, count);
  result.threads = threads;
#pragma omp parallel for schedule(dynamic) num_threads(threads)
#endif
  for (int i = 0; i < count; ++i) {
    try {
#ifdef _OPENMP
      Progress* shown = omp_get_thread_num() == 0 ? &progress : nullptr;
#else
      Progress* shown = &progress;
#endif
      result.sequences[i] = Triangulate(sequences[i], options, &frames_done, shown);
    } catch (...) {
      // Exceptions must not cross the OpenMP region: keep the first, rethrow after.
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);

  metrics::MetricsAccumulator accumulator(EvalOptionsFor(sequences, options.eval));
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;
  for (int i = 0; i < count; ++i) {
    const Sequence& sequence = sequences[i];
    const TriangulatedSequence& run = result.sequences[i];
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      accumulator.Add(sequence.frames[f].id, sequence.frames[f].gt, sequence.gt_joints, run.predictions[f],
                      run.output_joints);
      result.gt_persons += sequence.frames[f].gt.num_persons();
      result.output_persons += run.predictions[f].num_persons();
    }
    result.frames += static_cast<long>(sequence.frames.size());
    timing.Merge(run.timing);
    counts.Merge(run.counts);
  }
  result.metrics = accumulator.Finalize();
  result.timing = timing.Finalize();
  result.counts = counts.Finalize();
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rpt::cli

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
    try {
      triangulator.Process(frame->views.empty() ? no_views : frame->views, frame->timestamp_s, &prediction, &stats);
    } catch (const InputError& e) {  // e.g. more persons in a view than triangulate.max_persons_per_view
      throw InputError(header.name + ": frame '" + frame->id + "': " + e.what());
    }
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

// Runs body(i, progress) for i in 0..count-1 on up to `threads` threads (0 = OpenMP default),
// `progress` being non-null on one thread only; the first exception is rethrown once all
// finished (exceptions must not cross the OpenMP region). Returns the threads used.
int ForEachSequence(int count, int threads, Progress* progress, const std::function<void(int, Progress*)>& body) {
  std::exception_ptr error;
  std::mutex error_mutex;
  int used = 1;
#ifdef _OPENMP
  const int team = ClampThreads(threads, count);  // at most the cores and the work
  used = team;
#pragma omp parallel for schedule(dynamic) num_threads(team)
#endif
  for (int i = 0; i < count; ++i) {
    try {
#ifdef _OPENMP
      body(i, omp_get_thread_num() == 0 ? progress : nullptr);
#else
      body(i, progress);
#endif
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  return used;
}

// The metrics, times and counts of triangulated sequences (`result->sequences`, one per entry of
// `sequences`, whose frames need only id and GT), accumulated in sequence order so the numbers do
// not depend on the thread count.
void Evaluate(const std::vector<Sequence>& sequences, const RunOptions& options, RunResult* result) {
  const metrics::EvalOptions eval_options = EvalOptionsFor(sequences, options.eval);
  metrics::MetricsAccumulator accumulator(eval_options);
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;
  const bool per_sequence = sequences.size() > 1;
  for (size_t i = 0; i < sequences.size(); ++i) {
    const Sequence& sequence = sequences[i];
    const TriangulatedSequence& run = result->sequences[i];
    metrics::MetricsAccumulator own(eval_options);
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      accumulator.Add(sequence.frames[f].id, sequence.frames[f].gt, sequence.gt_joints, run.predictions[f],
                      run.output_joints);
      if (per_sequence) {
        own.Add(sequence.frames[f].id, sequence.frames[f].gt, sequence.gt_joints, run.predictions[f],
                run.output_joints);
      }
      result->gt_persons += sequence.frames[f].gt.num_persons();
      result->output_persons += run.predictions[f].num_persons();
    }
    result->frames += static_cast<long>(sequence.frames.size());
    if (per_sequence) {
      result->per_sequence.push_back(
          {sequence.name, own.Finalize(), run.timing.Finalize(), static_cast<long>(sequence.frames.size())});
    }
    timing.Merge(run.timing);
    counts.Merge(run.counts);
  }
  result->metrics = accumulator.Finalize();
  result->timing = timing.Finalize();
  result->counts = counts.Finalize();
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
  result.threads = ForEachSequence(static_cast<int>(sequences.size()), options.threads, &progress,
                                   [&](int i, Progress* shown) {
                                     result.sequences[i] = Triangulate(sequences[i], options, &frames_done, shown);
                                   });
  Evaluate(sequences, options, &result);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

StreamedRun RunSources(std::vector<std::unique_ptr<FrameSource>> sources, const RunOptions& options,
                       const DetectionCheckOptions& check_options) {
  const auto start = std::chrono::steady_clock::now();
  const int count = static_cast<int>(sources.size());
  StreamedRun out;
  out.run.sequences.resize(count);
  out.sequences.resize(count);
  out.checks.resize(count);
  long total = 0;
  for (const auto& source : sources) total = source->num_frames() < 0 || total < 0 ? -1 : total + source->num_frames();
  Progress progress(count == 1 ? sources[0]->header().name : "triangulating", count == 0 ? 0 : total,
                    options.progress);
  std::atomic<long> frames_done{0};
  out.run.threads = ForEachSequence(count, options.threads, &progress, [&](int i, Progress* shown) {
    FrameSource& source = *sources[i];
    const SequenceHeader& header = source.header();
    ValidateSequenceHeader(header, header.name);
    Sequence& kept = out.sequences[i];
    static_cast<SequenceHeader&>(kept) = header;
    if (source.num_frames() > 0) kept.frames.reserve(static_cast<size_t>(source.num_frames()));
    DetectionChecker checker(header, source.num_frames(), check_options);
    SequenceFrame buffer;  // the one input frame alive: each Next overwrites it
    const auto next_frame = [&]() -> const SequenceFrame* {
      if (!source.Next(&buffer)) return nullptr;
      ValidateFrame(header, buffer, header.name);
      checker.Add(buffer);
      SequenceFrame& frame = kept.frames.emplace_back();  // id, time and GT: what the metrics need
      frame.id = buffer.id;
      frame.timestamp_s = buffer.timestamp_s;
      frame.gt = buffer.gt;
      return &buffer;
    };
    out.run.sequences[i] = Triangulate(header, source.num_frames(), next_frame, options, {}, &frames_done, shown);
    out.checks[i] = checker.Finish();
    kept.warnings = source.warnings();
    sources[i].reset();  // whatever the reader still holds
  });
  for (const Sequence& s : out.sequences) out.warnings.Merge(s.warnings);
  Evaluate(out.sequences, options, &out.run);
  out.run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rpt::cli

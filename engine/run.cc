// SPDX-License-Identifier: MIT
#include "engine/run.h"

#include <algorithm>
#include <cmath>
#include <atomic>
#include <chrono>
#include <exception>
#include <new>

#include "core/errors.h"
#include "core/joint_offsets.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/triangulator.h"
#include "core/pipeline/offline_smoother.h"
#include "engine/checked_source.h"
#include "engine/frame_time_check.h"
#include "engine/frame_pipeline.h"
#include "engine/input.h"
#include "engine/joint_adapter.h"
#include "engine/parallel_for.h"
#include "engine/thread_count.h"
#include "metrics/accumulator.h"
#include "metrics/timing.h"
#include "core/option_codec.h"
#include "core/printable_text.h"

namespace rpt::engine {
namespace {

// One sequence's running totals.
struct SequenceRun {
  SequenceResult result;
  std::optional<metrics::MetricsAccumulator> metrics;
  metrics::IdentityAccumulator identity;  // with the metrics
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;
  std::optional<LossAccumulator> losses;
  long gt_persons = 0, output_persons = 0, frames_with_gt = 0, frames_with_gt_without_prediction = 0;
  std::optional<FrameTimeCheck> times;  // made with the sequence's track.max_gap_s
};

// The run's joint adapter (RunOptions::adapter) on one sequence: each frame's persons copied and
// moved before they are measured and written.
class FrameAdapter {
 public:
  FrameAdapter(const JointAdapter* adapter, const JointNames& output_joints) : adapter_(adapter) {
    if (adapter_ == nullptr) return;
    CheckAdapterJoints(*adapter_, output_joints);
    frame_joints_ = BodyFrameJoints::Find(output_joints);
  }
  // `persons` with the adapter applied (itself without an adapter). Throws ConfigError when the
  // adapter was fitted on this frame. Allocates nothing once warm.
  const Poses3D& Apply(const SequenceFrame& frame, const Poses3D& persons, SequenceResult* result) {
    if (adapter_ == nullptr) return persons;
    if (adapter_->IsFitFrame(frame.id)) {
      throw ConfigError((adapter_->path.empty() ? std::string("joint adapter") : adapter_->path) + ": frame '" +
                        frame.id + "' is one it was fitted on (" + FitDescription(adapter_->fit) +
                        "); an adapter is never evaluated on its own fitting frames: select other frames");
    }
    adapted_ = persons;  // keeps the buffers' capacity
    const int moved = ApplyJointOffsets(adapter_->offset_m, frame_joints_, &adapted_);
    result->adapted_persons += moved;
    result->unadapted_persons += adapted_.num_persons() - moved;
    return adapted_;
  }

 private:
  const JointAdapter* adapter_;
  BodyFrameJoints frame_joints_;
  Poses3D adapted_;
};

// The frame handed to the sink, then what is measured of it.
void Emit(int index, const SequenceFrame& frame, const Poses3D& triangulated, const FrameStats& stats,
          const FrameTrace& trace, const SequenceHeader& header, const JointNames& output_joints, SequenceRun* run,
          std::optional<DetectionChecker>* checker, std::optional<CameraAgreementCheck>* agreement,
          std::optional<UprightCheck>* upright, std::optional<CameraSyncCheck>* sync,
          std::optional<FrozenViewCheck>* frozen, FrameAdapter* adapter, FrameSink* sink) {
  const Poses3D& persons = adapter->Apply(frame, triangulated, &run->result);
  // Out first (a live line waits for nothing else), then measured: the checks below (the
  // camera-sync comparison of a stream runs on every frame) would add to a live line's latency.
  if (sink != nullptr) sink->Frame(FrameOutput{index, &frame, &persons, &stats});
  run->timing.Add(stats, frame.paf_grouping_us);
  run->counts.Add(stats);
  if (*agreement) (*agreement)->Add(run->result.frames, frame, persons);
  if (*upright) (*upright)->Add(persons);
  if (*sync) (*sync)->Add(frame);
  if (*frozen) (*frozen)->Add(frame);
  ++run->result.frames;
  run->gt_persons += frame.gt.num_persons();
  run->output_persons += persons.num_persons();
  if (frame.gt.num_persons() > 0) {
    ++run->frames_with_gt;
    if (persons.num_persons() == 0) ++run->frames_with_gt_without_prediction;
  }
  if (run->metrics) {
    run->metrics->Add(frame.id, frame.gt, header.gt_joints, persons, output_joints);
    if (header.gt_ids_across_frames) run->identity.Add(run->metrics->LastFrame(), frame.gt, persons);
  }
  if (run->losses) run->losses->Add(frame, trace, persons, run->metrics->LastFrame());
  if (*checker) (*checker)->Add(frame);
}

// One frame in the pipeline's ring (engine/frame_pipeline.h): the input frame, what the
// triangulator made of it and its trace (for the loss table). Reused frame after frame.
struct FrameSlot {
  SequenceFrame frame;
  Poses3D persons;
  FrameStats stats;
  FrameTrace trace;
};

// Frames in flight when a sequence runs on several threads: enough for the stages to run ahead of
// each other by a few frames, so that one slow frame does not stall the others, and for every
// thread to have a frame to complete (memory: this many input frames, however long the sequence).
constexpr long kPipelineFrames = 16;
// Threads that can work on one sequence at once: one per in-order stage (read, process, emit) and
// the rest completing frames (the per-frame part of reading), at most half the ring's frames so
// that each has frames to work on.
constexpr int kPipelineThreads = static_cast<int>(kPipelineFrames / 2);

// Triangulates the frames of `source` (sequence `index`) as they are pulled, on `threads` threads:
// reading (the source's Pull), completing (its Complete, on several frames at once: simulation,
// validation), triangulating, and measuring + writing (Emit) are the pipeline's four stages
// (engine/frame_pipeline.h). One thread holds one input frame at a time (a window's worth with
// offline smoothing, which looks 3 x smooth.offline_sigma_s ahead); more threads hold
// kPipelineFrames (or that window).
// `detections_file`: where the frames' detections come from (Input::detections_file), named in
// errors about a frame's detections; may be empty.
void RunSequence(int index, FrameSource& source, const RunOptions& options, const metrics::EvalOptions* eval,
                 FrameSink* sink, int threads, std::atomic<long>* frames_done, bool report_progress,
                 const std::string& detections_file, SequenceRun* run) {
  const SequenceHeader& header = source.header();
  const TriangulatorOptions tri_options = TriangulatorOptionsFor(options.triangulator, header);
  Triangulator triangulator(header.cameras, header.detection_joints, tri_options);
  const JointNames& output_joints = triangulator.output_joints();
  run->result.name = header.name;
  run->result.cameras = static_cast<int>(header.cameras.size());
  run->result.output_joints = output_joints;
  run->timing = metrics::TimingAccumulator(options.warmup_frames);
  run->times.emplace(tri_options.track.max_gap_s);
  if (eval != nullptr) run->metrics.emplace(*eval);
  if (options.loss_table) {
    if (eval == nullptr) throw ConfigError("the loss table needs the metrics (ground truth)");
    run->losses.emplace(header, output_joints, *eval);
  }
  std::optional<DetectionChecker> checker;
  if (options.checks) checker.emplace(header, source.num_frames(), tri_options.track.max_gap_s, *options.checks);
  std::optional<CameraAgreementCheck> agreement;
  if (options.camera_agreement) agreement.emplace(header, output_joints, source.num_frames());
  std::optional<UprightCheck> upright;
  if (options.upright_check) upright.emplace(output_joints);
  std::optional<CameraSyncCheck> sync;
  if (options.camera_sync) sync.emplace(header, source.num_frames(), tri_options.track.max_gap_s);
  std::optional<FrozenViewCheck> frozen;  // with the camera sync: both ask whether a camera's frames keep time
  if (options.camera_sync) frozen.emplace(header.cameras.size());
  FrameAdapter adapter(options.adapter.get(), output_joints);
  if (sink != nullptr) sink->BeginSequence(index, header, output_joints);

  const std::vector<Poses2D> no_views(header.cameras.size());
  // smooth.mode = offline: frames come back from the smoother once their window is complete; the
  // input frames wait in their slots meanwhile (the ring grows to a window's worth).
  const bool offline = tri_options.track.enabled && tri_options.smooth.mode == SmoothMode::kOffline;
  OfflineSmoother smoother(tri_options.smooth, tri_options.track.max_gap_s, tri_options.UnobservedScore());
  const long capacity = threads > 1 ? kPipelineFrames : 1;
  std::vector<FrameSlot> slots(static_cast<size_t>(capacity));
  const auto slot = [&slots](long frame) -> FrameSlot& { return slots[static_cast<size_t>(frame) % slots.size()]; };
  long popped = 0;  // frames the smoother handed back (offline)
  const auto pop_ready = [&] {
    long ready = 0;
    while (true) {
      FrameSlot& s = slot(popped);
      if (!smoother.Pop(&s.persons, &s.stats)) break;
      ++popped;
      ++ready;
    }
    return ready;
  };

  FrameStages stages;
  stages.read = [&](long frame) { return source.Pull(&slot(frame).frame); };
  stages.complete = [&](long frame) { source.Complete(frame, &slot(frame).frame); };
  stages.process = [&](long frame) -> long {
    FrameSlot& s = slot(frame);
    run->times->Add(s.frame.timestamp_s);
    if (options.early_warning) {
      InputWarnings early;  // empty: allocates nothing unless a warning is given
      run->times->AddEarlyWarnings(header.name, header.fps, &early);
      for (const std::string& line : InputWarningLines(early)) options.early_warning(line);
    }
    try {
      triangulator.Process(s.frame.views.empty() ? no_views : s.frame.views, s.frame.timestamp_s, &s.persons,
                           &s.stats, run->losses ? &s.trace : nullptr);
    } catch (const InputError& e) {  // e.g. more persons in a view than triangulate.max_persons_per_view
      throw InputError((detections_file.empty() ? "" : detections_file + ": ") + header.name + ": frame " +
                       QuoteName(s.frame.id) + ": " + e.what());
    } catch (const std::bad_alloc&) {
      throw InputError(header.name + ": frame " + QuoteName(s.frame.id) +
                       ": out of memory triangulating the frame (lower triangulate.max_pairs_per_frame or "
                       "triangulate.max_persons_per_view to refuse such frames early)");
    }
    if (!offline) return 1;
    smoother.Push(s.frame.timestamp_s, s.persons, s.persons.num_persons() - s.stats.coasting_tracks, s.stats);
    return pop_ready();
  };
  stages.flush = [&]() -> long {
    if (!offline) return 0;
    smoother.Flush();
    return pop_ready();
  };
  stages.emit = [&](long frame) {
    FrameSlot& s = slot(frame);
    Emit(index, s.frame, s.persons, s.stats, s.trace, header, output_joints, run, &checker, &agreement, &upright, &sync,
         &frozen, &adapter, sink);
    const long done = ++*frames_done;
    if (report_progress && options.progress) options.progress(done);
  };
  stages.grow = [&](long old_capacity, long new_capacity, long first, long end) {
    std::vector<FrameSlot> grown(static_cast<size_t>(new_capacity));
    for (long f = first; f < end; ++f) grown[f % new_capacity] = std::move(slots[f % old_capacity]);
    slots = std::move(grown);
  };
  RunFramePipeline(stages, threads, capacity);

  if (checker) run->result.check = checker->Finish();
  if (agreement) run->result.camera_agreement = agreement->cameras();
  if (upright) run->result.upright = upright->count();
  if (sync) run->result.camera_sync = CameraSyncWarnings(header.name, header.cameras, sync->pairs(), sync->frame_step_s());
  if (frozen) {
    const double fps = header.fps > 0 ? header.fps : (sync && sync->frame_step_s() > 0 ? 1.0 / sync->frame_step_s() : 0.0);
    for (std::string& line : FrozenViewWarnings(header.name, header.cameras, frozen->longest(), fps)) {
      run->result.camera_sync.push_back(std::move(line));
    }
  }
  run->result.timing = run->timing.Finalize();
  if (run->metrics) {
    run->result.metrics = run->metrics->Finalize();
    run->result.identity = run->identity.counts();
  }
  if (run->losses) run->result.losses = run->losses->table();
  if (sink != nullptr) sink->EndSequence(index);
}

// A loaded sequence as a source, without taking it: each frame is copied out when pulled.
class SequenceView final : public FrameSource {
 public:
  explicit SequenceView(const Sequence& sequence) : sequence_(sequence) {}
  const SequenceHeader& header() const override { return sequence_; }
  long num_frames() const override { return static_cast<long>(sequence_.frames.size()); }
  bool Pull(SequenceFrame* frame) override {
    if (next_ >= sequence_.frames.size()) return false;
    *frame = sequence_.frames[next_++];
    return true;
  }
  const InputWarnings& warnings() const override { return sequence_.warnings; }

 private:
  const Sequence& sequence_;
  size_t next_ = 0;
};

}  // namespace

TriangulatorOptions TriangulatorOptionsFor(const TriangulatorOptions& options, const SequenceHeader& header) {
  TriangulatorOptions resolved = options;
  UseDatasetRoomIfUnset(header.room.center_m, header.room.size_m, &resolved.room_check);
  return resolved;
}

metrics::EvalOptions EvalOptionsFor(const metrics::EvalOptions& options,
                                    std::span<const SequenceHeader* const> headers) {
  metrics::EvalOptions resolved = options;
  if (!resolved.evaluated_joints.empty() || headers.empty()) return resolved;
  resolved.evaluated_joints = headers.front()->evaluated_joints;
  for (const SequenceHeader* h : headers) {
    if (h->evaluated_joints != resolved.evaluated_joints) {
      throw ConfigError("sequences " + QuoteName(headers.front()->name) + " and " + QuoteName(h->name) +
                        " evaluate different joints; set metrics.evaluated_joints");
    }
  }
  return resolved;
}

RunResult Run(Input& input, const RunOptions& options, FrameSink* sink) {
  const auto start = std::chrono::steady_clock::now();
  const int count = input.size();
  std::vector<const SequenceHeader*> headers;
  for (int i = 0; i < count; ++i) {
    headers.push_back(&input.header(i));
    if (headers.back()->cameras.size() < 2) {
      const std::string& origin = input.cameras_origin();
      throw InputError((origin.empty() ? "" : PrintableText(origin, LineBreaks::kEscape) + ": ") + "sequence " +
                       QuoteName(headers.back()->name) + ": " + TooFewCamerasMessage(headers.back()->cameras));
    }
  }
  std::optional<metrics::EvalOptions> eval;
  if (options.eval) eval = EvalOptionsFor(*options.eval, headers);
  // One accumulator for the whole run, fed in sequence order once the sequences are done (its
  // records do not depend on the thread count); each sequence also has its own.
  std::vector<SequenceRun> runs(static_cast<size_t>(count));
  std::atomic<long> frames_done{0};
  RunResult result;
  if (count == 1) {
    // One sequence: its stages (read, complete, triangulate, measure + write) on several threads.
    result.threads = ClampThreads(options.threads, kPipelineThreads);
    RunSequence(0, input.source(0), options, eval ? &*eval : nullptr, sink, result.threads, &frames_done, true,
                input.detections_file(), &runs[0]);
    input.Finished(0);
  } else {
    // Several: one thread per sequence, its stages taking turns.
    result.threads = ParallelFor(count, options.threads, [&](int i, bool report_progress) {
      RunSequence(i, input.source(i), options, eval ? &*eval : nullptr, sink, 1, &frames_done, report_progress,
                  input.detections_file(), &runs[i]);
      input.Finished(i);
    });
  }
  result.warnings = input.Warnings();
  // Times going back end tracks; a time in milliseconds where seconds are expected ends every track.
  for (int i = 0; i < count; ++i) {
    if (runs[i].times) runs[i].times->AddWarnings(input.header(i).name, input.header(i).fps, &result.warnings);
  }
  input.CheckStrict();
  if (options.require_frames) {
    long frames = 0;
    for (const SequenceRun& run : runs) frames += run.result.frames;
    if (frames == 0) {
      const std::string& origin = input.frames_origin();
      const bool detection_frames = !input.detections_file().empty() && origin == input.detections_file();
      throw InputError((origin.empty() ? std::string("the input") : PrintableText(origin, LineBreaks::kEscape)) +
                       ": no frame to triangulate" +
                       (detection_frames ? std::string(" (the detections file has no frames)")
                                         : " in " + std::to_string(count) + (count == 1 ? " sequence" : " sequences") +
                                               " (a selection such as --param frames=, every= or days=, or a reader "
                                               "dropping frames without ground truth, such as panoptic's skip_empty, "
                                               "can leave none)"));
    }
  }

  result.evaluated = eval.has_value();
  std::optional<metrics::MetricsAccumulator> all;
  if (eval) all.emplace(*eval);
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;
  if (options.loss_table) result.losses.emplace();
  for (SequenceRun& run : runs) {
    if (result.losses && run.result.losses) result.losses->Merge(*run.result.losses);
    if (all) all->Merge(*run.metrics);
    result.identity.Merge(run.result.identity);
    timing.Merge(run.timing);
    counts.Merge(run.counts);
    result.frames += run.result.frames;
    result.gt_persons += run.gt_persons;
    result.output_persons += run.output_persons;
    result.adapted_persons += run.result.adapted_persons;
    result.unadapted_persons += run.result.unadapted_persons;
    result.frames_with_gt += run.frames_with_gt;
    result.frames_with_gt_without_prediction += run.frames_with_gt_without_prediction;
    result.sequences.push_back(std::move(run.result));
  }
  if (all) result.metrics = all->Finalize();
  result.timing = timing.Finalize();
  result.counts = counts.Finalize();
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

RunResult Run(std::vector<std::unique_ptr<FrameSource>> sources, const RunOptions& options, FrameSink* sink) {
  for (auto& source : sources) source = std::make_unique<CheckedSource>(std::move(source));
  Input input(std::move(sources), {}, /*strict=*/false);
  return Run(input, options, sink);
}

RunResult Run(std::span<const Sequence> sequences, const RunOptions& options, FrameSink* sink) {
  std::vector<std::unique_ptr<FrameSource>> views;
  for (const Sequence& sequence : sequences) views.push_back(std::make_unique<SequenceView>(sequence));
  Input input(std::move(views), {}, /*strict=*/false);
  return Run(input, options, sink);
}

}  // namespace rpt::engine

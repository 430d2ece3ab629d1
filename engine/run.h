// SPDX-License-Identifier: MIT
// The run loop every entry point shares (rpt eval, triangulate, demo, check, sweep, render,
// report, the live input and the Python module): frame sources in, per-frame results out.
//
//   Input input = OpenInput(spec, needs, &warnings);        // engine/input.h
//   PredictionsWriter writer(...);                          // any FrameSink (engine/frame_sink.h)
//   RunResult run = Run(input, options, &writer);
//
// Each source (one sequence) is pulled frame by frame; each frame is triangulated, measured
// (metrics and input checks, when asked) and handed to the sink, then dropped: memory does not
// grow with the number of frames beyond what the metrics keep per person (metrics/accumulator.h).
// Independent sequences run in parallel (OpenMP, one Triangulator per sequence); the totals are
// merged in sequence order, so no number depends on the thread count. A single sequence runs as a
// pipeline of four stages on up to eight threads (engine/frame_pipeline.h): reading the next
// frames (the source's Pull: parsing, the synthetic walk, in order), completing them (its Complete:
// simulated detections, validation; several frames at once), triangulating (in order: its state
// carries from frame to frame) and measuring + writing (metrics, checks, the sink, in order), with
// up to 16 frames in flight; the in-order stages see the frames in the order one thread would and
// each frame is completed from its own data, so the results are the same.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/pipeline/options.h"
#include "datasets/frame_source.h"
#include "datasets/input_warnings.h"
#include "datasets/sequence.h"
#include "engine/camera_agreement.h"
#include "engine/camera_sync_check.h"
#include "engine/frozen_view_check.h"
#include "engine/upright_check.h"
#include "engine/detection_checks.h"
#include "engine/frame_sink.h"
#include "engine/loss_table.h"
#include "metrics/eval_options.h"
#include "metrics/metrics_result.h"
#include "metrics/identity_counts.h"
#include "metrics/step_counts.h"
#include "metrics/timing.h"

namespace rpt::engine {

class Input;
struct JointAdapter;

struct RunOptions {
  // The sequence's room is used unless room_check.size_m is set (TriangulatorOptionsFor).
  TriangulatorOptions triangulator;
  // Metrics against the frames' ground truth; empty: none (input without GT).
  std::optional<metrics::EvalOptions> eval = metrics::EvalOptions{};
  // Input checks (detections against GT and cameras, engine/detection_checks.h); empty: none.
  std::optional<DetectionCheckOptions> checks;
  // Where the GT persons are lost (engine/loss_table.h); needs `eval`. Recording what the
  // association did costs time, which counts in the frames' total (not in any step's).
  bool loss_table = false;
  // Compare each frame's persons with every camera's detections (engine/camera_agreement.h): the
  // check of the calibration a run without ground truth has.
  bool camera_agreement = false;
  // Compare each camera's detections with the others' a few frames apart (engine/camera_sync_check.h):
  // a camera whose clock or frame numbering is off the others'; and find a camera whose detections
  // stop changing while the others' change (engine/frozen_view_check.h).
  bool camera_sync = false;
  // Count the persons standing on their heads (engine/upright_check.h): flipped pixel rows or a
  // calibration whose world z points down, which the camera agreement cannot see.
  bool upright_check = false;
  // A joint-definition adapter (engine/joint_adapter.h): applied to every frame's persons after
  // triangulation, before they are measured and written; null = none. The run refuses (ConfigError)
  // predictions of other joints and a frame the adapter was fitted on. Its time is outside the
  // steps' (like the metrics').
  std::shared_ptr<const JointAdapter> adapter;
  int warmup_frames = 0;  // frames per sequence excluded from timing
  // An input that gives no frame at all is an InputError naming it (eval, triangulate, check and
  // sweep: a run of 0 frames measured nothing, and exit 0 would pass a script's check); off for a
  // live stream that ended before its first frame and for the library.
  bool require_frames = false;
  // Threads: sequences in parallel, or with one sequence its pipeline's stages (at most 8);
  // 0 = automatic (at most the cores, the sequences or 8). 1: one input frame at a time.
  int threads = 0;
  // Called with the frames done so far (all sequences), by one thread at a time; may be empty.
  std::function<void(long frames_done)> progress;
  // Called with a warning line as soon as the run sees it, for a run whose end may be hours away
  // (a live stream): frame times not after the last, times in another unit than seconds
  // (FrameTimeCheck::AddEarlyWarnings); each kind once per sequence. The run's warnings still
  // count them all at the end. Called by one thread per sequence (sequences running in parallel
  // may call it at the same time). May be empty.
  std::function<void(const std::string& line)> early_warning;
};

// One sequence of a run.
struct SequenceResult {
  std::string name;
  long frames = 0;
  int cameras = 0;
  JointNames output_joints;
  metrics::MetricsResult metrics;         // when RunOptions::eval is set
  metrics::IdentityCounts identity;       // the same: track ids against the GT's ids
  metrics::TimingSummary timing;
  std::optional<SequenceCheck> check;     // when RunOptions::checks is set
  std::optional<LossTable> losses;        // when RunOptions::loss_table is set
  std::vector<CameraAgreement> camera_agreement;  // when RunOptions::camera_agreement is set
  UprightCount upright;                   // when RunOptions::upright_check is set
  std::vector<std::string> camera_sync;   // warning lines (sync, frozen views), when RunOptions::camera_sync is set
  long adapted_persons = 0;               // persons the adapter moved (RunOptions::adapter)
  long unadapted_persons = 0;             // persons it left as they were: no body frame
};

struct RunResult {
  bool evaluated = false;           // metrics were computed (RunOptions::eval)
  metrics::MetricsResult metrics;   // over all sequences
  metrics::IdentityCounts identity; // summed over the sequences (when evaluated)
  metrics::TimingSummary timing;    // over all frames of all sequences
  metrics::StepCountSummary counts; // items per step per frame, over all frames
  std::optional<LossTable> losses;  // over all sequences, when RunOptions::loss_table is set
  long frames = 0;
  double wall_seconds = 0;          // the whole run, steady clock
  int threads = 1;                  // threads used (for the sequences, or one sequence's stages)
  long gt_persons = 0;              // GT person-frames
  long output_persons = 0;          // triangulated person-frames
  long adapted_persons = 0;         // of those: moved by RunOptions::adapter
  long unadapted_persons = 0;       // of those: left as they were by it (no body frame)
  long frames_with_gt = 0;          // frames with at least one GT person
  long frames_with_gt_without_prediction = 0;  // of those: nobody triangulated
  std::vector<SequenceResult> sequences;       // in input order
  InputWarnings warnings;           // the input's corrections and unused input (complete)
};

// The triangulator options for one sequence: its room unless room_check.size_m is set (the one
// place where the dataset's room becomes the room check's box).
TriangulatorOptions TriangulatorOptionsFor(const TriangulatorOptions& options, const SequenceHeader& header);

// The evaluation options for the sequences of `headers`: metrics.evaluated_joints when set, else
// the joints their dataset evaluates (SequenceHeader::evaluated_joints; empty = the paper's 13).
// Throws ConfigError when the sequences disagree.
metrics::EvalOptions EvalOptionsFor(const metrics::EvalOptions& options,
                                    std::span<const SequenceHeader* const> headers);

// Runs every source of `input` (engine/input.h) and returns the totals; `sink` (may be null)
// gets every frame. Throws ConfigError / InputError (naming the sequence and the frame); with
// --strict, unused input throws once the sources are exhausted.
RunResult Run(Input& input, const RunOptions& options, FrameSink* sink = nullptr);

// The same on sources that are not an opened input (generated scenes, in-memory sequences):
// `sources` are validated frame by frame like an opened input's.
RunResult Run(std::vector<std::unique_ptr<FrameSource>> sources, const RunOptions& options, FrameSink* sink = nullptr);

// The same on sequences in memory that were loaded (and so validated) by LoadInput: a sweep runs
// one loaded input under many configurations. Each frame is copied out as it is pulled.
RunResult Run(std::span<const Sequence> sequences, const RunOptions& options, FrameSink* sink = nullptr);

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// What `rpt eval` says when something looks wrong: the detection/GT checks of the input
// (engine/detection_checks.h) plus checks of the results (no predictions, low recall, many
// frames without a prediction), printed as "warning: ..." lines on stderr and recorded in
// summary.json. docs/diagnostics.md lists every warning, its trigger and what to do.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "engine/run.h"
#include "engine/detection_checks.h"
#include "datasets/sequence.h"

namespace rpt::engine {

// Result warning triggers.
inline constexpr double kMinRecall500 = 50.0;                 // %, below: "low_recall"
inline constexpr double kMinFilledShareWarned = 0.9;          // of a whole-body group: "wholebody_group_filled"
inline constexpr double kMaxShareFramesWithoutPrediction = 0.3;  // of frames with GT persons

struct EvalDiagnostics {
  std::vector<SequenceCheck> checks;   // one per sequence
  std::vector<CheckWarning> warnings;  // input warnings first (sequence order), then result warnings
};

// Warnings about the results of `run`.
std::vector<CheckWarning> ResultWarnings(const RunResult& run);

// More than this share of the output joints moved by speed clipping: fast motion (a sprint's
// ankles pass 19 m/s) clipped to clip_speed.max_speed_m_s lags behind. Generated walking scenes
// clip 0.1-0.5 %, Shelf-4DA 0.1 %, MVOR none; walkers against a 0.5 m/s limit 88 % (`rpt eval
// --dataset synthetic --set clip_speed.max_speed_m_s=0.5`: MPJPE 233 mm instead of 42).
inline constexpr double kMaxClippedJointShare = 0.05;
// The warning ("speed_clipped") when more than kMaxClippedJointShare of the joints of the persons
// output were speed-clipped, naming the option and its value; empty otherwise.
std::string SpeedClipWarning(const RunResult& run, const ClipSpeedOptions& clip);

// All warnings of an evaluation: those of the input checks (SequenceResult::check, when the run
// made them) and those of the results.
EvalDiagnostics Diagnose(const RunResult& run);

// {"warnings": [{"code", "message"}, ...], "data_checks": [per sequence]} for summary.json.
nlohmann::ordered_json DiagnosticsJson(const EvalDiagnostics& diagnostics);
// One sequence's measurements (also `rpt inspect --json`'s per-camera and frame-shift fields).
nlohmann::ordered_json CameraCheckJson(const CameraCheck& camera);
nlohmann::ordered_json ShiftCheckJson(const ShiftCheck& shift);

// "frame shift (...): not tested, <reason>" or the measured medians.
std::string ShiftLine(const ShiftCheck& shift);
// One or two lines summarising the input checks (for the terminal).
void PrintCheckSummary(std::ostream& out, const EvalDiagnostics& diagnostics);
// "warning: <message>" per warning.
void PrintWarnings(std::ostream& err, const EvalDiagnostics& diagnostics);

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// rpt.metrics.evaluate: predictions against the ground truth, folded exactly as engine::Run folds a
// run (engine/run.cc: one accumulator per sequence, merged in sequence order; the input checks of
// engine/detection_checks.h), so the summary is `rpt eval --json`'s: SummaryJson plus the warnings
// and data checks of engine/diagnostics.h.
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/readers/generic_common.h"
#include "engine/detection_checks.h"
#include "engine/diagnostics.h"
#include "engine/outputs/results_writer.h"
#include "engine/run.h"
#include "metrics/accumulator.h"
#include "metrics/step_counts.h"
#include "metrics/timing.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/option_values.h"

namespace rpt::python {
namespace {

// A sequence made of ground-truth arrays: frames "000000", ... without times or detections.
std::shared_ptr<Sequence> SequenceOfArrays(const py::sequence& gt, const JointNames& gt_joints) {
  auto sequence = std::make_shared<Sequence>();
  sequence->name = "python";
  sequence->gt_joints = gt_joints;
  for (size_t i = 0; i < gt.size(); ++i) {
    SequenceFrame& frame = sequence->frames.emplace_back();
    char id[32];
    std::snprintf(id, sizeof(id), "%06zu", i);
    frame.id = id;
    frame.timestamp_s = kUnknownTime;
    frame.gt = PersonsFromArray(gt[i], static_cast<int>(gt_joints.size()), "gt[" + std::to_string(i) + "]");
  }
  return sequence;
}

Predictions PredictionsOfArrays(const py::sequence& predictions, const JointNames& joints, const Sequence& sequence) {
  Predictions out;
  out.sequence = sequence.name;
  out.joints = joints;
  for (size_t i = 0; i < predictions.size(); ++i) {
    out.persons.push_back(
        PersonsFromArray(predictions[i], static_cast<int>(joints.size()), "predictions[" + std::to_string(i) + "]"));
    out.stats.emplace_back();
    out.frame_ids.push_back(i < sequence.frames.size() ? sequence.frames[i].id : std::to_string(i));
    out.timestamps_s.push_back(kUnknownTime);
  }
  return out;
}

bool IsArrayList(py::handle object) {
  if (!py::isinstance<py::list>(object) && !py::isinstance<py::tuple>(object)) return false;
  const py::sequence list = py::reinterpret_borrow<py::sequence>(object);
  return list.size() == 0 || py::isinstance<py::array>(list[0]) || list[0].is_none() ||
         py::isinstance<py::list>(list[0]);
}

py::object Evaluate(py::handle gt, py::handle predictions, py::handle options, py::handle gt_joints,
                    py::handle joint_names, const py::kwargs& metric_options) {
  engine::Config config = ConfigOf(options);
  for (const auto& [key, value] : metric_options) {
    const std::string k = "metrics." + py::str(key).cast<std::string>();
    engine::SetConfigOption(k, OptionText(value, "metrics.evaluate", k), "metrics.evaluate", &config);
  }
  engine::CheckConfig(config);

  std::vector<std::shared_ptr<Sequence>> sequences;
  std::vector<Predictions> runs;
  if (IsArrayList(gt)) {  // arrays per frame
    if (gt_joints.is_none() || joint_names.is_none()) {
      throw py::value_error("metrics.evaluate: with arrays, give gt_joints= and joint_names= (the predictions')");
    }
    if (!IsArrayList(predictions)) throw py::type_error("metrics.evaluate: gt are arrays, so must the predictions be");
    const JointNames gt_names = gt_joints.cast<JointNames>(), prediction_names = joint_names.cast<JointNames>();
    CheckJointNames(gt_names, "metrics.evaluate: gt_joints");
    CheckJointNames(prediction_names, "metrics.evaluate: joint_names");
    sequences.push_back(SequenceOfArrays(py::reinterpret_borrow<py::sequence>(gt), gt_names));
    runs.push_back(PredictionsOfArrays(py::reinterpret_borrow<py::sequence>(predictions), prediction_names,
                                       *sequences.back()));
  } else {
    // pybind11's own cast error says only "Unable to cast Python instance to C++ type".
    const auto cast = [](py::handle value, const char* argument, const char* expected, auto* out) {
      try {
        *out = value.cast<std::remove_pointer_t<decltype(out)>>();
      } catch (const py::cast_error&) {
        throw py::type_error(std::string("metrics.evaluate: ") + argument + " must be " + expected + ", got " +
                             py::str(py::type::of(value).attr("__name__")).cast<std::string>());
      }
    };
    if (py::isinstance<Sequence>(gt)) {
      sequences.emplace_back();
      runs.emplace_back();
      cast(gt, "gt", "an rpt.datasets.Sequence", &sequences.back());
      cast(predictions, "predictions", "the rpt.Predictions of process_sequence (gt is one Sequence)", &runs.back());
    } else {
      cast(gt, "gt", "an rpt.datasets.Sequence, a list of them, or per frame an array", &sequences);
      cast(predictions, "predictions", "a list of rpt.Predictions (gt is a list of Sequences)", &runs);
    }
  }
  if (sequences.size() != runs.size()) {
    throw py::value_error("metrics.evaluate: " + std::to_string(sequences.size()) + " sequences, " +
                          std::to_string(runs.size()) + " predictions");
  }

  py::gil_scoped_release release;
  std::vector<const SequenceHeader*> headers;
  for (const auto& s : sequences) headers.push_back(s.get());
  const metrics::EvalOptions eval = engine::EvalOptionsFor(config.metrics, headers);
  engine::RunResult run;
  run.evaluated = true;
  metrics::MetricsAccumulator all(eval);
  metrics::TimingAccumulator timing;
  metrics::StepCountAccumulator counts;
  for (size_t i = 0; i < sequences.size(); ++i) {
    const Sequence& sequence = *sequences[i];
    const Predictions& prediction = runs[i];
    if (prediction.persons.size() != sequence.frames.size()) {
      throw InputError("metrics.evaluate: sequence " + QuoteName(sequence.name) + " has " +
                       std::to_string(sequence.frames.size()) + " frames, its predictions " +
                       std::to_string(prediction.persons.size()));
    }
    engine::SequenceResult result;
    result.name = sequence.name;
    result.cameras = static_cast<int>(sequence.cameras.size());
    result.output_joints = prediction.joints;
    metrics::MetricsAccumulator accumulator(eval);
    metrics::IdentityAccumulator identity;
    metrics::TimingAccumulator sequence_timing(0);
    metrics::StepCountAccumulator sequence_counts;
    std::optional<engine::DetectionChecker> checker;
    if (!sequence.cameras.empty()) {
      checker.emplace(sequence, static_cast<long>(sequence.frames.size()), config.triangulator.track.max_gap_s,
                      engine::DetectionCheckOptions{});
    }
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      const SequenceFrame& frame = sequence.frames[f];
      if (prediction.frame_ids[f] != frame.id) {
        throw InputError("metrics.evaluate: sequence " + QuoteName(sequence.name) + ", frame " + std::to_string(f) + ": '" +
                         frame.id + "' in the ground truth, " + QuoteName(prediction.frame_ids[f]) + " in the predictions");
      }
      const Poses3D& persons = prediction.persons[f];
      sequence_timing.Add(prediction.stats[f]);
      sequence_counts.Add(prediction.stats[f]);
      ++result.frames;
      run.gt_persons += frame.gt.num_persons();
      run.output_persons += persons.num_persons();
      if (frame.gt.num_persons() > 0) {
        ++run.frames_with_gt;
        if (persons.num_persons() == 0) ++run.frames_with_gt_without_prediction;
      }
      accumulator.Add(frame.id, frame.gt, sequence.gt_joints, persons, prediction.joints);
      if (sequence.gt_ids_across_frames) identity.Add(accumulator.LastFrame(), frame.gt, persons);
      if (checker) checker->Add(frame);
    }
    if (checker) result.check = checker->Finish();
    result.timing = sequence_timing.Finalize();
    result.metrics = accumulator.Finalize();
    result.identity = identity.counts();
    run.identity.Merge(result.identity);
    all.Merge(accumulator);
    timing.Merge(sequence_timing);
    counts.Merge(sequence_counts);
    run.frames += result.frames;
    run.wall_seconds += prediction.wall_seconds;
    run.sequences.push_back(std::move(result));
  }
  run.metrics = all.Finalize();
  run.timing = timing.Finalize();
  run.counts = counts.Finalize();
  nlohmann::ordered_json summary = engine::SummaryJson(run);
  summary.update(engine::DiagnosticsJson(engine::Diagnose(run)));
  py::gil_scoped_acquire acquire;
  return PythonOf(summary);
}

}  // namespace

void RegisterMetrics(py::module_& metrics) {
  metrics.def("evaluate", &Evaluate, py::arg("gt"), py::arg("predictions"), py::kw_only(),
              py::arg("options") = py::none(), py::arg("gt_joints") = py::none(), py::arg("joint_names") = py::none(),
              "The summary of `rpt eval --json` (PCP, PCK, MPJPE, recall, invalid, F1, AP, step times, warnings, data "
              "checks) of predictions against ground truth. gt: an rpt.datasets.Sequence (or a list of them) with "
              "predictions: the rpt.Predictions of process_sequence (or a list); or gt: per frame an array "
              "(persons, joints, 4) with gt_joints=, predictions: per frame an array with joint_names=. "
              "options: rpt.Options or dict (its 'metrics' section); other keyword arguments are metrics options "
              "(min_gt_score=0.1, matching='hungarian', ...).");
}

}  // namespace rpt::python

// SPDX-License-Identifier: MIT
// The data of the HTML report as one JSON object (what report/report.js draws): the run's summary
// with the paper's row for its dataset, per-joint errors, step times and counts, configuration and
// run info from the run folder; and, when the run's input could be re-loaded, per-frame errors of
// every sequence, the recall curve, the cameras, and for a sample of frames the 3D scene (GT and
// predictions with their match state) and per camera the 2D detections and the reprojected 3D
// result with reprojection errors (engine/reprojection.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/report/report_run.h"
#include "datasets/sequence.h"
#include "metrics/eval_options.h"

namespace rpt::engine {

struct ReportDataOptions {
  int max_scene_frames = 200;  // frames with a 3D scene and camera views; evenly spaced over the run when more
  // The scenes' share of the page: fewer frames carry a scene when max_scene_frames of them would
  // take more (the size of a scene grows with cameras x persons; estimated from the first ones).
  double max_scene_mb = 10;
};

// `sequences` is null when the input could not be re-loaded (`why_no_input` says why): the report
// then holds the recorded tables only. `eval_options` is the run's resolved metrics options.
// `warnings` receives lines worth printing (also listed in the report).
nlohmann::ordered_json BuildReportData(const RecordedRun& run, const std::vector<Sequence>* sequences,
                                       const std::string& why_no_input, const metrics::EvalOptions& eval_options,
                                       const ReportDataOptions& options, std::vector<std::string>* warnings);

// The paper's row for a dataset name (results/paper.json, embedded at build time), null when the
// paper has none.
nlohmann::ordered_json PaperResultsFor(const std::string& dataset);

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// Result files of an evaluation: summary.{json,csv,md} with fixed columns and units (the whole
// run, then one row per sequence when there are several),
// per_joint.csv, steps.csv (time and items per step), the resolved config.json, run.json (revision, machine, threads) and
// predictions.json (3D persons of every frame).
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "datasets/io/staged_output.h"
#include "engine/config.h"
#include "engine/frame_sink.h"
#include "engine/outputs/array_frames.h"
#include "engine/outputs/csv_export.h"
#include "engine/outputs/export_options.h"
#include "engine/outputs/predictions_writer.h"
#include "engine/outputs/run_info.h"
#include "engine/outputs/trc_export.h"
#include "engine/run.h"

namespace rpt::engine {

// A result column: JSON key, unit and how to read it from a run.
struct SummaryColumn {
  std::string key;   // JSON key and CSV header, e.g. "mpjpe_mm"
  std::string unit;  // "%", "mm", "1/s", "us", "count"
  std::string title; // paper-style column title
};
const std::vector<SummaryColumn>& SummaryColumns();

// Throws InputError "<source>: <pointer>/<key>: ..." for a summary value no run writes: a
// SummaryColumns() key (or legacy_pcp*) that is neither a number nor null, a percentage outside
// [0, 100], a count or measure below 0 or not finite. Other keys are not looked at. For summaries
// from someone else: rpt merge's shard rows, rpt report's summary.json.
void CheckSummaryValues(const nlohmann::json& summary, const std::string& source, const std::string& pointer);

// The summary of a run as one JSON object with SummaryColumns() keys (NaN -> null), plus
// "wholebody_mpjpe_mm" and "legacy_pcp" (the average over the actors) with "legacy_pcp_actor1",
// "legacy_pcp_actor2", ... (one per averaged actor) when available, "step_time_us_median",
// "step_count_per_frame", "counter_per_frame" and "detection_noise_m" (null when not estimated),
// "frame_with_grouping_us_median" where a reader grouped raw candidates, and with several sequences
// "per_sequence": one SequenceSummaryJson per sequence.
nlohmann::ordered_json SummaryJson(const RunResult& run);
// The summary of a run without metrics (rpt triangulate): "evaluated": false, "fps",
// "frame_time_us_median", "frames", "eval_frames_per_s", "output_persons" (triangulated
// person-frames), the step times, counts and counters, "detection_noise_m", "per_sequence" (with
// several: sequence, fps, frame_time_us_median, frames) and "units".
nlohmann::ordered_json TriangulationSummaryJson(const RunResult& run);
// One sequence of a run: "sequence" (its name) and the SummaryColumns() keys it has on its own
// (everything but the run's wall-clock throughput), plus "wholebody_mpjpe_mm" / "legacy_pcp".
nlohmann::ordered_json SequenceSummaryJson(const SequenceResult& sequence);

// CSV / Markdown tables with one row per (label, summary). When a row has a legacy PCP, the CSV
// gains the columns legacy_pcp, legacy_pcp_actor1, ... after the fixed ones, and the Markdown a
// second table in the papers' layout: Actor 1 | Actor 2 | ... | Average.
// Labels go through the tables' escaping (CsvField, MarkdownText: engine/outputs/text_escaping.h).
std::string SummaryCsv(const std::vector<std::pair<std::string, nlohmann::ordered_json>>& rows);
std::string SummaryMarkdown(const std::vector<std::pair<std::string, nlohmann::ordered_json>>& rows);

// The paper-style row printed on the terminal: PCP | PCK@100/500 | MPJPE | Recall@100/500 | Invalid | F1 | FPS.
std::string PaperRow(const RunResult& run);

// The counted predictions that are not matches, by cause (metrics::InvalidCauses), as one line;
// empty when there are none. `gate_mm` = metrics.match_threshold_mm.
std::string InvalidCausesLine(const metrics::MetricsResult& m, double gate_mm);

// The output folder of a run (`rpt eval`, `rpt triangulate`): built beside the target and swapped
// in whole when complete (io::StagedFolder), so `dir` holds either its old contents or the complete
// new run. predictions.json streams in while the run goes (sink()); Finish() writes
// summary.{json,csv,md} (`extra_summary`, e.g. eval's warnings and data checks, merged into
// summary.json), per_joint.csv (the last three only for an evaluated run; without metrics
// summary.json is TriangulationSummaryJson), steps.csv, config.json and run.json (last: the
// marker of a complete run; summary,
// predictions and run carry the same "run_id"), then swaps the folder in. Strings that are not
// valid UTF-8 are written as U+FFFD with one "warning: <file>: ..." line on stderr per file.
// Throws InputError naming the file when anything cannot be written; `dir` is then left as it
// was, and so it is when the run fails before Finish (the destructor removes the temporary).
class RunFolder {
 public:
  // `exports`: the files of 3D persons written (export_options.h; default predictions.json).
  RunFolder(const std::filesystem::path& dir, const std::string& run_id, int num_sequences,
            const ExportOptions& exports = {});
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  // Writes the exports: predictions.json (predictions_writer.h), predictions.csv (csv_export.h),
  // trc/ (trc_export.h), predictions.npz (npz_export.h) and predictions.h5 (h5_export.h). The
  // folder holds only this run's exports: those of an earlier run there that this run does not
  // write are removed (its TRC files all), whatever --export that run had.
  FrameSink* sink();
  void Finish(const RunResult& run, const Config& config, const RunInfo& info,
              const nlohmann::ordered_json& extra_summary = nlohmann::ordered_json::object());

 private:
  std::filesystem::path dir_;
  ExportOptions exports_;
  std::unique_ptr<io::StagedFolder> folder_;
  std::unique_ptr<PredictionsWriter> predictions_;
  std::unique_ptr<CsvExport> csv_;
  std::unique_ptr<TrcExport> trc_;
  std::unique_ptr<ArrayFrames> arrays_;  // for predictions.npz and predictions.h5
  std::unique_ptr<SinkList> sinks_;
  class NamedSink;
  std::unique_ptr<NamedSink> named_sink_;  // sinks_, their errors naming the folder given
};

// "<dir>/report.html: the page of the earlier run here (carried over with the folder's other files):
// `rpt report <dir>` makes this run's" when the run folder `dir` holds a report.html (a run never
// writes one), else "".
std::string StaleReportWarning(const std::filesystem::path& dir);

// run.json: run id, git revision, date, command ("command": one line for people; "argv": the
// argument vector, which keeps paths with spaces whole), machine, threads, build, and
// "input_warnings" (the readers' correction lines, [] when none).
// `written_in`: the folder the JSON is written in; "working_directory" is then the folder the command
// ran in relative to it (omitted without it, or when there is no relative path).
nlohmann::ordered_json RunInfoJson(const RunInfo& info, const std::filesystem::path& written_in = {});

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
#include "engine/outputs/results_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "core/option_codec.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/staged_output.h"
#include "datasets/io/text_file.h"
#include "engine/outputs/h5_export.h"
#include "engine/outputs/loss_tables.h"
#include "engine/outputs/npz_export.h"
#include "engine/outputs/step_tables.h"
#include "engine/outputs/text_escaping.h"

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson Number(double value) { return std::isfinite(value) ? OrderedJson(value) : OrderedJson(nullptr); }

// A value for the tables: "-" when undefined (null), the CSVs use CsvCell.
std::string Cell(const OrderedJson& value, int decimals = 1) {
  if (value.is_null()) return "-";
  if (value.is_number_integer()) return std::to_string(value.get<long>());
  if (value.is_number()) return FixedText(value.get<double>(), decimals);
  return value.is_string() ? value.get<std::string>() : value.dump();
}

// A value for a CSV file: an undefined one (null in the JSON) is an empty field, which pandas and
// spreadsheets read as missing ("-" made float() fail).
std::string CsvCell(const OrderedJson& value, int decimals) { return value.is_null() ? "" : Cell(value, decimals); }

// "legacy_pcp_actor1" for actor id 0: the papers number Shelf/Campus actors from 1.
std::string LegacyPcpActorKey(int actor_id) { return "legacy_pcp_actor" + std::to_string(actor_id + 1); }

// The legacy PCP keys of any row: "legacy_pcp", then the per-actor keys from actor 1 to the
// highest any row reports; empty when no row has a legacy PCP.
std::vector<std::string> LegacyPcpKeys(const std::vector<std::pair<std::string, OrderedJson>>& rows) {
  std::vector<int> actors;
  bool any = false;
  const std::string prefix = "legacy_pcp_actor";
  for (const auto& [label, j] : rows) {
    any |= j.contains("legacy_pcp");
    for (const auto& [key, value] : j.items()) {
      if (key.rfind(prefix, 0) != 0) continue;
      const int actor = std::atoi(key.c_str() + prefix.size()) - 1;
      if (std::find(actors.begin(), actors.end(), actor) == actors.end()) actors.push_back(actor);
    }
  }
  std::vector<std::string> keys;
  if (!any) return keys;
  keys.push_back("legacy_pcp");
  // Actors 1 to the highest reported: an actor without GT in the frames evaluated shows "-".
  const int last = actors.empty() ? -1 : *std::max_element(actors.begin(), actors.end());
  for (int actor = 0; actor <= last; ++actor) keys.push_back(LegacyPcpActorKey(actor));
  return keys;
}

}  // namespace

const std::vector<SummaryColumn>& SummaryColumns() {
  static const std::vector<SummaryColumn> columns = {
      {"pcp", "%", "PCP"},
      {"pck100", "%", "PCK@100"},
      {"pck500", "%", "PCK@500"},
      {"mpjpe_mm", "mm", "MPJPE"},
      {"recall100", "%", "Recall@100"},
      {"recall500", "%", "Recall@500"},
      {"invalid", "%", "Invalid"},
      {"f1", "%", "F1"},
      {"fps", "1/s", "FPS"},
      {"frame_time_us_median", "us", "Time/frame"},
      {"frames", "count", "Frames"},
      {"eval_frames_per_s", "1/s", "Eval throughput"},
      {"gt_persons", "count", "GT persons"},
      {"predictions", "count", "Predictions"},
      {"matches", "count", "Matches"},
      {"ap25", "%", "AP@25"},
      {"ap50", "%", "AP@50"},
      {"ap75", "%", "AP@75"},
      {"ap100", "%", "AP@100"},
      {"ap125", "%", "AP@125"},
      {"ap150", "%", "AP@150"},
  };
  return columns;
}

std::string StaleReportWarning(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(dir / "report.html", ec))) return "";
  const std::string folder = PrintableText(dir.string(), LineBreaks::kEscape);
  return folder + "/report.html: the page of the earlier run here (carried over with the folder's other files): "
                  "`rpt report " + folder + "` makes this run's";
}

void CheckSummaryValues(const nlohmann::json& summary, const std::string& source, const std::string& pointer) {
  if (!summary.is_object()) throw InputError(source + ": " + pointer + ": expected an object of metrics");
  for (const auto& [key, value] : summary.items()) {
    // The summary column of the key and its unit ("%" bounds it to [0, 100]); legacy_pcp* are PCP.
    const auto& columns = SummaryColumns();
    const auto found =
        std::find_if(columns.begin(), columns.end(), [&key = key](const SummaryColumn& c) { return c.key == key; });
    const bool legacy = key.rfind("legacy_pcp", 0) == 0;
    if (!legacy && found == columns.end()) continue;  // not a column: kept as written
    const std::string where = source + ": " + io::JsonPointerJoin(pointer, key) + ": ";
    if (!value.is_number() && !value.is_null()) {
      throw InputError(where + "expected a number or null, got " + value.type_name());
    }
    // Numbers no run writes: a percentage outside [0, 100], a negative count or measure, infinity.
    if (value.is_number()) {
      const double number = value.get<double>();
      const bool percent = legacy || found->unit == "%";
      if (!std::isfinite(number) || number < 0 || (percent && number > 100)) {
        throw InputError(where + FormatNumber(number) +
                         (percent ? " is not a percentage in [0, 100]" : " is not a count or measure >= 0"));
      }
    }
  }
}

namespace {

// The metric columns of one result (SummaryColumns' keys that the metrics give) into *j.
void AddMetricColumns(const metrics::MetricsResult& m, OrderedJson* j) {
  (*j)["pcp"] = Number(m.pcp);
  (*j)["pck100"] = Number(m.pck_100);
  (*j)["pck500"] = Number(m.pck_500);
  (*j)["mpjpe_mm"] = Number(m.mpjpe_mm);
  (*j)["recall100"] = Number(m.recall_100);
  (*j)["recall500"] = Number(m.recall_500);
  (*j)["invalid"] = Number(m.invalid);
  (*j)["f1"] = Number(m.f1);
}

void AddCountColumns(const metrics::MetricsResult& m, OrderedJson* j) {
  (*j)["gt_persons"] = m.num_gt_persons;
  (*j)["predictions"] = m.num_predictions;
  (*j)["matches"] = m.num_matches;
  // What the metrics left out (docs/metrics.md): GT persons without a valid evaluated joint,
  // GT-valid joints a matched prediction lacks, matched pairs without a pelvis for alignment.
  (*j)["dropped_gt_persons"] = m.num_dropped_gt_persons;
  (*j)["missing_pred_joints"] = m.num_missing_pred_joints;
  (*j)["unaligned_matches"] = m.num_unaligned_matches;
  for (size_t i = 0; i < metrics::kApThresholdsMm.size(); ++i) {
    (*j)["ap" + std::to_string(static_cast<int>(metrics::kApThresholdsMm[i]))] = Number(m.ap[i]);
  }
  OrderedJson parts;  // per PCP part (parts the evaluated joints define and some GT person has)
  for (const auto& part : m.pcp_parts) {
    if (part.total > 0) parts[part.name] = Number(part.pcp);
  }
  if (!parts.empty()) (*j)["pcp_parts"] = parts;
  (*j)["invalid_causes"] = {{"duplicate", m.invalid_causes.duplicate},
                            {"near_matched_gt", m.invalid_causes.near_matched_gt},
                            {"near_missed_gt", m.invalid_causes.near_missed_gt},
                            {"far_from_gt", m.invalid_causes.far_from_gt},
                            {"no_gt", m.invalid_causes.no_gt}};
  if (!m.wholebody.empty()) {
    OrderedJson groups;
    for (const auto& g : m.wholebody) groups[g.name] = Number(g.mpjpe_mm);
    (*j)["wholebody_mpjpe_mm"] = groups;
    // What each group's number is over (metrics.md, section 5): a group of fewer joints than its
    // name says (body-only predictions: "All" over 17) or of no person is visible.
    OrderedJson counts;
    for (const auto& g : m.wholebody) {
      counts[g.name] = {{"joints", g.num_joints},
                        {"gt_only_joints", g.num_gt_only_joints},
                        {"persons", g.num_persons},
                        {"filled_share", g.filled_share}};
    }
    (*j)["wholebody_counts"] = counts;
  }
  if (m.legacy_pcp) {
    (*j)["legacy_pcp"] = Number(m.legacy_pcp->average_pcp);
    // Per actor the average is over (metrics.legacy_pcp_actors), numbered from 1 as in the papers.
    for (const auto& actor : m.legacy_pcp->actors) {
      if (actor.averaged) (*j)[LegacyPcpActorKey(actor.actor_id)] = Number(actor.pcp);
    }
  }
}

// The units of the keys both summaries may hold beyond the summary columns (when present in `j`):
// every number of summary.json has one.
void AddOtherUnits(const OrderedJson& j, OrderedJson* units) {
  static const std::vector<std::pair<std::string, std::string>> kUnits = {
      {"dropped_gt_persons", "GT persons"},
      {"missing_pred_joints", "joints"},
      {"unaligned_matches", "matches"},
      {"track_ids", "count"},
      {"gt_identities", "count"},
      {"gt_identities_matched", "count"},
      {"id_switches", "count"},
      {"wholebody_mpjpe_mm", "mm"},
      {"wholebody_counts", "count"},
      {"output_persons", "count"},
      {"frame_with_grouping_us_median", "us"},
      {"step_time_us_median", "us"},
      {"step_count_per_frame", "items per frame"},
      {"counter_per_frame", "per frame"},
      {"detection_noise_m", "m"},
      {"camera_agreement", "persons"},
  };
  for (const auto& [key, unit] : kUnits) {
    if (j.contains(key)) (*units)[key] = unit;
  }
}

// Track ids against the GT's ids (metrics/identity_counts.h), when there are both: GT ids across
// frames (not MVOR's) and predictions with track ids (tracking on).
void AddIdentityColumns(const metrics::IdentityCounts& identity, OrderedJson* j) {
  if (identity.gt_identities == 0 || identity.track_ids == 0) return;
  (*j)["track_ids"] = identity.track_ids;
  (*j)["gt_identities"] = identity.gt_identities;
  (*j)["gt_identities_matched"] = identity.matched_identities;
  (*j)["id_switches"] = identity.id_switches;
}

// With a reader that groups raw candidates (shelf-4da): the frame's median time with the grouping,
// the time a user feeding raw candidates pays (fps and frame_time_us_median are the pipeline's).
void AddGroupingTime(const metrics::TimingSummary& timing, OrderedJson* j) {
  if (timing.paf_grouping_frames > 0) {
    (*j)["frame_with_grouping_us_median"] = Number(timing.frame_with_grouping_us_median);
  }
}

}  // namespace

OrderedJson SequenceSummaryJson(const SequenceResult& sequence) {
  OrderedJson j;
  j["sequence"] = sequence.name;
  AddMetricColumns(sequence.metrics, &j);
  j["fps"] = Number(sequence.timing.fps);
  j["frame_time_us_median"] = Number(sequence.timing.frame_us_median);
  j["frames"] = sequence.frames;
  AddCountColumns(sequence.metrics, &j);
  AddIdentityColumns(sequence.identity, &j);
  return j;
}

OrderedJson SummaryJson(const RunResult& run) {
  const metrics::MetricsResult& m = run.metrics;
  OrderedJson j;
  AddMetricColumns(m, &j);
  j["fps"] = Number(run.timing.fps);
  j["frame_time_us_median"] = Number(run.timing.frame_us_median);
  AddGroupingTime(run.timing, &j);
  j["frames"] = run.frames;
  j["eval_frames_per_s"] = Number(run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0);
  AddCountColumns(m, &j);
  AddIdentityColumns(run.identity, &j);
  j["step_time_us_median"] = StepTimesJson(run.timing);
  j["step_count_per_frame"] = StepCountsJson(run.counts);
  j["counter_per_frame"] = CountersJson(run.counts);
  j["detection_noise_m"] = run.counts.noise_frames > 0 ? OrderedJson(run.counts.noise_m_median) : OrderedJson(nullptr);
  if (run.sequences.size() > 1) {
    j["per_sequence"] = OrderedJson::array();
    for (const SequenceResult& sequence : run.sequences) j["per_sequence"].push_back(SequenceSummaryJson(sequence));
  }
  OrderedJson units;
  for (const SummaryColumn& c : SummaryColumns()) units[c.key] = c.unit;
  for (const std::string& key : LegacyPcpKeys({{"", j}})) {
    if (j.contains(key)) units[key] = "%";
  }
  if (j.contains("pcp_parts")) units["pcp_parts"] = "%";
  units["invalid_causes"] = "predictions";
  AddOtherUnits(j, &units);
  j["units"] = units;
  return j;
}

OrderedJson TriangulationSummaryJson(const RunResult& run) {
  OrderedJson j;
  j["evaluated"] = false;
  j["fps"] = Number(run.timing.fps);
  j["frame_time_us_median"] = Number(run.timing.frame_us_median);
  AddGroupingTime(run.timing, &j);
  j["frames"] = run.frames;
  j["eval_frames_per_s"] = Number(run.wall_seconds > 0 ? run.frames / run.wall_seconds : 0.0);
  j["output_persons"] = run.output_persons;
  j["step_time_us_median"] = StepTimesJson(run.timing);
  j["step_count_per_frame"] = StepCountsJson(run.counts);
  j["counter_per_frame"] = CountersJson(run.counts);
  j["detection_noise_m"] = run.counts.noise_frames > 0 ? OrderedJson(run.counts.noise_m_median) : OrderedJson(nullptr);
  // Per camera, how many 3D persons in its view match its detections (engine/camera_agreement.h).
  OrderedJson agreement = OrderedJson::array();
  for (const SequenceResult& sequence : run.sequences) {
    for (const CameraAgreement& camera : sequence.camera_agreement) {
      agreement.push_back({{"sequence", sequence.name},
                           {"camera", camera.camera},
                           {"persons_in_view", camera.in_view},
                           {"persons_matching", camera.agreeing},
                           {"persons_in_view_without_detections", camera.in_view_without_detections},
                           {"persons_while_detecting", camera.while_detecting}});
    }
  }
  if (!agreement.empty()) j["camera_agreement"] = agreement;
  if (run.sequences.size() > 1) {
    j["per_sequence"] = OrderedJson::array();
    for (const SequenceResult& sequence : run.sequences) {
      j["per_sequence"].push_back({{"sequence", sequence.name},
                                   {"fps", Number(sequence.timing.fps)},
                                   {"frame_time_us_median", Number(sequence.timing.frame_us_median)},
                                   {"frames", sequence.frames}});
    }
  }
  OrderedJson units;
  for (const SummaryColumn& c : SummaryColumns()) {
    if (j.contains(c.key)) units[c.key] = c.unit;
  }
  AddOtherUnits(j, &units);
  j["units"] = units;
  return j;
}

std::string SummaryCsv(const std::vector<std::pair<std::string, OrderedJson>>& rows) {
  std::ostringstream out;
  const std::vector<std::string> legacy = LegacyPcpKeys(rows);  // after the fixed columns, when any row has them
  out << "run";
  for (const SummaryColumn& c : SummaryColumns()) out << "," << c.key;
  for (const std::string& key : legacy) out << "," << key;
  out << "\n";
  for (const auto& [label, j] : rows) {
    out << CsvField(label);
    for (const SummaryColumn& c : SummaryColumns()) out << "," << (j.contains(c.key) ? CsvCell(j[c.key], 4) : "");
    for (const std::string& key : legacy) out << "," << (j.contains(key) ? CsvCell(j[key], 4) : "");
    out << "\n";
  }
  return out.str();
}

std::string SummaryMarkdown(const std::vector<std::pair<std::string, OrderedJson>>& rows) {
  static const std::vector<std::string> keys = {"pcp",       "pck100",    "pck500",  "mpjpe_mm", "recall100",
                                                "recall500", "invalid",   "f1",      "fps",      "frames"};
  std::ostringstream out;
  out << "| run |";
  for (const std::string& key : keys) {
    for (const SummaryColumn& c : SummaryColumns()) {
      if (c.key == key) out << " " << c.title << " (" << c.unit << ") |";
    }
  }
  out << "\n|---|";
  for (size_t i = 0; i < keys.size(); ++i) out << "---|";
  out << "\n";
  for (const auto& [label, j] : rows) {
    out << "| " << MarkdownText(label) << " |";
    for (const std::string& key : keys) out << " " << (j.contains(key) ? Cell(j[key], key == "fps" ? 0 : 1) : "-") << " |";
    out << "\n";
  }
  // The legacy Shelf/Campus PCP as the papers report it: per actor, then their average.
  std::vector<std::string> legacy = LegacyPcpKeys(rows);
  if (legacy.empty()) return out.str();
  std::rotate(legacy.begin(), legacy.begin() + 1, legacy.end());  // the average last
  out << "\nLegacy Shelf/Campus PCP (%, `metrics.legacy_pcp`):\n\n| run |";
  for (const std::string& key : legacy) {
    out << (key == "legacy_pcp" ? std::string(" Average |") : " Actor " + key.substr(key.rfind('r') + 1) + " |");
  }
  out << "\n|---|";
  for (size_t i = 0; i < legacy.size(); ++i) out << "---|";
  out << "\n";
  for (const auto& [label, j] : rows) {
    out << "| " << MarkdownText(label) << " |";
    for (const std::string& key : legacy) out << " " << (j.contains(key) ? Cell(j[key], 1) : "-") << " |";
    out << "\n";
  }
  return out.str();
}

std::string PaperRow(const RunResult& run) {
  const OrderedJson j = SummaryJson(run);
  char line[512];
  std::snprintf(line, sizeof(line),
                "PCP %s | PCK@100/500 %s / %s | MPJPE %s mm | Recall@100/500 %s / %s | Invalid %s | F1 %s | FPS %s",
                Cell(j["pcp"]).c_str(), Cell(j["pck100"]).c_str(), Cell(j["pck500"]).c_str(),
                Cell(j["mpjpe_mm"]).c_str(), Cell(j["recall100"]).c_str(), Cell(j["recall500"]).c_str(),
                Cell(j["invalid"]).c_str(), Cell(j["f1"]).c_str(), Cell(j["fps"], 0).c_str());
  return line;
}

std::string InvalidCausesLine(const metrics::MetricsResult& m, double gate_mm) {
  const metrics::InvalidCauses& c = m.invalid_causes;
  if (c.Total() == 0) return "";
  char line[512];
  std::snprintf(line, sizeof(line),
                "unmatched predictions (Invalid): %d = %d duplicate + %d beside a found person (%.0f-%.0f mm) + %d "
                "near a missed person (%.0f-%.0f mm) + %d far from every GT person + %d without GT to compare",
                c.Total(), c.duplicate, c.near_matched_gt, gate_mm, 2 * gate_mm, c.near_missed_gt, gate_mm,
                2 * gate_mm, c.far_from_gt, c.no_gt);
  return line;
}

OrderedJson RunInfoJson(const RunInfo& info, const std::filesystem::path& written_in) {
  OrderedJson j;
  j["run_id"] = info.run_id;
  j["git_revision"] = info.git_revision;
  j["date_utc"] = info.date_utc;
  j["command"] = info.command_line;
  j["argv"] = info.command_args;
  if (!written_in.empty() && !info.working_directory.empty()) {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::weakly_canonical(std::filesystem::absolute(written_in), ec);
    const std::filesystem::path relative = std::filesystem::path(info.working_directory).lexically_relative(folder);
    if (!ec && !relative.empty()) j["working_directory"] = relative.generic_string();
  }
  j["cpu"] = info.cpu;
  j["hardware_threads"] = info.hardware_threads;
  j["threads"] = info.threads;
  j["compiler"] = info.compiler;
  j["build_type"] = info.build_type;
  j["input_warnings"] = info.input_warnings;
  OrderedJson settings = OrderedJson::object();
  for (const auto& [key, value] : info.input_settings) settings[key] = value;
  j["input_settings"] = settings;
  OrderedJson digests = OrderedJson::object();
  for (const auto& [path, digest] : info.input_digests) digests[path] = digest;
  j["input_digests"] = digests;
  return j;
}

namespace {

// The files of one run into `staging`, run.json last.
void WriteRunFiles(const std::filesystem::path& staging, const std::filesystem::path& target, const RunResult& run,
                   const Config& config, const RunInfo& info, const OrderedJson& extra_summary,
                   std::vector<std::pair<std::string, int>>* replaced) {
  const auto write_json = [&](const std::string& name, const OrderedJson& value) {
    int count = 0;
    const std::string text = io::DumpJson(value, 2, &count) + "\n";
    io::WriteTextFile(staging / name, io::NamedBy::kRpt, text);
    if (count > 0) replaced->emplace_back(name, count);
  };
  OrderedJson summary;
  summary["run_id"] = info.run_id;
  summary.update(run.evaluated ? SummaryJson(run) : TriangulationSummaryJson(run));
  summary.update(extra_summary);
  write_json("summary.json", summary);
  if (!run.evaluated) {  // no metrics: no summary tables, no per-joint errors
    io::WriteTextFile(staging / "steps.csv", io::NamedBy::kRpt, StepsCsv(run.timing, run.counts));
    io::WriteTextFile(staging / "config.json", io::NamedBy::kRpt, DumpConfig(config, /*with_comments=*/false));
    write_json("run.json", RunInfoJson(info, target));  // last: the marker of a complete run
    return;
  }
  std::string label;
  for (const SequenceResult& s : run.sequences) AppendItem(&label, s.name, "+");
  if (run.sequences.size() > 3) {
    label = run.sequences.front().name + "+" + std::to_string(run.sequences.size() - 1) + " more";
  }
  // The whole run first, then (with several sequences) one row per sequence.
  std::vector<std::pair<std::string, OrderedJson>> rows = {{label, summary}};
  if (run.sequences.size() > 1) {
    for (const SequenceResult& sequence : run.sequences) rows.emplace_back(sequence.name, SequenceSummaryJson(sequence));
  }
  io::WriteTextFile(staging / "summary.csv", io::NamedBy::kRpt, SummaryCsv(rows));
  io::WriteTextFile(staging / "summary.md", io::NamedBy::kRpt,
                    SummaryMarkdown(rows) + "\nRevision " + MarkdownText(info.git_revision) + ", " +
                        MarkdownText(info.cpu) + ", " + std::to_string(info.threads) +
                        " thread(s). Command: " + MarkdownCode(info.command_line) + "\n");
  std::ostringstream joints;
  joints << "joint,mean_error_mm,pck100_pct,count,num_gt\n";
  for (const auto& row : run.metrics.joints) {
    joints << CsvField(row.name) << "," << CsvCell(Number(row.mean_error_mm), 2) << "," << CsvCell(Number(row.pck_100), 2) << ","
           << row.count << "," << row.num_gt << "\n";
  }
  io::WriteTextFile(staging / "per_joint.csv", io::NamedBy::kRpt, joints.str());
  io::WriteTextFile(staging / "steps.csv", io::NamedBy::kRpt, StepsCsv(run.timing, run.counts));
  if (run.losses) {
    io::WriteTextFile(staging / "losses.csv", io::NamedBy::kRpt, LossesCsv(*run.losses));
  } else {  // an earlier run's table (carried over into the folder) is not this run's
    std::error_code ec;
    std::filesystem::remove(staging / "losses.csv", ec);
    if (ec) throw InputError((staging / "losses.csv").string() + ": cannot remove the earlier run's table: " + ec.message());
  }
  io::WriteTextFile(staging / "config.json", io::NamedBy::kRpt, DumpConfig(config, /*with_comments=*/false));
  write_json("run.json", RunInfoJson(info, target));  // last: the marker of a complete run
}

// Removes what `format` writes in `folder` (a file, or the trc folder with its files), links
// included and never followed; throws InputError naming it when it cannot.
void RemoveExport(const std::filesystem::path& folder, ExportFormat format) {
  const std::filesystem::path path = folder / ExportFileName(format);
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return;
  std::filesystem::remove_all(path, ec);  // a link itself is removed, not what it points to
  if (ec) throw InputError(path.string() + ": cannot remove the earlier run's export: " + ec.message());
}

}  // namespace

// The run folder's sinks, their errors naming the folder the user gave rather than its staging
// sibling (`run.tmp-<pid>-0/...`), as Finish's do.
class RunFolder::NamedSink final : public FrameSink {
 public:
  NamedSink(FrameSink* sinks, const io::StagedFolder* folder) : sinks_(sinks), folder_(folder) {}
  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override {
    Named([&] { sinks_->BeginSequence(sequence, header, output_joints); });
  }
  void Frame(const FrameOutput& frame) override {
    Named([&] { sinks_->Frame(frame); });
  }
  void EndSequence(int sequence) override {
    Named([&] { sinks_->EndSequence(sequence); });
  }

 private:
  template <class Call>
  void Named(const Call& call) const {
    try {
      call();
    } catch (const InputError& e) {
      throw InputError(folder_->NamedAsTarget(e.what()));
    }
  }

  FrameSink* sinks_;
  const io::StagedFolder* folder_;
};

RunFolder::RunFolder(const std::filesystem::path& dir, const std::string& run_id, int num_sequences,
                     const ExportOptions& exports)
    : dir_(dir), exports_(exports), folder_(std::make_unique<io::StagedFolder>(dir)) {
  // When the folder must be replaced in place, the old run marker goes first, so a reader never
  // takes a mixed folder for a complete run.
  if (folder_->in_place()) {
    std::error_code ec;
    std::filesystem::remove(folder_->path() / "run.json", ec);
    if (ec) throw InputError((dir / "run.json").string() + ": cannot remove the old run marker: " + ec.message());
  }
  if (exports.Has(ExportFormat::kJson)) {
    predictions_ = std::make_unique<PredictionsWriter>(folder_->path() / ExportFileName(ExportFormat::kJson), run_id,
                                                       num_sequences, exports);
  }
  if (exports.Has(ExportFormat::kCsv)) {
    csv_ = std::make_unique<CsvExport>(folder_->path() / ExportFileName(ExportFormat::kCsv), num_sequences, exports);
  }
  if (exports.Has(ExportFormat::kTrc)) {
    // The TRC files of an earlier run in this folder would stay beside the new ones (tracks this
    // run does not have): the folder starts empty. Staged, the old folder is untouched (its
    // entries here are hard links); in place, its TRC files go now.
    RemoveExport(folder_->path(), ExportFormat::kTrc);
    trc_ = std::make_unique<TrcExport>(folder_->path() / ExportFileName(ExportFormat::kTrc), num_sequences, exports);
  }
  if (exports.Has(ExportFormat::kNpz) || exports.Has(ExportFormat::kH5)) {
    arrays_ = std::make_unique<ArrayFrames>(folder_->path() / "predictions.arrays", run_id, num_sequences, exports);
  }
  sinks_ =
      std::make_unique<SinkList>(std::vector<FrameSink*>{predictions_.get(), csv_.get(), trc_.get(), arrays_.get()});
  named_sink_ = std::make_unique<NamedSink>(sinks_.get(), folder_.get());
}

RunFolder::~RunFolder() = default;

FrameSink* RunFolder::sink() { return named_sink_.get(); }

void RunFolder::Finish(const RunResult& run, const Config& config, const RunInfo& info,
                       const OrderedJson& extra_summary) {
  std::vector<std::pair<std::string, int>> replaced;  // file, strings with invalid UTF-8
  try {
    if (predictions_ != nullptr) {
      if (const int count = predictions_->Finish(); count > 0) replaced.emplace_back("predictions.json", count);
    }
    if (csv_ != nullptr) csv_->Finish();
    if (exports_.Has(ExportFormat::kNpz))
      WriteNpzExport(folder_->path() / ExportFileName(ExportFormat::kNpz), *arrays_);
    if (exports_.Has(ExportFormat::kH5)) WriteH5Export(folder_->path() / ExportFileName(ExportFormat::kH5), *arrays_);
    arrays_.reset();  // its scratch files go
    // An earlier run's exports that this run does not write (carried over with the folder's other
    // entries, or left in place) go: the folder holds only this run's.
    for (const ExportFormat format : kExportFormats) {
      if (!exports_.Has(format)) RemoveExport(folder_->path(), format);
    }
    WriteRunFiles(folder_->path(), folder_->target(), run, config, info, extra_summary, &replaced);
    folder_->Commit();
  } catch (const InputError& e) {
    throw InputError(folder_->NamedAsTarget(e.what()));
  }
  for (const auto& [name, count] : replaced) {
    std::fprintf(stderr, "warning: %s: %d string(s) not valid UTF-8 (frame ids, names); invalid bytes written as U+FFFD\n",
                 (dir_ / name).string().c_str(), count);
  }
  // TRC holds tracks only: a run without any (times unknown: no --fps) wrote an empty folder.
  if (trc_ != nullptr) {
    const std::string warning =
        NoTrcFileWarning(*trc_, dir_ / ExportFileName(ExportFormat::kTrc), run.output_persons, "give --fps or times");
    if (!warning.empty()) std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
}

}  // namespace rpt::engine

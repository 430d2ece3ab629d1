// SPDX-License-Identifier: MIT
#include "engine/thresholds_file.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/closest_name.h"
#include "engine/json_text.h"
#include "engine/outputs/results_writer.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/text.h"
#include "datasets/dataset_params.h"
#include "datasets/io/json_file.h"
#include "engine/dataset_registry.h"
#include "core/printable_text.h"

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::vector<std::string> kFileKeys = {"description", "evaluations"};
const std::vector<std::string> kEvaluationKeys = {"name",     "description", "dataset",  "root",   "labels",
                                                  "detections", "params",    "set",      "simulate",
                                                  "simulate_perfect", "detector", "seed", "min", "max"};

// Validates one file; every error names the file and the JSON path.
class Validator {
 public:
  explicit Validator(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void Fail(const std::string& where, const std::string& what) const {
    throw InputError(path_ + ": " + (where.empty() ? "/" : where) + ": " + what);
  }

  void CheckKeys(const Json& object, const std::string& where, const std::vector<std::string>& known) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        Fail(io::JsonPointerJoin(where, key), "unknown key " + QuoteName(key) + DidYouMean(key, known));
      }
    }
  }

  std::string String(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.contains(key)) return "";
    if (!object[key].is_string()) Fail(where + "/" + key, "expected a string, got " + Describe(object[key]));
    return object[key].get<std::string>();
  }

  bool Bool(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.contains(key)) return false;
    if (!object[key].is_boolean()) Fail(where + "/" + key, "expected true or false, got " + Describe(object[key]));
    return object[key].get<bool>();
  }

  const Json& Object(const Json& object, const std::string& key, const std::string& where) const {
    static const Json empty = Json::object();
    if (!object.contains(key)) return empty;
    if (!object[key].is_object()) Fail(where + "/" + key, "expected an object, got " + Describe(object[key]));
    return object[key];
  }

  static std::string Describe(const Json& value) { return std::string(value.type_name()) + " " + io::JsonExcerpt(value); }

 private:
  std::string path_;
};

std::vector<std::string> DatasetNames() {
  std::vector<std::string> names;
  for (const DatasetEntry& entry : DatasetRegistry()) names.push_back(entry.info.name);
  return names;
}

// The parameter names `dataset` accepts (empty for an unknown dataset).
std::vector<std::string> DatasetParamNames(const std::string& dataset) {
  std::vector<std::string> names;
  if (const DatasetInfo* info = FindDatasetInfo(dataset)) {
    for (const DatasetParam& param : info->params) names.push_back(param.name);
  }
  return names;
}

ThresholdEvaluation ReadEvaluation(const Validator& v, const Json& e, const std::string& where, const fs::path& base) {
  if (!e.is_object()) v.Fail(where, "expected an object, got " + Validator::Describe(e));
  v.CheckKeys(e, where, kEvaluationKeys);
  ThresholdEvaluation evaluation;
  evaluation.json_path = where;
  if (!e.contains("name")) v.Fail(where, "missing \"name\"");
  evaluation.name = v.String(e, "name", where);
  if (evaluation.name.empty()) v.Fail(where + "/name", "empty (the name tells the evaluation apart in the table and JUnit)");
  v.String(e, "description", where);

  InputSpec& input = evaluation.input;
  input.dataset = v.String(e, "dataset", where);
  const std::string labels = v.String(e, "labels", where);
  if (input.dataset.empty() == labels.empty()) v.Fail(where, "give either \"dataset\" or \"labels\"");
  if (!input.dataset.empty()) {
    const std::vector<std::string> known = DatasetNames();
    if (std::find(known.begin(), known.end(), input.dataset) == known.end()) {
      v.Fail(where + "/dataset", "unknown dataset " + QuoteName(input.dataset) + DidYouMean(input.dataset, known) +
                                     "; known: " + Join(known));
    }
  }
  auto resolve = [&](const std::string& key) {
    const std::string value = v.String(e, key, where);
    return value.empty() ? std::string() : (base / value).string();
  };
  input.labels = labels.empty() ? "" : (base / labels).string();
  input.detections = resolve("detections");
  input.root = resolve("root");
  input.simulate = v.Bool(e, "simulate", where);
  input.simulate_perfect = v.Bool(e, "simulate_perfect", where);  // deprecated: "detector": "perfect"
  input.detector = v.String(e, "detector", where);
  if (e.contains("seed")) {
    if (!e["seed"].is_number_unsigned()) {
      v.Fail(where + "/seed", "expected a non-negative integer, got " + Validator::Describe(e["seed"]));
    }
    input.seed = e["seed"].get<uint64_t>();
    input.seed_given = true;
  }
  const std::vector<std::string> param_names = DatasetParamNames(input.dataset);
  for (const auto& [key, value] : v.Object(e, "params", where).items()) {
    if (!input.dataset.empty() && std::find(param_names.begin(), param_names.end(), key) == param_names.end()) {
      v.Fail(io::JsonPointerJoin(where + "/params", key),
             dataset_params::UnknownParamProblem(input.dataset, key, param_names));
    }
    if (!value.is_primitive() || value.is_null()) {
      v.Fail(io::JsonPointerJoin(where + "/params", key), "expected a string, number or boolean, got " +
                                                         Validator::Describe(value));
    }
    input.params.push_back(key + "=" + JsonValueText(value));
  }
  // What rpt eval would refuse before reading anything (a detector without simulate, an unknown
  // profile, a root for the generated dataset), here with the file's place.
  try {
    CheckInputSpec(input);
  } catch (const ConfigError& error) {
    v.Fail(where, std::string("as rpt eval's options: ") + error.what());
  }
  evaluation.required_path = !input.root.empty() ? input.root : !input.labels.empty() ? input.labels : input.detections;

  std::vector<std::string> overrides;
  for (const auto& [key, value] : v.Object(e, "set", where).items()) {
    if (value.is_object() || value.is_null()) {
      v.Fail(io::JsonPointerJoin(where + "/set", key), "expected a string, number, boolean or list, got " +
                                                      Validator::Describe(value));
    }
    overrides.push_back(key + "=" + JsonValueText(value));
  }
  try {
    evaluation.config = ResolveConfig({}, overrides);
  } catch (const ConfigError& error) {
    v.Fail(where + "/set", error.what());
  }

  for (const char* bound : {"min", "max"}) {
    const std::string bound_where = where + "/" + bound;
    for (const auto& [metric, limit] : v.Object(e, bound, where).items()) {
      const std::string metric_where = io::JsonPointerJoin(bound_where, metric);
      const std::vector<std::string>& known = ThresholdMetricNames();
      if (std::find(known.begin(), known.end(), metric) == known.end()) {
        v.Fail(metric_where, "unknown metric " + QuoteName(metric) + DidYouMean(metric, known) + "; known: " + Join(known));
      }
      if (!limit.is_number()) v.Fail(metric_where, "expected a number, got " + Validator::Describe(limit));
      if (metric == "legacy_pcp" && evaluation.config.metrics.legacy_pcp == metrics::LegacyPcpLayout::kNone) {
        v.Fail(metric_where, "legacy_pcp is computed only with metrics.legacy_pcp set (add \"set\": "
                             "{\"metrics.legacy_pcp\": \"shelf\"} or \"campus\")");
      }
      evaluation.checks.push_back({metric, bound, limit.get<double>()});
    }
  }
  // An evaluation without bounds would run and pass whatever it measures.
  if (evaluation.checks.empty()) v.Fail(where, "no \"min\" or \"max\" bound: the evaluation would check nothing");
  for (const ThresholdCheck& low : evaluation.checks) {
    for (const ThresholdCheck& high : evaluation.checks) {
      if (low.bound != "min" || high.bound != "max" || low.metric != high.metric || low.limit <= high.limit) continue;
      v.Fail(io::JsonPointerJoin(where + "/min", low.metric),
             "min " + FormatNumber(low.limit) + " is above max " + FormatNumber(high.limit) + ": the check can never pass");
    }
  }
  return evaluation;
}

}  // namespace

const std::vector<std::string>& ThresholdMetricNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const SummaryColumn& column : SummaryColumns()) out.push_back(column.key);
    out.push_back("legacy_pcp");
    // What the metrics leave out (summary.json; metrics.md): a gate can bound them too.
    for (const char* count : {"dropped_gt_persons", "missing_pred_joints", "unaligned_matches"}) out.push_back(count);
    return out;
  }();
  return names;
}

const std::string& ThresholdsSchemaText() {
  static const std::string text = R"(Thresholds file (JSON; validated as a whole before anything runs):
  {"description": "...",                       optional
   "evaluations": [{
     "name": "synthetic body",                 required, shown in the table
     "description": "...",                     optional
     "dataset": "synthetic",                   a reader of `rpt datasets` (or "labels")
     "labels": "labels.json",                  generic labels file instead of "dataset"
     "root": "../data/shelf",                  dataset folder; absent -> the evaluation is skipped
     "detections": "dets.json",                detections file or folder
     "params": {"cameras": 5},                 dataset parameters (--param)
     "set": {"merge.top_k": 0},                option overrides (--set)
     "simulate": true, "detector": "clean",    simulated detections and their profile
     "seed": 1,                                simulation seed (non-negative integer)
     "min": {"recall500": 99.0},               floors: achieved >= value
     "max": {"mpjpe_mm": 30.0}}]}              ceilings: achieved <= value
  Paths are relative to the thresholds file. Metrics: the summary keys (pcp, pck100, pck500, mpjpe_mm,
  recall100, recall500, invalid, f1, fps, frame_time_us_median, ..., ap25..ap150, legacy_pcp).
  Exit: 0 all checks pass; 1 a check failed, an evaluation failed to run, or (--fail-on-skip) one was
  skipped; 2 the file is invalid (the message names the file and the JSON path).
)";
  return text;
}

ThresholdsFile ReadThresholdsFile(const std::string& path) {
  const Json root = io::LoadJsonFile(path);
  const Validator v(path);
  if (!root.is_object()) v.Fail("", "expected {\"evaluations\": [...]}");
  v.CheckKeys(root, "", kFileKeys);
  v.String(root, "description", "");
  if (!root.contains("evaluations") || !root["evaluations"].is_array()) {
    v.Fail("/evaluations", "expected a list of evaluations");
  }
  ThresholdsFile file;
  file.path = path;
  const fs::path base = fs::path(path).parent_path();
  // An empty list would pass in CI without checking anything.
  if (root["evaluations"].empty()) v.Fail("/evaluations", "no evaluations: the file would check nothing");
  for (size_t i = 0; i < root["evaluations"].size(); ++i) {
    file.evaluations.push_back(
        ReadEvaluation(v, root["evaluations"][i], "/evaluations/" + std::to_string(i), base));
    // Names tell the checks apart in the table, the JSON and the JUnit cases.
    const ThresholdEvaluation& added = file.evaluations.back();
    for (size_t j = 0; j + 1 < file.evaluations.size(); ++j) {
      if (file.evaluations[j].name == added.name)
        v.Fail(added.json_path + "/name", "the name " + QuoteName(added.name) + " is also " +
                                              file.evaluations[j].json_path + "'s: each evaluation needs its own");
    }
  }
  return file;
}

}  // namespace rpt::engine

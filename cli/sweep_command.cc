// SPDX-License-Identifier: MIT
// `rpt sweep`: one evaluation per configuration (a list, or the grid of --grid options), run in
// parallel across configurations with OpenMP, one row per configuration in sweep.{csv,md,json,html}
// (sweep.html: engine/outputs/sweep_html.h).
// `--shard k/N` runs every N-th configuration starting at k (1-based) so a sweep can be split
// across machines; `rpt merge` joins the shard files. `--slurm N` submits the shards as a Slurm job
// array and the merge as a job after it (cli/slurm_submit.h; docs/sweeps.md shows a real run).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "cli/commands.h"
#include "core/printable_text.h"
#include "cli/config_args.h"
#include "cli/input_options.h"
#include "engine/input.h"
#include "engine/output_place.h"
#include "cli/progress.h"
#include "cli/slurm_submit.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/run_info.h"
#include "engine/diagnostics.h"
#include "engine/run.h"
#include "engine/outputs/sweep_html.h"
#include "engine/sweep_configurations.h"
#include "cli/threads_option.h"
#include "engine/parallel_for.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/text.h"
#include "datasets/dataset_request.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/staged_output.h"
#include "datasets/io/text_file.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;
using OrderedJson = nlohmann::ordered_json;

struct SweepArgs {
  engine::InputSpec input;
  ConfigArgs config;
  std::vector<std::string> grid;  // key=v1,v2,...
  std::string list;               // JSON file
  std::string shard = "1/1";
  std::string out = "out/sweep";
  int threads = 0;
  bool threads_given = false;
  int slurm = 0;                            // --slurm N: submit as a job array of N shards
  std::vector<std::string> slurm_options;   // --slurm-option key=value
  bool slurm_dry_run = false;
  bool shard_given = false;
};

std::pair<int, int> ParseShard(const std::string& text) {
  int k = 0, n = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || k < 1 || k > n) {
    throw ConfigError("--shard " + text + ": expected k/N with 1 <= k <= N");
  }
  return {k, n};
}

void WriteTables(const fs::path& dir, const OrderedJson& rows, const std::string& stem) {
  std::vector<std::pair<std::string, OrderedJson>> table;
  for (const OrderedJson& row : rows) table.emplace_back(row["name"].get<std::string>(), row["summary"]);
  io::WriteTextFile(dir / (stem + ".csv"), io::NamedBy::kRpt, engine::SummaryCsv(table));
  io::WriteTextFile(dir / (stem + ".md"), io::NamedBy::kRpt, engine::SummaryMarkdown(table));
}

// <stem>.{csv,md,json} into `out`, each file atomic, the JSON (the data the tables show) last. With
// `whole_folder` the three are swapped in together (io::StagedFolder; other files in `out`, e.g. shard
// files, are kept). Shards share a folder and may finish at the same time on different machines:
// a folder swap could then drop another shard's files, so a shard replaces only its own files.
void WriteSweepFiles(const fs::path& out, const OrderedJson& file, const std::string& stem, bool whole_folder) {
  std::optional<io::StagedFolder> folder;
  if (whole_folder) folder.emplace(out);
  std::error_code ec;
  if (!whole_folder) fs::create_directories(out, ec);
  if (ec) throw InputError(out.string() + ": cannot create output folder: " + ec.message());
  const fs::path dir = whole_folder ? folder->path() : out;
  int replaced = 0;
  try {
    WriteTables(dir, file["rows"], stem);
    io::WriteTextFile(dir / (stem + ".html"), io::NamedBy::kRpt, engine::SweepHtml(file));
    io::WriteTextFile(dir / (stem + ".json"), io::NamedBy::kRpt, io::DumpJson(file, 2, &replaced) + "\n");  // last
    if (folder) folder->Commit();
  } catch (const InputError& e) {
    throw InputError(folder ? folder->NamedAsTarget(e.what()) : std::string(e.what()));
  }
  if (replaced > 0) {
    std::fprintf(stderr, "warning: %s: %d string(s) not valid UTF-8; invalid bytes written as U+FFFD\n",
                 PrintableText((out / (stem + ".json")).string()).c_str(), replaced);
  }
}

// --slurm N: every configuration resolved here first (a typo fails now, not in N jobs), then the
// job scripts written and submitted (cli/slurm_submit.h).
void SubmitToSlurm(const SweepArgs& args, const std::vector<engine::SweepConfiguration>& all) {
  if (args.shard_given) throw ConfigError("--slurm runs every shard itself: leave out --shard");
  for (const engine::SweepConfiguration& configuration : all) {
    ConfigArgs config_args = args.config;
    for (const auto& [key, value] : configuration.overrides) {
      if (key.rfind("param.", 0) != 0) config_args.overrides.push_back(key + "=" + value);
    }
    ResolveConfig(config_args);
  }
  SlurmSweep sweep;
  sweep.shards = std::min<int>(args.slurm, static_cast<int>(all.size()));
  if (sweep.shards < args.slurm) {
    std::fprintf(stderr, "note: --slurm %d: the sweep has %zu configurations; submitting %d shards\n", args.slurm,
                 all.size(), sweep.shards);
  }
  const std::vector<std::string>& command = engine::CurrentCommandArgs();
  sweep.sweep_args.assign(command.begin() + std::min<size_t>(1, command.size()), command.end());
  sweep.sbatch_options = args.slurm_options;
  sweep.out = args.out;
  sweep.threads_given = args.threads_given;
  sweep.dry_run = args.slurm_dry_run;
  SubmitSlurmSweep(sweep);
}

// Rows of configurations that failed to run carry "error" (and an empty summary). Each is printed
// with where the configuration was given (`origin_of`: --grid, a list file's JSON pointer; empty
// when not known, as in a merge), then the command fails (exit 2), after the tables of the others
// were written.
void ThrowIfConfigurationsFailed(const OrderedJson& rows, const std::string& file,
                                 const std::function<std::string(int)>& origin_of) {
  int failed = 0;
  for (const OrderedJson& row : rows) {
    if (!row.contains("error")) continue;
    const int index = row["index"].get<int>();
    const std::string origin = origin_of ? origin_of(index) : std::string();
    const std::string which = "configuration " + QuoteName(row["name"].get<std::string>()) + ", " +
                              std::to_string(index + 1) + " of the sweep";
    std::fprintf(stderr, "error: %s: %s\n",
                 PrintableText(origin.empty() ? which : origin + " (" + which + ")").c_str(),
                 PrintableText(row["error"].get<std::string>()).c_str());
    ++failed;
  }
  if (failed == 0) return;
  throw InputError(std::to_string(failed) + " of " + std::to_string(rows.size()) +
                   " configurations failed to run (above); the others ran: their rows are in " + file);
}

void RunSweep(const SweepArgs& args) {
  if (args.grid.empty() == args.list.empty()) throw ConfigError("give either --grid key=v1,v2 (repeatable) or --list FILE");
  const std::vector<engine::SweepConfiguration> all =
      args.list.empty() ? engine::ExpandSweepGrid(args.grid) : engine::ReadSweepList(args.list);
  // An empty list would write an empty table and pass.
  if (all.empty()) throw InputError(args.list + ": no configurations: the sweep would run nothing");
  for (size_t i = 1; i < all.size(); ++i) {  // a list file checks its own names; a grid can repeat a value
    for (size_t j = 0; j < i; ++j) {
      if (all[i].name == all[j].name) throw ConfigError(all[i].origin + ": configuration " + QuoteName(all[i].name) + " twice");
    }
  }
  if (args.slurm > 0) {
    SubmitToSlurm(args, all);
    return;
  }
  if (!args.slurm_options.empty() || args.slurm_dry_run) throw ConfigError("--slurm-option and --slurm-dry-run need --slurm N");
  const auto [shard, shards] = ParseShard(args.shard);
  engine::CheckOutputOutsideInput(args.out, args.input);
  std::vector<int> mine;
  for (int i = shard - 1; i < static_cast<int>(all.size()); i += shards) mine.push_back(i);

  // Resolve every configuration before running anything: a typo fails fast. Axes named
  // "param.<key>" are dataset parameters (e.g. param.cameras=3,5,10): those configurations load
  // their own input.
  std::vector<engine::Config> configs;
  std::vector<engine::InputSpec> inputs;
  std::vector<bool> is_default;  // the configuration is the base one (sweep.html's deltas are against it)
  std::vector<bool> measured_differently;  // its metrics options differ from the base's: no deltas
  const auto metrics_text = [](const engine::Config& config) {
    engine::Config metrics_only;
    metrics_only.metrics = config.metrics;
    return engine::DumpConfig(metrics_only, false);
  };
  bool per_config_input = false;
  std::vector<std::vector<std::string>> option_warnings;  // per configuration: settings without effect
  const engine::Config base_options = ResolveConfig(args.config);
  const std::string base_config = engine::DumpConfig(base_options, false);
  const std::string base_metrics = metrics_text(base_options);
  for (int i : mine) {
    ConfigArgs config_args = args.config;
    engine::InputSpec input = args.input;
    for (const auto& [key, value] : all[i].overrides) {
      if (key.rfind("param.", 0) == 0) {
        input.params.push_back(key.substr(6) + "=" + value);
        per_config_input = true;
      } else {
        config_args.overrides.push_back(key + "=" + value);
      }
    }
    try {
      // Settings without effect are the configuration's own warnings (in its row, named when
      // printed), not unnamed lines before the run.
      configs.push_back(engine::ResolveConfig(config_args.config_file, config_args.overrides));
      option_warnings.push_back(engine::ConfigWarnings(configs.back()));
    } catch (const ConfigError& e) {  // name the configuration and where it was given
      throw ConfigError(all[i].origin + " (configuration " + QuoteName(all[i].name) + "): " + e.what());
    }
    inputs.push_back(input);
    is_default.push_back(input.params == args.input.params && engine::DumpConfig(configs.back(), false) == base_config);
    measured_differently.push_back(metrics_text(configs.back()) != base_metrics);
    if (measured_differently.back()) {
      std::fprintf(stderr,
                   "warning: configuration %s changes a metrics option: it is measured differently from the others, "
                   "so sweep.html shows no difference for it\n",
                   PrintableText(QuoteName(all[i].name)).c_str());
    }
  }
  // One warning line per file and kind, not one per configuration: configurations that load their
  // own input read the same files again (MergeRepeated).
  InputWarnings warnings;
  const std::vector<Sequence> shared_input =
      per_config_input ? std::vector<Sequence>{} : engine::LoadInput(args.input, {}, &warnings);
  if (!per_config_input) PrintInputWarnings(warnings);
  std::vector<InputWarnings> config_warnings(mine.size());
  std::vector<std::vector<std::string>> evaluated_joints(mine.size());  // per configuration, from its metrics

  std::vector<OrderedJson> summaries(mine.size());
  // A configuration that fails when it runs (e.g. core joints the input does not have) does not
  // cost the others: its row records the error, named with where it was given (one of 23
  // ablations was not otherwise told apart), and the sweep exits 2 once the tables are written.
  std::vector<std::string> failures(mine.size());
  std::atomic<long> done{0};
  std::optional<Progress> progress;  // ended before the warnings are printed (its bar owns the line)
  progress.emplace("sweep", static_cast<long>(mine.size()));
  const int count = static_cast<int>(mine.size());
  const int threads = engine::ParallelFor(count, args.threads, [&](int c, bool report_progress) {
    try {
      engine::RunOptions options;
      options.triangulator = configs[c].triangulator;
      options.eval = configs[c].metrics;
      options.threads = 1;
      options.require_frames = true;
      // The result warnings `rpt eval` would give (no predictions, low recall, ...) go into the
      // row's summary as in summary.json, and are printed after the table.
      const auto summarise = [&](const engine::RunResult& run) {
        summaries[c] = engine::SummaryJson(run);
        for (const metrics::JointResult& joint : run.metrics.joints) evaluated_joints[c].push_back(joint.name);
        OrderedJson listed = OrderedJson::array();
        for (const std::string& w : option_warnings[c]) listed.push_back({{"code", "option_without_effect"}, {"message", w}});
        for (const engine::CheckWarning& w : engine::ResultWarnings(run)) listed.push_back({{"code", w.code}, {"message", w.message}});
        summaries[c]["warnings"] = listed;
      };
      if (per_config_input) {
        engine::Input input = engine::OpenInput(inputs[c]);
        const engine::RunResult run = engine::Run(input, options);
        config_warnings[c] = run.warnings;
        summarise(run);
      } else {
        summarise(engine::Run(shared_input, options));
      }
    } catch (const InputError& e) {
      failures[c] = e.what();
    } catch (const ConfigError& e) {
      failures[c] = e.what();
    }
    if (!failures[c].empty()) summaries[c] = OrderedJson::object();
    const long finished = ++done;
    if (report_progress) progress->Update(finished);
  });
  progress.reset();
  if (per_config_input) {
    for (const InputWarnings& w : config_warnings) warnings.MergeRepeated(w);
    PrintInputWarnings(warnings);
    // A param.* axis may change what is evaluated (MVOR's param.evaluated adds the head): such a
    // row is measured differently from the reference (the default row, else the first).
    int reference = 0;
    for (int c = 0; c < count; ++c) {
      if (is_default[c]) {
        reference = c;
        break;
      }
    }
    for (int c = 0; c < count; ++c) {
      if (!failures[c].empty() || !failures[reference].empty() || measured_differently[c] ||
          evaluated_joints[c] == evaluated_joints[reference]) {
        continue;
      }
      measured_differently[c] = true;
      std::fprintf(stderr,
                   "warning: configuration %s evaluates other joints (%s) than %s: it is measured differently from "
                   "the others, so sweep.html shows no difference for it\n",
                   PrintableText(QuoteName(all[mine[c]].name)).c_str(), PrintableText(Join(evaluated_joints[c])).c_str(),
                   PrintableText(QuoteName(all[mine[reference]].name)).c_str());
    }
  }

  OrderedJson rows = OrderedJson::array();
  for (int c = 0; c < count; ++c) {
    OrderedJson set = OrderedJson::object();
    for (const auto& [key, value] : all[mine[c]].overrides) set[key] = value;
    rows.push_back({{"index", mine[c]},
                    {"name", all[mine[c]].name},
                    {"set", set},
                    {"default", static_cast<bool>(is_default[c])},
                    {"measured_differently", static_cast<bool>(measured_differently[c])},
                    {"summary", summaries[c]}});
    if (!failures[c].empty()) rows.back()["error"] = failures[c];
  }
  // The base configuration's value of every varied option (sweep.html shows them greyed where a
  // row does not set the option).
  OrderedJson base = OrderedJson::object();
  for (const engine::SweepConfiguration& v : all) {
    for (const auto& [key, value] : v.overrides) {
      if (key.rfind("param.", 0) != 0 && !base.contains(key)) base[key] = engine::GetConfigOption(base_options, key);
    }
  }
  OrderedJson file;
  file["total"] = all.size();
  file["shard"] = args.shard;
  engine::RunInfo info = engine::CollectRunInfo(threads);
  info.input_warnings = engine::InputWarningLines(warnings);
  file["run"] = engine::RunInfoJson(info, args.out);
  file["sweep"] = engine::SweepIdentity(all, base_config, args.input);
  file["base"] = base;
  // Every option of the base configuration (defaults, --config, --set), as `rpt config --dump`
  // prints it: what a reader cites, and what the sweep ran with should the --config file change.
  file["base_options"] = OrderedJson::parse(base_config);
  file["rows"] = rows;
  // A shard asked for (also 1/1: a job array of one task) writes its shard file for `rpt merge`.
  const bool shard_file = args.shard_given;
  const std::string stem =
      shard_file ? "sweep-shard-" + std::to_string(shard) + "-of-" + std::to_string(shards) : "sweep";
  WriteSweepFiles(args.out, file, stem, /*whole_folder=*/!shard_file);
  std::cout << engine::SummaryMarkdown([&] {
    std::vector<std::pair<std::string, OrderedJson>> table;
    for (const OrderedJson& row : rows) table.emplace_back(row["name"].get<std::string>(), row["summary"]);
    return table;
  }());
  std::fflush(stdout);  // the table is the data (stdout); where it was written is a status line (stderr)
  std::fprintf(stderr, "%d of %zu configurations; tables in %s/%s.{json,csv,md,html}\n", count, all.size(),
               PrintableText(args.out, LineBreaks::kEscape).c_str(), stem.c_str());
  for (const OrderedJson& row : rows) {
    if (!row["summary"].contains("warnings")) continue;
    for (const OrderedJson& w : row["summary"]["warnings"]) {
      std::fprintf(stderr, "warning: configuration %s: %s\n", QuoteName(row["name"].get<std::string>()).c_str(),
                   PrintableText(w["message"].get<std::string>()).c_str());
    }
  }
  ThrowIfConfigurationsFailed(rows, args.out + "/" + stem + ".json", [&](int index) { return all[index].origin; });
}

[[noreturn]] void FailAt(const std::string& source, const std::string& pointer, const std::string& what) {
  throw InputError(source + ": " + pointer + ": " + what);
}

// The value at `pointer` when it is an object, else an InputError naming file and pointer.
const nlohmann::json& ObjectAt(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                               const std::string& what) {
  const nlohmann::json& j = io::JsonAt(root, pointer, source);
  if (!j.is_object()) FailAt(source, pointer, "expected " + what + ", got " + j.type_name());
  return j;
}

// A row of a shard file, checked field by field as the tables and sweep.html read it: index in
// [0, total), name, set (optional object), default (optional boolean), summary (an object whose
// table columns are numbers or null). A damaged or hand-edited file is an InputError naming the
// file and the JSON pointer, not an "internal error" from deep inside nlohmann.
OrderedJson CheckedShardRow(const nlohmann::json& shard, const std::string& pointer, const std::string& source,
                            std::int64_t total, int* index) {
  ObjectAt(shard, pointer, source, "a row {\"index\", \"name\", \"set\", \"summary\"}");
  *index = static_cast<int>(io::JsonIntIn(shard, pointer + "/index", source, 0, total - 1));
  const std::string name = io::JsonString(shard, pointer + "/name", source);
  if (io::JsonFind(shard, pointer + "/set")) ObjectAt(shard, pointer + "/set", source, "an object {option: value}");
  // The row must be the configuration its index names in the shard's own sweep (a row whose "set"
  // says top_k 7 under the name top_k=0 was merged as is).
  const nlohmann::json* configurations = io::JsonFind(shard, "/sweep/configurations");
  if (configurations != nullptr && configurations->is_array()) {
    if (static_cast<std::int64_t>(configurations->size()) != total) {
      FailAt(source, "/sweep/configurations", "lists " + std::to_string(configurations->size()) +
                                                  " configurations, /total says " + std::to_string(total));
    }
    const nlohmann::json& configuration = (*configurations)[static_cast<size_t>(*index)];
    const nlohmann::json set = io::JsonFind(shard, pointer + "/set") ? io::JsonAt(shard, pointer + "/set", source)
                                                                     : nlohmann::json::object();
    if (configuration.value("name", std::string()) != name || configuration.value("set", nlohmann::json::object()) != set) {
      FailAt(source, pointer, "is not configuration " + std::to_string(*index + 1) + " of the shard's sweep (/sweep/" +
                                  "configurations/" + std::to_string(*index) + " is " +
                                  QuoteName(configuration.value("name", std::string())) + " with other options)");
    }
  }
  if (io::JsonFind(shard, pointer + "/default")) io::JsonBool(shard, pointer + "/default", source);
  if (io::JsonFind(shard, pointer + "/error")) io::JsonString(shard, pointer + "/error", source);  // it failed to run
  if (io::JsonFind(shard, pointer + "/measured_differently")) {
    io::JsonBool(shard, pointer + "/measured_differently", source);
  }
  engine::CheckSummaryValues(ObjectAt(shard, pointer + "/summary", source, "an object of metrics"), source,
                             pointer + "/summary");
  return OrderedJson::parse(io::JsonAt(shard, pointer, source).dump());
}

void RunMerge(const std::vector<std::string>& inputs, const std::string& out, bool strict) {
  std::map<int, OrderedJson> by_index;
  OrderedJson base_options;  // the first shard's "base_options" (all shards share base_config)
  OrderedJson base = OrderedJson::object();
  std::int64_t total = -1;
  // The sweep the first shard belongs to (its configurations, base options and input): every other
  // shard must record the same, or the table would mix rows of different sweeps.
  nlohmann::json sweep;
  std::string sweep_source;
  OrderedJson shard_runs = OrderedJson::array();
  std::vector<std::pair<std::string, std::string>> revisions;  // shard file, rpt revision that ran it
  for (const std::string& path : inputs) {
    const nlohmann::json shard = io::LoadJsonFile(path);
    if (!shard.is_object() || !shard.contains("rows") || !shard.contains("total")) {
      throw InputError(path + ": not a sweep shard file (expected an object with \"total\" and \"rows\")");
    }
    if (!shard.contains("sweep")) {
      throw InputError(path + ": records no \"sweep\" (what it is a shard of; written by an older rpt): it cannot be told "
                       "apart from a shard of another sweep; run the shards again");
    }
    if (sweep_source.empty()) {
      sweep = shard["sweep"];
      sweep_source = path;
    } else if (shard["sweep"] != sweep) {
      std::string part = "configurations";
      for (const char* key : {"input", "base_config", "configurations"}) {
        if (!shard["sweep"].contains(key) || shard["sweep"][key] != sweep.value(key, nlohmann::json())) {
          part = key;
          break;
        }
      }
      throw InputError(path + ": a shard of another sweep than " + sweep_source + " (their /sweep/" + part +
                       " differ): merge the shards of one sweep");
    }
    if (shard.contains("run")) {
      shard_runs.push_back(OrderedJson::parse(shard["run"].dump()));
      const nlohmann::json* revision = io::JsonFind(shard, "/run/git_revision");
      if (revision != nullptr && revision->is_string()) revisions.emplace_back(path, revision->get<std::string>());
    }
    // Configuration indices are ints; the bound also keeps the check for missing ones short.
    const std::int64_t shard_total = io::JsonIntIn(shard, "/total", path, 0, std::numeric_limits<int>::max());
    if (total >= 0 && shard_total != total) {
      throw InputError(path + ": belongs to a sweep of " + std::to_string(shard_total) +
                       " configurations, the others to " + std::to_string(total));
    }
    total = shard_total;
    if (shard.contains("base")) {
      base.update(OrderedJson::parse(ObjectAt(shard, "/base", path, "an object {option: base value}").dump()));
    }
    if (shard.contains("base_options") && base_options.is_null()) {
      base_options = OrderedJson::parse(ObjectAt(shard, "/base_options", path, "an object (rpt config --dump)").dump());
    }
    const nlohmann::json& rows = io::JsonAt(shard, "/rows", path);
    if (!rows.is_array()) FailAt(path, "/rows", std::string("expected a list of rows, got ") + rows.type_name());
    // The rows must be those of the shard the file says it is (a file renamed or edited by hand).
    int shard_k = 1, shard_n = 1;
    if (io::JsonFind(shard, "/shard")) {
      const std::string text = io::JsonString(shard, "/shard", path);
      try {
        std::tie(shard_k, shard_n) = ParseShard(text);
      } catch (const ConfigError&) {
        FailAt(path, "/shard", QuoteName(text) + " is not k/N with 1 <= k <= N");
      }
    }
    for (size_t i = 0; i < rows.size(); ++i) {
      int index = 0;
      OrderedJson row = CheckedShardRow(shard, io::JsonPointerJoin("/rows", i), path, total, &index);
      if (index % shard_n != shard_k - 1) {
        FailAt(path, io::JsonPointerJoin("/rows", i) + "/index",
               "configuration " + std::to_string(index + 1) + " is not one of shard " + std::to_string(shard_k) + "/" +
                   std::to_string(shard_n) + " (/shard), which runs configurations " + std::to_string(shard_k) +
                   ", " + std::to_string(shard_k + shard_n) + ", ...");
      }
      if (!by_index.emplace(index, std::move(row)).second) {
        throw InputError(path + ": configuration " + std::to_string(index + 1) + " of " + std::to_string(total) +
                         " appears in two shard files");
      }
    }
  }
  // Every index is in [0, total): the missing ones are total - found; the first 20 are named.
  const std::int64_t missing_count = total - static_cast<std::int64_t>(by_index.size());
  if (missing_count > 0) {
    std::string missing;
    int named = 0;
    for (int i = 0; i < total && named < 20; ++i) {
      if (!by_index.count(i)) {
        AppendItem(&missing, std::to_string(i + 1));
        ++named;
      }
    }
    if (missing_count > named) missing += ", ... (" + std::to_string(missing_count) + " in all)";
    throw InputError("merge: configurations missing (shard files absent?), counted from 1 as --shard counts: " +
                     missing + " of " + std::to_string(total));
  }
  // Shards run by different builds of rpt (one rebuilt between shards) may not measure alike.
  for (const auto& [path, revision] : revisions) {
    if (revision == revisions.front().second) continue;
    const std::string message = "merge: the shards were run by different revisions of rpt (" +
                                revisions.front().second + " in " + revisions.front().first + ", " + revision + " in " +
                                path + "): rows of different builds may not be comparable";
    if (strict) throw InputError(message + " (--strict)");
    std::fprintf(stderr, "warning: %s\n", PrintableText(message).c_str());
    break;
  }
  OrderedJson rows = OrderedJson::array();
  for (auto& [index, row] : by_index) rows.push_back(row);
  OrderedJson file;
  file["total"] = total;
  file["shard"] = "1/1";
  file["run"] = engine::RunInfoJson(engine::CollectRunInfo(1), out);  // the merge; the shards' runs follow
  file["shard_runs"] = shard_runs;
  file["sweep"] = OrderedJson::parse(sweep.dump());
  file["base"] = base;
  if (!base_options.is_null()) file["base_options"] = base_options;  // the shards' base is one (checked above)
  file["rows"] = rows;
  WriteSweepFiles(out, file, "sweep", /*whole_folder=*/true);
  std::fprintf(stderr, "merged %zu configurations from %zu shard files into %s/sweep.{json,csv,md,html}\n",
               by_index.size(), inputs.size(), PrintableText(out, LineBreaks::kEscape).c_str());
  ThrowIfConfigurationsFailed(rows, out + "/sweep.json", nullptr);
}

}  // namespace

void RegisterSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* command = app.add_subcommand("sweep", "Evaluate a list or grid of configurations, one row each");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  command->add_option("--grid", args->grid,
                      "key=v1,v2,... (repeatable; the product of all axes); param.<key> axes vary a dataset parameter")
      ->take_all();
  command->add_option("--list", args->list, "JSON list of {\"name\", \"set\": {key: value}} (e.g. results/ablations.json)");
  command->add_option("--shard", args->shard, "k/N: run configurations k, k+N, ... (1-based)")->capture_default_str();
  command->add_option("--out", args->out, "output folder")->capture_default_str();
  AddThreadsOption(command, &args->threads, "configurations");
  const std::string slurm_group = "Slurm (docs/sweeps.md)";
  command
      ->add_option("--slurm", args->slurm,
                   "N: submit the sweep to Slurm as a job array of N shards (at most the configurations) and a merge "
                   "job that runs when all succeeded; the job scripts and logs go to <out>/slurm/")
      ->check(CLI::PositiveNumber)
      ->group(slurm_group);
  command
      ->add_option("--slurm-option", args->slurm_options,
                   "sbatch option for both jobs without its dashes, e.g. time=01:00:00, partition=cpu, "
                   "cpus-per-task=4 (repeatable)")
      ->group(slurm_group);
  command->add_flag("--slurm-dry-run", args->slurm_dry_run, "with --slurm: write the job scripts, do not submit")
      ->group(slurm_group);
  command->callback([args, command] {
    args->threads_given = command->get_option("--threads")->count() > 0;
    args->shard_given = command->get_option("--shard")->count() > 0;
    RunSweep(*args);
  });
}

void RegisterMergeCommand(CLI::App& app) {
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto out = std::make_shared<std::string>("out/sweep");
  CLI::App* command = app.add_subcommand("merge", "Join the shard files of a sharded sweep into one table");
  command->add_option("shards", *inputs, "sweep-shard-*.json files")->required();
  command->add_option("--out", *out, "output folder")->capture_default_str();
  auto strict = std::make_shared<bool>(false);
  command->add_flag("--strict", *strict, "shards run by different revisions of rpt are an error (exit 2), not a warning");
  command->callback([inputs, out, strict] { RunMerge(*inputs, *out, *strict); });
}

}  // namespace rpt::cli

// SPDX-License-Identifier: MIT
#include "engine/report/report_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <fstream>
#include <sstream>

#include "core/errors.h"
#include "core/option_codec.h"
#include "datasets/io/json_output.h"
#include "engine/outputs/export_options.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/text_escaping.h"
#include "datasets/io/json_file.h"
#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;

// Through the one guarded JSON path (a regular file within --max-input-mb, nesting within
// io::kMaxJsonDepth, messages that quote at most a short excerpt); ordered: the report lists steps
// and options in the run's order.
OrderedJson LoadOrdered(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    const std::filesystem::path folder = path.parent_path();
    if (std::filesystem::exists(folder / "sweep.json")) {  // a sweep's folder has its own page
      throw InputError(path.string() + ": file not found: " + folder.string() +
                       " is the output folder of `rpt sweep`, whose report is its sweep.html");
    }
    throw InputError(path.string() + ": file not found (is this the output folder of `rpt eval` or `rpt triangulate`?)");
  }
  return io::LoadOrderedJsonFile(path);
}

// per_joint.csv: joint,mean_error_mm,pck100_pct,count,num_gt ("-" = no value).
OrderedJson ReadPerJoint(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": file not found");
  if (!std::filesystem::is_regular_file(path)) throw InputError(path.string() + ": not a regular file");
  OrderedJson rows = OrderedJson::array();
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 || line.empty()) continue;
    std::vector<std::string> fields;
    try {
      fields = SplitCsvLine(line);  // the writer's quoting (a joint name may hold a comma)
    } catch (const std::invalid_argument& e) {
      throw InputError(path.string() + ":" + std::to_string(line_number) + ": " + e.what());
    }
    if (fields.size() != 5) {
      throw InputError(path.string() + ":" + std::to_string(line_number) + ": expected 5 fields, found " +
                       std::to_string(fields.size()));
    }
    auto number = [&](const std::string& text) -> OrderedJson {
      if (text == "-" || text.empty()) return nullptr;
      double value = 0;
      if (!ParseNumber(text, &value)) {
        throw InputError(path.string() + ":" + std::to_string(line_number) + ": " + QuoteName(text) + " is not a number");
      }
      return value;
    };
    rows.push_back({{"joint", fields[0]}, {"mean_error_mm", number(fields[1])}, {"pck100", number(fields[2])},
                    {"count", number(fields[3])}});
  }
  return rows;
}

// A person of predictions.json: num_joints rows of x, y, z, score. A joint the export did not write
// (a filled one with --no-filled-joints) is [null, null, null, 0]: missing, score 0 (report and
// render refused such runs: "found null in row 9").
std::vector<double> PersonValues(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                                 int num_joints) {
  const nlohmann::json& rows = io::JsonAt(root, pointer, source);
  std::vector<double> values(4 * static_cast<size_t>(num_joints), 0.0);
  const auto fail = [&]() -> void {
    throw InputError(source + ": " + pointer + ": expected " + std::to_string(num_joints) +
                     "x4 array of numbers (a joint not written: null, null, null, 0)");
  };
  if (!rows.is_array() || rows.size() != static_cast<size_t>(num_joints)) fail();
  for (int j = 0; j < num_joints; ++j) {
    const nlohmann::json& row = rows[static_cast<size_t>(j)];
    if (!row.is_array() || row.size() != 4) fail();
    if (row[0].is_null() && row[1].is_null() && row[2].is_null() && row[3].is_number() && row[3].get<double>() == 0) {
      continue;  // not written: missing
    }
    for (int k = 0; k < 4; ++k) {
      if (!row[static_cast<size_t>(k)].is_number()) fail();
      values[4 * static_cast<size_t>(j) + k] = row[static_cast<size_t>(k)].get<double>();
    }
  }
  return values;
}

RecordedPredictions ReadPredictions(const std::filesystem::path& path) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  RecordedPredictions out;
  if (const auto id = root.find("run_id"); id != root.end() && id->is_string()) out.run_id = id->get<std::string>();
  for (const auto& name : io::JsonAt(root, "/joints", source)) {
    if (!name.is_string()) throw InputError(source + ": /joints: expected strings");
    out.joints.push_back(name.get<std::string>());
  }
  const nlohmann::json& frames = io::JsonAt(root, "/frames", source);
  if (!frames.is_array()) throw InputError(source + ": /frames: expected an array");
  const int num_joints = static_cast<int>(out.joints.size());
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::string pointer = "/frames/" + std::to_string(f);
    const nlohmann::json& id = io::JsonAt(root, pointer + "/id", source);
    if (!id.is_string() && !id.is_number_integer()) {
      throw InputError(source + ": " + pointer + "/id: expected a string or an integer, got " + io::JsonExcerpt(id));
    }
    out.frame_ids.push_back(id.is_string() ? id.get<std::string>() : id.dump());
    const nlohmann::json& persons = io::JsonAt(root, pointer + "/persons", source);
    const std::vector<double> track_ids = io::JsonNumbers(root, pointer + "/track_ids", source, persons.size());
    Poses3D poses;
    poses.Clear(num_joints);
    for (size_t p = 0; p < persons.size(); ++p) {
      const std::vector<double> values = PersonValues(root, pointer + "/persons/" + std::to_string(p), source, num_joints);
      // A track id rpt writes: -1 (untracked) or a non-negative int. Another value (1e30, 2.5) was
      // cast to some other id, shown on the page and in the images as a different track.
      const double track_id = track_ids[p];
      if (!(track_id >= -1 && track_id <= std::numeric_limits<int>::max() && track_id == std::floor(track_id))) {
        const std::string at = pointer + "/track_ids/" + std::to_string(p);
        throw InputError(source + ": " + at + ": " + io::JsonExcerpt(root.at(nlohmann::json::json_pointer(at))) +
                         " is not a track id (-1 or an integer from 0 to " +
                         std::to_string(std::numeric_limits<int>::max()) + ")");
      }
      // Joint scores rpt writes lie in [0, 1].
      for (int j = 0; j < num_joints; ++j) {
        const double score = values[4 * j + 3];
        if (!(score >= 0 && score <= 1)) {
          throw InputError(source + ": " + pointer + "/persons/" + std::to_string(p) + "/" + std::to_string(j) +
                           "/3: score " + FormatNumber(score) + " outside [0, 1]");
        }
      }
      auto person = poses.AddPerson(static_cast<int>(track_id));
      for (int j = 0; j < num_joints; ++j) {
        for (int k = 0; k < 4; ++k) person(k, j) = values[4 * j + k];
      }
    }
    out.frames.push_back(std::move(poses));
  }
  return out;
}

}  // namespace

// The recorded command's words: "argv" (the argument vector) when run.json has it, else "command"
// split at spaces (run.json files written before "argv": a path with a space is cut there). An
// "argv" that is not a list of strings gives no words and says why in *problem.
std::vector<std::string> RecordedWords(const RecordedRun& run, std::string* problem) {
  const auto argv = run.run_info.find("argv");
  if (argv != run.run_info.end()) {
    std::vector<std::string> words;
    for (size_t i = 0; argv->is_array() && i < argv->size(); ++i) {
      if (!(*argv)[i].is_string()) break;
      words.push_back((*argv)[i].get<std::string>());
    }
    if (argv->is_array() && words.size() == argv->size()) return words;
    if (problem) {
      *problem = (run.dir / "run.json").string() + ": /argv: expected a list of strings, got " +
                 (argv->is_array() ? "a list holding a " + std::string((*argv)[words.size()].type_name())
                                   : std::string(argv->type_name()));
    }
    return {};
  }
  const auto it = run.run_info.find("command");
  if (it == run.run_info.end() || !it->is_string()) return {};
  std::vector<std::string> words;
  std::stringstream s(it->get<std::string>());
  std::string word;
  while (s >> word) words.push_back(word);
  return words;
}


RecordedRun ReadRecordedRun(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) throw InputError(dir.string() + ": not a folder");
  RecordedRun run;
  run.dir = dir;
  run.summary = LoadOrdered(dir / "summary.json");
  // A summary from someone else: its numbers go into the page as they are, so ones no run writes
  // (a string, a percentage above 100, a negative count) are refused as rpt merge refuses them.
  CheckSummaryValues(nlohmann::json(run.summary), (dir / "summary.json").string(), "");
  run.config = LoadOrdered(dir / "config.json");
  run.run_info = LoadOrdered(dir / "run.json");
  // A run without ground truth (rpt triangulate, summary "evaluated": false) has no per-joint errors.
  const auto evaluated = run.summary.find("evaluated");
  const bool without_gt = evaluated != run.summary.end() && evaluated->is_boolean() && !evaluated->get<bool>();
  run.per_joint = without_gt ? OrderedJson::array() : ReadPerJoint(dir / "per_joint.csv");
  if (!std::filesystem::exists(dir / "predictions.json")) {
    const std::vector<std::string> words = RecordedWords(run);
    if (std::find(words.begin(), words.end(), "--no-predictions") != words.end()) {
      throw InputError((dir / "predictions.json").string() +
                       ": not written: the run was made with --no-predictions (run.json), so there are no 3D persons "
                       "to draw; run its command again without that option");
    }
    // --export without json (csv for pandas): predictions.json is not written, and the page reads it.
    for (size_t i = 0; i < words.size(); ++i) {
      std::string formats;
      if (words[i] == "--export" && i + 1 < words.size()) formats = words[i + 1];
      if (words[i].rfind("--export=", 0) == 0) formats = words[i].substr(9);
      if (formats.empty()) continue;
      // A run that did write json (predictions.json deleted since) is told "file not found" below.
      std::vector<ExportFormat> exported;
      try {
        exported = ParseExportFormats(formats);
      } catch (const ConfigError&) {
        continue;
      }
      if (std::find(exported.begin(), exported.end(), ExportFormat::kJson) != exported.end()) continue;
      throw InputError((dir / "predictions.json").string() + ": not written: the run was made with --export " +
                       PrintableText(formats, LineBreaks::kEscape) +
                       " (run.json), without json; the report reads predictions.json: run its command again with "
                       "--export json," + PrintableText(formats, LineBreaks::kEscape));
    }
  }
  run.predictions = ReadPredictions(dir / "predictions.json");
  // The files of one run share its run_id: a predictions.json copied in from another run would give
  // a page whose plots and 3D frames contradict its summary.
  std::vector<std::pair<std::string, std::string>> ids;  // file, run_id
  for (const auto& [file, json] : {std::pair<const char*, const OrderedJson*>{"summary.json", &run.summary},
                                   {"run.json", &run.run_info}}) {
    if (const auto id = json->find("run_id"); id != json->end() && id->is_string()) ids.emplace_back(file, id->get<std::string>());
  }
  if (!run.predictions.run_id.empty()) ids.emplace_back("predictions.json", run.predictions.run_id);
  for (const auto& [file, id] : ids) {
    if (id == ids.front().second) continue;
    throw InputError(dir.string() + ": " + ids.front().first + " is of run " + QuoteName(ids.front().second) + ", " +
                     file + " of run " + QuoteName(id) +
                     ": the folder mixes the files of two runs (re-run the command of run.json into a new folder)");
  }
  return run;
}

std::string RecordedDataset(const RecordedRun& run) {
  const std::vector<std::string> words = RecordedWords(run);
  for (size_t i = 0; i + 1 < words.size(); ++i) {
    if (words[i] == "--dataset") return words[i + 1];
  }
  for (const std::string& word : words) {
    if (word.rfind("--dataset=", 0) == 0) return word.substr(10);
  }
  return "";
}

bool SplitPredictions(const RecordedPredictions& predictions, const std::vector<Sequence>& sequences,
                      std::vector<std::vector<Poses3D>>* per_sequence, std::string* why) {
  size_t total = 0;
  for (const Sequence& s : sequences) total += s.frames.size();
  if (total != predictions.frames.size()) {
    *why = "predictions.json has " + std::to_string(predictions.frames.size()) + " frames, the input " +
           std::to_string(total);
    return false;
  }
  per_sequence->assign(sequences.size(), {});
  size_t k = 0;
  for (size_t s = 0; s < sequences.size(); ++s) {
    for (const SequenceFrame& frame : sequences[s].frames) {
      // predictions.json holds an id that is not UTF-8 (bytes of a file name) with U+FFFD in place
      // of the bad bytes: compared as written.
      if (frame.id != predictions.frame_ids[k] && io::ValidUtf8(frame.id) != predictions.frame_ids[k]) {
        *why = "frame " + std::to_string(k) + " of predictions.json is " + QuoteName(predictions.frame_ids[k]) +
               ", the input's is " + QuoteName(frame.id);
        return false;
      }
      (*per_sequence)[s].push_back(predictions.frames[k++]);
    }
  }
  return true;
}

}  // namespace rpt::engine

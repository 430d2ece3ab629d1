// SPDX-License-Identifier: MIT
#include "engine/outputs/loss_tables.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace rpt::engine {
namespace {

double PercentOfWhole(long part, long whole) { return whole > 0 ? 100.0 * static_cast<double>(part) / whole : 0.0; }

// PCP with every part that `beyond` parts of `parts.evaluated` miss.
double PcpWithout(const PartLosses& parts, long beyond) {
  return PercentOfWhole(parts.evaluated - beyond, parts.evaluated);
}

void PrintPartLosses(std::ostream& out, const LossTable& table) {
  const PartLosses all = table.AllParts();
  if (all.evaluated == 0) return;
  char line[200];
  std::snprintf(line, sizeof(line), "PCP parts: %ld evaluated, %ld wrong (PCP %.2f %%)\n", all.evaluated, all.wrong,
                PcpWithout(all, all.wrong));
  out << line;
  std::snprintf(line, sizeof(line),
                "  beyond the best pair of the person's own detections: %ld (PCP %.2f %% if only those were wrong), "
                "%ld of them wrong\n",
                all.beyond_best_pair, PcpWithout(all, all.beyond_best_pair), all.wrong_beyond_best_pair);
  out << line;
  std::snprintf(line, sizeof(line), "  %-20s %9s %7s %16s %22s\n", "part", "evaluated", "wrong", "beyond_best_pair",
                "wrong_beyond_best_pair");
  out << line;
  for (int k = 0; k < kNumPcpParts; ++k) {
    const PartLosses& part = table.parts[k];
    if (part.evaluated == 0) continue;
    std::snprintf(line, sizeof(line), "  %-20s %9ld %7ld %16ld %22ld\n", metrics::GenericPcpParts()[k].name.c_str(),
                  part.evaluated, part.wrong, part.beyond_best_pair, part.wrong_beyond_best_pair);
    out << line;
  }
}

void PrintJointReferences(std::ostream& out, const JointReferences& joints) {
  if (joints.joints == 0) return;
  const double n = static_cast<double>(joints.joints);
  char line[200];
  std::snprintf(line, sizeof(line),
                "joint errors over the %ld joints of matched persons that 2 or more of their views detected (mean, "
                "mm):\n",
                joints.joints);
  out << line;
  std::snprintf(line, sizeof(line),
                "  output %.1f, all those views fitted (confidence-weighted rays) %.1f, best pair per joint (chosen "
                "with the GT) %.1f\n",
                joints.output_mm / n, joints.all_views_mm / n, joints.best_pair_mm / n);
  out << line;
}

nlohmann::ordered_json PartLossesJson(const PartLosses& parts) {
  nlohmann::ordered_json j;
  j["evaluated"] = parts.evaluated;
  j["wrong"] = parts.wrong;
  j["beyond_best_pair"] = parts.beyond_best_pair;
  j["wrong_beyond_best_pair"] = parts.wrong_beyond_best_pair;
  return j;
}

}  // namespace

std::vector<LossRow> LossRows(const LossTable& t) {
  std::vector<LossRow> rows;
  const auto category = [&](Loss loss, const char* label) { rows.push_back({LossKey(loss), "", label, t[loss]}); };
  const auto detail = [&](Loss loss, const char* key, const char* label, long persons) {
    rows.push_back({LossKey(loss), key, label, persons});
  };
  category(Loss::kFound, "found (matched within 500 mm)");
  detail(Loss::kFound, "fewer_than_2_views", "of those, detected in fewer than 2 views", t.found_fewer_than_2_views);
  category(Loss::kFewerThanTwoViews, "detected in fewer than 2 views");
  detail(Loss::kFewerThanTwoViews, "no_view", "in no view", t.in_no_view);
  detail(Loss::kFewerThanTwoViews, "one_view", "in one view", t.in_one_view);
  category(Loss::kPairFiltered, "pair filtered (no true pair left)");
  static constexpr std::array<const char*, 5> kDropperLabels = {
      "no pair made (undistort: too few core joints)", "by prefilter", "by triangulate_core", "by room_check",
      "by filter (pair score)"};
  for (size_t s = 0; s < kPairDroppers.size(); ++s) {
    detail(Loss::kPairFiltered, kPairDroppers[s], kDropperLabels[s], t.pairs_dropped_by[s]);
  }
  category(Loss::kGroupedWrongly, "grouped wrongly");
  detail(Loss::kGroupedWrongly, "dropped", "true pairs all dropped by grouping", t.grouped_dropped);
  detail(Loss::kGroupedWrongly, "absorbed", "true pairs only in other persons' groups", t.grouped_absorbed);
  category(Loss::kMergedWrongly, "merged wrongly (merged >= 500 mm off)");
  detail(Loss::kMergedWrongly, "mixed", "a group of its own also held other pairs", t.merged_mixed);
  detail(Loss::kMergedWrongly, "own_pairs_only", "its groups held only its true pairs", t.merged_own_pairs_only);
  category(Loss::kRejected, "rejected");
  detail(Loss::kRejected, "verify", "by verify", t.rejected_by_verify);
  detail(Loss::kRejected, "postprocess", "by postprocess", t.rejected_by_postprocess);
  category(Loss::kPlacedOff, "placed off (output, not matched within 500 mm)");
  return rows;
}

void PrintLossTable(std::ostream& out, const LossTable& table) {
  char line[200];
  std::snprintf(line, sizeof(line),
                "where the GT persons are lost (first step that loses each): %ld GT persons, %ld (%.1f %%) detected "
                "in 2 or more views\n",
                table.gt_persons, table.triangulable, PercentOfWhole(table.triangulable, table.gt_persons));
  out << line;
  std::snprintf(line, sizeof(line), "  %-52s %8s %8s\n", "category", "persons", "% of GT");
  out << line;
  for (const LossRow& row : LossRows(table)) {
    const std::string label = row.detail.empty() ? row.label : "  " + row.label;
    std::snprintf(line, sizeof(line), "  %-52s %8ld %8.1f\n", label.c_str(), row.persons,
                  PercentOfWhole(row.persons, table.gt_persons));
    out << line;
  }
  PrintPartLosses(out, table);
  PrintJointReferences(out, table.joints);
  if (table.unmatched_with_2d_labels == 0) return;
  const auto& by = table.unmatched_by_source;
  const auto n = [&](UnmatchedSource source) { return by[static_cast<int>(source)]; };
  std::snprintf(line, sizeof(line),
                "unmatched predictions in frames with 2D labels, by what they show in the images: %ld = %ld a "
                "3D-labelled person\n",
                table.unmatched_with_2d_labels, n(UnmatchedSource::kLabelled3d));
  out << line;
  std::snprintf(line, sizeof(line),
                "  + %ld a person labelled in 2D only + %ld partly such a person + %ld nobody labelled (%ld judged by "
                "their projection: not merged from pairs)\n",
                n(UnmatchedSource::kLabelled2dOnly), n(UnmatchedSource::kPartly2dOnly), n(UnmatchedSource::kUnlabelled),
                table.unmatched_by_projection);
  out << line;
}

nlohmann::ordered_json LossTableJson(const LossTable& table) {
  nlohmann::ordered_json j;
  j["gt_persons"] = table.gt_persons;
  j["triangulable"] = table.triangulable;
  nlohmann::ordered_json categories = nlohmann::ordered_json::object(), details = nlohmann::ordered_json::object();
  for (const LossRow& row : LossRows(table)) {
    if (row.detail.empty()) {
      categories[row.category] = row.persons;
    } else {
      details[row.category][row.detail] = row.persons;
    }
  }
  j["categories"] = std::move(categories);
  j["details"] = std::move(details);
  // Predictions, not GT persons: only for frames with 2D labels (engine/loss_table.h).
  nlohmann::ordered_json unmatched;
  unmatched["predictions"] = table.unmatched_with_2d_labels;
  for (int k = 0; k < kNumUnmatchedSources; ++k) {
    unmatched[UnmatchedSourceKey(static_cast<UnmatchedSource>(k))] = table.unmatched_by_source[k];
  }
  unmatched["by_projection"] = table.unmatched_by_projection;
  j["unmatched_with_2d_labels"] = std::move(unmatched);
  // Parts, not persons (engine/loss_table.h PartLosses).
  const PartLosses all = table.AllParts();
  nlohmann::ordered_json parts = PartLossesJson(all);
  parts["pcp"] = PcpWithout(all, all.wrong);
  parts["pcp_best_pair"] = PcpWithout(all, all.beyond_best_pair);
  nlohmann::ordered_json per_part = nlohmann::ordered_json::object();
  for (int k = 0; k < kNumPcpParts; ++k) {
    if (table.parts[k].evaluated > 0) per_part[metrics::GenericPcpParts()[k].name] = PartLossesJson(table.parts[k]);
  }
  parts["per_part"] = std::move(per_part);
  j["parts"] = std::move(parts);
  // Joints of matched persons (engine/loss_table.h JointReferences): mean errors, mm.
  nlohmann::ordered_json joints;
  const double n = static_cast<double>(std::max(1L, table.joints.joints));
  joints["joints"] = table.joints.joints;
  joints["output_mm"] = table.joints.output_mm / n;
  joints["all_views_mm"] = table.joints.all_views_mm / n;
  joints["best_pair_mm"] = table.joints.best_pair_mm / n;
  j["joint_references"] = std::move(joints);
  return j;
}

nlohmann::ordered_json RunLossTablesJson(const RunResult& run) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (!run.losses) return j;
  j["loss_table"] = LossTableJson(*run.losses);
  if (run.sequences.size() > 1) {
    nlohmann::ordered_json per_sequence = nlohmann::ordered_json::array();
    for (const SequenceResult& sequence : run.sequences) {
      if (!sequence.losses) continue;
      nlohmann::ordered_json entry;
      entry["sequence"] = sequence.name;
      entry.update(LossTableJson(*sequence.losses));
      per_sequence.push_back(std::move(entry));
    }
    j["loss_table_per_sequence"] = std::move(per_sequence);
  }
  return j;
}

std::string LossesCsv(const LossTable& table) {
  std::ostringstream out;
  out << "category,detail,persons,percent_of_gt\n";
  char percent[32];
  const auto row = [&](const std::string& category, const std::string& detail, long persons) {
    std::snprintf(percent, sizeof(percent), "%.2f", PercentOfWhole(persons, table.gt_persons));
    out << category << "," << detail << "," << persons << "," << percent << "\n";
  };
  for (const LossRow& r : LossRows(table)) row(r.category, r.detail, r.persons);
  row("all", "", table.gt_persons);
  row("all", "triangulable", table.triangulable);
  return out.str();
}

}  // namespace rpt::engine

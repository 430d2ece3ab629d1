// SPDX-License-Identifier: MIT
// The loss table (engine/loss_table.h) for the terminal, summary.json and losses.csv.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "engine/loss_table.h"
#include "engine/run.h"

namespace rpt::engine {

// One line of the table: a category (detail empty) or one of its details.
struct LossRow {
  std::string category;  // LossKey()
  std::string detail;    // "" for the category itself
  std::string label;     // for people
  long persons = 0;
};
// The categories in order, each followed by its details.
std::vector<LossRow> LossRows(const LossTable& table);

// The table with the persons and their share of the GT persons.
void PrintLossTable(std::ostream& out, const LossTable& table);

// {"gt_persons", "triangulable", "categories": {key: persons}, "details": {key: {detail: persons}}}.
nlohmann::ordered_json LossTableJson(const LossTable& table);
// {"loss_table": LossTableJson(run), "loss_table_per_sequence": [{"sequence", ...}] (several only)};
// empty when the run made no loss table.
nlohmann::ordered_json RunLossTablesJson(const RunResult& run);

// losses.csv: category,detail,persons,percent_of_gt (the rows of LossRows, then "all").
std::string LossesCsv(const LossTable& table);

}  // namespace rpt::engine

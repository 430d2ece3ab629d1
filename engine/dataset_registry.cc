// SPDX-License-Identifier: MIT
#include "engine/dataset_registry.h"

#include "core/errors.h"
#include "core/text.h"
#include "datasets/readers/egohumans.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/h3wb.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/mvor.h"
#include "datasets/readers/panoptic.h"
#include "datasets/readers/shelf_4da.h"
#include "datasets/readers/shelf_campus.h"
#include "datasets/readers/synthetic_dataset.h"

namespace rpt::engine {

const std::vector<DatasetEntry>& DatasetRegistry() {
  static const std::vector<DatasetEntry> entries = {
      {ShelfInfo(), ReadShelf},
      {Shelf4daInfo(), ReadShelf4da},
      {CampusInfo(), ReadCampus},
      {PanopticInfo(), ReadPanoptic, StreamPanoptic},
      {Human36mInfo(), ReadHuman36m},
      {H3wbInfo(), ReadH3wb},
      {EgohumansInfo(), ReadEgohumans},
      {MvorInfo(), ReadMvor},
      {GenericInfo(), ReadGeneric},
      {SyntheticInfo(), ReadSynthetic, StreamSyntheticDataset},
  };
  return entries;
}

std::string DatasetParamsMarkdown() {
  const auto cell = [](const std::string& text) {  // '|' would end the table cell
    std::string out;
    for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  std::string out;
  for (const DatasetEntry& entry : DatasetRegistry()) {
    out += "\n### " + entry.info.name + "\n\n";
    out += "| `--param` | default | value | meaning |\n|---|---|---|---|\n";
    for (const DatasetParam& p : entry.info.params) {
      out += "| `" + p.name + "` | " + (p.default_value.empty() ? std::string("(empty)") : "`" + p.default_value + "`") +
             " | " + cell(p.type) + " | " + cell(p.help) + " |\n";
    }
  }
  return out;
}

namespace {

const DatasetEntry& FindDataset(const std::string& name) {
  std::string known;
  for (const DatasetEntry& entry : DatasetRegistry()) {
    if (entry.info.name == name) return entry;
    AppendItem(&known, entry.info.name);
  }
  throw ConfigError("unknown dataset '" + name + "' (known: " + known + "; see `rpt datasets`)");
}

}  // namespace

std::vector<std::unique_ptr<FrameSource>> OpenDataset(const DatasetRequest& request) {
  const DatasetEntry& entry = FindDataset(request.dataset);
  return entry.stream ? entry.stream(request) : SourcesOf(entry.read(request));
}

std::vector<Sequence> ReadDataset(const DatasetRequest& request) {
  std::vector<Sequence> sequences;
  for (const auto& source : OpenDataset(request)) sequences.push_back(Materialize(*source));
  return sequences;
}

}  // namespace rpt::engine

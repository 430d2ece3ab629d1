// SPDX-License-Identifier: MIT
#include "engine/dataset_registry.h"

#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/readers/egohumans.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/h3wb.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/mvor.h"
#include "datasets/readers/panoptic.h"
#include "datasets/readers/shelf_4da.h"
#include "datasets/readers/shelf_campus.h"
#include "datasets/synthetic/synthetic_dataset.h"

namespace rpt::engine {

const std::vector<DatasetEntry>& DatasetRegistry() {
  static const std::vector<DatasetEntry> entries = {
      {ShelfInfo(), OpenShelf},          // readers/shelf_campus.h
      {Shelf4daInfo(), OpenShelf4da},    // readers/shelf_4da.h
      {CampusInfo(), OpenCampus},        // readers/shelf_campus.h
      {PanopticInfo(), OpenPanoptic},    // readers/panoptic.h
      {Human36mInfo(), OpenHuman36m},    // readers/human36m.h
      {H3wbInfo(), OpenH3wb},            // readers/h3wb.h
      {EgohumansInfo(), OpenEgohumans},  // readers/egohumans.h
      {MvorInfo(), OpenMvor},            // readers/mvor.h
      {GenericInfo(), OpenGeneric},      // readers/generic_labels.h
      {SyntheticInfo(), OpenSynthetic},  // readers/synthetic_dataset.h
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
  throw ConfigError("unknown dataset " + QuoteName(name) + " (known: " + known + "; see `rpt datasets`)");
}

}  // namespace

void CheckDatasetName(const std::string& dataset) { FindDataset(dataset); }

std::vector<std::unique_ptr<FrameSource>> OpenDataset(const DatasetRequest& request) {
  const DatasetEntry& entry = FindDataset(request.dataset);
  if (request.root.empty() && request.dataset != "synthetic") {  // the generated scene reads no files
    throw ConfigError("--dataset " + request.dataset + " needs --root DIR, the folder holding the dataset in its "
                      "original layout (`rpt datasets` shows what it reads there)");
  }
  return entry.open(request);
}

std::vector<Sequence> ReadDataset(const DatasetRequest& request) { return MaterializeAll(OpenDataset(request)); }

const DatasetInfo* FindDatasetInfo(const std::string& dataset) {
  for (const DatasetEntry& entry : DatasetRegistry()) {
    if (entry.info.name == dataset) return &entry.info;
  }
  return nullptr;
}

}  // namespace rpt::engine

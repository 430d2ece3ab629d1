// SPDX-License-Identifier: MIT
// `rpt datasets`: the readers, what each needs on disk and its parameters.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "engine/dataset_registry.h"

namespace rpt::cli {

using engine::DatasetEntry;
using engine::DatasetParamsMarkdown;
using engine::DatasetRegistry;

void RegisterDatasetsCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand("datasets", "List the dataset readers, their layouts and parameters");
  auto markdown = std::make_shared<bool>(false);
  command->add_flag("--markdown", *markdown, "print only the parameter tables of docs/datasets.md");
  command->callback([markdown] {
    if (*markdown) {
      std::printf("%s", DatasetParamsMarkdown().c_str());
      return;
    }
    for (const DatasetEntry& entry : DatasetRegistry()) {
      const DatasetInfo& info = entry.info;
      std::printf("%s: %s\n", info.name.c_str(), info.description.c_str());
      // A layout of several lines: the later ones under the first.
      std::string layout = info.layout;
      for (size_t at = layout.find('\n'); at != std::string::npos; at = layout.find('\n', at + 1)) {
        layout.insert(at + 1, "           ");
      }
      std::printf("  on disk: %s\n", layout.c_str());
      for (const DatasetParam& p : info.params) {
        std::printf("  --param %s=%s  %s [%s]\n", p.name.c_str(), p.default_value.empty() ? "..." : p.default_value.c_str(),
                    p.help.c_str(), p.type.c_str());
      }
      std::printf("\n");
    }
    std::printf("Detections: --detections FILE (generic JSON, HDF5 cache, OpenPose folder, COCO result list) or "
                "--simulate.\nGeneric labels: rpt eval --labels LABELS.json --detections DETECTIONS.json\n");
  });
}

}  // namespace rpt::cli

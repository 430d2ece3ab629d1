// SPDX-License-Identifier: MIT
#include "engine/outputs/export_options.h"

#include <algorithm>
#include <array>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::engine {
namespace {

struct FormatNames {
  ExportFormat format;
  std::string_view name;  // in --export
  std::string_view file;  // in the run folder
};
constexpr std::array<FormatNames, 5> kFormats = {{
    {ExportFormat::kJson, "json", "predictions.json"},
    {ExportFormat::kCsv, "csv", "predictions.csv"},
    {ExportFormat::kTrc, "trc", "trc"},
    {ExportFormat::kNpz, "npz", "predictions.npz"},
    {ExportFormat::kH5, "h5", "predictions.h5"},
}};

}  // namespace

bool ExportOptions::Has(ExportFormat format) const {
  return std::find(formats.begin(), formats.end(), format) != formats.end();
}

std::string_view ExportFormatName(ExportFormat format) {
  for (const FormatNames& f : kFormats) {
    if (f.format == format) return f.name;
  }
  return "?";
}

std::string_view ExportFileName(ExportFormat format) {
  for (const FormatNames& f : kFormats) {
    if (f.format == format) return f.file;
  }
  return "?";
}

std::vector<ExportFormat> ParseExportFormats(const std::string& text) {
  if (text.empty()) throw ConfigError("--export '': no format given (one or more of json, csv, trc, npz, h5)");
  std::vector<ExportFormat> formats;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, comma - start);
    const auto it =
        std::find_if(kFormats.begin(), kFormats.end(), [&](const FormatNames& f) { return f.name == name; });
    if (it == kFormats.end()) {
      throw ConfigError("--export " + text + ": " + QuoteName(name) + " is not one of json, csv, trc, npz, h5");
    }
    if (std::find(formats.begin(), formats.end(), it->format) != formats.end()) {
      throw ConfigError("--export " + text + ": " + QuoteName(name) + " given twice");
    }
    formats.push_back(it->format);
    start = comma + 1;
  }
  return formats;
}

const std::vector<std::string>& ProvenanceNames() {
  static const std::vector<std::string> names = {"triangulated", "filled", "smoothed", "lifted", "predicted"};
  return names;
}

std::string_view ProvenanceName(JointProvenance provenance) {
  const auto code = static_cast<size_t>(provenance);
  return code < ProvenanceNames().size() ? std::string_view(ProvenanceNames()[code]) : std::string_view("?");
}

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
#include "engine/config.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>

#include "engine/json_text.h"
#include "core/closest_name.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/options_check.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/io/json_file.h"

namespace rpt::engine {
namespace {

using Json = nlohmann::json;

// Calls f(section, key, field, spec) for every option of `config` (Config or const Config), in
// dump order.
template <class Self, class F>
void ForEachOption(Self& config, F&& f) {
  auto section_visitor = [&f](std::string_view section, auto& options) {
    auto field_visitor = [&f, section](std::string_view key, auto& field, const OptionSpec& spec) {
      f(section, key, field, spec);
    };
    VisitFields(field_visitor, options);
  };
  VisitSections(section_visitor, config);
}

std::string FullKey(std::string_view section, std::string_view key) {
  return std::string(section) + "." + std::string(key);
}

// Calls f(field, spec) for the option named `key` ("section.name"); false when there is none.
template <class Self, class F>
bool ForOption(Self& config, const std::string& key, F&& f) {
  bool found = false;
  ForEachOption(config, [&](std::string_view section, std::string_view name, auto& field, const OptionSpec& spec) {
    if (!found && key.size() == section.size() + 1 + name.size() && FullKey(section, name) == key) {
      found = true;
      f(field, spec);
    }
  });
  return found;
}

std::vector<std::string> Sections() {
  std::vector<std::string> sections;
  const Config config;
  ForEachOption(config, [&](std::string_view section, std::string_view, const auto&, const OptionSpec&) {
    if (sections.empty() || sections.back() != section) sections.emplace_back(section);
  });
  return sections;
}

std::vector<std::string> Keys() {
  std::vector<std::string> keys;
  for (const ConfigOptionInfo& option : ConfigOptions()) keys.push_back(option.key);
  return keys;
}

[[noreturn]] void UnknownOption(const std::string& where, const std::string& key) {
  const std::string section = key.substr(0, key.find('.'));
  std::string known;  // the keys of the section, or the sections
  for (const std::string& candidate : Keys()) {
    if (candidate.rfind(section + ".", 0) == 0) AppendItem(&known, candidate.substr(section.size() + 1));
  }
  known = known.empty() ? "sections: " + Join(Sections()) : section + " has: " + known;
  throw ConfigError(where + ": " + UnknownNameProblem("option", key, Keys(), known));
}

template <class>
[[maybe_unused]] constexpr bool kUnsupportedOptionType = false;

// The value in the JSON of `rpt config --dump` (a config file reads it back through the codec).
template <class T>
Json ToJson(const T& value) {
  if constexpr (std::is_enum_v<T>) {
    return Json(std::string(EnumName(value)));
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    return Json::array({value.x(), value.y(), value.z()});
  } else if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, int> || std::is_same_v<T, double> ||
                       std::is_same_v<T, JointNames>) {
    return Json(value);
  } else {
    static_assert(kUnsupportedOptionType<T>, "add the type to ToJson");
  }
}

// One option of a configuration, ready to print.
struct OptionText {
  std::string section, name;
  std::string value;    // JSON
  std::string comment;  // "value, unit: help"
};

std::vector<OptionText> OptionTexts(const Config& config) {
  std::vector<OptionText> out;
  ForEachOption(config, [&](std::string_view section, std::string_view name, const auto& field, const OptionSpec& spec) {
    using T = std::decay_t<decltype(field)>;
    std::string comment = OptionTypeText<T>(spec);
    if (!spec.unit.empty()) AppendItem(&comment, spec.unit);
    out.push_back({std::string(section), std::string(name), ToJson(field).dump(), comment + ": " + std::string(spec.help)});
  });
  return out;
}

// `text` in a Markdown table cell: each '|' escaped ("a \| b").
std::string TableCell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::vector<ConfigOptionInfo> ConfigOptions() {
  std::vector<ConfigOptionInfo> out;
  const Config defaults;
  ForEachOption(defaults, [&](std::string_view section, std::string_view name, const auto& field, const OptionSpec& spec) {
    using T = std::decay_t<decltype(field)>;
    out.push_back({FullKey(section, name), OptionTypeText<T>(spec), FormatOption(field), spec});
  });
  return out;
}

void SetConfigOption(const std::string& key, const std::string& value, const std::string& where, Config* config) {
  const bool found = ForOption(*config, key, [&](auto& field, const OptionSpec& spec) {
    if (const std::string problem = ParseOption(value, spec, &field); !problem.empty()) {
      throw ConfigError(OptionMessage(where, key, problem));
    }
  });
  if (!found) UnknownOption(where, key);
}

void ApplyConfigOverride(const std::string& assignment, Config* config) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw ConfigError("--set " + assignment + ": expected section.key=value");
  SetConfigOption(std::string(TrimBlanks(std::string_view(assignment).substr(0, eq))), assignment.substr(eq + 1),
                  "--set " + assignment, config);
}

std::string GetConfigOption(const Config& config, const std::string& key) {
  std::string text;
  if (!ForOption(config, key, [&](const auto& field, const OptionSpec&) { text = FormatOption(field); })) {
    UnknownOption("option", key);
  }
  return text;
}

void LoadConfigFile(const std::filesystem::path& path, Config* config) {
  const Json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  if (!root.is_object()) throw ConfigError(source + ": expected an object of sections");
  const std::vector<std::string> sections = Sections();
  for (const auto& [section, values] : root.items()) {
    const std::string pointer = io::JsonPointerJoin("", section);
    if (std::find(sections.begin(), sections.end(), section) == sections.end()) {
      throw ConfigError(source + ": " + pointer + ": " +
                        UnknownNameProblem("section", section, sections, "sections: " + Join(sections)));
    }
    if (!values.is_object()) throw ConfigError(source + ": " + pointer + ": expected an object of options");
    for (const auto& [name, value] : values.items()) {
      // A JSON value is read as its text (a string as is, others as JSON writes them): the rules
      // and messages of --set. An object or null is no value (as text it could pass for a name).
      const std::string key = section + "." + name;
      const std::string where = source + ": " + io::JsonPointerJoin(pointer, name);
      if (value.is_object() || value.is_null()) {
        if (!ForOption(*config, key, [](const auto&, const OptionSpec&) {})) UnknownOption(where, key);
        throw ConfigError(
            OptionMessage(where, key, QuoteName(io::JsonExcerpt(value)) + " is not a value (a string, number, boolean or list)"));
      }
      SetConfigOption(key, JsonValueText(value), where, config);
    }
  }
  try {
    CheckConfig(*config);
  } catch (const ConfigError& e) {
    throw ConfigError(source + ": " + e.what());
  }
}

std::string DumpConfig(const Config& config, bool with_comments) {
  const std::vector<OptionText> options = OptionTexts(config);
  std::ostringstream out;
  if (with_comments) {
    out << "// rpt configuration with a comment per option (value, unit: meaning). The comments make\n"
           "// this text documentation, not JSON: `rpt config --dump` prints the JSON that --config reads.\n";
  }
  out << "{\n";
  for (size_t i = 0; i < options.size(); ++i) {
    const OptionText& o = options[i];
    const bool first_of_section = i == 0 || options[i - 1].section != o.section;
    const bool last_of_section = i + 1 == options.size() || options[i + 1].section != o.section;
    if (first_of_section) out << "  \"" << o.section << "\": {\n";
    out << "    \"" << o.name << "\": " << o.value << (last_of_section ? "" : ",");
    if (with_comments) out << "  // " << o.comment;
    out << "\n";
    if (last_of_section) out << "  }" << (i + 1 < options.size() ? "," : "") << "\n";
  }
  out << "}\n";
  return out.str();
}

std::string ConfigMarkdown() {
  std::ostringstream out;
  out << "# Options\n\n"
         "<!-- Generated by `rpt config --markdown > docs/options.md` from the VisitFields functions beside\n"
         "the options structs; a test fails when this file differs. Edit the help texts there. -->\n\n"
         "Every option of the triangulator (one section per pipeline step, see [algorithm.md](algorithm.md)) and\n"
         "of the evaluation (section `metrics`, see [metrics.md](metrics.md)), with its default.\n\n"
         "* `rpt config --dump` prints the configuration as JSON; `--config FILE` reads such a file (any\n"
         "  subset of sections and keys) on every command that runs the pipeline. `--dump --comments` adds\n"
         "  each option's value, unit and meaning as comments (then it is no longer JSON).\n"
         "* `--set section.key=value` sets one option (repeatable, applied after `--config`).\n"
         "* Values are read alike by `--set`, config files and the datasets' `--param` (see\n"
         "  [datasets.md](datasets.md#parameters)). Booleans are `true`/`false`, `yes`/`no`, `on`/`off` or\n"
         "  `1`/`0`. Integers are whole numbers (`3`; not `3.0` or `1e3`), numbers finite (`0.5`, `1e3`; not\n"
         "  `nan` or `inf`). Lists are JSON lists\n"
         "  (`--set 'triangulate.core_joints=[\"shoulder_left\", \"shoulder_right\", \"hip_left\", \"hip_right\"]'`)\n"
         "  or comma lists (`--set triangulate.core_joints=shoulder_left,shoulder_right,hip_left,hip_right`; empty\n"
         "  items are dropped, `\"\"` is the empty list); 3-vectors likewise (`[8, 8, 3]` or `8,8,3`). Blanks around a value or an item are\n"
         "  ignored. In a config file a JSON string is read like the text of `--set` (`\"yes\"`, `\"8,8,3\"`), any\n"
         "  other JSON value as JSON writes it (`true`, `3`, `[8, 8, 3]`; `3.0` is not an integer).\n"
         "* Unknown keys, values of the wrong type and values outside the range are errors (exit code 2)\n"
         "  naming the place and the key, `<where>: <key>: '<value>' is not <value column>`:\n"
         "  `--set filter.min_match_score=1.5: filter.min_match_score: '1.5' is not a number in [0, 1]`; in a\n"
         "  config file `<where>` is the file and the JSON pointer. Unknown keys get a \"did you mean\".\n"
         "  Settings changed from their defaults that are valid but have no effect (such as\n"
         "  `smooth.mode=causal` with `track.enabled=false`) print a warning; a default that another setting\n"
         "  makes useless (`clip_speed.enabled` with `track.enabled=false`) does not.\n";
  const std::vector<OptionText> options = OptionTexts(Config{});
  const std::vector<ConfigOptionInfo> infos = ConfigOptions();
  for (size_t i = 0; i < options.size(); ++i) {
    const OptionText& o = options[i];
    const ConfigOptionInfo& info = infos[i];
    if (i == 0 || options[i - 1].section != o.section) {
      out << "\n## `" << o.section << "`\n\n"
          << "| option | default | value | unit | meaning |\n"
          << "|---|---|---|---|---|\n";
    }
    out << "| `" << info.key << "` | " << (info.default_value.empty() ? "(empty)" : "`" + info.default_value + "`")
        << " | " << TableCell(info.type) << " | " << info.spec.unit << " | " << TableCell(info.spec.help) << " |\n";
  }
  return out.str();
}

Config ResolveConfig(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  Config config;
  if (!file.empty()) LoadConfigFile(file, &config);
  for (const std::string& assignment : overrides) ApplyConfigOverride(assignment, &config);
  CheckConfig(config);
  return config;
}

void CheckConfig(const Config& config) {
  ThrowIfInvalid(config.triangulator);
  ThrowIfInvalid(config.metrics);
}

std::vector<std::string> ConfigWarnings(const Config& config) { return config.triangulator.Warnings(); }

}  // namespace rpt::engine

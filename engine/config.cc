// SPDX-License-Identifier: MIT
#include "engine/config.h"

#include <Eigen/Core>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <type_traits>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/options_check.h"
#include "core/text.h"
#include "datasets/io/json_file.h"

namespace rpt::engine {
namespace {

using Json = nlohmann::json;

template <class>
constexpr bool kUnsupportedOptionType = false;

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
  throw ConfigError(where + ": unknown option '" + key + "'" + DidYouMean(key, Keys()) + " (" + known + ")");
}

[[noreturn]] void Bad(const std::string& where, const std::string& key, const std::string& problem) {
  throw ConfigError(where + ": " + key + ": " + problem);
}

template <class T>
std::string TypeName() {
  if constexpr (std::is_same_v<T, bool>) {
    return "bool";
  } else if constexpr (std::is_same_v<T, int>) {
    return "int";
  } else if constexpr (std::is_same_v<T, double>) {
    return "number";
  } else if constexpr (std::is_same_v<T, JointNames>) {
    return "list of joint names";
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    return "[x, y, z]";
  } else if constexpr (std::is_enum_v<T>) {
    std::string names;
    for (const auto& [value, name] : EnumNames<T>::values) AppendItem(&names, name, "|");
    return names;
  } else {
    static_assert(kUnsupportedOptionType<T>, "add the type to TypeName, ToJson, FromJson and TextToJson");
  }
}

template <class T>
Json ToJson(const T& value) {
  if constexpr (std::is_enum_v<T>) {
    return Json(std::string(EnumName(value)));
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    return Json::array({value.x(), value.y(), value.z()});
  } else {
    return Json(value);
  }
}

// Sets *out from a JSON value; returns the problem ("" when set).
template <class T>
std::string FromJson(const Json& v, T* out) {
  const std::string got = ", got " + v.dump();
  if constexpr (std::is_same_v<T, bool>) {
    if (!v.is_boolean()) return "expected true or false" + got;
    *out = v.get<bool>();
  } else if constexpr (std::is_same_v<T, int>) {
    if (!v.is_number_integer()) return "expected an integer" + got;
    const long long value = v.get<long long>();
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
      return "integer out of range" + got;
    }
    *out = static_cast<int>(value);
  } else if constexpr (std::is_same_v<T, double>) {
    if (!v.is_number()) return "expected a number" + got;
    *out = v.get<double>();
  } else if constexpr (std::is_same_v<T, JointNames>) {
    if (!v.is_array()) return "expected a list of joint names" + got;
    JointNames names;
    for (const Json& item : v) {
      if (!item.is_string()) return "expected a list of joint names" + got;
      names.push_back(item.get<std::string>());
    }
    *out = std::move(names);
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
      return "expected [x, y, z]" + got;
    }
    *out = Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  } else if constexpr (std::is_enum_v<T>) {
    std::vector<std::string> names;
    for (const auto& [value, name] : EnumNames<T>::values) names.emplace_back(name);
    if (!v.is_string() || !EnumFromName(v.get<std::string>(), out)) {
      return "expected one of " + TypeName<T>() + got + (v.is_string() ? DidYouMean(v.get<std::string>(), names) : "");
    }
  }
  return {};
}

std::string Trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

// The comma-separated items of `text`, trimmed, empty ones left out.
std::vector<std::string> CommaItems(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream s(text);
  for (std::string item; std::getline(s, item, ',');) {
    if (!Trim(item).empty()) items.push_back(Trim(item));
  }
  return items;
}

double ParseNumber(const std::string& text, const std::string& where, const std::string& key) {
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  Bad(where, key, "'" + text + "' is not a number");
}

// The JSON value a `--set` text stands for, by the option's type.
template <class T>
Json TextToJson(const std::string& text, const std::string& where, const std::string& key) {
  if constexpr (std::is_same_v<T, bool>) {
    if (text == "true" || text == "1" || text == "on") return Json(true);
    if (text == "false" || text == "0" || text == "off") return Json(false);
    Bad(where, key, "expected true or false, got '" + text + "'");
  } else if constexpr (std::is_same_v<T, int>) {
    const double value = ParseNumber(text, where, key);
    if (value != static_cast<double>(static_cast<long long>(value))) {
      Bad(where, key, "expected an integer, got '" + text + "'");
    }
    return Json(static_cast<long long>(value));
  } else if constexpr (std::is_same_v<T, double>) {
    return Json(ParseNumber(text, where, key));
  } else if constexpr (std::is_same_v<T, JointNames> || std::is_same_v<T, Eigen::Vector3d>) {
    if (!text.empty() && text.front() == '[') {  // a JSON list
      try {
        return Json::parse(text);
      } catch (const Json::exception&) {
        Bad(where, key, "'" + text + "' is not a JSON list (write [\"a\", \"b\"] or a,b)");
      }
    }
    Json list = Json::array();
    for (const std::string& item : CommaItems(text)) {
      if constexpr (std::is_same_v<T, JointNames>) {
        list.push_back(item);
      } else {
        list.push_back(ParseNumber(item, where, key));
      }
    }
    return list;
  } else {
    return Json(text);
  }
}

// One option of a configuration, ready to print.
struct OptionText {
  std::string section, name;
  std::string value;    // JSON
  std::string comment;  // "type, unit, range: help"
};

std::vector<OptionText> OptionTexts(const Config& config) {
  std::vector<OptionText> out;
  ForEachOption(config, [&](std::string_view section, std::string_view name, const auto& field, const OptionSpec& spec) {
    using T = std::decay_t<decltype(field)>;
    std::string comment = TypeName<T>();
    if (!spec.unit.empty()) AppendItem(&comment, spec.unit);
    if (const std::string range = DescribeRange(spec); !range.empty()) AppendItem(&comment, range);
    out.push_back({std::string(section), std::string(name), ToJson(field).dump(), comment + ": " + std::string(spec.help)});
  });
  return out;
}

// `text` in a Markdown table cell: each '|' escaped and spaced ("a \| b").
std::string TableCell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') {
      out += " \\| ";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::vector<ConfigOptionInfo> ConfigOptions() {
  std::vector<ConfigOptionInfo> out;
  const Config defaults;
  ForEachOption(defaults, [&](std::string_view section, std::string_view name, const auto& field, const OptionSpec& spec) {
    using T = std::decay_t<decltype(field)>;
    out.push_back({FullKey(section, name), TypeName<T>(), ToJson(field).dump(), spec});
  });
  return out;
}

void SetConfigOption(const std::string& key, const std::string& value, const std::string& where, Config* config) {
  const bool found = ForOption(*config, key, [&](auto& field, const OptionSpec&) {
    using T = std::decay_t<decltype(field)>;
    if (const std::string problem = FromJson(TextToJson<T>(value, where, key), &field); !problem.empty()) {
      Bad(where, key, problem);
    }
  });
  if (!found) UnknownOption(where, key);
}

void ApplyConfigOverride(const std::string& assignment, Config* config) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw ConfigError("--set " + assignment + ": expected section.key=value");
  SetConfigOption(Trim(assignment.substr(0, eq)), Trim(assignment.substr(eq + 1)), "--set " + assignment, config);
}

std::string GetConfigOption(const Config& config, const std::string& key) {
  Json value;
  if (!ForOption(config, key, [&](const auto& field, const OptionSpec&) { value = ToJson(field); })) {
    UnknownOption("option", key);
  }
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string out;
    for (const Json& item : value) AppendItem(&out, item.is_string() ? item.get<std::string>() : item.dump(), ",");
    return out;
  }
  return value.dump();
}

void LoadConfigFile(const std::filesystem::path& path, Config* config) {
  const Json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  if (!root.is_object()) throw ConfigError(source + ": expected an object of sections");
  const std::vector<std::string> sections = Sections();
  for (const auto& [section, values] : root.items()) {
    if (std::find(sections.begin(), sections.end(), section) == sections.end()) {
      throw ConfigError(source + ": unknown section '" + section + "'" + DidYouMean(section, sections) +
                        " (sections: " + Join(sections) + ")");
    }
    if (!values.is_object()) throw ConfigError(source + ": /" + section + ": expected an object of options");
    for (const auto& [name, value] : values.items()) {
      const std::string key = section + "." + name;
      const std::string where = source + ": /" + section + "/" + name;
      const bool found = ForOption(*config, key, [&](auto& field, const OptionSpec&) {
        if (const std::string problem = FromJson(value, &field); !problem.empty()) Bad(where, key, problem);
      });
      if (!found) UnknownOption(source, key);
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
    out << "// rpt configuration with a comment per option (type, unit, range: meaning). The comments make\n"
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
         "  each option's type, unit, range and meaning as comments (then it is no longer JSON).\n"
         "* `--set section.key=value` sets one option (repeatable, applied after `--config`). Booleans are\n"
         "  `true`/`false`; lists are JSON (`--set 'triangulate.core_joints=[\"hip_left\", \"hip_right\"]'`) or\n"
         "  comma lists (`--set triangulate.core_joints=hip_left,hip_right`); 3-vectors likewise\n"
         "  (`[8, 8, 3]` or `8,8,3`).\n"
         "* Unknown keys, values of the wrong type and values outside the range are errors (exit code 2)\n"
         "  naming the file or `--set` and the key. Settings that are valid but have no effect (such as\n"
         "  `clip_speed.enabled=true` with `track.enabled=false`) print a warning.\n";
  const std::vector<OptionText> options = OptionTexts(Config{});
  const std::vector<ConfigOptionInfo> infos = ConfigOptions();
  for (size_t i = 0; i < options.size(); ++i) {
    const OptionText& o = options[i];
    const ConfigOptionInfo& info = infos[i];
    if (i == 0 || options[i - 1].section != o.section) {
      out << "\n## `" << o.section << "`\n\n"
          << "| option | default | type | unit | range | meaning |\n"
          << "|---|---|---|---|---|---|\n";
    }
    std::string value = o.value;
    if (value.size() >= 2 && value.front() == '"') value = value.substr(1, value.size() - 2);
    out << "| `" << info.key << "` | " << value << " | " << TableCell(info.type) << " | " << info.spec.unit << " | "
        << DescribeRange(info.spec) << " | " << TableCell(info.spec.help) << " |\n";
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
  if (const std::string error = config.triangulator.Check(); !error.empty()) throw ConfigError(error);
  config.metrics.Check();
}

std::vector<std::string> ConfigWarnings(const Config& config) { return config.triangulator.Warnings(); }

}  // namespace rpt::engine

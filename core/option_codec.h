// SPDX-License-Identifier: MIT
// The one codec of option values: every value a user writes (`--set section.key=value`, a
// config file, `--param key=value`, a thresholds or sweep file) is read by ParseOption, every
// value shown (`rpt config --dump`, `rpt datasets`, docs/options.md, docs/datasets.md, messages)
// is written by FormatOption and described by OptionTypeText, and Check() reports values set in
// code with the same words (CheckOptionValue). The rules, per field type:
//
//   bool          true, false, yes, no, on, off, 1, 0 (lower case)
//   int, uint64   an integer in decimal, optional sign ("12", "+3", "-1"); not "3.0" or "1e3"
//   double        a finite decimal number ("0.5", "1e3", "-2", ".5"); not "nan" or "inf"
//   std::string   the text as written
//   list of names a JSON list of strings (["a", "b"]) or a comma list (a, b); items trimmed,
//                 empty items of a comma list dropped, "" is the empty list
//   Eigen::Vector3d  three numbers, as a JSON list ([8, 8, 3]) or a comma list (8,8,3)
//   enumerations  one of the names of their EnumNames specialisation
//
// Leading and trailing blanks (spaces, tabs, line breaks) of every text are ignored. Numbers are checked
// against the OptionSpec's range. A refused text gives the problem "'<text>' is not <what a value
// must be>", e.g. "'65' is not an integer in [2, 64]", which callers prefix with the place and the
// key: "<where>: <key>: <problem>" (OptionMessage). A JSON value of a file is read as its text
// (a string as is, anything else as JSON writes it), so files follow the same rules.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/option_spec.h"

namespace rpt {

// The comma-separated items of `text`, blanks trimmed, empty items dropped ("a, b,,c" -> a, b, c).
std::vector<std::string> SplitList(std::string_view text);

// A number as JSON writes it, the shortest text that reads back to the same double: "0.5",
// "25.0", "1e-05", "1e+16"; "nan" and "inf" for the values JSON cannot hold.
std::string FormatNumber(double value);

// The values an OptionSpec allows: "[0, 1]", "(0, 1]", ">= 0", "> 0", "<= 3"; "" when any.
std::string OptionRangeText(const OptionSpec& spec);

// "<where>: <key>: <problem>", the form of every message about an option value.
std::string OptionMessage(std::string_view where, std::string_view key, std::string_view problem);

namespace option_codec {

// The per-type rules behind the templates below (use those). Parse returns "" and sets *out, or
// the problem and leaves *out alone.
std::string Parse(std::string_view text, const OptionSpec& spec, bool* out);
std::string Parse(std::string_view text, const OptionSpec& spec, int* out);
std::string Parse(std::string_view text, const OptionSpec& spec, std::uint64_t* out);
std::string Parse(std::string_view text, const OptionSpec& spec, double* out);
std::string Parse(std::string_view text, const OptionSpec& spec, std::string* out);
std::string Parse(std::string_view text, const OptionSpec& spec, std::vector<std::string>* out);
std::string Parse(std::string_view text, const OptionSpec& spec, Eigen::Vector3d* out);
// An enumeration value: *index is the position of the name in `names`.
std::string ParseName(std::string_view text, const std::vector<std::string>& names, std::size_t* index);

std::string Format(bool value);
std::string Format(int value);
std::string Format(std::uint64_t value);
std::string Format(double value);
std::string Format(const std::string& value);
std::string Format(const std::vector<std::string>& value);
std::string Format(const Eigen::Vector3d& value);

std::string TypeText(const bool*, const OptionSpec& spec);
std::string TypeText(const int*, const OptionSpec& spec);
std::string TypeText(const std::uint64_t*, const OptionSpec& spec);
std::string TypeText(const double*, const OptionSpec& spec);
std::string TypeText(const std::string*, const OptionSpec& spec);
std::string TypeText(const std::vector<std::string>*, const OptionSpec& spec);
std::string TypeText(const Eigen::Vector3d*, const OptionSpec& spec);
std::string EnumTypeText(const std::vector<std::string>& names);

// The problem with a value set in code ("" when it is fine): numbers must be finite and in
// range, 3-vectors finite.
std::string Check(int value, const OptionSpec& spec);
std::string Check(std::uint64_t value, const OptionSpec& spec);
std::string Check(double value, const OptionSpec& spec);
std::string Check(const Eigen::Vector3d& value, const OptionSpec& spec);

template <class Enum>
std::vector<std::string> EnumNameList() {
  std::vector<std::string> names;
  for (const auto& [value, name] : EnumNames<Enum>::values) names.emplace_back(name);
  return names;
}

}  // namespace option_codec

// Sets *out from `text` by the rules of T (see the top of this file); returns "" when set, else
// the problem ("'<text>' is not ...") and leaves *out unchanged.
template <class T>
std::string ParseOption(std::string_view text, const OptionSpec& spec, T* out) {
  if constexpr (std::is_enum_v<T>) {
    std::size_t index = 0;
    std::string problem = option_codec::ParseName(text, option_codec::EnumNameList<T>(), &index);
    if (problem.empty()) *out = EnumNames<T>::values[index].first;
    return problem;
  } else {
    return option_codec::Parse(text, spec, out);
  }
}

// The text ParseOption reads back to `value`.
template <class T>
std::string FormatOption(const T& value) {
  if constexpr (std::is_enum_v<T>) {
    return std::string(EnumName(value));
  } else {
    return option_codec::Format(value);
  }
}

// What a value must be, for help texts and docs: "integer in [2, 64]", "number > 0",
// "true | false", "text", "list of names", "[x, y, z]", "red | green". The problems of
// ParseOption say the same: "'0' is not an integer in [2, 64]".
template <class T>
std::string OptionTypeText(const OptionSpec& spec) {
  if constexpr (std::is_enum_v<T>) {
    return option_codec::EnumTypeText(option_codec::EnumNameList<T>());
  } else {
    return option_codec::TypeText(static_cast<const T*>(nullptr), spec);
  }
}

// The problem with a value set in code, in ParseOption's words ("'1.5' is not a number in [0, 1]");
// "" when it is fine.
template <class T>
std::string CheckOptionValue(const T& value, const OptionSpec& spec) {
  if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::uint64_t> || std::is_same_v<T, double> ||
                std::is_same_v<T, Eigen::Vector3d>) {
    return option_codec::Check(value, spec);
  } else {
    return {};
  }
}

}  // namespace rpt

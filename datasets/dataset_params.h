// SPDX-License-Identifier: MIT
// Typed dataset parameters: the `--param key=value` text of a DatasetRequest parsed once into a
// reader's options struct, and the parameter list `rpt datasets` shows, both from the struct's
// VisitFields (core/option_spec.h).
//
//   struct PanopticParams { int every = 12; ... };
//   template <class Visitor, OptionsOf<PanopticParams> Self>
//   void VisitFields(Visitor& v, Self& o) { v("every", o.every, OptionSpec{.help = "...", .min = 1}); }
//
//   const PanopticParams p = ParseDatasetParams<PanopticParams>("panoptic", request);  // in the reader
//   info.params = DescribeDatasetParams<PanopticParams>();                  // in <Name>Info()
//
// Field types: int, uint64_t, double, bool, std::string, ParamList (comma-separated names) and
// enumerations with an EnumNames specialisation. Numbers are checked against OptionSpec's
// range (min_exclusive: "> min"). Errors are ConfigError (exit code 2) naming the
// dataset, the parameter and the value: "panoptic: param every: '0' is not an integer >= 1";
// an unknown key lists the valid ones and suggests the nearest ("did you mean 'cameras'?").
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/option_spec.h"
#include "datasets/dataset_request.h"

namespace rpt {

// A comma-separated list of names ("S9,S11"); empty items are dropped (SplitList).
using ParamList = std::vector<std::string>;

namespace dataset_params {

// "<dataset>: param <key>" (the prefix of every value error).
std::string What(std::string_view dataset, std::string_view key);

// Parse `text` into `out`, checking `spec`'s range; throw ConfigError("<what>: '<text>' is not ...").
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, int* out);
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, std::uint64_t* out);
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, double* out);
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, bool* out);
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, std::string* out);
void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, ParamList* out);

// The value as `--param` text (the inverse of Parse).
std::string Format(int value);
std::string Format(std::uint64_t value);
std::string Format(double value);
std::string Format(bool value);
std::string Format(const std::string& value);
std::string Format(const ParamList& value);

// What a value of the type must be, for `rpt datasets` and the docs: "integer in [2, 64]",
// "integer >= 0", "number > 0", "true | false", "text", "comma-separated list".
std::string TypeText(const int*, const OptionSpec& spec);
std::string TypeText(const std::uint64_t*, const OptionSpec& spec);
std::string TypeText(const double*, const OptionSpec& spec);
std::string TypeText(const bool*, const OptionSpec& spec);
std::string TypeText(const std::string*, const OptionSpec& spec);
std::string TypeText(const ParamList*, const OptionSpec& spec);

// Throws ConfigError "dataset '<dataset>' has no parameter '<key>' (valid: a, b); did you mean 'x'?"
// for the first key of `given` not in `known`.
void CheckKnownKeys(const std::string& dataset, const std::map<std::string, std::string>& given,
                    const std::vector<std::string>& known);

template <class Enum>
std::string EnumList(std::string_view separator) {
  std::string out;
  for (const auto& [value, name] : EnumNames<Enum>::values) {
    if (!out.empty()) out += separator;
    out += name;
  }
  return out;
}

template <class T>
void ParseField(std::string_view text, const OptionSpec& spec, const std::string& what, T* out) {
  if constexpr (std::is_enum_v<T>) {
    if (!EnumFromName(text, out)) {
      throw ConfigError(what + ": '" + std::string(text) + "' is not one of " + EnumList<T>(", "));
    }
  } else {
    Parse(text, spec, what, out);
  }
}

template <class T>
std::string FormatField(const T& value) {
  if constexpr (std::is_enum_v<T>) {
    return std::string(EnumName(value));
  } else {
    return Format(value);
  }
}

template <class T>
std::string TypeTextOf(const OptionSpec& spec) {
  if constexpr (std::is_enum_v<T>) {
    return EnumList<T>(" | ");
  } else {
    return TypeText(static_cast<const T*>(nullptr), spec);
  }
}

// Visitors over an options struct.
struct KeyLister {
  std::vector<std::string> keys;
  template <class T>
  void operator()(std::string_view key, const T&, const OptionSpec&) {
    keys.emplace_back(key);
  }
};

struct Describer {
  std::vector<DatasetParam> params;
  template <class T>
  void operator()(std::string_view key, const T& value, const OptionSpec& spec) {
    params.push_back(DatasetParam{std::string(key), FormatField(value), std::string(spec.help), TypeTextOf<T>(spec)});
  }
};

struct Reader {
  const std::string& dataset;
  const std::map<std::string, std::string>& given;
  template <class T>
  void operator()(std::string_view key, T& value, const OptionSpec& spec) {
    const auto it = given.find(std::string(key));
    if (it != given.end()) ParseField(it->second, spec, What(dataset, key), &value);
  }
};

}  // namespace dataset_params

// The parameters of `request` parsed into `Options`, starting from `defaults`; unknown keys and
// bad values throw ConfigError naming the dataset and the parameter.
template <class Options>
Options ParseDatasetParams(const std::string& dataset, const DatasetRequest& request, Options defaults = {}) {
  dataset_params::KeyLister lister;
  VisitFields(lister, std::as_const(defaults));
  dataset_params::CheckKnownKeys(dataset, request.params, lister.keys);
  dataset_params::Reader reader{dataset, request.params};
  VisitFields(reader, defaults);
  return defaults;
}

// The parameter list of DatasetInfo: each field's key, default (as text), help and type.
template <class Options>
std::vector<DatasetParam> DescribeDatasetParams(const Options& defaults = {}) {
  dataset_params::Describer describer;
  VisitFields(describer, defaults);
  return describer.params;
}

}  // namespace rpt

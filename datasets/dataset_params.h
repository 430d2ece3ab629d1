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
// The values are read by the one option codec (core/option_codec.h), like `--set` and config
// files: field types bool, int, uint64_t, double, std::string, ParamList and enumerations with an
// EnumNames specialisation, numbers checked against OptionSpec's range. Errors are ConfigError
// (exit code 2) in the codec's form "<where>: <dataset>.<key>: <problem>":
// "--param every=0: panoptic.every: '0' is not an integer >= 1"; an unknown key lists the valid
// ones and suggests the nearest ("did you mean 'cameras'?"). A params struct with checks beyond
// the ranges has `std::string Check() const` (core/options_check.h), run after parsing.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/option_spec.h"
#include "core/options_check.h"
#include "datasets/dataset_request.h"

namespace rpt {

// A list of names: a comma list ("S9,S11") or a JSON list (["S9", "S11"]); core/option_codec.h.
using ParamList = std::vector<std::string>;

namespace dataset_params {

// "<dataset>.<key>": how messages name a parameter ("panoptic.every").
std::string ParamKey(std::string_view dataset, std::string_view key);

// "" when every name of `names` is distinct, else "'<name>' is listed twice" for the first repeated
// one: a camera or sequence given twice was read twice (one view weighed double).
std::string RepeatedNameProblem(const std::vector<std::string>& names);

// "unknown parameter '<key>' (did you mean 'x'?) (<dataset> has: a, b)".
std::string UnknownParamProblem(std::string_view dataset, const std::string& key,
                                const std::vector<std::string>& known);

// Throws ConfigError "--param <key>=<value>: <UnknownParamProblem>" for the first key of `given`
// not in `known`.
void CheckKnownKeys(const std::string& dataset, const std::map<std::string, std::string>& given,
                    const std::vector<std::string>& known);

// Visitors over a params struct.
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
    params.push_back(
        DatasetParam{std::string(key), FormatOption(value), std::string(spec.help), OptionTypeText<T>(spec)});
  }
};

struct Reader {
  const std::string& dataset;
  const std::map<std::string, std::string>& given;
  template <class T>
  void operator()(std::string_view key, T& value, const OptionSpec& spec) {
    const auto it = given.find(std::string(key));
    if (it == given.end()) return;
    if (const std::string problem = ParseOption(it->second, spec, &value); !problem.empty()) {
      throw ConfigError(OptionMessage("--param " + it->first + "=" + it->second, ParamKey(dataset, key), problem));
    }
  }
};

}  // namespace dataset_params

// The parameters of `request` parsed into `Options`, starting from `defaults`, then its Check()
// if it has one; unknown keys and bad values throw ConfigError naming the parameter.
template <class Options>
Options ParseDatasetParams(const std::string& dataset, const DatasetRequest& request, Options defaults = {}) {
  dataset_params::KeyLister lister;
  VisitFields(lister, std::as_const(defaults));
  dataset_params::CheckKnownKeys(dataset, request.params, lister.keys);
  dataset_params::Reader reader{dataset, request.params};
  VisitFields(reader, defaults);
  if constexpr (requires { defaults.Check(); }) ThrowIfInvalid(defaults);
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

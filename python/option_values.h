// SPDX-License-Identifier: MIT
// Python values for options: a value passed from Python goes through the one option codec
// (core/option_codec.h) as the text a config file would hold (a str as is, a bool as true/false,
// numbers and lists as JSON writes them), so Python refuses what `--set` and config files refuse,
// with the same words; and options come back as typed Python values.
#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/option_spec.h"
#include "core/printable_text.h"

namespace rpt::python {

namespace py = pybind11;

// The text of a Python value as a config file would hold it; None is refused (ConfigError naming
// `where` and `key`).
std::string OptionText(py::handle value, std::string_view where, std::string_view key);

// An option's value as a Python object: bool, int, float, str (text, enumerations), list of str
// (names), tuple of 3 floats (3-vectors).
template <class T>
py::object OptionObject(const T& value) {
  if constexpr (std::is_enum_v<T>) {
    return py::str(std::string(EnumName(value)));
  } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
    return py::make_tuple(value.x(), value.y(), value.z());
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    py::list list;
    for (const std::string& item : value) list.append(py::str(item));
    return list;
  } else {
    return py::cast(value);
  }
}

// Sets the fields of `options` (a struct with VisitFields) named by the keys of `values` (a dict
// or kwargs); an unknown key or a refused value is a ConfigError "<where>: <prefix><key>: ...".
template <class Options>
void SetOptionFields(const py::dict& values, std::string_view where, std::string_view prefix, Options* options) {
  for (const auto& [key_object, value] : values) {
    const std::string key = py::str(key_object).cast<std::string>();
    const std::string full_key = std::string(prefix) + key;
    bool found = false;
    auto visitor = [&](std::string_view name, auto& field, const OptionSpec& spec) {
      if (found || name != key) return;
      found = true;
      const std::string problem = ParseOption(OptionText(value, where, full_key), spec, &field);
      if (!problem.empty()) throw ConfigError(OptionMessage(where, full_key, problem));
    };
    VisitFields(visitor, *options);
    if (!found) {
      std::string known;
      auto lister = [&](std::string_view name, const auto&, const OptionSpec&) {
        known += (known.empty() ? "" : ", ") + std::string(name);
      };
      VisitFields(lister, *options);
      throw ConfigError(std::string(where) + ": unknown option " + QuoteName(full_key) + " (known: " + known + ")");
    }
  }
}

}  // namespace rpt::python

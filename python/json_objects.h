// SPDX-License-Identifier: MIT
// JSON values (summaries, camera records) as Python objects: objects as dicts (key order kept),
// arrays as lists, numbers as int or float, null as None.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace rpt::python {

pybind11::object PythonOf(const nlohmann::ordered_json& value);

}  // namespace rpt::python

// SPDX-License-Identifier: MIT
// sweep.html: a sweep's table as one self-contained page (plain HTML and inline SVG, no script,
// no network): one row per configuration with a column per varied option, the headline metrics
// with their delta against the default configuration (green = better, red = worse), and one bar
// chart per headline metric. Written from the content of sweep.json, so `rpt sweep` and
// `rpt merge` write the same page. The markup is well-formed XML (void elements closed), so any
// XML parser can read it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rpt::engine {

// The row the deltas are measured against: the first row marked "default": true (its
// configuration equals the sweep's base configuration, i.e. no override changes anything), else
// the first row (`is_default` false, and the page says so).
struct SweepBaseline {
  size_t row = 0;
  bool is_default = false;
};
SweepBaseline FindSweepBaseline(const nlohmann::ordered_json& rows);

// The page for a sweep file: {"rows": [{"name", "set": {key: value}, "default": bool,
// "summary": {...}}, ...], "base": {key: value of the base configuration}, "run": {"command"}}
// ("base", "run" and "default" optional).
std::string SweepHtml(const nlohmann::ordered_json& sweep);

}  // namespace rpt::engine

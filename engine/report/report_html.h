// SPDX-License-Identifier: MIT
// Assembles the self-contained report.html: the template (report/report.html), its style and
// script (report/report.css, report/report.js; all three embedded at build time), the JavaScript
// libraries inlined from their Debian packages (three.js with its OrbitControls: libjs-three;
// Chart.js: libjs-chart.js), and the report data as an inline JSON block. No network, no server.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace rpt::engine {

// Where the libraries are read from: $RPT_JAVASCRIPT_DIR when set, else /usr/share/javascript
// (Debian's location).
std::filesystem::path JavascriptDir();

// The page. Throws InputError naming the library file and the Debian package when one is missing.
std::string ReportHtml(const nlohmann::ordered_json& data);

}  // namespace rpt::engine

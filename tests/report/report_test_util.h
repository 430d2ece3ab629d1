// SPDX-License-Identifier: MIT
// Helpers of the report tests: an `rpt eval` + `rpt report` run, the report's data block, and
// headless Chromium (DOM dump and screenshots).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_test_util.h"

namespace rpt::test {

// Runs `rpt eval <eval_args> --quiet --out DIR` and `rpt report DIR <report_args>`; fails the test
// (and returns false) when either fails.
inline bool EvalAndReport(const std::string& eval_args, const std::filesystem::path& dir,
                          const std::string& report_args = "") {
  const CommandResult eval = RunRpt("eval " + eval_args + " --quiet --out " + dir.string());
  EXPECT_EQ(eval.exit_code, 0) << eval.err;
  if (eval.exit_code != 0) return false;
  const CommandResult report = RunRpt("report " + dir.string() + " " + report_args);
  EXPECT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(report.out.find("report in "), std::string::npos) << report.out;
  return report.exit_code == 0;
}

// Labels and detections of a synthetic scene (`rpt convert`) whose cameras `far` (indices) are moved
// to the centre [distance, 0, 0]: accepted with a warning, they must not break the page. Returns the
// eval arguments reading them.
inline std::string FarCameraInput(const std::filesystem::path& dir, const std::vector<std::pair<int, std::string>>& far) {
  std::filesystem::create_directories(dir);
  const std::string labels = (dir / "labels.json").string(), detections = (dir / "detections.json").string();
  const CommandResult convert = RunRpt("convert --dataset synthetic --param frames=12 --param people=2 --param cameras=4 "
                                       "--labels-out " + labels + " --detections-out " + detections);
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  std::string text = ReadAll(labels), out;
  const std::regex centre(R"("T": ?\[\[[^\]]*\], ?\[[^\]]*\], ?\[[^\]]*\]\])");
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    int camera = 0;
    std::string edited;
    auto begin = std::sregex_iterator(line.begin(), line.end(), centre);
    size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it, ++camera) {
      edited += line.substr(last, static_cast<size_t>(it->position()) - last);
      std::string replacement = it->str();
      for (const auto& [index, distance] : far) {
        if (index == camera) replacement = "\"T\": [[" + distance + "], [0], [0]]";
      }
      edited += replacement;
      last = static_cast<size_t>(it->position() + it->length());
    }
    out += edited + line.substr(last) + "\n";
  }
  std::ofstream(labels) << out;
  return "--labels " + labels + " --detections " + detections;
}

// The JSON data block of a report page.
inline nlohmann::json ReportData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"rpt-data\">";
  const size_t begin = html.find(open);
  if (begin == std::string::npos) return nullptr;
  const size_t end = html.find("</script>", begin);
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

// Chromium: $RPT_CHROMIUM, else the Debian binary; empty when absent.
inline std::string ChromiumBinary() {
  if (const char* env = std::getenv("RPT_CHROMIUM"); env != nullptr && *env != '\0') return env;
  for (const char* path : {"/usr/bin/chromium", "/usr/bin/chromium-browser"}) {
    if (std::filesystem::exists(path)) return path;
  }
  return "";
}

// Flags for a headless run that needs no GPU (WebGL through SwiftShader), as root in CI.
inline std::string ChromiumCommand(const std::string& extra) {
  return ChromiumBinary() +
         " --headless --no-sandbox --disable-dev-shm-usage --use-angle=swiftshader --enable-unsafe-swiftshader"
         " --hide-scrollbars --force-device-scale-factor=1 --no-first-run --disable-extensions"
         " --virtual-time-budget=15000 " +
         extra + " 2>/dev/null";
}

// The DOM of `page` after its scripts ran; `query` is appended to the URL ("?scene=3").
inline std::string DumpDom(const std::filesystem::path& page, const std::string& query = "") {
  const std::string command =
      ChromiumCommand("--dump-dom 'file://" + std::filesystem::absolute(page).string() + query + "'");
  std::string dom;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return dom;
  char buffer[65536];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) dom.append(buffer, n);
  pclose(pipe);
  return dom;
}

// Attribute `name` of the <body> element in a DOM dump, "" when absent.
inline std::string BodyAttribute(const std::string& dom, const std::string& name) {
  const size_t body = dom.find("<body");
  if (body == std::string::npos) return "";
  const std::string tag = dom.substr(body, dom.find('>', body) - body);
  std::smatch m;
  if (std::regex_search(tag, m, std::regex(" " + name + "=\"([^\"]*)\""))) return m[1];
  return "";
}

// A PNG of the page at URL suffix `suffix` ("?scene=3#only-viewer"), width x height pixels.
inline bool Screenshot(const std::filesystem::path& page, const std::string& suffix, const std::filesystem::path& png,
                       int width, int height) {
  std::filesystem::create_directories(png.parent_path());
  std::filesystem::remove(png);
  const std::string command = ChromiumCommand("--window-size=" + std::to_string(width) + "," + std::to_string(height) +
                                              " --screenshot=" + png.string() + " 'file://" +
                                              std::filesystem::absolute(page).string() + suffix + "'");
  const int status = std::system((command + " >/dev/null").c_str());
  return status == 0 && std::filesystem::exists(png) && std::filesystem::file_size(png) > 1000;
}

}  // namespace rpt::test

// SPDX-License-Identifier: MIT
#include "engine/report/report_html.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/errors.h"
#include "engine/outputs/text_escaping.h"
#include "report_assets.h"

namespace rpt::engine {
namespace {

struct Library {
  const char* path;     // under JavascriptDir()
  const char* package;  // the Debian package that installs it
};
constexpr Library kLibraries[] = {
    {"three/three.min.js", "libjs-three"},
    {"three/examples/js/controls/OrbitControls.js", "libjs-three"},
    {"chart.js/chart.min.js", "libjs-chart.js"},
};

std::string ReadLibrary(const Library& library) {
  const std::filesystem::path path = JavascriptDir() / library.path;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string() + ": not found; rpt report inlines it into the page: install the Debian package " +
                     library.package + " (scripts/install_deps.sh) or set RPT_JAVASCRIPT_DIR");
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void ReplaceOnce(std::string* text, std::string_view marker, const std::string& with) {
  const size_t at = text->find(marker);
  if (at == std::string::npos) throw std::logic_error("report template lacks " + std::string(marker));
  text->replace(at, marker.size(), with);
}

}  // namespace

std::filesystem::path JavascriptDir() {
  const char* env = std::getenv("RPT_JAVASCRIPT_DIR");
  return env != nullptr && *env != '\0' ? std::filesystem::path(env) : std::filesystem::path("/usr/share/javascript");
}

std::string ReportHtml(const nlohmann::ordered_json& data) {
  std::string libraries;
  for (const Library& library : kLibraries) {
    // Inlined as they are: escaping "</" inside a library could change a regular expression, so one holding
    // "</script" is refused instead (the packaged versions hold none).
    const std::string text = ReadLibrary(library);
    if (text.find("</script") != std::string::npos) {
      throw InputError((JavascriptDir() / library.path).string() + ": holds '</script' and cannot be inlined");
    }
    libraries += "<script>/* " + std::string(library.path) + " */\n" + text + "\n</script>\n";
  }
  std::string page(assets::kReportHtml);
  ReplaceOnce(&page, "/*RPT_STYLE*/", std::string(assets::kReportCss));
  ReplaceOnce(&page, "<!--RPT_LIBRARIES-->", libraries);
  ReplaceOnce(&page, "/*RPT_SCRIPT*/", std::string(assets::kReportJs));
  // Names from the input (cameras, scenes, frame ids, joints, paths) are in there: ScriptJson keeps
  // "<!--<script>" or "</script" in one of them from ending or changing the element.
  ReplaceOnce(&page, "/*RPT_DATA*/",
              ScriptJson(data.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace)));
  return page;
}

}  // namespace rpt::engine

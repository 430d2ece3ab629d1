// SPDX-License-Identifier: MIT
#include "engine/outputs/sweep_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include "core/utf8.h"
#include "engine/json_text.h"
#include "engine/outputs/results_writer.h"
#include "engine/outputs/text_escaping.h"
#include "core/text.h"

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;

// A headline metric and which way is better.
struct Headline {
  std::string key;
  bool higher_is_better;
};
const std::vector<Headline>& Headlines() {
  static const std::vector<Headline> headlines = {
      {"pcp", true},
      {"mpjpe_mm", false},
      {"recall100", true},
      {"recall500", true},
      {"invalid", false},
      {"f1", true},
      {"frame_time_us_median", false},
      {"legacy_pcp", true},
  };
  return headlines;
}

// Title and unit of a summary key (SummaryColumns(), the one source of both).
std::string TitleOf(const std::string& key) {
  for (const SummaryColumn& c : SummaryColumns()) {
    if (c.key == key) return c.title + " (" + c.unit + ")";
  }
  return key == "legacy_pcp" ? "Legacy PCP (%)" : key;
}

// `name` cut to at most `max_characters` characters with "..." (whole UTF-8 characters: a cut
// never splits one; bytes that are not valid UTF-8 count as one character each).
std::string Shortened(const std::string& name, size_t max_characters) {
  size_t characters = 0, cut = 0;
  for (size_t i = 0; i < name.size(); ++characters) {
    if (characters == max_characters - 1) cut = i;
    i += std::max<size_t>(Utf8SequenceLength(name, i), 1);
  }
  return characters <= max_characters ? name : name.substr(0, cut) + "...";
}

int DecimalsOf(const std::string& key) { return key == "frame_time_us_median" ? 0 : 1; }

// The metric of a row, or NaN when the row does not report it.
double Value(const OrderedJson& row, const std::string& key) {
  const OrderedJson& summary = row.at("summary");
  if (!summary.contains(key) || !summary[key].is_number()) return std::nan("");
  return summary[key].get<double>();
}

// `value` as shown (rounded to its decimals): deltas are of the shown values, so that two values
// shown differently never get a delta of 0 (38.447 and 38.459 show as 38.4 and 38.5: -0.1).
double Shown(double value, const std::string& key) {
  double shown = value;
  ParseNumber(FixedText(value, DecimalsOf(key)), &shown);
  return shown;
}

// Whether a row's numbers can be compared with the baseline's (same metrics options).
bool Comparable(const OrderedJson& row, const OrderedJson& baseline) {
  return !row.value("measured_differently", false) && !baseline.value("measured_differently", false);
}

// "better", "worse" or "same" for `delta` at the display precision.
std::string Verdict(double delta, const Headline& metric) {
  if (!(std::fabs(delta) >= 0.5 * std::pow(10.0, -DecimalsOf(metric.key)))) return "same";
  return (delta > 0) == metric.higher_is_better ? "better" : "worse";
}

std::string DeltaText(double delta, const std::string& key) {
  const std::string text = FixedText(std::fabs(delta), DecimalsOf(key));
  if (text == FixedText(0.0, DecimalsOf(key))) return "\u00b1" + text;  // plus-minus sign
  return (delta > 0 ? "+" : "\u2212") + text;                       // minus sign
}

// One horizontal bar per row and a dashed line at the baseline. The bars start at 0, or, when the
// values lie close together (their spread under a third of the largest), just below the smallest
// so that their differences show; the chart then says where its axis starts. A row measured with
// other metrics options is grey (not better or worse).
std::string BarChart(const OrderedJson& rows, const Headline& metric, size_t baseline) {
  constexpr int kLabelWidth = 330, kBarWidth = 260, kRowHeight = 18, kTextWidth = 70;
  double max_value = 0, min_value = std::numeric_limits<double>::infinity();
  for (const OrderedJson& row : rows) {
    const double v = Value(row, metric.key);
    if (!std::isfinite(v)) continue;
    max_value = std::max(max_value, v);
    min_value = std::min(min_value, v);
  }
  if (!(max_value > 0)) max_value = 1;
  double start = 0;
  if (min_value > 0 && max_value > min_value && max_value - min_value < max_value / 3) {
    start = std::max(0.0, min_value - 0.5 * (max_value - min_value));
  }
  const auto length = [&](double v) { return std::max(0.0, v - start) / (max_value - start) * kBarWidth; };
  const int width = kLabelWidth + kBarWidth + kTextWidth;
  const int height = static_cast<int>(rows.size()) * kRowHeight + 6 + (start > 0 ? kRowHeight : 0);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"chart\" data-metric=\"" << metric.key << "\" width=\""
      << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " " << height << "\">\n";
  const double base_value = Value(rows[baseline], metric.key);
  for (size_t i = 0; i < rows.size(); ++i) {
    const OrderedJson& row = rows[i];
    const std::string name = row.at("name").get<std::string>();
    const std::string shown = Shortened(name, 48);
    const int y = static_cast<int>(i) * kRowHeight + 3;
    const double v = Value(row, metric.key);
    const std::string verdict = i == baseline                          ? "baseline"
                                : !Comparable(row, rows[baseline]) ? "incomparable"
                                                                   : Verdict(Shown(v, metric.key) - Shown(base_value, metric.key), metric);
    svg << "<g class=\"bar " << verdict << "\"><title>" << HtmlText(name) << ": "
        << (std::isfinite(v) ? FixedText(v, DecimalsOf(metric.key)) : "-") << "</title>";
    svg << "<text x=\"" << kLabelWidth - 6 << "\" y=\"" << y + 12 << "\" text-anchor=\"end\">" << HtmlText(shown)
        << "</text>";
    if (std::isfinite(v)) {
      const double w = length(v);
      svg << "<rect x=\"" << kLabelWidth << "\" y=\"" << y + 2 << "\" width=\"" << FixedText(w, 1) << "\" height=\""
          << kRowHeight - 5 << "\"/>";
      svg << "<text x=\"" << FixedText(kLabelWidth + w + 4, 1) << "\" y=\"" << y + 12 << "\">"
          << FixedText(v, DecimalsOf(metric.key)) << "</text>";
    } else {
      svg << "<text x=\"" << kLabelWidth + 4 << "\" y=\"" << y + 12 << "\">-</text>";
    }
    svg << "</g>\n";
  }
  const int bars_height = static_cast<int>(rows.size()) * kRowHeight + 6;
  if (std::isfinite(base_value)) {
    const std::string x = FixedText(kLabelWidth + length(base_value), 1);
    svg << "<line class=\"baseline-mark\" x1=\"" << x << "\" y1=\"0\" x2=\"" << x << "\" y2=\"" << bars_height
        << "\"/>\n";
  }
  if (start > 0) {
    svg << "<text class=\"axis-start\" x=\"" << kLabelWidth << "\" y=\"" << bars_height + 12 << "\">bars start at "
        << FixedText(start, DecimalsOf(metric.key)) << ", not 0</text>\n";
  }
  svg << "</svg>";
  return svg.str();
}

}  // namespace

SweepBaseline FindSweepBaseline(const OrderedJson& rows) {
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].value("default", false)) return {i, true};
  }
  return {0, false};
}

std::string SweepHtml(const OrderedJson& sweep) {
  const OrderedJson& rows = sweep.at("rows");
  const SweepBaseline baseline = FindSweepBaseline(rows);
  // The varied options, in order of first appearance.
  std::vector<std::string> options;
  for (const OrderedJson& row : rows) {
    const OrderedJson set = row.value("set", OrderedJson::object());  // items() must not outlive it
    for (const auto& [key, value] : set.items()) {
      if (std::find(options.begin(), options.end(), key) == options.end()) options.push_back(key);
    }
  }
  std::vector<Headline> metrics;
  for (const Headline& h : Headlines()) {
    bool reported = false;
    for (const OrderedJson& row : rows) reported |= row.at("summary").contains(h.key);
    if (reported) metrics.push_back(h);
  }
  const OrderedJson base = sweep.value("base", OrderedJson::object());
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>rpt sweep: " << rows.size()
       << " configurations</title>\n<style>\n"
          "body { font-family: sans-serif; margin: 2em; color: #222; }\n"
          "table { border-collapse: collapse; font-size: 14px; }\n"
          "th, td { padding: 3px 8px; border-bottom: 1px solid #ddd; text-align: right; white-space: nowrap; }\n"
          "th { background: #f0f0f0; }\n"
          ".name { text-align: left; white-space: normal; min-width: 12em; max-width: 28em; overflow-wrap: anywhere; }\n"
          ".table-wrap { overflow-x: auto; max-width: 100%; }\n"
          ".option { text-align: left; white-space: normal; min-width: 6em; max-width: 20em; overflow-wrap: anywhere; }\n"
          ".inherited { color: #999; }\n"
          "tr.baseline td { background: #eef3fa; font-weight: bold; }\n"
          ".better { color: #1a7f37; } .worse { color: #c62828; } .same { color: #888; }\n"
          ".charts { display: flex; flex-wrap: wrap; gap: 2em; }\n"
          "figure { margin: 0; } figcaption { font-weight: bold; margin-bottom: 4px; }\n"
          "svg.chart text { font-size: 11px; fill: #222; }\n"
          "g.bar rect { fill: #9e9e9e; } g.better rect { fill: #4caf50; } g.worse rect { fill: #e57373; }\n"
          "g.baseline rect { fill: #1f77b4; } g.incomparable rect { fill: #d0d0d0; }\n"
          "svg.chart text.axis-start { fill: #777; font-style: italic; }\n"
          "line.baseline-mark { stroke: #1f77b4; stroke-dasharray: 4 3; }\n"
          "</style>\n</head>\n<body>\n<h1>rpt sweep</h1>\n";
  html << "<p>" << rows.size() << " configuration(s). Deltas against <b>"
       << HtmlText(rows.empty() ? "" : rows[baseline.row].at("name").get<std::string>()) << "</b>";
  html << (baseline.is_default ? " (the base configuration: no override of the sweep changes an option of it; "
                                 "its options are sweep.json's <code>base_options</code>)"
                               : " (the first row: no configuration equals the base configuration)")
       << "; green is better, red is worse (light grey bars: measured with other metrics options, not compared). Grey "
          "option values are inherited from the base configuration.</p>\n";
  if (sweep.contains("run") && sweep["run"].contains("command")) {
    html << "<p>Command: <code>" << HtmlText(JsonValueText(sweep["run"]["command"])) << "</code></p>\n";
  }
  if (sweep.contains("shard_runs") && sweep["shard_runs"].is_array()) {  // a merged sweep: its shards
    html << "<p>Shards:</p>\n<ul class=\"shards\">\n";
    for (const OrderedJson& run : sweep["shard_runs"]) {
      if (!run.is_object() || !run.contains("command")) continue;
      html << "<li><code>" << HtmlText(JsonValueText(run["command"])) << "</code>"
           << (run.contains("git_revision") ? " (revision " + HtmlText(JsonValueText(run["git_revision"])) + ")" : "")
           << "</li>\n";
    }
    html << "</ul>\n";
  }
  // The table scrolls sideways on its own when it is wider than the window (many varied options):
  // the page and its charts stay put.
  html << "<div class=\"table-wrap\">\n<table id=\"sweep\">\n<thead>\n<tr><th class=\"name\">configuration</th>";
  for (const std::string& option : options) html << "<th class=\"option\">" << HtmlText(option) << "</th>";
  for (const Headline& h : metrics) html << "<th>" << HtmlText(TitleOf(h.key)) << "</th>";
  html << "</tr>\n</thead>\n<tbody>\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    const OrderedJson& row = rows[i];
    html << "<tr data-row=\"" << i << "\"" << (i == baseline.row ? " class=\"baseline\"" : "") << ">";
    html << "<td class=\"name\">" << HtmlText(row.at("name").get<std::string>()) << "</td>";
    const OrderedJson set = row.value("set", OrderedJson::object());
    for (const std::string& option : options) {
      if (set.contains(option)) {
        html << "<td class=\"option\">" << HtmlText(JsonValueText(set[option])) << "</td>";
      } else {
        html << "<td class=\"option inherited\">"
             << (base.contains(option) ? HtmlText(JsonValueText(base[option])) : "") << "</td>";
      }
    }
    for (const Headline& h : metrics) {
      const double v = Value(row, h.key);
      html << "<td data-metric=\"" << h.key << "\">";
      if (!std::isfinite(v)) {
        html << "-</td>";
        continue;
      }
      html << FixedText(v, DecimalsOf(h.key));
      const double base_value = Value(rows[baseline.row], h.key);
      if (i != baseline.row && !Comparable(row, rows[baseline.row])) {
        html << " <span class=\"delta incomparable\" title=\"measured with other metrics options\">n/a</span>";
      } else if (i != baseline.row && std::isfinite(base_value)) {
        const double delta = Shown(v, h.key) - Shown(base_value, h.key);
        html << " <span class=\"delta " << Verdict(delta, h) << "\" data-delta=\"" << FixedText(v - base_value, 4) << "\">"
             << DeltaText(delta, h.key) << "</span>";
      }
      html << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody>\n</table>\n</div>\n";
  // Configurations that failed to run (their rows have no metrics).
  std::ostringstream failed;
  for (const OrderedJson& row : rows) {
    if (!row.contains("error") || !row["error"].is_string()) continue;
    failed << "<li><b>" << HtmlText(row.at("name").get<std::string>()) << "</b>: "
           << HtmlText(row["error"].get<std::string>()) << "</li>\n";
  }
  if (!failed.str().empty()) {
    html << "<h2>Failed configurations</h2>\n<ul id=\"errors\">\n" << failed.str() << "</ul>\n";
  }
  // The result warnings of the configurations (as rpt eval prints them: no predictions, low recall).
  std::ostringstream warned;
  for (const OrderedJson& row : rows) {
    const OrderedJson& summary = row.at("summary");
    if (!summary.contains("warnings") || !summary["warnings"].is_array()) continue;
    for (const OrderedJson& w : summary["warnings"]) {
      if (!w.is_object() || !w.contains("message") || !w["message"].is_string()) continue;
      warned << "<li><b>" << HtmlText(row.at("name").get<std::string>()) << "</b>: "
             << HtmlText(w["message"].get<std::string>()) << "</li>\n";
    }
  }
  if (!warned.str().empty()) html << "<h2>Warnings</h2>\n<ul id=\"warnings\">\n" << warned.str() << "</ul>\n";
  html << "<h2>Headline metrics</h2>\n<div class=\"charts\">\n";
  for (const Headline& h : metrics) {
    if (rows.empty()) break;
    html << "<figure>\n<figcaption>" << HtmlText(TitleOf(h.key)) << ", "
         << (h.higher_is_better ? "higher is better" : "lower is better") << "</figcaption>\n"
         << BarChart(rows, h, baseline.row) << "\n</figure>\n";
  }
  html << "</div>\n</body>\n</html>\n";
  return html.str();
}

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
// "did you mean": the known name closest to a misspelt one (edit distance), for the error messages
// of every command, option key, dataset parameter and thresholds key (one rule everywhere).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace rpt {

// Edits (insert, delete, substitute, swap two neighbours: 1 each) that turn `a` into `b`
// (optimal string alignment distance: "cuont" is one swap from "count").
inline int EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<int>> d(a.size() + 1, std::vector<int>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// The candidate closest to `name` when it is close enough to be a typo (distance at most a third
// of the name's length, at least 1; ties: the first), else "".
inline std::string ClosestName(std::string_view name, const std::vector<std::string>& candidates) {
  const int limit = std::max<int>(1, static_cast<int>(name.size()) / 3);
  std::string best;
  int best_distance = limit + 1;
  for (const std::string& candidate : candidates) {
    const int distance = EditDistance(name, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

// " (did you mean 'x'?)" or "".
inline std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string closest = ClosestName(name, candidates);
  return closest.empty() ? std::string() : " (did you mean '" + closest + "'?)";
}

// DidYouMean for a key of a JSON object: also the usual other names of a known key ("timestamp",
// "ts", "t" for "time"; "frame_id", "frame" for "id"; "cameras" for "views"), which are no typos.
inline std::string DidYouMeanKey(std::string_view key, const std::vector<std::string>& known) {
  static const std::vector<std::pair<std::string_view, std::string_view>> kOtherNames = {
      {"timestamp", "time"}, {"timestamp_s", "time"}, {"time_s", "time"}, {"ts", "time"}, {"t", "time"},
      {"stamp", "time"},     {"frame_id", "id"},      {"frame", "id"},    {"cameras", "views"}};
  for (const auto& [other, name] : kOtherNames) {
    if (key == other && std::find(known.begin(), known.end(), name) != known.end()) {
      return " (did you mean '" + std::string(name) + "'?)";
    }
  }
  return DidYouMean(key, known);
}

// " (did you mean 'x'?)" when `name` is a candidate written otherwise: in another case or with other
// separators ('Cam0', 'cam_0', 'CAM-0' for 'cam0'), else "". For names such as camera names, where
// an edit distance of 1 is another camera ('cam9' is no typo of 'cam0').
inline std::string DidYouMeanSpelling(std::string_view name, const std::vector<std::string>& candidates) {
  const auto plain = [](std::string_view text) {
    std::string out;
    for (const char c : text) {
      if (c == '_' || c == '-' || c == ' ' || c == '.') continue;
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
  };
  const std::string wanted = plain(name);
  for (const std::string& candidate : candidates) {
    if (candidate != name && plain(candidate) == wanted) return " (did you mean '" + candidate + "'?)";
  }
  return "";
}

// "unknown <noun> '<name>' (did you mean 'x'?) (<known>)": the one message for an unknown option
// key, section or dataset parameter; `known` says what there is ("filter has: min_match_score").
inline std::string UnknownNameProblem(std::string_view noun, std::string_view name,
                                      const std::vector<std::string>& candidates, std::string_view known) {
  return "unknown " + std::string(noun) + " '" + std::string(name) + "'" + DidYouMean(name, candidates) + " (" +
         std::string(known) + ")";
}

}  // namespace rpt

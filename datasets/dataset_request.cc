// SPDX-License-Identifier: MIT
#include "datasets/dataset_request.h"

#include <algorithm>
#include <charconv>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "datasets/io/number_text.h"

namespace rpt {
namespace {

int ParseInt(std::string_view text, const std::string& what) {
  int value = 0;
  if (!io::ParseInteger(text, &value)) {
    throw ConfigError(what + ": " + QuoteName(std::string(text)) + " is not an integer");
  }
  return value;
}

}  // namespace

std::vector<int> ParseFrameRanges(const std::string& text, const std::string& what) {
  std::vector<int> frames;
  for (const std::string& item : SplitList(text)) {
    std::string range = item;
    int step = 1;
    if (const size_t colon = range.find(':'); colon != std::string::npos) {
      step = ParseInt(std::string_view(range).substr(colon + 1), what);
      range = range.substr(0, colon);
      if (step <= 0) throw ConfigError(what + ": step in " + QuoteName(item) + " must be positive");
    }
    const size_t dash = range.find('-', 1);
    const int first = ParseInt(std::string_view(range).substr(0, dash), what);
    const int last = dash == std::string::npos ? first : ParseInt(std::string_view(range).substr(dash + 1), what);
    if (last < first) throw ConfigError(what + ": empty range " + QuoteName(item));
    if (static_cast<long>(last - first) / step > 10000000) throw ConfigError(what + ": range " + QuoteName(item) + " is too large");
    for (int f = first; f <= last; f += step) frames.push_back(f);
  }
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  if (frames.empty()) throw ConfigError(what + ": no frames selected by " + QuoteName(text));
  return frames;
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "datasets/dataset_params.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/closest_name.h"
#include "core/text.h"
#include "datasets/io/number_text.h"

namespace rpt::dataset_params {
namespace {

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

// "in [2, 64]", ">= 1", "> 0", "<= 5" or "" (no limit), for a type whose own limits are
// [type_min, type_max].
std::string RangeText(const OptionSpec& spec, double type_min, double type_max) {
  const bool has_min = spec.min > type_min;
  const bool has_max = spec.max < type_max;
  if (spec.min_exclusive && has_max) return "in (" + Number(spec.min) + ", " + Number(spec.max) + "]";
  if (spec.min_exclusive) return "> " + Number(spec.min);
  if (has_min && has_max) return "in [" + Number(spec.min) + ", " + Number(spec.max) + "]";
  if (has_min) return ">= " + Number(spec.min);
  if (has_max) return "<= " + Number(spec.max);
  return "";
}

std::string WithRange(const std::string& noun, const OptionSpec& spec, double type_min, double type_max) {
  const std::string range = RangeText(spec, type_min, type_max);
  return range.empty() ? noun : noun + " " + range;
}

bool InRange(double value, const OptionSpec& spec) {
  if (spec.min_exclusive) return value > spec.min && value <= spec.max;
  return value >= spec.min && value <= spec.max;
}

[[noreturn]] void Fail(std::string_view text, const std::string& what, const std::string& expected) {
  throw ConfigError(what + ": '" + std::string(text) + "' is not " + expected);
}

template <class Int>
void ParseInteger(std::string_view text, const OptionSpec& spec, const std::string& what, Int* out) {
  constexpr double lo = static_cast<double>(std::numeric_limits<Int>::min());
  constexpr double hi = static_cast<double>(std::numeric_limits<Int>::max());
  Int value = 0;
  if (!io::ParseInteger(text, &value) || !InRange(static_cast<double>(value), spec)) Fail(text, what, WithRange("an integer", spec, lo, hi));
  *out = value;
}

}  // namespace

std::string What(std::string_view dataset, std::string_view key) {
  return std::string(dataset) + ": param " + std::string(key);
}

void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, int* out) {
  ParseInteger(text, spec, what, out);
}

void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, std::uint64_t* out) {
  ParseInteger(text, spec, what, out);
}

void Parse(std::string_view text, const OptionSpec& spec, const std::string& what, double* out) {
  double value = 0;
  if (!io::ParseFiniteNumber(text, &value) || !InRange(value, spec)) {
    const std::string range = RangeText(spec, -HUGE_VAL, HUGE_VAL);
    Fail(text, what, range == "> 0" ? "a positive number" : range.empty() ? "a number" : "a number " + range);
  }
  *out = value;
}

void Parse(std::string_view text, const OptionSpec&, const std::string& what, bool* out) {
  if (text == "true" || text == "1" || text == "yes" || text == "on") {
    *out = true;
  } else if (text == "false" || text == "0" || text == "no" || text == "off") {
    *out = false;
  } else {
    Fail(text, what, "true or false");
  }
}

void Parse(std::string_view text, const OptionSpec&, const std::string&, std::string* out) { *out = std::string(text); }

void Parse(std::string_view text, const OptionSpec&, const std::string&, ParamList* out) {
  *out = SplitList(std::string(text));
}

std::string Format(int value) { return std::to_string(value); }
std::string Format(std::uint64_t value) { return std::to_string(value); }
std::string Format(double value) { return Number(value); }
std::string Format(bool value) { return value ? "true" : "false"; }
std::string Format(const std::string& value) { return value; }
std::string Format(const ParamList& value) { return Join(value, ","); }

std::string TypeText(const int*, const OptionSpec& spec) {
  return WithRange("integer", spec, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
}
std::string TypeText(const std::uint64_t*, const OptionSpec& spec) {
  return WithRange("integer", spec, 0, static_cast<double>(std::numeric_limits<std::uint64_t>::max()));
}
std::string TypeText(const double*, const OptionSpec& spec) { return WithRange("number", spec, -HUGE_VAL, HUGE_VAL); }
std::string TypeText(const bool*, const OptionSpec&) { return "true | false"; }
std::string TypeText(const std::string*, const OptionSpec&) { return "text"; }
std::string TypeText(const ParamList*, const OptionSpec&) { return "comma-separated list"; }

void CheckKnownKeys(const std::string& dataset, const std::map<std::string, std::string>& given,
                    const std::vector<std::string>& known) {
  for (const auto& [key, value] : given) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const std::string nearest = ClosestName(key, known);
    throw ConfigError("dataset '" + dataset + "' has no parameter '" + key + "' (valid: " +
                      (known.empty() ? std::string("(none)") : Join(known)) + ")" +
                      (nearest.empty() ? std::string() : "; did you mean '" + nearest + "'?"));
  }
}

}  // namespace rpt::dataset_params

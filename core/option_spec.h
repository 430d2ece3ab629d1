// SPDX-License-Identifier: MIT
// The one convention for describing options, used by every options struct of the project
// (triangulator steps, metrics, dataset readers, the synthetic generator).
//
// Each options struct has, beside its definition, a function template that names each field
// once, with its key and an OptionSpec:
//
//   struct FilterOptions {
//     double min_match_score = 0.7;
//   };
//   template <class Visitor, OptionsOf<FilterOptions> Self>  // FilterOptions or const FilterOptions
//   void VisitFields(Visitor& v, Self& o) {
//     v("min_match_score", o.min_match_score,
//       OptionSpec{.help = "pairs with a lower pair score are dropped", .min = 0, .max = 1});
//   }
//
// The struct's initialisers stay the only source of the defaults; the visit is the only source
// of keys, help texts, units and ranges. Everything that reads or writes options by name (the
// command line, config files, the config dump, the docs tables, Check()) is a visitor, so
// they cannot drift apart. Enumerations name their values with an EnumNames specialisation.
#pragma once

#include <array>
#include <concepts>
#include <limits>
#include <string_view>
#include <type_traits>
#include <utility>

namespace rpt {

struct OptionSpec {
  std::string_view help = {};   // one line: what the value does (not how it is typed)
  std::string_view unit = {};   // "m", "m/s", "s", "px", "rel" (of the bbox diagonal), "" = none
  double min = -std::numeric_limits<double>::infinity();  // inclusive range of numbers
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;   // true: values must be > min (not >= min)
};

// Specialise for each enumeration used in options:
//   template <> struct EnumNames<ScoreScale> {
//     static constexpr std::array<std::pair<ScoreScale, std::string_view>, 2> values = {{
//         {ScoreScale::kAdaptive, "adaptive"}, {ScoreScale::kFixed, "fixed"}}};
//   };
template <class Enum>
struct EnumNames;

// `Self` is `Options` or `const Options`: keeps the VisitFields templates of different structs in
// one namespace apart (one template serves reading and writing).
template <class Self, class Options>
concept OptionsOf = std::same_as<std::remove_const_t<Self>, Options>;

// The name of an enumeration value ("" when it has none).
template <class Enum>
constexpr std::string_view EnumName(Enum value) {
  for (const auto& [v, name] : EnumNames<Enum>::values) {
    if (v == value) return name;
  }
  return {};
}

// Sets `out` to the value named `name`; false when no value has that name.
template <class Enum>
constexpr bool EnumFromName(std::string_view name, Enum* out) {
  for (const auto& [v, n] : EnumNames<Enum>::values) {
    if (n == name) {
      *out = v;
      return true;
    }
  }
  return false;
}

}  // namespace rpt

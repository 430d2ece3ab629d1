// SPDX-License-Identifier: MIT
// The step table (steps.h) bound to code: for every per-frame step, the function that runs it and
// the options section it reads, held together in one line each (RPT_BIND_STEP below).
//
// Triangulator::Process runs every step through RunStep<Step::kX>, which calls the bound function
// with the bound section, so a step's timing and count row (its Step value) always belong to the
// function bound to its key. When this header compiles, each binding checks that
//   * the function is the key in CamelCase (`triangulate_core` -> steps::TriangulateCore),
//   * the options member is the section the step table names (`section`),
//   * the function's first parameter is that member's options type.
// tests/pipeline/step_table_test.cc checks the rest: VisitSections names the member like the
// section, and the step's file (StepInfo::file) defines the function.
#pragma once

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include "core/fast_math.h"
#include "core/pipeline/bone_lengths.h"
#include "core/pipeline/choose_core_joints.h"
#include "core/pipeline/clip_speed.h"
#include "core/pipeline/filter.h"
#include "core/pipeline/group.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/merge.h"
#include "core/pipeline/options.h"
#include "core/pipeline/postprocess.h"
#include "core/pipeline/prefilter.h"
#include "core/pipeline/refine.h"
#include "core/pipeline/remember.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/score.h"
#include "core/pipeline/single_view.h"
#include "core/pipeline/smooth.h"
#include "core/pipeline/steps.h"
#include "core/pipeline/track.h"
#include "core/pipeline/triangulate_core.h"
#include "core/pipeline/triangulate_full.h"
#include "core/pipeline/undistort.h"
#include "core/pipeline/verify.h"

namespace rpt {

// StepBinding<S>::function runs step S; ::options is the member of TriangulatorOptions it reads
// (nullptr for a step without options); ::function_name and ::options_name spell them.
template <Step S>
struct StepBinding;

namespace step_binding {

// True when `camel` is `snake` in CamelCase ("triangulate_core" -> "TriangulateCore").
constexpr bool IsCamelCaseOf(std::string_view camel, std::string_view snake) {
  size_t c = 0;
  bool word_start = true;
  for (const char ch : snake) {
    if (ch == '_') {
      word_start = true;
      continue;
    }
    const char expected = word_start && ch >= 'a' && ch <= 'z' ? static_cast<char>(ch - 'a' + 'A') : ch;
    if (c >= camel.size() || camel[c++] != expected) return false;
    word_start = false;
  }
  return c == camel.size();
}

template <class Function>
struct FirstParameter;
template <class Result, class First, class... Rest>
struct FirstParameter<Result (*)(First, Rest...)> {
  using type = First;
};

}  // namespace step_binding

#define RPT_BIND_STEP(step_value, function_, section_)                                                     \
  template <>                                                                                              \
  struct StepBinding<Step::step_value> {                                                                   \
    static constexpr auto function = &steps::function_;                                                    \
    static constexpr std::string_view function_name = #function_;                                          \
    static constexpr auto options = &TriangulatorOptions::section_;                                        \
    static constexpr std::string_view options_name = #section_;                                            \
  };                                                                                                       \
  static_assert(step_binding::IsCamelCaseOf(#function_, Info(Step::step_value).key), "function = key");    \
  static_assert(Info(Step::step_value).section == #section_, "options member = the step table's section"); \
  static_assert(std::is_same_v<step_binding::FirstParameter<decltype(&steps::function_)>::type,            \
                               const decltype(TriangulatorOptions::section_)&>,                            \
                "the function takes its section's options first")

#define RPT_BIND_STEP_WITHOUT_OPTIONS(step_value, function_)                                            \
  template <>                                                                                           \
  struct StepBinding<Step::step_value> {                                                                \
    static constexpr auto function = &steps::function_;                                                 \
    static constexpr std::string_view function_name = #function_;                                       \
    static constexpr std::nullptr_t options = nullptr;                                                  \
    static constexpr std::string_view options_name = "";                                                \
  };                                                                                                    \
  static_assert(step_binding::IsCamelCaseOf(#function_, Info(Step::step_value).key), "function = key"); \
  static_assert(Info(Step::step_value).section.empty(), "the step table names no section")

RPT_BIND_STEP(kUndistort, Undistort, undistort);
RPT_BIND_STEP_WITHOUT_OPTIONS(kMakePairs, MakePairs);
RPT_BIND_STEP(kPrefilter, Prefilter, prefilter);
RPT_BIND_STEP(kTriangulateCore, TriangulateCore, triangulate);
RPT_BIND_STEP(kRoomCheck, RoomCheck, room_check);
RPT_BIND_STEP(kScore, Score, score);
RPT_BIND_STEP(kFilter, Filter, filter);
RPT_BIND_STEP(kGroup, Group, group);
RPT_BIND_STEP(kTriangulateFull, TriangulateFull, triangulate);
RPT_BIND_STEP(kMerge, Merge, merge);
RPT_BIND_STEP(kRefine, Refine, refine);
RPT_BIND_STEP(kVerify, Verify, verify);
RPT_BIND_STEP(kPostprocess, Postprocess, postprocess);
RPT_BIND_STEP(kSingleView, SingleView, single_view);
RPT_BIND_STEP(kTrack, Track, track);
RPT_BIND_STEP(kClipSpeed, ClipSpeed, clip_speed);
RPT_BIND_STEP(kBoneLengths, BoneLengths, bone_lengths);
RPT_BIND_STEP(kSmooth, Smooth, smooth);
RPT_BIND_STEP_WITHOUT_OPTIONS(kRemember, Remember);

#undef RPT_BIND_STEP
#undef RPT_BIND_STEP_WITHOUT_OPTIONS

// Step 3 runs once, when the model is built (model.cc), not per frame; the same checks.
static_assert(step_binding::IsCamelCaseOf("ChooseCoreJoints", kChooseCoreJoints.key));
static_assert(kChooseCoreJoints.section == "triangulate");
static_assert(
    std::is_same_v<step_binding::FirstParameter<decltype(&steps::ChooseCoreJoints)>::type, const TriangulateOptions&>);

// Runs step S: its bound function with its bound options section (if any) and `args` (the step's
// input struct and outputs). Returns what the function returns (the step's count).
template <Step S, class... Args>
RPT_ALWAYS_INLINE int RunStep(const TriangulatorOptions& options, Args&&... args) {
  using Binding = StepBinding<S>;
  if constexpr (std::is_null_pointer_v<std::remove_cv_t<decltype(Binding::options)>>) {
    return Binding::function(std::forward<Args>(args)...);
  } else {
    return Binding::function(options.*Binding::options, std::forward<Args>(args)...);
  }
}

}  // namespace rpt

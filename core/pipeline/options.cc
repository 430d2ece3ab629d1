// SPDX-License-Identifier: MIT
#include "core/pipeline/options.h"

#include <sstream>

#include "core/joints.h"
#include "core/options_check.h"

namespace rpt {

std::string TriangulatorOptions::Check() const {
  std::string error;
  auto check_section = [&error](std::string_view section, const auto& options) {
    if (error.empty()) error = CheckOptionRanges(section, options);
  };
  VisitSections(check_section, *this);
  if (!error.empty()) return error;
  // Checks between fields.
  std::ostringstream s;
  // The core joints are counted here as listed (the Triangulator checks again against the input's
  // joints): a list shorter than what a pose or a pair needs could never triangulate anyone.
  const size_t core = triangulate.core_joints.empty() ? DefaultCoreJoints().size() : triangulate.core_joints.size();
  if (triangulate.min_core_joints > static_cast<int>(core)) {
    s << "triangulate.min_core_joints: " << triangulate.min_core_joints << " exceeds the number of core joints ("
      << core << ", triangulate.core_joints)";
  } else if (undistort.min_core_joints > static_cast<int>(core)) {
    s << "undistort.min_core_joints: " << undistort.min_core_joints << " exceeds the number of core joints (" << core
      << ", triangulate.core_joints)";
  } else if (postprocess.max_extent_m < postprocess.min_extent_m) {
    s << "postprocess.max_extent_m: " << postprocess.max_extent_m << " is below postprocess.min_extent_m ("
      << postprocess.min_extent_m << ")";
  } else if (bone_lengths.min_observations > bone_lengths.window) {
    s << "bone_lengths.min_observations: " << bone_lengths.min_observations << " is above bone_lengths.window ("
      << bone_lengths.window << ")";
  }
  return s.str();
}

std::vector<std::string> TriangulatorOptions::Warnings() const {
  // Only settings changed from their defaults: turning tracking off (an ablation) warned about
  // clip_speed.enabled=true, which nobody had set.
  const TriangulatorOptions defaults;
  std::vector<std::string> warnings;
  if (!track.enabled) {
    const std::string why = " has no effect with track.enabled=false (it needs track ids)";
    if (clip_speed.enabled && !defaults.clip_speed.enabled) warnings.push_back("clip_speed.enabled=true" + why);
    if (bone_lengths.enabled && !defaults.bone_lengths.enabled) warnings.push_back("bone_lengths.enabled=true" + why);
    if (smooth.mode != SmoothMode::kOff && smooth.mode != defaults.smooth.mode) {
      warnings.push_back("smooth.mode=" + std::string(EnumName(smooth.mode)) + why);
    }
    if (single_view.enabled && single_view.track_assist && !defaults.single_view.track_assist) {
      warnings.push_back("single_view.track_assist=true" + why);
    }
  }
  if (!refine.enabled && refine.one_view_joints && !defaults.refine.one_view_joints) {
    warnings.push_back("refine.one_view_joints=true has no effect with refine.enabled=false (the refinement places "
                       "those joints)");
  }
  if (!single_view.enabled) {
    const std::string why = " has no effect with single_view.enabled=false";
    if (single_view.track_assist && !defaults.single_view.track_assist) warnings.push_back("single_view.track_assist=true" + why);
    if (single_view.ground_prior && !defaults.single_view.ground_prior) warnings.push_back("single_view.ground_prior=true" + why);
  }
  return warnings;
}

}  // namespace rpt

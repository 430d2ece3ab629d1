// SPDX-License-Identifier: MIT
#include "core/pipeline/choose_core_joints.h"

#include <string>

#include "core/errors.h"

namespace rpt {

std::vector<int> steps::ChooseCoreJoints(const TriangulateOptions& options, const JointNames& output_joints) {
  const JointNames& names = options.core_joints.empty() ? DefaultCoreJoints() : options.core_joints;
  std::vector<int> core_joints;
  for (const std::string& name : names) {
    const int j = FindJoint(output_joints, name);
    if (j < 0 && !options.core_joints.empty()) {
      throw ConfigError("triangulate.core_joints: joint '" + name + "' is not among the input joints");
    }
    if (j < 0) {
      // The default set on input without some of its joints (e.g. upper-body detections): say
      // which of them the input has, as a value to give.
      std::string present;
      for (const std::string& other : names) {
        if (FindJoint(output_joints, other) >= 0) present += (present.empty() ? "" : ",") + other;
      }
      throw ConfigError("triangulate.core_joints: the default core joints include '" + name +
                        "', which the input joints do not have; set triangulate.core_joints to joints the input has" +
                        (present.empty() ? std::string(" (none of the default ones)")
                                         : ", e.g. the default ones it has: " + present));
    }
    core_joints.push_back(j);
  }
  if (options.min_core_joints > static_cast<int>(core_joints.size())) {
    throw ConfigError("triangulate.min_core_joints (" + std::to_string(options.min_core_joints) +
                      ") exceeds the number of core joints (" + std::to_string(core_joints.size()) + ")");
  }
  return core_joints;
}

}  // namespace rpt

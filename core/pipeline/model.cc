// SPDX-License-Identifier: MIT
#include "core/pipeline/model.h"

#include <algorithm>
#include <set>
#include <string>

#include "core/errors.h"
#include "core/options_check.h"
#include "core/pipeline/choose_core_joints.h"
#include "core/pipeline/group.h"
#include "core/pipeline/view_geometry.h"

namespace rpt {

std::vector<ResolvedLimb> ResolveLimbs(const std::vector<LimbSpec>& limbs, const JointNames& names) {
  std::vector<ResolvedLimb> out;
  for (const LimbSpec& limb : limbs) {
    const int a = FindJoint(names, limb.a), b = FindJoint(names, limb.b);
    if (a >= 0 && b >= 0) out.push_back(ResolvedLimb{a, b, limb.min_length_m, limb.max_length_m});
  }
  return out;
}

namespace {

std::vector<DerivedJointRule> ResolveDerivedJoints(const JointNames& input_joints, const JointNames& output_joints) {
  std::vector<DerivedJointRule> derived;
  for (int j = static_cast<int>(input_joints.size()); j < static_cast<int>(output_joints.size()); ++j) {
    DerivedJointRule rule{j, {}};
    for (const JointNames& alternative : DerivedJointSources(output_joints[j])) {
      std::vector<int> indices;
      for (const std::string& name : alternative) indices.push_back(FindJoint(input_joints, name));
      if (std::find(indices.begin(), indices.end(), -1) == indices.end()) rule.alternatives.push_back(indices);
    }
    derived.push_back(std::move(rule));
  }
  return derived;
}

}  // namespace

TriangulatorModel BuildModel(std::vector<Camera> cameras, JointNames input_joints, TriangulatorOptions options) {
  ThrowIfInvalid(options);
  if (cameras.size() < 2) throw ConfigError("the triangulator needs at least 2 cameras, got " + std::to_string(cameras.size()));
  for (const Camera& camera : cameras) {
    if (const std::string error = camera.Validate(); !error.empty()) throw ConfigError(error);
  }
  if (input_joints.empty()) throw ConfigError("the input joint list is empty");
  std::set<std::string> seen;
  for (const std::string& name : input_joints) {
    if (!seen.insert(name).second) throw ConfigError("duplicate input joint '" + name + "'");
  }

  TriangulatorModel m;
  m.cameras = std::move(cameras);
  for (const Camera& camera : m.cameras) m.geometry.push_back(MakeViewGeometry(camera));
  m.input_joints = std::move(input_joints);
  m.output_joints = options.undistort.add_derived_joints ? AddDerivedJoints(m.input_joints) : m.input_joints;
  m.options = std::move(options);
  m.resolved = m.options;
  m.resolved.group.min_group_size = ResolveMinGroupSize(m.options.group, static_cast<int>(m.cameras.size()));
  m.derived = ResolveDerivedJoints(m.input_joints, m.output_joints);

  m.core_joints = steps::ChooseCoreJoints(m.resolved.triangulate, m.output_joints);
  if (m.resolved.undistort.min_core_joints > m.num_core_joints()) {
    throw ConfigError("undistort.min_core_joints (" + std::to_string(m.resolved.undistort.min_core_joints) +
                      ") exceeds the number of core joints (" + std::to_string(m.num_core_joints()) + ")");
  }
  JointNames core_names;
  for (int j : m.core_joints) core_names.push_back(m.output_joints[j]);
  for (int j = 0; j < m.num_output_joints(); ++j) m.all_joints.push_back(j);
  m.neighbour = NeighbourIndices(m.output_joints);
  m.core_limbs = ResolveLimbs(LimbsFor(core_names), core_names);
  m.core_mirror = MirrorIndices(core_names);
  m.all_limbs = ResolveLimbs(LimbsFor(m.output_joints), m.output_joints);
  m.core_limb_columns = ToLimbColumns(m.core_limbs);
  m.all_limb_columns = ToLimbColumns(m.all_limbs);
  m.typical_limbs = ResolveTypicalLimbs(m.output_joints);
  m.ground_joints = ResolveGroundJoints(m.output_joints);
  m.room = Room{m.resolved.room_check.center_m, m.resolved.room_check.size_m};
  m.max_gap_s = m.resolved.track.max_gap_s;
  m.unobserved_score = m.resolved.UnobservedScore();
  return m;
}

}  // namespace rpt

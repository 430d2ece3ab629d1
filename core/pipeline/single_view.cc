// SPDX-License-Identifier: MIT
#include "core/pipeline/single_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "core/joints.h"
#include "core/pipeline/box_iou.h"

namespace rpt {
namespace {

struct TypicalLimbName {
  std::string_view a, b;
  double length_m;
};

// Typical adult lengths (m) between joint centres as 2D detectors place them.
constexpr std::array<TypicalLimbName, 11> kTypicalLimbs = {{
    {"shoulder_left", "shoulder_right", 0.36},
    {"hip_left", "hip_right", 0.24},
    {"shoulder_left", "hip_left", 0.50},
    {"shoulder_right", "hip_right", 0.50},
    {"shoulder_left", "elbow_left", 0.29},
    {"shoulder_right", "elbow_right", 0.29},
    {"elbow_left", "wrist_left", 0.26},
    {"elbow_right", "wrist_right", 0.26},
    {"hip_left", "knee_left", 0.42},
    {"hip_right", "knee_right", 0.42},
    {"knee_left", "ankle_left", 0.40},
}};

// Centre of the valid core joints; false when none is valid.
bool Center(const Eigen::Ref<const Eigen::Matrix4Xd>& person, std::span<const int> core_joints, Eigen::Vector3d* center) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int j : core_joints) {
    if (person(3, j) <= 0) continue;
    sum += person.col(j).head<3>();
    ++n;
  }
  if (n > 0) *center = sum / n;
  return n > 0;
}

}  // namespace

std::vector<TypicalLimb> ResolveTypicalLimbs(const JointNames& joints) {
  std::vector<TypicalLimb> out;
  for (const TypicalLimbName& limb : kTypicalLimbs) {
    const int a = FindJoint(joints, std::string(limb.a)), b = FindJoint(joints, std::string(limb.b));
    if (a >= 0 && b >= 0) out.push_back(TypicalLimb{a, b, limb.length_m});
  }
  return out;
}

int steps::SingleView(const SingleViewOptions& options, const SingleViewInput& in, SingleViewScratch* scratch,
                      Poses3D* lifted, FrameStats* stats) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const std::span<const int> core_joints = in.core_joints;
  const Proposals& proposals = in.proposals;
  const Groups& groups = in.groups;
  const Poses3D& found = in.found;
  ViewVerdictScratch* verdict = &scratch->verdict;
  const int num_joints = found.num_joints;
  lifted->Clear(num_joints);
  if (!options.enabled) return 0;
  const int num_views = static_cast<int>(geometry.size());
  // Poses of the kept groups are taken.
  scratch->taken.assign(views.num_poses(), 0);
  for (int m = 0; m < static_cast<int>(groups.members.size()); ++m) {
    scratch->taken[proposals.pairs[m].a] = scratch->taken[proposals.pairs[m].b] = 1;
  }
  PoseBoxes(views, &verdict->boxes);
  // Poses overlapping a person already found (in that person's projection) are taken too.
  scratch->centers.clear();
  for (int p = 0; p < found.num_persons(); ++p) {
    const auto person = found.Person(p);
    Eigen::Vector3d center;
    if (Center(person, core_joints, &center)) scratch->centers.push_back(center);
    for (int v = 0; v < num_views; ++v) {
      Eigen::Vector4d box;
      JudgeView(views, geometry[v], v, core_joints, person, in.kernel.scale_m, options.min_inside_fraction, verdict,
                &box);
      if (!box.allFinite()) continue;
      for (int g = views.view_begin[v]; g < views.view_begin[v + 1]; ++g) {
        if (BoxIou(box, verdict->boxes[g]) >= options.max_overlap_iou) scratch->taken[g] = 1;
      }
    }
  }
  // Candidates by decreasing mean core-joint confidence.
  scratch->order.clear();
  for (int g = 0; g < views.num_poses(); ++g) {
    if (scratch->taken[g]) continue;
    const Keypoint* kps = views.Pose(g);
    int confident = 0;
    double sum = 0;
    for (int j : core_joints) {
      if (kps[j].score < options.min_joint_score) continue;
      ++confident;
      sum += kps[j].score;
    }
    if (confident >= options.min_core_joints) scratch->order.emplace_back(-sum / confident, g);
  }
  std::sort(scratch->order.begin(), scratch->order.end());

  for (const auto& [negative_confidence, g] : scratch->order) {
    const Keypoint* kps = views.Pose(g);
    const ViewGeometry& geo = geometry[views.view_of[g]];
    scratch->depths.clear();
    for (const TypicalLimb& limb : in.limbs) {
      const int a = limb.a, b = limb.b;
      if (kps[a].score < options.min_joint_score || kps[b].score < options.min_joint_score) continue;
      const double length = std::hypot(kps[a].x - kps[b].x, kps[a].y - kps[b].y);  // normalised units
      if (length > 1e-6) scratch->depths.push_back(limb.length_m / length);
    }
    if (scratch->depths.size() < 2) continue;
    std::sort(scratch->depths.begin(), scratch->depths.end());
    const double depth = scratch->depths[scratch->depths.size() >= 3 ? 1 : 0];

    scratch->person.setZero(4, num_joints);
    for (int j = 0; j < num_joints; ++j) {
      if (kps[j].score <= 0) continue;
      scratch->person.col(j) << geo.center + kps[j].ray * depth, kps[j].score * options.score_factor;
    }
    Eigen::Vector3d center;
    if (!Center(scratch->person, core_joints, &center)) continue;
    bool duplicate = false;
    for (const Eigen::Vector3d& other : scratch->centers) duplicate |= (other - center).norm() < options.duplicate_distance_m;
    if (duplicate) continue;
    int empty = 0;
    for (int v = 0; v < num_views; ++v) {
      if (v == views.view_of[g]) continue;
      empty += JudgeView(views, geometry[v], v, core_joints, scratch->person, in.kernel.scale_m,
                         options.min_inside_fraction, verdict, nullptr) == ViewVerdict::kEmpty;
    }
    if (empty >= options.min_empty_views && empty > 1) continue;
    lifted->AddPerson() = scratch->person;
    scratch->centers.push_back(center);
  }
  stats->single_view_persons = lifted->num_persons();
  return lifted->num_persons();
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "core/pipeline/single_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
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

// Mean ray of the confident joints among a and b; false when neither is confident.
bool MeanRay(const Keypoint* kps, int a, int b, double min_score, Eigen::Vector3d* ray) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int j : {a, b}) {
    if (j < 0 || kps[j].score < min_score) continue;
    sum += kps[j].ray;
    ++n;
  }
  if (n > 0) *ray = sum / n;
  return n > 0;
}

// Camera depth (normalised camera z) of a world point; <= 0 behind the camera.
double CameraDepth(const ViewGeometry& geo, const Eigen::Vector3d& point) {
  return geo.Rt.row(2).head<3>().dot(point) + geo.Rt(2, 3);
}

// The slot of the live track, supported by two views at most track_max_age_s ago and not used
// yet, whose projection lies closest to the pose (mean normalised distance over the core joints
// valid in both, at least 3, at most track_max_distance x `diag`); -1 when none.
int MatchTrack(const SingleViewOptions& options, const Tracks& tracks, double timestamp_s, const Keypoint* kps,
               const ViewGeometry& geo, double diag, std::span<const int> core_joints,
               const std::vector<char>& used) {
  int best = -1;
  double best_distance = options.track_max_distance * diag;
  const int num_slots = static_cast<int>(tracks.slots.size());
  for (int s = 0; s < num_slots; ++s) {
    const Tracks::Slot& slot = tracks.slots[s];
    const double age = timestamp_s - slot.supported_s;
    if (slot.id < 0 || used[s] || slot.pose.empty() || !(age <= options.track_max_age_s)) continue;
    const int num_joints = static_cast<int>(slot.pose.size() / 4);
    const Eigen::Map<const Eigen::Matrix4Xd> pose(slot.pose.data(), 4, num_joints);
    double sum = 0;
    int n = 0;
    for (int j : core_joints) {
      if (pose(3, j) <= 0 || kps[j].score < options.min_joint_score) continue;
      const Eigen::Vector3d c = geo.Rt * pose.col(j).head<3>().homogeneous();
      if (c.z() <= 0) continue;
      sum += std::hypot(c.x() / c.z() - kps[j].x, c.y() / c.z() - kps[j].y);
      ++n;
    }
    if (n < 3) continue;
    if (sum / n < best_distance) {
      best_distance = sum / n;
      best = s;
    }
  }
  return best;
}

// Places the pose's joints on their rays at the camera depths of the track's joints (its
// core-joint centre's for joints it lacks); scores x score_factor x exp(-age / track_decay_s).
void PlaceAtTrack(const SingleViewOptions& options, const Tracks::Slot& slot, double timestamp_s, const Keypoint* kps,
                  const ViewGeometry& geo, std::span<const int> core_joints, Eigen::Matrix4Xd* person) {
  const int num_joints = static_cast<int>(slot.pose.size() / 4);
  const Eigen::Map<const Eigen::Matrix4Xd> pose(slot.pose.data(), 4, num_joints);
  person->setZero(4, num_joints);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int j : core_joints) {
    if (pose(3, j) <= 0) continue;
    sum += pose.col(j).head<3>();
    ++n;
  }
  if (n == 0) return;
  const double center_depth = CameraDepth(geo, sum / n);
  if (!(center_depth > 0)) return;
  const double factor = options.score_factor * std::exp(-(timestamp_s - slot.supported_s) / options.track_decay_s);
  for (int j = 0; j < num_joints; ++j) {
    if (kps[j].score <= 0) continue;
    const double joint_depth = pose(3, j) > 0 ? CameraDepth(geo, pose.col(j).head<3>()) : 0.0;
    const double depth = joint_depth > 0 ? joint_depth : center_depth;
    person->col(j) << geo.center + kps[j].ray * depth, kps[j].score * factor;
  }
}

}  // namespace

GroundJoints ResolveGroundJoints(const JointNames& joints) {
  return GroundJoints{.ankle_left = FindJoint(joints, "ankle_left"),
                      .ankle_right = FindJoint(joints, "ankle_right"),
                      .hip_left = FindJoint(joints, "hip_left"),
                      .hip_right = FindJoint(joints, "hip_right"),
                      .shoulder_left = FindJoint(joints, "shoulder_left"),
                      .shoulder_right = FindJoint(joints, "shoulder_right")};
}

bool PlaceOnGround(const SingleViewOptions& options, const Keypoint* kps, const ViewGeometry& geo,
                   std::span<const TypicalLimb> limbs, const GroundJoints& ground, std::vector<double>* ratios,
                   Eigen::Matrix4Xd* person, double* body_scale) {
  const int num_joints = static_cast<int>(person->cols());
  person->setZero();
  if (body_scale != nullptr) *body_scale = 0;
  // The anchor: ankles on their plane, else hips on theirs.
  Eigen::Vector3d ray;
  double anchor_z = 0;
  if (MeanRay(kps, ground.ankle_left, ground.ankle_right, options.min_joint_score, &ray)) {
    anchor_z = options.floor_z_m + options.ankle_height_m;
  } else if (MeanRay(kps, ground.hip_left, ground.hip_right, options.min_joint_score, &ray)) {
    anchor_z = options.floor_z_m + options.hip_height_m;
  } else {
    return false;
  }
  if (std::abs(ray.z()) < 1e-12) return false;
  const double t = (anchor_z - geo.center.z()) / ray.z();
  if (!(t > 0) || !std::isfinite(t)) return false;  // the plane lies behind the camera along this ray
  const Eigen::Vector3d anchor = geo.center + t * ray;
  // The vertical plane through the anchor facing the camera: normal = horizontal viewing direction.
  Eigen::Vector3d normal(anchor.x() - geo.center.x(), anchor.y() - geo.center.y(), 0.0);
  const double horizontal = normal.norm();
  if (horizontal < 1e-6) return false;  // straight below the camera: no facing plane
  normal /= horizontal;
  for (int j = 0; j < num_joints; ++j) {
    if (kps[j].score <= 0) continue;
    const double along = normal.dot(kps[j].ray);
    if (!(along > 1e-12)) continue;  // a ray parallel to or away from the plane: joint left out
    person->col(j) << geo.center + kps[j].ray * (horizontal / along), kps[j].score * options.score_factor;
  }
  // Body size: placed limb length / typical length, the second largest (foreshortening only shortens).
  ratios->clear();
  for (const TypicalLimb& limb : limbs) {
    if (kps[limb.a].score < options.min_joint_score || kps[limb.b].score < options.min_joint_score) continue;
    if ((*person)(3, limb.a) <= 0 || (*person)(3, limb.b) <= 0) continue;
    ratios->push_back((person->col(limb.a).head<3>() - person->col(limb.b).head<3>()).norm() / limb.length_m);
  }
  if (ratios->size() < 2) return false;
  std::sort(ratios->begin(), ratios->end(), std::greater<>());
  const double scale = (*ratios)[ratios->size() >= 3 ? 1 : 0];
  if (body_scale != nullptr) *body_scale = scale;
  if (scale < options.min_body_scale || scale > options.max_body_scale) return false;
  // Posture: hip-to-shoulder direction near the vertical (when hips and shoulders are placed).
  Eigen::Vector3d hips = Eigen::Vector3d::Zero(), shoulders = Eigen::Vector3d::Zero();
  int num_hips = 0, num_shoulders = 0;
  for (int j : {ground.hip_left, ground.hip_right}) {
    if (j < 0 || (*person)(3, j) <= 0 || kps[j].score < options.min_joint_score) continue;
    hips += person->col(j).head<3>();
    ++num_hips;
  }
  for (int j : {ground.shoulder_left, ground.shoulder_right}) {
    if (j < 0 || (*person)(3, j) <= 0 || kps[j].score < options.min_joint_score) continue;
    shoulders += person->col(j).head<3>();
    ++num_shoulders;
  }
  if (num_hips > 0 && num_shoulders > 0) {
    const Eigen::Vector3d torso = shoulders / num_shoulders - hips / num_hips;
    const double length = torso.norm();
    if (!(length > 1e-9) || torso.z() / length < options.min_upright) return false;
  }
  return true;
}

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

  int implausible = 0, tracked = 0;
  const bool assist = options.track_assist && in.tracks != nullptr;
  if (assist) {
    // Tracks continued by a person found this frame (centre within duplicate_distance_m) assist nobody.
    scratch->track_used.assign(in.tracks->slots.size(), 0);
    for (size_t s = 0; s < in.tracks->slots.size(); ++s) {
      const Tracks::Slot& slot = in.tracks->slots[s];
      if (slot.id < 0 || slot.pose.size() != 4 * static_cast<size_t>(num_joints)) {
        scratch->track_used[s] = 1;
        continue;
      }
      Eigen::Vector3d track_center;
      if (!Center(Eigen::Map<const Eigen::Matrix4Xd>(slot.pose.data(), 4, num_joints), core_joints, &track_center)) {
        continue;
      }
      for (const Eigen::Vector3d& other : scratch->centers) {
        if ((other - track_center).norm() < options.duplicate_distance_m) scratch->track_used[s] = 1;
      }
    }
  }
  for (const auto& [negative_confidence, g] : scratch->order) {
    const Keypoint* kps = views.Pose(g);
    const ViewGeometry& geo = geometry[views.view_of[g]];
    Eigen::Vector3d center;
    const int track_slot = assist ? MatchTrack(options, *in.tracks, in.timestamp_s, kps, geo,
                                               views.bbox_diag[g] / geo.focal, core_joints, scratch->track_used)
                                  : -1;
    bool from_track = false;
    if (track_slot >= 0) {
      PlaceAtTrack(options, in.tracks->slots[track_slot], in.timestamp_s, kps, geo, core_joints, &scratch->person);
      from_track = Center(scratch->person, core_joints, &center);
    }
    if (from_track) {
      // placed at the track's depth
    } else if (options.ground_prior) {
      scratch->person.resize(4, num_joints);
      if (!PlaceOnGround(options, kps, geo, in.limbs, in.ground, &scratch->depths, &scratch->person, nullptr) ||
          !Center(scratch->person, core_joints, &center) || !in.room.Contains(center, 0.0)) {
        ++implausible;
        continue;
      }
    } else {
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
      if (!Center(scratch->person, core_joints, &center)) continue;
    }
    bool duplicate = false;
    for (const Eigen::Vector3d& other : scratch->centers) duplicate |= (other - center).norm() < options.duplicate_distance_m;
    if (duplicate) continue;
    int empty = 0;
    for (int v = 0; v < num_views; ++v) {
      if (v == views.view_of[g]) continue;
      empty += JudgeView(views, geometry[v], v, core_joints, scratch->person, in.kernel.scale_m,
                         options.min_inside_fraction, verdict, nullptr) == ViewVerdict::kEmpty;
    }
    if (empty >= options.min_empty_views) continue;
    lifted->AddPerson() = scratch->person;
    scratch->centers.push_back(center);
    if (from_track) {
      scratch->track_used[track_slot] = 1;
      ++tracked;
    }
  }
  stats->single_view_persons = lifted->num_persons();
  stats->single_view_implausible = implausible;
  stats->single_view_tracked = tracked;
  return lifted->num_persons();
}

}  // namespace rpt

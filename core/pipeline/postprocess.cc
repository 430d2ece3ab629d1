// SPDX-License-Identifier: MIT
#include "core/pipeline/postprocess.h"

#include <algorithm>

namespace rpt {

int FillMissingJoints(std::span<const int> neighbour, double filled_score, Eigen::Map<Eigen::Matrix4Xd> person,
                      std::span<uint8_t> provenance) {
  const int n = static_cast<int>(person.cols());
  int filled = 0;
  // Repeated passes let fills propagate along chains (e.g. finger tip <- ... <- wrist).
  for (int pass = 0; pass < 6; ++pass) {
    bool changed = false;
    for (int j = 0; j < n; ++j) {
      if (person(3, j) > 0 || neighbour[j] < 0 || person(3, neighbour[j]) <= 0) continue;
      person.col(j).head<3>() = person.col(neighbour[j]).head<3>();
      person(3, j) = filled_score;
      if (!provenance.empty()) provenance[j] = static_cast<uint8_t>(JointProvenance::kFilled);
      ++filled;
      changed = true;
    }
    if (!changed) break;
  }
  return filled;
}

int HoldFilledJoints(std::span<const int> neighbour, const double* last, Eigen::Map<Eigen::Matrix4Xd> person,
                      std::span<const uint8_t> provenance, std::vector<char>* settled) {
  const int n = static_cast<int>(person.cols());
  const auto filled = static_cast<uint8_t>(JointProvenance::kFilled);
  const auto lifted = static_cast<uint8_t>(JointProvenance::kLifted);
  settled->resize(n);
  int first = n, last_filled = -1;  // the joints to place lie in [first, last_filled]
  for (int j = 0; j < n; ++j) {
    // Filled joints, and joints placed from one view beside a joint that was not (refine's
    // one_view_joints; a person single_view placed has every joint lifted and keeps them).
    const int nb = neighbour[j];
    const bool one_view = provenance[j] == lifted && nb >= 0 && provenance[nb] != lifted;
    (*settled)[j] = provenance[j] != filled && !one_view;
    if (!(*settled)[j]) {
      first = std::min(first, j);
      last_filled = j;
    }
  }
  int held = 0;
  // A filled joint is placed once its neighbour is (passes as in post-processing's fill).
  for (int pass = 0; pass < 6 && first <= last_filled; ++pass) {
    bool changed = false;
    for (int j = first; j <= last_filled; ++j) {
      const int nb = neighbour[j];
      if ((*settled)[j] || nb < 0 || !(*settled)[nb]) continue;
      const double* lj = last + 4 * j;
      const double* ln = last + 4 * nb;
      if (lj[3] > 0 && ln[3] > 0) {
        person.col(j).head<3>() = person.col(nb).head<3>() + Eigen::Vector3d(lj[0] - ln[0], lj[1] - ln[1], lj[2] - ln[2]);
        ++held;
      } else if (provenance[j] == filled) {
        person.col(j).head<3>() = person.col(nb).head<3>();  // on its neighbour, wherever that was placed
      }
      (*settled)[j] = 1;
      changed = true;
    }
    if (!changed) break;
  }
  return held;
}

int steps::Postprocess(const PostprocessOptions& options, const PostprocessInput& in, Poses3D* persons,
                       FrameStats* stats) {
  if (!options.enabled) return persons->num_persons();
  const int n = persons->num_joints;
  int kept = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    auto person = persons->Person(p);
    // Joints placed from one view (refine.one_view_joints; single_view's persons are marked only
    // after this step) neither decide about the person nor outweigh a triangulated joint.
    const std::span<const uint8_t> provenance = persons->PersonProvenance(p);
    auto lifted = [&](int j) {
      return !provenance.empty() && provenance[j] == static_cast<uint8_t>(JointProvenance::kLifted);
    };
    int replaced = 0;
    if (options.replace_wrong_joints) {
      // A limb whose proximal joint was never triangulated measures its distal joint from the nearest
      // joint up the chain that was, allowing the limb's maximum once per limb between them (a
      // whole-body user's finding: with junk hand points a finger joint whose parents were missing
      // was never measured, stood 0.6-2.2 m from its wrist, and such joints pushed whole persons past
      // max_extent_m). Joints this rule removes are marked so until the pass ends, and a limb from
      // one is not measured, as before: walking past them cost the clean whole-body scene's hands
      // 0.4 mm (a wrong wrist took its right hand joints with it).
      constexpr double kRemoved = -1;
      for (const ResolvedLimb& limb : in.limbs) {
        if (person(3, limb.b) <= 0) continue;
        int a = limb.a, limbs = 1;
        // At most kMaxChain limbs up (the neighbours of the two shoulders, hips, nose and head are
        // each other: no endless walk).
        constexpr int kMaxChain = 6;
        while (person(3, a) == 0 && in.neighbour[a] >= 0 && limbs < kMaxChain) {
          a = in.neighbour[a];
          ++limbs;
        }
        if (person(3, a) <= 0) continue;
        const double length_sq = (person.col(a).head<3>() - person.col(limb.b).head<3>()).squaredNorm();
        const double max_length = limbs * limb.max_length_m;
        if ((limbs == 1 && length_sq < limb.min_length_sq()) || length_sq > max_length * max_length) {
          person(3, limbs == 1 && lifted(a) && !lifted(limb.b) ? a : limb.b) = kRemoved;
          ++replaced;
        }
      }
      for (int j = 0; j < n; ++j) {
        if (person(3, j) == kRemoved) person(3, j) = 0;
      }
    }
    int valid = 0;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (int j = 0; j < n; ++j) {
      if (person(3, j) <= 0 || lifted(j)) continue;
      const Eigen::Vector3d x = person.col(j).head<3>();
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
      center += x;
      ++valid;
    }
    if (valid < options.min_valid_joints || valid == 0) continue;
    const double extent = (hi - lo).norm();
    if (extent < options.min_extent_m || extent > options.max_extent_m) continue;
    if (options.drop_outside_room && !in.room.Contains(center / valid, options.room_margin_m)) continue;
    stats->replaced_joints += replaced;

    if (options.fill_missing_joints)
      stats->filled_joints +=
          FillMissingJoints(in.neighbour, options.filled_joint_score, person, persons->PersonProvenance(p));
    if (kept != p) persons->MovePerson(p, kept);
    ++kept;
  }
  persons->Truncate(kept);
  return kept;
}

}  // namespace rpt

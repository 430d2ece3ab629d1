// SPDX-License-Identifier: MIT
// The PAF association as it was before PafAssociator (issue 22): vectors allocated per limb and per
// person, std::sort per limb. Kept, unchanged, as the reference the fast one must equal
// (tests/datasets/paf_association_equality_test.cc) and as the "before" of its benchmark
// (bench/paf_association_benchmark.cc).
#include "bench/baseline_paf_association.h"

#include <algorithm>
#include <tuple>

namespace rpt::bench {
namespace {

struct Connection {
  double score = 0;
  int limb = 0;
  int a = 0;  // candidate index of the limb's first joint
  int b = 0;  // candidate index of the limb's second joint
};

// Decreasing score; ties by limb, a, b so the result never depends on sort stability.
bool Before(const Connection& x, const Connection& y) {
  if (x.score != y.score) return x.score > y.score;
  return std::tie(x.limb, x.a, x.b) < std::tie(y.limb, y.a, y.b);
}

// Step 1: the greedy one-to-one matching of one limb.
void MatchLimb(const PafCandidates& candidates, int limb, int joint_a, int joint_b, double min_paf_score,
               std::vector<Connection>* kept) {
  const Eigen::MatrixXd& paf = candidates.pafs[static_cast<size_t>(limb)];
  const Eigen::Matrix3Xd& cand_a = candidates.joints[static_cast<size_t>(joint_a)];
  const Eigen::Matrix3Xd& cand_b = candidates.joints[static_cast<size_t>(joint_b)];
  std::vector<Connection> possible;
  for (int i = 0; i < paf.rows(); ++i) {
    if (!(cand_a(2, i) > 0)) continue;
    for (int j = 0; j < paf.cols(); ++j) {
      const double score = paf(i, j);
      if (cand_b(2, j) > 0 && score > 0 && score >= min_paf_score) possible.push_back({score, limb, i, j});
    }
  }
  std::sort(possible.begin(), possible.end(), Before);
  std::vector<bool> used_a(static_cast<size_t>(paf.rows()), false);
  std::vector<bool> used_b(static_cast<size_t>(paf.cols()), false);
  for (const Connection& c : possible) {
    if (used_a[static_cast<size_t>(c.a)] || used_b[static_cast<size_t>(c.b)]) continue;
    used_a[static_cast<size_t>(c.a)] = used_b[static_cast<size_t>(c.b)] = true;
    kept->push_back(c);
  }
}

}  // namespace

std::vector<PafPerson> AssociatePafsBaseline(const PafSkeleton& skeleton, const PafCandidates& candidates,
                                             const PafAssociationOptions& options) {
  std::vector<Connection> kept;
  for (size_t k = 0; k < skeleton.limbs.size(); ++k) {
    MatchLimb(candidates, static_cast<int>(k), skeleton.limbs[k].first, skeleton.limbs[k].second,
              options.min_paf_score, &kept);
  }
  std::sort(kept.begin(), kept.end(), Before);

  // Step 2. owner[joint][candidate] = person index or -1; merged persons are emptied, not erased,
  // so indices stay valid and the output order is the order of creation.
  std::vector<std::vector<int>> owner(static_cast<size_t>(skeleton.num_joints));
  for (int j = 0; j < skeleton.num_joints; ++j) {
    owner[static_cast<size_t>(j)].assign(static_cast<size_t>(candidates.joints[static_cast<size_t>(j)].cols()), -1);
  }
  std::vector<PafPerson> persons;
  for (const Connection& c : kept) {
    const auto [joint_a, joint_b] = skeleton.limbs[static_cast<size_t>(c.limb)];
    int& owner_a = owner[static_cast<size_t>(joint_a)][static_cast<size_t>(c.a)];
    int& owner_b = owner[static_cast<size_t>(joint_b)][static_cast<size_t>(c.b)];
    if (owner_a < 0 && owner_b < 0) {
      PafPerson person(static_cast<size_t>(skeleton.num_joints), -1);
      person[static_cast<size_t>(joint_a)] = c.a;
      person[static_cast<size_t>(joint_b)] = c.b;
      owner_a = owner_b = static_cast<int>(persons.size());
      persons.push_back(std::move(person));
    } else if (owner_a < 0 || owner_b < 0) {
      const int p = std::max(owner_a, owner_b);
      const int joint = owner_a < 0 ? joint_a : joint_b;
      const int candidate = owner_a < 0 ? c.a : c.b;
      PafPerson& person = persons[static_cast<size_t>(p)];
      if (person[static_cast<size_t>(joint)] >= 0) continue;  // it has another candidate of this joint
      person[static_cast<size_t>(joint)] = candidate;
      (owner_a < 0 ? owner_a : owner_b) = p;
    } else if (owner_a != owner_b) {
      const int keep = std::min(owner_a, owner_b);
      const int drop = std::max(owner_a, owner_b);
      PafPerson& first = persons[static_cast<size_t>(keep)];
      PafPerson& second = persons[static_cast<size_t>(drop)];
      bool shared_joint = false;
      for (size_t j = 0; j < first.size() && !shared_joint; ++j) shared_joint = first[j] >= 0 && second[j] >= 0;
      if (shared_joint) continue;
      for (size_t j = 0; j < second.size(); ++j) {
        if (second[j] < 0) continue;
        first[j] = second[j];
        owner[j][static_cast<size_t>(second[j])] = keep;
        second[j] = -1;
      }
    }
    // else: both ends already in the same person (a redundant limb).
  }

  // Step 3.
  std::vector<PafPerson> out;
  for (PafPerson& person : persons) {
    const auto joints = std::count_if(person.begin(), person.end(), [](int c) { return c >= 0; });
    if (joints > 0 && joints >= options.min_joints) out.push_back(std::move(person));
  }
  return out;
}

}  // namespace rpt::bench

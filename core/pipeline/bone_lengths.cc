// SPDX-License-Identifier: MIT
#include "core/pipeline/bone_lengths.h"

#include <algorithm>
#include <cmath>

#include "core/pipeline/median.h"
#include "core/pipeline/postprocess.h"

namespace rpt {

int steps::BoneLengths(const BoneLengthOptions& options, const BoneLengthsInput& in, BoneLengthHistory* history,
                       BoneLengthsScratch* scratch, Poses3D* persons, FrameStats* stats) {
  if (!options.enabled) return 0;
  const std::span<const ResolvedLimb> limbs = in.limbs;
  const double unobserved_score = in.unobserved_score;
  const int num_detected = in.num_detected;
  std::vector<double>& length = scratch->length;
  std::vector<double>& expected = scratch->expected;
  std::vector<char>& disagrees = scratch->disagrees;
  std::vector<char>& active = scratch->active;
  std::vector<int>& num_checked = scratch->num_checked;
  std::vector<int>& num_bad = scratch->num_bad;
  std::vector<char>& distal_bad = scratch->distal_bad;
  std::vector<double>& median = scratch->median;
  TrackStates<BoneLengthHistory::Track>& tracks = history->tracks;
  tracks.BeginFrame(*persons);
  const int n = persons->num_joints;
  const int num_limbs = static_cast<int>(limbs.size());
  const int window = options.window;
  int checked = 0;
  for (int p = 0; p < num_detected; ++p) {
    const int id = persons->track_ids[p];
    if (id < 0) continue;
    bool created = false;
    BoneLengthHistory::Track& track = tracks.Get(id, &created);
    if (created || static_cast<int>(track.observed.size()) != num_limbs ||
        static_cast<int>(track.lengths.size()) != num_limbs * window) {
      track.lengths.assign(static_cast<size_t>(num_limbs) * window, 0.0);
      track.observed.assign(num_limbs, 0);
    }
    auto person = persons->Person(p);

    // This frame's lengths and the track's running lengths.
    length.assign(num_limbs, -1.0);
    expected.assign(num_limbs, -1.0);
    disagrees.assign(num_limbs, 0);
    active.assign(num_limbs, 1);
    for (int l = 0; l < num_limbs; ++l) {
      const ResolvedLimb& limb = limbs[l];
      if (!(person(3, limb.a) > unobserved_score) || !(person(3, limb.b) > unobserved_score)) continue;
      length[l] = (person.col(limb.a).head<3>() - person.col(limb.b).head<3>()).norm();
      const int stored = std::min(track.observed[l], window);
      if (stored < options.min_observations) continue;
      const double* recorded = track.lengths.data() + static_cast<size_t>(l) * window;
      median.assign(recorded, recorded + stored);
      expected[l] = Median(median.data(), static_cast<int>(median.size()));
      const double tolerance = std::max(options.tolerance_rel * expected[l], options.min_tolerance_m);
      disagrees[l] = std::abs(length[l] - expected[l]) > tolerance;
    }

    // Mark the joints that explain the disagreeing limbs, most disagreeing first.
    int marked = 0;
    for (bool first = true;; first = false) {
      num_checked.assign(n, 0);
      num_bad.assign(n, 0);
      distal_bad.assign(n, 0);
      for (int l = 0; l < num_limbs; ++l) {
        if (!active[l] || expected[l] < 0) continue;
        const ResolvedLimb& limb = limbs[l];
        ++num_checked[limb.a];
        ++num_checked[limb.b];
        if (!disagrees[l]) continue;
        ++num_bad[limb.a];
        ++num_bad[limb.b];
        distal_bad[limb.b] = 1;
      }
      if (first) {
        for (int j = 0; j < n; ++j) checked += num_checked[j] > 0;
      }
      int worst = -1;
      for (int j = 0; j < n; ++j) {
        if (num_bad[j] == 0) continue;
        if (worst < 0 || num_bad[j] > num_bad[worst]) {
          worst = j;
          continue;
        }
        if (num_bad[j] < num_bad[worst]) continue;
        // Same count: the larger share of disagreeing limbs (compared without division), then distal.
        const long share_j = static_cast<long>(num_bad[j]) * num_checked[worst];
        const long share_worst = static_cast<long>(num_bad[worst]) * num_checked[j];
        if (share_j > share_worst || (share_j == share_worst && distal_bad[j] && !distal_bad[worst])) worst = j;
      }
      if (worst < 0) break;
      person(3, worst) = 0;
      ++marked;
      for (int l = 0; l < num_limbs; ++l) {
        if (limbs[l].a == worst || limbs[l].b == worst) active[l] = 0;
      }
    }

    // Record every observed length (also disagreeing ones: the median keeps them out while they
    // are rare, and follows if the track's first lengths were the wrong ones).
    for (int l = 0; l < num_limbs; ++l) {
      if (length[l] < 0) continue;
      track.lengths[static_cast<size_t>(l) * window + track.observed[l] % window] = length[l];
      ++track.observed[l];
    }
    stats->bone_length_corrections += marked;
    if (marked > 0 && unobserved_score > 0) {
      stats->filled_joints += FillMissingJoints(in.neighbour, unobserved_score, person, persons->PersonProvenance(p));
      double last_time = 0;
      const double* last = in.tracks != nullptr ? in.tracks->LastPose(persons->track_ids[p], &last_time) : nullptr;
      if (last != nullptr) HoldFilledJoints(in.neighbour, last, person, persons->PersonProvenance(p), &scratch->settled);
    }
  }
  return checked;
}

}  // namespace rpt

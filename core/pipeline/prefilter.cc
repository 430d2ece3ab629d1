// SPDX-License-Identifier: MIT
#include "core/pipeline/prefilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/pipeline/simd_kernels.h"

namespace rpt {

namespace {

// The mean of person q's valid core joints (zero when none is valid).
Eigen::Vector3d PersonCentre(const PreviousPersons& previous, int q) {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  int n = 0;
  for (int c = 0; c < previous.num_core; ++c) {
    const size_t idx = static_cast<size_t>(q) * previous.num_core + c;
    if (previous.score[idx] <= 0) continue;
    center += previous.xyz[idx];
    ++n;
  }
  return n > 0 ? Eigen::Vector3d(center / n) : center;
}

// The core joints' sqrt(score) of every pose side by side (num_poses rows of core_joints.size()):
// a pair's evidence reads two short rows instead of gathering from two poses' keypoints. The
// undistort step's core columns hold them when its core joints are these; else they are gathered.
const double* CoreSqrtScores(const PreparedViews& views, std::span<const int> core_joints, PrefilterScratch* scratch) {
  if (std::equal(core_joints.begin(), core_joints.end(), views.core_joints.begin(), views.core_joints.end())) {
    return views.core_columns.sqrt_score.data();
  }
  const int num_core_joints = static_cast<int>(core_joints.size());
  scratch->core_sqrt_scores.resize(static_cast<size_t>(views.num_poses()) * num_core_joints);
  for (int g = 0; g < views.num_poses(); ++g) {
    const Keypoint* kps = views.Pose(g);
    double* row = scratch->core_sqrt_scores.data() + static_cast<size_t>(g) * num_core_joints;
    for (int c = 0; c < num_core_joints; ++c) row[c] = kps[core_joints[c]].sqrt_score;
  }
  return scratch->core_sqrt_scores.data();
}

// Keeps the pairs whose `keep` entry is set, in order; returns how many.
int CompactKept(const std::vector<char>& keep, std::vector<PosePair>* pairs) {
  int kept = 0;
  for (size_t k = 0; k < pairs->size(); ++k) {
    (*pairs)[kept] = (*pairs)[k];
    kept += keep[k] != 0 ? 1 : 0;
  }
  pairs->resize(kept);
  return kept;
}

// A pair's quality for the budgets: sin of the angle between the unit directions from a person's
// last centre to the two cameras (da, db) x the 2D confidence both poses share on the core joints
// (their rows sa, sb of CoreSqrtScores).
double PairQuality(const Eigen::Vector3d& da, const Eigen::Vector3d& db, const double* sa, const double* sb,
                   int num_core_joints) {
  double evidence = 0;
  for (int c = 0; c < num_core_joints; ++c) evidence += sa[c] * sb[c];  // in the core joints' order
  return da.cross(db).norm() * evidence;
}

// Keeps, of the pairs between an ambiguous pose and the poses matched to one person, only the
// max_pairs_per_ambiguous_pose best (see the header). The classification filter listed those
// pairs in scratch->ambiguous (bucket = (ambiguous pose, person); pair = index into `pairs`, in
// increasing order) and counted them per bucket in scratch->ambiguous_count.
int LimitAmbiguousPairs(const PreparedViews& views, std::span<const ViewGeometry> geometry,
                        std::span<const int> core_joints, const PreviousPersons& previous,
                        const PrefilterOptions& options, PrefilterScratch* scratch, std::vector<PosePair>* pairs) {
  const int limit = options.max_pairs_per_ambiguous_pose;
  const int num_previous = previous.size();
  std::vector<int>& count = scratch->ambiguous_count;
  // An ambiguous pose over the limit needs many views: the usual frame stops here.
  if (std::none_of(count.begin(), count.end(), [limit](int n) { return n > limit; })) {
    return static_cast<int>(pairs->size());
  }
  // Entries by bucket (a stable counting sort: within a bucket by pair index), then per bucket over
  // the limit the `limit` best by quality (of equal quality the earlier pair) stay.
  const size_t num_buckets = count.size();
  scratch->bucket_begin.assign(num_buckets + 1, 0);
  for (size_t b = 0; b < num_buckets; ++b) scratch->bucket_begin[b + 1] = scratch->bucket_begin[b] + count[b];
  scratch->bucket_fill.assign(scratch->bucket_begin.begin(), scratch->bucket_begin.end() - 1);
  scratch->ambiguous_sorted.resize(scratch->ambiguous.size());
  for (const AmbiguousPair& entry : scratch->ambiguous) {
    scratch->ambiguous_sorted[scratch->bucket_fill[entry.bucket]++] = entry;
  }
  const int num_core_joints = static_cast<int>(core_joints.size());
  const double* core_sqrt_scores = CoreSqrtScores(views, core_joints, scratch);
  scratch->keep.assign(pairs->size(), 1);
  for (size_t b = 0; b < num_buckets; ++b) {
    if (count[b] <= limit) continue;
    AmbiguousPair* first = scratch->ambiguous_sorted.data() + scratch->bucket_begin[b];
    AmbiguousPair* last = first + count[b];
    // Every pair of the bucket shares the ambiguous pose: its view's direction once.
    const Eigen::Vector3d center = PersonCentre(previous, static_cast<int>(b % num_previous));
    const int ambiguous_pose = scratch->ambiguous_pose[b / num_previous];
    const Eigen::Vector3d direction = (geometry[views.view_of[ambiguous_pose]].center - center).normalized();
    const double* row = core_sqrt_scores + static_cast<size_t>(ambiguous_pose) * num_core_joints;
    for (AmbiguousPair* e = first; e != last; ++e) {
      const PosePair& pair = (*pairs)[e->pair];
      const int other = pair.a == ambiguous_pose ? pair.b : pair.a;
      // The quality does not depend on the pair's order (|da x db| = |db x da|, products commute).
      e->quality = PairQuality(direction, (geometry[views.view_of[other]].center - center).normalized(), row,
                               core_sqrt_scores + static_cast<size_t>(other) * num_core_joints, num_core_joints);
    }
    std::nth_element(first, first + (limit - 1), last, [](const AmbiguousPair& x, const AmbiguousPair& y) {
      return x.quality != y.quality ? x.quality > y.quality : x.pair < y.pair;
    });
    for (AmbiguousPair* e = first + limit; e != last; ++e) scratch->keep[e->pair] = 0;
  }
  return CompactKept(scratch->keep, pairs);
}

// A pose's kPerPose best entries of one person's budget, best first (quality -1: none yet): views
// of its row in PrefilterScratch::best_quality and best_entry.
template <int kPerPose>
struct PoseBest {
  double* quality;
  int* entry;
  // Entries arrive in increasing pair order, so of equal qualities the one already held is the
  // better (lower pair index): a new entry must be strictly better to enter.
  void Offer(double q, int e) {
    if (!(q > quality[kPerPose - 1])) return;
    int t = kPerPose - 1;
    for (; t > 0 && q > quality[t - 1]; --t) quality[t] = quality[t - 1], entry[t] = entry[t - 1];
    quality[t] = q;
    entry[t] = e;
  }
  bool Holds(int e) const {
    bool holds = false;
    for (int t = 0; t < kPerPose; ++t) holds |= entry[t] == e;
    return holds;
  }
};

// Of one person's budget entries (pair indices in increasing order, their qualities in
// scratch->quality), marks in scratch->keep the kPerPose best of every pose (best = higher
// quality, then lower pair index), then the best of the others until `budget` entries are marked
// (the best of every pose stay even above it). Qualities are not negative; a NaN one is never
// among the best. Both selections are exact without sorting the entries.
template <int kPerPose>
void KeepBestEntries(std::span<const int> entries, const std::vector<PosePair>& pairs, size_t budget,
                     PrefilterScratch* scratch) {
  const int num_entries = static_cast<int>(entries.size());
  const double* quality = scratch->quality.data();
  const auto best = [scratch](int pose) {
    return PoseBest<kPerPose>{scratch->best_quality.data() + static_cast<size_t>(pose) * kPerPose,
                              scratch->best_entry.data() + static_cast<size_t>(pose) * kPerPose};
  };
  std::fill(scratch->best_quality.begin(), scratch->best_quality.end(), -1.0);  // every pose: none yet
  std::fill(scratch->best_entry.begin(), scratch->best_entry.end(), -1);
  for (int e = 0; e < num_entries; ++e) {
    const PosePair& pair = pairs[entries[e]];
    best(pair.a).Offer(quality[e], e);
    best(pair.b).Offer(quality[e], e);
  }
  size_t used = 0;
  for (int e = 0; e < num_entries; ++e) {
    const PosePair& pair = pairs[entries[e]];
    const bool among_best = best(pair.a).Holds(e) || best(pair.b).Holds(e);
    scratch->keep[entries[e]] = among_best ? 1 : 0;
    used += among_best ? 1 : 0;
  }
  if (used >= budget) return;  // the usual case with many views: the poses' best pairs fill it
  // The best others: the `room` best so far, best first (equal qualities in entry order).
  const size_t room = budget - used;
  std::vector<std::pair<double, int>>& top = scratch->top;
  top.clear();
  for (int e = 0; e < num_entries; ++e) {
    if (scratch->keep[entries[e]] || (top.size() == room && !(quality[e] > top.back().first))) continue;
    if (top.size() < room) top.emplace_back(-1.0, -1);
    size_t t = top.size() - 1;
    for (; t > 0 && quality[e] > top[t - 1].first; --t) top[t] = top[t - 1];
    top[t] = {quality[e], e};
  }
  for (const auto& entry : top) scratch->keep[entries[entry.second]] = 1;
}

// Keeps at most max_pairs_per_person of the pairs matched to each previous person (see the header).
int ApplyPairBudget(const PreparedViews& views, std::span<const ViewGeometry> geometry, std::span<const int> core_joints,
                    const PreviousPersons& previous, const PrefilterOptions& options, PrefilterScratch* scratch,
                    std::vector<PosePair>* pairs) {
  const int num_previous = previous.size();
  const int num_views = static_cast<int>(geometry.size());
  const std::vector<int>& match = scratch->match;
  const size_t budget = static_cast<size_t>(options.max_pairs_per_person);

  // Pairs per person (a matched to it; b too, or b ambiguous near it): counting sort.
  scratch->bucket_begin.assign(num_previous + 1, 0);
  for (const PosePair& pair : *pairs) {
    if (match[pair.a] >= 0) ++scratch->bucket_begin[match[pair.a] + 1];
  }
  bool over_budget = false;
  for (int q = 0; q < num_previous; ++q) {
    over_budget |= static_cast<size_t>(scratch->bucket_begin[q + 1]) > budget;
    scratch->bucket_begin[q + 1] += scratch->bucket_begin[q];
  }
  if (!over_budget) return static_cast<int>(pairs->size());
  scratch->bucket.resize(scratch->bucket_begin[num_previous]);
  scratch->bucket_fill.assign(scratch->bucket_begin.begin(), scratch->bucket_begin.end() - 1);
  for (size_t k = 0; k < pairs->size(); ++k) {
    const int q = match[(*pairs)[k].a];
    if (q >= 0) scratch->bucket[scratch->bucket_fill[q]++] = static_cast<int>(k);
  }

  scratch->keep.assign(pairs->size(), 1);
  const int best_per_pose = std::clamp(options.best_pairs_per_pose, 1, kMaxBestPairsPerPose);
  scratch->best_quality.resize(static_cast<size_t>(views.num_poses()) * best_per_pose);
  scratch->best_entry.resize(static_cast<size_t>(views.num_poses()) * best_per_pose);
  const int num_core_joints = static_cast<int>(core_joints.size());
  const double* core_sqrt_scores = CoreSqrtScores(views, core_joints, scratch);
  scratch->directions.resize(static_cast<size_t>(num_views));
  for (int q = 0; q < num_previous; ++q) {
    const int first = scratch->bucket_begin[q], last = scratch->bucket_begin[q + 1];
    if (static_cast<size_t>(last - first) <= budget) continue;
    // The person's last centre and the unit direction from it to every camera.
    const Eigen::Vector3d center = PersonCentre(previous, q);
    for (int v = 0; v < num_views; ++v) scratch->directions[v] = (geometry[v].center - center).normalized();
    // Quality: sin of the ray angle at the person x the 2D confidence both poses share.
    const std::span<const int> entries(scratch->bucket.data() + first, static_cast<size_t>(last - first));
    scratch->quality.resize(entries.size());
    for (size_t e = 0; e < entries.size(); ++e) {
      const PosePair& pair = (*pairs)[entries[e]];
      scratch->quality[e] =
          PairQuality(scratch->directions[views.view_of[pair.a]], scratch->directions[views.view_of[pair.b]],
                      core_sqrt_scores + static_cast<size_t>(pair.a) * num_core_joints,
                      core_sqrt_scores + static_cast<size_t>(pair.b) * num_core_joints, num_core_joints);
    }
    // Every pose of the person keeps its best_pairs_per_pose best pairs (so the person's group
    // can claim all its poses), then the budget fills by quality.
    switch (best_per_pose) {  // unrolled per count
      case 1: KeepBestEntries<1>(entries, *pairs, budget, scratch); break;
      case 2: KeepBestEntries<2>(entries, *pairs, budget, scratch); break;
      case 3: KeepBestEntries<3>(entries, *pairs, budget, scratch); break;
      default: KeepBestEntries<4>(entries, *pairs, budget, scratch); break;
    }
  }
  return CompactKept(scratch->keep, pairs);
}

// Lists the kept pairs (see below) from the classification in scratch->match and scratch->near.
// Not inlined: inlined, it cost the classification loop of steps::Prefilter about 0.15 us per
// frame on the small bench scenes (worse register use), more than the listing itself takes.
[[gnu::noinline]] void ListKeptPairs(const PreparedViews& views, int num_previous, bool limit_ambiguous,
                                    PrefilterScratch* scratch, std::vector<PosePair>* pairs) {
  const int num_views = static_cast<int>(views.view_begin.size()) - 1;
  const int words = (num_previous + 63) / 64;
  const std::vector<int>& match = scratch->match;
  // Kept: both matched to the same person, both free, and an ambiguous pose with a free or
  // ambiguous one or with a pose matched to a person within twice the radius of it (one of the
  // persons it is ambiguous between); dropped: matched to different persons, one matched and the
  // other free, an ambiguous pose with a pose matched to a person far from it. The kept pairs are
  // listed directly, in make_pairs' order (view pair, pose a, pose b), without visiting the
  // dropped ones: a pose matched to person q meets, in each later view, only the pose matched to
  // q there and the view's unmatched (free or ambiguous) poses; with 31 cameras tens of thousands
  // of pairs become a few thousand candidates.
  scratch->person_pose.assign(static_cast<size_t>(num_views) * num_previous, -1);
  scratch->unmatched.clear();
  scratch->unmatched_begin.resize(num_views + 1);
  for (int v = 0; v < num_views; ++v) {
    scratch->unmatched_begin[v] = static_cast<int>(scratch->unmatched.size());
    for (int g = views.view_begin[v]; g < views.view_begin[v + 1]; ++g) {
      if (match[g] >= 0) {
        scratch->person_pose[static_cast<size_t>(v) * num_previous + match[g]] = g;
      } else {
        scratch->unmatched.push_back(g);
      }
    }
  }
  scratch->unmatched_begin[num_views] = static_cast<int>(scratch->unmatched.size());
  const auto near = [&](int pose, int person) {
    return ((scratch->near[static_cast<size_t>(pose) * words + person / 64] >> (person % 64)) & 1) != 0;
  };
  // An ambiguous pose's pair with a pose matched to `person`: counted for LimitAmbiguousPairs.
  const auto note_ambiguous = [&](int ambiguous_pose, int person) {
    if (!limit_ambiguous) return;
    const int bucket = scratch->ambiguous_slot[ambiguous_pose] * num_previous + person;
    ++scratch->ambiguous_count[bucket];
    scratch->ambiguous.push_back({.bucket = bucket, .quality = 0, .pair = static_cast<int>(pairs->size())});
  };
  pairs->clear();
  for (int va = 0; va < num_views; ++va) {
    for (int vb = va + 1; vb < num_views; ++vb) {
      const int* unmatched_first = scratch->unmatched.data() + scratch->unmatched_begin[vb];
      const int* unmatched_last = scratch->unmatched.data() + scratch->unmatched_begin[vb + 1];
      for (int a = views.view_begin[va]; a < views.view_begin[va + 1]; ++a) {
        const int ma = match[a];
        if (ma == kPoseAmbiguous) {  // every pose of vb but those matched to persons far from a
          for (int b = views.view_begin[vb]; b < views.view_begin[vb + 1]; ++b) {
            const int mb = match[b];
            if (mb >= 0 && !near(a, mb)) continue;
            if (mb >= 0) note_ambiguous(a, mb);
            pairs->push_back(PosePair{a, b});
          }
          continue;
        }
        // a is free or matched to ma: the pose of vb matched to ma, merged in order into vb's
        // unmatched poses (free ones pair with a free a; ambiguous ones with a free a, or with a
        // matched one when ma is among the persons they are ambiguous between).
        int partner = ma >= 0 ? scratch->person_pose[static_cast<size_t>(vb) * num_previous + ma] : -1;
        for (const int* it = unmatched_first; it != unmatched_last; ++it) {
          const int b = *it;
          if (partner >= 0 && partner < b) {
            pairs->push_back(PosePair{a, partner});
            partner = -1;
          }
          if (match[b] == kPoseFree) {
            if (ma == kPoseFree) pairs->push_back(PosePair{a, b});
          } else if (ma < 0 || near(b, ma)) {
            if (ma >= 0) note_ambiguous(b, ma);
            pairs->push_back(PosePair{a, b});
          }
        }
        if (partner >= 0) pairs->push_back(PosePair{a, partner});
      }
    }
  }
}

}  // namespace

int steps::Prefilter(const PrefilterOptions& options, const PrefilterInput& in, PrefilterScratch* scratch,
                     std::vector<PosePair>* pairs) {
  const PreparedViews& views = in.views;
  const std::span<const ViewGeometry> geometry = in.geometry;
  const std::span<const int> core_joints = in.core_joints;
  const PreviousPersons& previous = in.previous;
  const double timestamp_s = in.timestamp_s;
  std::vector<int>* match = &scratch->match;
  const int num_previous = previous.size();
  if (!PrefilterActs(options, previous)) return static_cast<int>(pairs->size());

  const int num_core = static_cast<int>(core_joints.size());
  constexpr double kPersonSizeM = 1.8;
  const double elapsed_s = std::max(0.0, timestamp_s - previous.timestamp_s);
  const double radius_rel = options.max_distance_rel + options.person_speed_m_s * elapsed_s / kPersonSizeM;
  match->assign(views.num_poses(), kPoseFree);
  scratch->distance.assign(views.num_poses(), 0.0);
  const int words = (num_previous + 63) / 64;
  scratch->near.assign(static_cast<size_t>(views.num_poses()) * words, 0);
  // Project every previous person into every view once.
  const int num_views = static_cast<int>(views.view_begin.size()) - 1;
  const size_t per_view = static_cast<size_t>(num_previous) * num_core;
  scratch->projected.resize(per_view * num_views);
  scratch->distance_sum.resize(num_previous);
  scratch->distance_count.resize(num_previous);
  for (int v = 0; v < num_views; ++v) {
    const ViewGeometry& geo = geometry[v];
    for (size_t idx = 0; idx < per_view; ++idx) {
      Eigen::Vector2d& uv = scratch->projected[v * per_view + idx];
      const Eigen::Vector3d h = geo.P.leftCols<3>() * previous.xyz[idx] + geo.P.col(3);
      if (previous.score[idx] <= 0 || h.z() <= 0) {
        uv.setConstant(std::numeric_limits<double>::quiet_NaN());
      } else {
        uv = h.head<2>() / h.z();
      }
    }
  }
  // The SIMD kernel reads the core joints' columns of the undistort step (other subsets: scalar).
  const bool columns = simd::Enabled() && num_core > 0 &&
                       std::equal(core_joints.begin(), core_joints.end(), views.core_joints.begin(),
                                  views.core_joints.end());
  for (int g = 0; g < views.num_poses(); ++g) {
    const Keypoint* kps = views.Pose(g);
    const Eigen::Vector2d* projected = scratch->projected.data() + views.view_of[g] * per_view;
    const double radius = radius_rel * views.bbox_diag[g];
    uint64_t* near = scratch->near.data() + static_cast<size_t>(g) * words;
    double best = std::numeric_limits<double>::infinity(), second = best;
    int best_q = -1;
    double* const sums = scratch->distance_sum.data();
    int* const counts = scratch->distance_count.data();
    if (columns) {
      simd::PixelDistanceSums(projected->data(), num_previous, simd::ColumnsOf(views.core_columns, g), num_core, sums,
                              counts);
    } else {
      for (int q = 0; q < num_previous; ++q) {
        sums[q] = 0;
        counts[q] = 0;
        for (int c = 0; c < num_core; ++c) {
          const Keypoint& kp = kps[core_joints[c]];
          const Eigen::Vector2d& uv = projected[static_cast<size_t>(q) * num_core + c];
          if (kp.score <= 0 || std::isnan(uv.x())) continue;
          const double du = uv.x() - kp.u, dv = uv.y() - kp.v;
          sums[q] += std::sqrt(du * du + dv * dv);
          ++counts[q];
        }
      }
    }
    for (int q = 0; q < num_previous; ++q) {
      if (counts[q] < 3) continue;
      const double mean = sums[q] / counts[q];
      if (mean < 2 * radius) near[q / 64] |= uint64_t{1} << (q % 64);
      if (mean < best) {
        second = best;
        best = mean;
        best_q = q;
      } else if (mean < second) {
        second = mean;
      }
    }
    if (best < radius && second >= options.ambiguity_ratio * best) {
      (*match)[g] = best_q;
      scratch->distance[g] = best;
    } else if (best < 2 * radius) {
      (*match)[g] = kPoseAmbiguous;
    }
  }
  // One match per person and view: of several poses of a view matching q, only the closest keeps it.
  for (int v = 0; v < num_views; ++v) {
    for (int g = views.view_begin[v]; g < views.view_begin[v + 1]; ++g) {
      if ((*match)[g] < 0) continue;
      for (int h = g + 1; h < views.view_begin[v + 1]; ++h) {
        if ((*match)[h] != (*match)[g]) continue;
        const int loser = scratch->distance[h] < scratch->distance[g] ? g : h;
        (*match)[loser] = kPoseAmbiguous;
        if (loser == g) break;
      }
    }
  }

  // The ambiguous poses numbered, to count their pairs per person below (LimitAmbiguousPairs).
  const bool limit_ambiguous = options.max_pairs_per_ambiguous_pose > 0;
  int num_ambiguous = 0;
  if (limit_ambiguous) {
    scratch->ambiguous_slot.resize(views.num_poses());
    scratch->ambiguous_pose.clear();
    for (int g = 0; g < views.num_poses(); ++g) {
      scratch->ambiguous_slot[g] = -1;
      if ((*match)[g] != kPoseAmbiguous) continue;
      scratch->ambiguous_slot[g] = num_ambiguous++;
      scratch->ambiguous_pose.push_back(g);
    }
    scratch->ambiguous_count.assign(static_cast<size_t>(num_ambiguous) * num_previous, 0);
    scratch->ambiguous.clear();
  }

  ListKeptPairs(views, num_previous, limit_ambiguous, scratch, pairs);
  int kept = static_cast<int>(pairs->size());
  if (limit_ambiguous && num_ambiguous > 0) {
    kept = LimitAmbiguousPairs(views, geometry, core_joints, previous, options, scratch, pairs);
  }
  if (options.max_pairs_per_person > 0) kept = ApplyPairBudget(views, geometry, core_joints, previous, options, scratch, pairs);
  return kept;
}

}  // namespace rpt

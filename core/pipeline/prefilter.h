// SPDX-License-Identifier: MIT
// Step 2: filter pairs with the last frame's 3D poses.
//
// The previous persons' core joints are projected into every view and compared with each 2D pose
// (mean core-joint distance relative to the pose's bounding-box diagonal). A pose is
//   matched to person q  when q is within the match radius, clearly the closest (the second
//                        closest is at least `ambiguity_ratio` times farther), and this pose is
//                        q's closest pose in its view (a person is matched once per view),
//   free                 when nobody is within twice the radius (a new person),
//   ambiguous            otherwise.
// A pair is dropped when its poses match different persons, when one is matched and the other
// free (the paper's one-sided case: the other pose is somebody else), or when an ambiguous pose
// meets a pose matched to a person farther than twice the radius from it (one-sided again); every
// other pair is kept: both-matched-same, both-free, and an ambiguous pose with a free or ambiguous
// one or with the poses of the persons it is ambiguous between. Refusing to act on ambiguous
// matches keeps true pairs in crowded views and in sparsely sampled sequences.
//
// Pair budget (an addition to the paper): a person matched in k views yields k(k-1)/2 pairs, 465
// with 31 cameras, far more than the merge needs (it keeps the top-k closest proposals per
// joint). Of the pairs matched to one person only max_pairs_per_person are kept: first the
// best_pairs_per_pose (1) best pairs of every pose (so no pose of the person is left unclaimed),
// then the best remaining ones. Quality = sin of the angle
// at which the viewing rays meet at the person's last position x the 2D confidence both poses
// share on the core joints.
//
// Ambiguous pairs (an addition too): an ambiguous pose near person q pairs with every pose matched
// to q, up to one per view. Of those pairs only the max_pairs_per_ambiguous_pose best are kept
// (quality as above, at q's last position): enough for the pose to join q's group, should it be
// q, or to start its own group with another ambiguous or free pose, should it be a new person.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"

namespace rpt {

// Core joints of the previous frame's persons: `num_core` entries per person; score 0 = missing.
struct PreviousPersons {
  int num_core = 0;
  double timestamp_s = 0;  // when these persons were output
  std::vector<Eigen::Vector3d> xyz;
  std::vector<double> score;
  int size() const { return num_core > 0 ? static_cast<int>(score.size()) / num_core : 0; }
  void Clear(int core) {
    num_core = core;
    xyz.clear();
    score.clear();
  }
};

inline constexpr int kPoseFree = -1;
inline constexpr int kPoseAmbiguous = -2;

// A pair of an ambiguous pose with a pose matched to a person, and its quality (see above).
struct AmbiguousPair {
  int bucket;  // the ambiguous pose's number x the number of previous persons + the person
  double quality;
  int pair;  // index into the pairs
};

inline constexpr int kMaxBestPairsPerPose = 4;  // PrefilterOptions::best_pairs_per_pose at most

struct PrefilterScratch {
  std::vector<int> match;         // per pose: person index, kPoseFree or kPoseAmbiguous
  std::vector<double> distance;   // per pose: distance to the matched person (px)
  std::vector<uint64_t> near;     // per pose, (previous persons + 63) / 64 words: bit q set when
                                  // person q is within twice the radius
  std::vector<Eigen::Vector2d> projected;  // per view, person and core joint (NaN = not visible)
  std::vector<double> distance_sum;        // per previous person: one pose's summed core-joint distance (px)
  std::vector<int> distance_count;         // and the number of joints summed
  std::vector<int> bucket_begin;           // per bucket + 1 (previous person, or ambiguous pose and person): offsets
  std::vector<int> bucket;                 // pair indices grouped by matched person
  std::vector<int> bucket_fill;
  std::vector<Eigen::Vector3d> directions;  // per view: unit vector from the person to the camera
  std::vector<double> quality;              // per pair of one person's bucket: its quality for the budget
  std::vector<std::pair<double, int>> top;  // (quality, bucket entry): the best beyond the poses' best
  std::vector<char> keep;                   // per pair
  std::vector<double> best_quality;  // per pose, best_pairs_per_pose slots: its best entries' qualities
  std::vector<int> best_entry;       // and the entries (best first), while a person's budget is chosen
  std::vector<double> core_sqrt_scores;    // per pose and core joint: sqrt(score), when the core columns lack them
  std::vector<int> ambiguous_slot;         // per pose: its number among the ambiguous poses (-1: not ambiguous)
  std::vector<int> ambiguous_pose;         // per ambiguous pose number: the pose
  std::vector<int> ambiguous_count;        // per ambiguous pose and previous person: its pairs with that person
  std::vector<AmbiguousPair> ambiguous;    // the pairs of an ambiguous pose with a matched one, in pair order
  std::vector<AmbiguousPair> ambiguous_sorted;  // the same, by bucket
  std::vector<int> person_pose;      // per view and previous person: the pose matched to it (-1: none)
  std::vector<int> unmatched;        // the free and ambiguous poses, by view, ascending
  std::vector<int> unmatched_begin;  // per view + 1: offsets into `unmatched`
};

// Whether the pre-filter acts on this frame: enabled, and there are previous persons.
inline bool PrefilterActs(const PrefilterOptions& options, const PreviousPersons& previous) {
  return options.enabled && previous.size() > 0;
}

namespace steps {

struct PrefilterInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  std::span<const int> core_joints;        // output-joint indices of the core joints (step 3)
  const PreviousPersons& previous;         // the last frame's persons (remember)
  double timestamp_s;                      // this frame's time: the radius grows with the time since `previous`
};

// When it acts, classifies every pose into scratch->match and writes the kept cross-view pairs to
// `pairs` (replacing its content: make_pairs need not list them, see PairListing), in make_pairs'
// order. Returns the number of pairs kept. Otherwise leaves `pairs` (make_pairs' list) as it is.
int Prefilter(const PrefilterOptions& options, const PrefilterInput& in, PrefilterScratch* scratch,
              std::vector<PosePair>* pairs);

}  // namespace steps

}  // namespace rpt

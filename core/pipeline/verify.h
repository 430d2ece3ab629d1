// SPDX-License-Identifier: MIT
// Step 11b (`verify`, an addition): re-score each merged person against all views, to reject
// phantoms: persons assembled from poses of different people that happen to agree in the two or
// three views they came from.
//
// Every view judges the person (view_verdict.h): unseen, supporting, occupied or empty. A view
// that holds one of the person's own poses (the group's pairs) supports it without being judged.
// A person with at least min_empty_views empty views and more empty views than supporting views
// is dropped: more cameras look at the spot and see nobody than see the person. With few
// cameras (a phantom from 2 of 3 views has at most one empty view) the check cannot decide and
// keeps the person. Only persons that could be dropped (enough views outside their own) are
// projected, so the step costs next to nothing when every person is seen by most cameras.
//
// Duplicates first (duplicate_distance_m): a person whose core joints lie within that mean distance
// of a stronger person's (made from more views, then from more pairs) and who was made from none of
// that person's views is the same person again, from poses whose pairs with the stronger
// person's poses did not survive the pair budget: dropped. Persons sharing a view are kept apart:
// two poses in one view are two people to that camera. exclusive_poses (group step) already
// parts groups that share a pose; this catches those that share nothing.
//
// Then parts (part_distance_m): a person with fewer joints (score > 0) than another person not
// dropped before it (as a duplicate, or as a part, in person order), at least 2 of whose joints
// each lie within part_distance_m of that person's same joint, is a part of it: a body whose
// poses formed two groups (e.g. an arm and the legs apart from the rest, when the rest got wrong
// legs). Two people cannot hold the same joint at one spot. Dropped and
// counted with the duplicates.
#pragma once

#include <span>
#include <vector>

#include "core/pipeline/frame_stats.h"
#include "core/pipeline/options.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/proposal_scoring.h"
#include "core/pipeline/view_verdict.h"
#include "core/poses.h"

namespace rpt {

struct VerifyScratch {
  ViewVerdictScratch verdict;
  std::vector<char> views_of;       // per person and view: holds one of the person's own poses
  std::vector<int> num_views;       // per person: how many views it was made from
  std::vector<int> by_strength;     // persons, strongest first
  std::vector<char> duplicate;      // per person: dropped as a duplicate or a part
  std::vector<int> num_joints;      // per person: joints with score > 0
};

namespace steps {

struct VerifyInput {
  const PreparedViews& views;
  std::span<const ViewGeometry> geometry;  // per camera
  std::span<const int> core_joints;        // output-joint indices of the core joints
  const Proposals& proposals;              // triangulate_full's: person i was merged from group i
  const Groups& groups;                    // (step 11), whose pairs give its own views
  const ScoreKernel& kernel;               // the frame's kernels (step 6-7): agreement scale
};

// Removes dropped persons from `persons` (merge's output; their track ids are not assigned yet)
// and counts them in stats->duplicate_persons (duplicates and parts) and
// stats->unsupported_persons. Returns the number of persons kept.
int Verify(const VerifyOptions& options, const VerifyInput& in, VerifyScratch* scratch, Poses3D* persons,
           FrameStats* stats);

}  // namespace steps

}  // namespace rpt

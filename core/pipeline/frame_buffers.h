// SPDX-License-Identifier: MIT
// The Triangulator's per-frame buffers: each step's output and scratch space. Cleared and refilled
// every frame; clear() keeps their capacity, so a warm Triangulator does not allocate. Nothing in
// here carries meaning from one frame to the next (that is temporal_state.h).
#pragma once

#include <vector>

#include "core/pipeline/bone_lengths.h"
#include "core/pipeline/group.h"
#include "core/pipeline/merge.h"
#include "core/pipeline/pipeline_types.h"
#include "core/pipeline/prefilter.h"
#include "core/pipeline/proposal_scoring.h"
#include "core/pipeline/refine.h"
#include "core/pipeline/score.h"
#include "core/pipeline/single_view.h"
#include "core/pipeline/track.h"
#include "core/pipeline/triangulate_full.h"
#include "core/pipeline/verify.h"
#include "core/poses.h"

namespace rpt {

struct FrameBuffers {
  PreparedViews prepared;        // undistort
  std::vector<PosePair> pairs;   // make_pairs, prefilter
  PrefilterScratch prefilter;
  Proposals core;                // triangulate_core .. filter
  ScoreScratch score_scratch;
  ScoreKernel kernel;  // score: the frame's kernels (triangulate_full, verify, single_view)
  GroupScratch group_scratch;
  Groups groups;                 // group
  Proposals full;                // triangulate_full
  TriangulateFullScratch triangulate_full_scratch;
  MergeScratch merge_scratch;
  RefineScratch refine_scratch;
  VerifyScratch verify_scratch;
  SingleViewScratch single_view_scratch;
  Poses3D lifted;                // single_view: this frame's persons placed from one view
  TrackScratch track_scratch;
  BoneLengthsScratch bone_lengths_scratch;
};

}  // namespace rpt

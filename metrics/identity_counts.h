// SPDX-License-Identifier: MIT
// Track identities against the ground truth's: a GT person (with an id) matched to a prediction
// with another track id than in the last frame it was matched is an identity switch (the IDSW of
// the MOT benchmarks: a track that breaks and resumes under a new id counts, as does a swap of two
// people). The matches are the metrics' (kMatch pairs of FrameRecords, match_threshold_mm).
// Per sequence: track ids of two sequences are never the same person.
#pragma once

#include <unordered_map>
#include <unordered_set>

#include "core/poses.h"
#include "metrics/eval_records.h"

namespace rpt::metrics {

struct IdentityCounts {
  long gt_identities = 0;   // distinct GT person ids (id >= 0) in the frames added
  long matched_identities = 0;  // of those: matched to a tracked prediction at least once
  long track_ids = 0;       // distinct track ids among the predictions (matched or not)
  long tracked_matches = 0; // matches of a GT person with an id to a tracked prediction
  long id_switches = 0;     // of those: another track id than the GT person's last match
  // Sums (another sequence: its ids are other people and other tracks).
  void Merge(const IdentityCounts& other);
};

class IdentityAccumulator {
 public:
  // The frame's records as the MetricsAccumulator left them (LastFrame()) for `gt` and
  // `predictions`, the frame just added. GT without ids (track_ids -1 or absent) counts nothing.
  void Add(const FrameRecords& frame, const Poses3D& gt, const Poses3D& predictions);
  IdentityCounts counts() const;

 private:
  std::unordered_map<int, int> last_track_;  // per GT id: the track id of its last match
  std::unordered_set<int> track_ids_;
  std::unordered_set<int> gt_ids_;
  long tracked_matches_ = 0;
  long id_switches_ = 0;
};

}  // namespace rpt::metrics

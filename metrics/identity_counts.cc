// SPDX-License-Identifier: MIT
#include "metrics/identity_counts.h"

namespace rpt::metrics {

void IdentityCounts::Merge(const IdentityCounts& other) {
  gt_identities += other.gt_identities;
  matched_identities += other.matched_identities;
  track_ids += other.track_ids;
  tracked_matches += other.tracked_matches;
  id_switches += other.id_switches;
}

void IdentityAccumulator::Add(const FrameRecords& frame, const Poses3D& gt, const Poses3D& predictions) {
  for (int p = 0; p < predictions.num_persons(); ++p) {
    if (static_cast<size_t>(p) < predictions.track_ids.size() && predictions.track_ids[p] >= 0) {
      track_ids_.insert(predictions.track_ids[p]);
    }
  }
  for (const int id : gt.track_ids) {
    if (id >= 0) gt_ids_.insert(id);
  }
  for (const PairRecord& pair : frame.pairs) {
    if ((pair.flags & kMatch) == 0 || pair.gt_idx < 0 || pair.pred_idx < 0) continue;
    const int g = frame.kept_gt_idx[static_cast<size_t>(pair.gt_idx)];
    if (static_cast<size_t>(g) >= gt.track_ids.size() || static_cast<size_t>(pair.pred_idx) >= predictions.track_ids.size()) {
      continue;
    }
    const int gt_id = gt.track_ids[static_cast<size_t>(g)];
    const int track = predictions.track_ids[static_cast<size_t>(pair.pred_idx)];
    if (gt_id < 0 || track < 0) continue;
    ++tracked_matches_;
    const auto [it, first] = last_track_.try_emplace(gt_id, track);
    if (!first && it->second != track) {
      ++id_switches_;
      it->second = track;
    }
  }
}

IdentityCounts IdentityAccumulator::counts() const {
  IdentityCounts c;
  c.gt_identities = static_cast<long>(gt_ids_.size());
  c.matched_identities = static_cast<long>(last_track_.size());
  c.track_ids = static_cast<long>(track_ids_.size());
  c.tracked_matches = tracked_matches_;
  c.id_switches = id_switches_;
  return c;
}

}  // namespace rpt::metrics

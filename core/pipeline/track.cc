// SPDX-License-Identifier: MIT
#include "core/pipeline/track.h"

#include <algorithm>

namespace rpt {

void Tracker::Reset() {
  for (Track& t : tracks_) t.id = -1;
  next_id_ = 0;
}

void Tracker::EndTracks() {
  for (Track& t : tracks_) t.id = -1;
}

int Tracker::FindSlot(int track_id) const {
  for (size_t s = 0; s < tracks_.size(); ++s) {
    if (tracks_[s].id == track_id) return static_cast<int>(s);
  }
  return -1;
}

const double* Tracker::LastPose(int track_id, double* timestamp_s) const {
  const int s = track_id >= 0 ? FindSlot(track_id) : -1;
  if (s < 0) return nullptr;
  *timestamp_s = tracks_[s].timestamp_s;
  return tracks_[s].pose.data();
}

int Tracker::Assign(const TrackOptions& options, std::span<const int> match_joints, Poses3D* persons,
                    FrameStats* stats) {
  const int num_detected = persons->num_persons();
  const int n = persons->num_joints;
  const int num_slots = static_cast<int>(tracks_.size());

  candidates_.clear();
  for (int p = 0; p < num_detected; ++p) {
    const auto person = persons->Person(p);
    for (int s = 0; s < num_slots; ++s) {
      const Track& t = tracks_[s];
      if (t.id < 0 || static_cast<int>(t.pose.size()) != 4 * n) continue;
      double sum = 0;
      int common = 0;
      for (int j : match_joints) {
        const double* q = t.pose.data() + 4 * j;
        if (person(3, j) <= 0 || q[3] <= 0) continue;
        sum += (person.col(j).head<3>() - Eigen::Vector3d(q[0], q[1], q[2])).norm();
        ++common;
      }
      if (common < 3) continue;
      const double distance = sum / common;
      if (distance < options.max_distance_m) candidates_.emplace_back(distance, p, s);
    }
  }
  std::sort(candidates_.begin(), candidates_.end());

  person_slot_.assign(num_detected, -1);
  slot_used_.assign(num_slots, 0);
  for (const auto& [distance, p, s] : candidates_) {
    if (person_slot_[p] >= 0 || slot_used_[s]) continue;
    person_slot_[p] = s;
    slot_used_[s] = 1;
  }
  for (int p = 0; p < num_detected; ++p) {
    if (person_slot_[p] >= 0) {
      persons->track_ids[p] = tracks_[person_slot_[p]].id;
      continue;
    }
    // New track: reuse a free slot when there is one (keeps its buffer).
    int s = FindSlot(-1);
    if (s < 0) {
      s = static_cast<int>(tracks_.size());
      tracks_.emplace_back();
      slot_used_.push_back(0);
    }
    tracks_[s].id = next_id_++;
    tracks_[s].missing = 0;
    tracks_[s].pose.clear();
    slot_used_[s] = 1;
    persons->track_ids[p] = tracks_[s].id;
    ++stats->new_tracks;
  }
  // Tracks without a person: coast for a few frames, then end.
  for (int s = 0; s < static_cast<int>(tracks_.size()); ++s) {
    Track& t = tracks_[s];
    if (t.id < 0 || slot_used_[s]) continue;
    if (++t.missing > options.max_missing_frames || static_cast<int>(t.pose.size()) != 4 * n) {
      t.id = -1;
      continue;
    }
    auto person = persons->AddPerson(t.id);
    person = Eigen::Map<const Eigen::Matrix4Xd>(t.pose.data(), 4, n);
    ++stats->coasting_tracks;
  }
  return num_detected;
}

void Tracker::Commit(const Poses3D& persons, int num_detected, double timestamp_s) {
  const size_t size = 4 * static_cast<size_t>(persons.num_joints);
  for (int p = 0; p < num_detected; ++p) {
    const int s = FindSlot(persons.track_ids[p]);
    if (s < 0) continue;
    Track& t = tracks_[s];
    t.pose.resize(size);
    std::copy_n(persons.data.data() + p * size, size, t.pose.data());
    t.timestamp_s = timestamp_s;
    t.missing = 0;
  }
}

}  // namespace rpt

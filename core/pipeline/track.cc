// SPDX-License-Identifier: MIT
#include "core/pipeline/track.h"

#include <algorithm>
#include <limits>

#include "core/pipeline/postprocess.h"

namespace rpt {

void Tracks::Reset() {
  EndTracks();
  next_id = 0;
}

void Tracks::EndTracks() {
  for (Slot& slot : slots) slot.id = -1;
}

int Tracks::FindSlot(int track_id) const {
  for (size_t s = 0; s < slots.size(); ++s) {
    if (slots[s].id == track_id) return static_cast<int>(s);
  }
  return -1;
}

const double* Tracks::LastPose(int track_id, double* timestamp_s) const {
  const int s = track_id >= 0 ? FindSlot(track_id) : -1;
  // A track started this frame has no pose yet; its slot may hold an ended track's buffer.
  if (s < 0 || slots[s].pose.empty()) return nullptr;
  *timestamp_s = slots[s].timestamp_s;
  return slots[s].pose.data();
}

void Tracks::Commit(const Poses3D& persons, int num_detected, double timestamp_s) {
  const size_t size = 4 * static_cast<size_t>(persons.num_joints);
  for (int p = 0; p < num_detected; ++p) {
    const int s = FindSlot(persons.track_ids[p]);
    if (s < 0) continue;
    Slot& slot = slots[s];
    slot.pose.resize(size);
    std::copy_n(persons.data.data() + p * size, size, slot.pose.data());
    slot.timestamp_s = timestamp_s;
    slot.missing = 0;
    bool multi_view = false, lifted = false;
    for (int j = 0; j < persons.num_joints; ++j) {
      const JointProvenance source = persons.Provenance(p, j);
      multi_view |= source == JointProvenance::kTriangulated || source == JointProvenance::kSmoothed;
      lifted |= source == JointProvenance::kLifted;
    }
    if (multi_view && !lifted) slot.supported_s = timestamp_s;
  }
}

namespace {

// Mean distance of `person` from a track's last pose over `joints` scored above `min_score` in
// the person and above `min_last` in the last pose; `*common` = how many.
double MeanDistance(const Eigen::Ref<const Eigen::Matrix4Xd>& person, const double* last, std::span<const int> joints,
                    double min_score, double min_last, int* common) {
  double sum = 0;
  *common = 0;
  for (int j : joints) {
    const double* q = last + 4 * j;
    if (person(3, j) <= min_score || q[3] <= min_last) continue;
    sum += (person.col(j).head<3>() - Eigen::Vector3d(q[0], q[1], q[2])).norm();
    ++*common;
  }
  return sum / std::max(*common, 1);
}

}  // namespace

int steps::Track(const TrackOptions& options, const TrackInput& in, Tracks* tracks, TrackScratch* scratch,
                 Poses3D* persons, FrameStats* stats) {
  const std::span<const int> match_joints = in.match_joints;
  std::vector<Tracks::Slot>& slots = tracks->slots;
  const int num_detected = persons->num_persons();
  const int n = persons->num_joints;
  const int num_slots = static_cast<int>(slots.size());

  std::vector<std::tuple<double, int, int>>& candidates = scratch->candidates;
  candidates.clear();
  for (int p = 0; p < num_detected; ++p) {
    const auto person = persons->Person(p);
    for (int s = 0; s < num_slots; ++s) {
      const Tracks::Slot& t = slots[s];
      if (t.id < 0 || static_cast<int>(t.pose.size()) != 4 * n) continue;
      // Observed joints first: a filled joint sits wherever its fill put it, in either pose. Then
      // the joints observed now against the last pose's valid ones (its held joints are near
      // where they were), then every valid joint.
      const double unobserved = in.unobserved_score;
      int common = 0;
      double distance = MeanDistance(person, t.pose.data(), match_joints, unobserved, unobserved, &common);
      if (common < 3) distance = MeanDistance(person, t.pose.data(), match_joints, unobserved, 0.0, &common);
      if (common < 3) distance = MeanDistance(person, t.pose.data(), match_joints, 0.0, 0.0, &common);
      if (common < 3) continue;
      // Time since the track was last seen (a coasting track keeps the time of its last person).
      const double since_seen_s = std::max(0.0, in.timestamp_s - t.timestamp_s);
      const double gate = std::max(options.max_distance_m, options.max_person_speed_m_s * since_seen_s);
      if (distance < gate) candidates.emplace_back(distance, p, s);
    }
  }
  std::sort(candidates.begin(), candidates.end());

  std::vector<int>& person_slot = scratch->person_slot;
  std::vector<char>& slot_used = scratch->slot_used;
  person_slot.assign(num_detected, -1);
  slot_used.assign(num_slots, 0);
  for (const auto& [distance, p, s] : candidates) {
    if (person_slot[p] >= 0 || slot_used[s]) continue;
    person_slot[p] = s;
    slot_used[s] = 1;
  }
  for (int p = 0; p < num_detected; ++p) {
    if (person_slot[p] >= 0) {
      const Tracks::Slot& t = slots[person_slot[p]];
      persons->track_ids[p] = t.id;
      const std::span<const uint8_t> provenance = persons->PersonProvenance(p);
      if (options.hold_missing_joints && !in.neighbour.empty() && !provenance.empty()) {
        stats->held_joints += HoldFilledJoints(in.neighbour, t.pose.data(), persons->Person(p), provenance, &scratch->settled);
      }
      continue;
    }
    // New track: reuse a free slot when there is one (keeps its buffer).
    int s = tracks->FindSlot(-1);
    if (s < 0) {
      s = static_cast<int>(slots.size());
      slots.emplace_back();
      slot_used.push_back(0);
    }
    slots[s].id = tracks->next_id++;
    slots[s].missing = 0;
    slots[s].supported_s = -std::numeric_limits<double>::infinity();
    slots[s].pose.clear();
    slot_used[s] = 1;
    persons->track_ids[p] = slots[s].id;
    ++stats->new_tracks;
  }
  // Tracks without a person: coast for a few frames, then end.
  for (int s = 0; s < static_cast<int>(slots.size()); ++s) {
    Tracks::Slot& t = slots[s];
    if (t.id < 0 || slot_used[s]) continue;
    if (++t.missing > options.max_missing_frames || static_cast<int>(t.pose.size()) != 4 * n) {
      t.id = -1;
      continue;
    }
    auto person = persons->AddPerson(t.id);
    person = Eigen::Map<const Eigen::Matrix4Xd>(t.pose.data(), 4, n);
    for (uint8_t& source : persons->PersonProvenance(persons->num_persons() - 1)) {
      source = static_cast<uint8_t>(JointProvenance::kPredicted);
    }
    ++stats->coasting_tracks;
  }
  return persons->num_persons();
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "core/pipeline/remember.h"

namespace rpt {

int steps::Remember(std::span<const int> core_joints, const Poses3D& persons, int first_lifted, int num_lifted,
                    int num_detected, double timestamp_s, PreviousPersons* previous, Tracker* tracker) {
  if (tracker != nullptr) tracker->Commit(persons, num_detected, timestamp_s);
  const int num_core = static_cast<int>(core_joints.size());
  previous->Clear(num_core);
  previous->timestamp_s = timestamp_s;
  for (int p = 0; p < persons.num_persons(); ++p) {
    if (p >= first_lifted && p < first_lifted + num_lifted) continue;  // single-view persons
    const auto person = persons.Person(p);
    for (int c = 0; c < num_core; ++c) {
      previous->xyz.push_back(person.col(core_joints[c]).head<3>());
      previous->score.push_back(person(3, core_joints[c]));
    }
  }
  return previous->size();
}

}  // namespace rpt

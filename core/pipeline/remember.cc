// SPDX-License-Identifier: MIT
#include "core/pipeline/remember.h"

namespace rpt {

int steps::Remember(const RememberInput& in, PreviousPersons* previous, Tracks* tracks) {
  if (tracks != nullptr) tracks->Commit(in.persons, in.num_detected, in.timestamp_s);
  const int num_core = static_cast<int>(in.core_joints.size());
  previous->Clear(num_core);
  previous->timestamp_s = in.timestamp_s;
  for (int p = 0; p < in.persons.num_persons(); ++p) {
    if (p >= in.first_lifted && p < in.first_lifted + in.num_lifted) continue;  // single-view persons
    const auto person = in.persons.Person(p);
    for (int c = 0; c < num_core; ++c) {
      previous->xyz.push_back(person.col(in.core_joints[c]).head<3>());
      previous->score.push_back(person(3, in.core_joints[c]));
    }
  }
  return previous->size();
}

}  // namespace rpt

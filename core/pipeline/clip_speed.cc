// SPDX-License-Identifier: MIT
#include "core/pipeline/clip_speed.h"

namespace rpt {

int steps::ClipSpeed(const ClipSpeedOptions& options, const ClipSpeedInput& in, Poses3D* persons) {
  if (!options.enabled) return 0;
  int clipped = 0;
  for (int p = 0; p < in.num_detected; ++p) {
    double last_time = 0;
    const double* last = in.tracks.LastPose(persons->track_ids[p], &last_time);
    const double dt = in.timestamp_s - last_time;
    if (last == nullptr || !(dt > 0)) continue;
    const double max_step = options.max_speed_m_s * dt;
    auto person = persons->Person(p);
    for (int j = 0; j < persons->num_joints; ++j) {
      if (person(3, j) <= 0 || last[4 * j + 3] <= 0) continue;
      const Eigen::Vector3d from(last[4 * j], last[4 * j + 1], last[4 * j + 2]);
      const Eigen::Vector3d step = person.col(j).head<3>() - from;
      const double length = step.norm();
      if (length <= max_step) continue;
      person.col(j).head<3>() = from + step * (max_step / length);
      // A filled or lifted joint stays what it is: moving it does not make it observed.
      const std::span<uint8_t> source = persons->PersonProvenance(p);
      if (!source.empty() && source[j] == static_cast<uint8_t>(JointProvenance::kTriangulated)) {
        source[j] = static_cast<uint8_t>(JointProvenance::kSmoothed);
      }
      ++clipped;
    }
  }
  return clipped;
}

}  // namespace rpt

// SPDX-License-Identifier: MIT
#include "core/pipeline/smooth.h"

namespace rpt {
namespace {

// Velocity variance of a new filter (m^2/s^2): effectively unknown, so the second observation
// sets the velocity (the classic two-point start).
constexpr double kUnknownVelocityVariance = 1e4;

}  // namespace

int steps::Smooth(const SmoothOptions& options, const SmoothInput& in, JointFilters* state, Poses3D* persons) {
  if (options.mode != SmoothMode::kCausal) return 0;
  const double timestamp_s = in.timestamp_s;
  TrackStates<JointFilters::Track>& tracks = state->tracks;
  tracks.BeginFrame(*persons);
  const int n = persons->num_joints;
  const double r = options.measurement_noise_m * options.measurement_noise_m;
  const double q = options.acceleration_m_s2 * options.acceleration_m_s2;
  int smoothed = 0;
  for (int p = 0; p < in.num_detected; ++p) {
    const int id = persons->track_ids[p];
    if (id < 0) continue;
    bool created = false;
    std::vector<JointFilters::Filter>& filters = tracks.Get(id, &created).joints;
    if (created || static_cast<int>(filters.size()) != n) filters.assign(n, JointFilters::Filter{});
    auto person = persons->Person(p);
    const std::span<uint8_t> provenance = persons->PersonProvenance(p);
    for (int j = 0; j < n; ++j) {
      if (!(person(3, j) > in.unobserved_score)) continue;
      JointFilters::Filter& f = filters[j];
      const Eigen::Vector3d z = person.col(j).head<3>();
      const double dt = timestamp_s - f.timestamp_s;  // NaN when either time is unknown
      f.timestamp_s = timestamp_s;
      if (!f.started || !(dt > 0 && dt <= in.max_gap_s)) {
        f.x = z;
        f.v.setZero();
        f.p00 = r;
        f.p01 = 0;
        f.p11 = kUnknownVelocityVariance;
        f.started = true;
        continue;
      }
      // Predict over dt (acceleration noise held constant over the interval).
      const double dt2 = dt * dt;
      f.x += f.v * dt;
      f.p00 += 2 * dt * f.p01 + dt2 * f.p11 + q * dt2 * dt2 / 4;
      f.p01 += dt * f.p11 + q * dt2 * dt / 2;
      f.p11 += q * dt2;
      // Update with the observed position.
      const double k0 = f.p00 / (f.p00 + r), k1 = f.p01 / (f.p00 + r);
      const Eigen::Vector3d residual = z - f.x;
      f.x += k0 * residual;
      f.v += k1 * residual;
      f.p11 -= k1 * f.p01;
      f.p01 *= 1 - k0;
      f.p00 *= 1 - k0;
      person.col(j).head<3>() = f.x;
      if (!provenance.empty() && provenance[j] == static_cast<uint8_t>(JointProvenance::kTriangulated)) {
        provenance[j] = static_cast<uint8_t>(JointProvenance::kSmoothed);  // a lifted joint stays lifted
      }
      ++smoothed;
    }
  }
  return smoothed;
}

}  // namespace rpt

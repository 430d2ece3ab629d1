// SPDX-License-Identifier: MIT
#include "core/pipeline/offline_smoother.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <cmath>

namespace rpt {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxDegree = 3;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree + 1, kMaxDegree + 1>;
using Rhs = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxDegree + 1, 3>;

double MicrosecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

}  // namespace

OfflineSmoother::OfflineSmoother(const SmoothOptions& options, double max_gap_s, double unobserved_score)
    : options_(options),
      enabled_(options.mode == SmoothMode::kOffline),
      max_gap_s_(max_gap_s),
      unobserved_score_(unobserved_score),
      reach_s_(3 * options.offline_sigma_s) {}

void OfflineSmoother::Push(double timestamp_s, const Poses3D& persons, int num_detected, const FrameStats& stats) {
  const Clock::time_point start = Clock::now();
  // Continuity with the newest frame, as Triangulator::Process judges it.
  const double dt = timestamp_s - last_timestamp_s_;  // NaN when either time is unknown
  const bool other_joints = persons.num_persons() > 0 && segment_joints_ >= 0 && persons.num_joints != segment_joints_;
  if (segment_closed_ || !(dt > 0 && dt <= max_gap_s_) || other_joints) {
    ++segment_;
    segment_joints_ = -1;
  }
  segment_closed_ = std::isnan(timestamp_s);  // no frame continues one at an unknown time
  last_timestamp_s_ = timestamp_s;
  if (persons.num_persons() > 0) segment_joints_ = persons.num_joints;

  if (num_held_ == 0) first_ = 0;                     // the same slots for the same frames of each sequence
  if (num_held_ == static_cast<int>(ring_.size())) {  // full: grow (only until warm)
    std::rotate(ring_.begin(), ring_.begin() + first_, ring_.end());
    first_ = 0;
    ring_.emplace_back();
  }
  Frame& frame = Held(num_held_++);
  frame.timestamp_s = timestamp_s;
  frame.segment = segment_;
  frame.num_detected = std::clamp(num_detected, 0, persons.num_persons());
  frame.persons = persons;  // copy-assignment reuses the slot's capacity
  frame.stats = stats;
  if (enabled_) {
    const double elapsed_us = MicrosecondsSince(start);
    frame.stats.time_us[static_cast<int>(Step::kSmooth)] += elapsed_us;
    frame.stats.total_us += elapsed_us;
  }
}

void OfflineSmoother::Flush() { segment_closed_ = true; }

bool OfflineSmoother::Ready(const Frame& frame) const {
  if (!enabled_ || segment_closed_ || frame.segment != segment_) return true;
  // Times increase within a segment: once a frame beyond the window has arrived, all have.
  return !(last_timestamp_s_ <= frame.timestamp_s + reach_s_);
}

bool OfflineSmoother::Pop(Poses3D* persons, FrameStats* stats) {
  if (next_ == num_held_ || !Ready(Held(next_))) return false;
  const Clock::time_point start = Clock::now();
  const Frame& frame = Held(next_);
  *persons = frame.persons;
  *stats = frame.stats;
  if (enabled_) stats->count[static_cast<int>(Step::kSmooth)] = SmoothFrame(next_, persons);
  ++next_;
  DropUnneeded();
  if (enabled_) {
    const double elapsed_us = MicrosecondsSince(start);
    stats->time_us[static_cast<int>(Step::kSmooth)] += elapsed_us;
    stats->total_us += elapsed_us;
  }
  return true;
}

void OfflineSmoother::DropUnneeded() {
  while (next_ > 0) {
    const Frame& oldest = Held(0);
    if (next_ < num_held_) {
      const Frame& waiting = Held(next_);
      // Still in the window of the oldest frame to be handed back (the same test as its fits use).
      if (oldest.segment == waiting.segment && !(oldest.timestamp_s < waiting.timestamp_s - reach_s_)) return;
    }
    first_ = (first_ + 1) % static_cast<int>(ring_.size());
    --num_held_;
    --next_;
  }
}

namespace {

// Value at t0 = obs[i].t of the Gaussian-weighted polynomial fit to the observations (in time
// order) of one track and joint within the window of obs[i].
template <class Observations>
Eigen::Vector3d Fit(const Observations& obs, int i, double sigma, int degree) {
  const int n = static_cast<int>(obs.size());
  degree = std::min(degree, n - 1);
  const double t0 = obs[i].t;
  for (; degree >= 1; --degree) {
    const int m = degree + 1;
    Matrix A = Matrix::Zero(m, m);
    Rhs b = Rhs::Zero(m, 3);
    for (int k = 0; k < n; ++k) {
      const double u = (obs[k].t - t0) / sigma;
      const double w = std::exp(-0.5 * u * u);
      double basis[kMaxDegree + 1];
      basis[0] = 1;
      for (int d = 1; d < m; ++d) basis[d] = basis[d - 1] * u;
      for (int r = 0; r < m; ++r) {
        for (int c = 0; c < m; ++c) A(r, c) += w * basis[r] * basis[c];
        b.row(r) += w * basis[r] * obs[k].x.transpose();
      }
    }
    const Eigen::LDLT<Matrix> ldlt(A);
    // Observations far out in the tails carry almost no weight: too few effective points for
    // this degree make the system near-singular; then fit a lower degree.
    if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-10)) continue;
    const Rhs coefficients = ldlt.solve(b);
    return coefficients.row(0).transpose();
  }
  return obs[i].x;  // degree 0 around a lone observation: leave it
}

}  // namespace

int OfflineSmoother::SmoothFrame(int i, Poses3D* persons) {
  const Frame& frame = Held(i);
  const double t0 = frame.timestamp_s;
  // The window: the frames of the segment within 3 sigma (times increase within a segment).
  int lo = i, hi = i + 1;
  while (lo > 0 && Held(lo - 1).segment == frame.segment && !(Held(lo - 1).timestamp_s < t0 - reach_s_)) --lo;
  while (hi < num_held_ && Held(hi).segment == frame.segment && Held(hi).timestamp_s <= t0 + reach_s_) ++hi;
  if (hi - lo < 2) return 0;  // a lone frame: nothing to fit
  person_in_.resize(hi - lo);
  int changed = 0;
  for (int p = 0; p < frame.num_detected; ++p) {
    const int id = frame.persons.track_ids[p];
    if (id < 0) continue;
    for (int g = lo; g < hi; ++g) {
      const Frame& other = Held(g);
      const auto begin = other.persons.track_ids.begin();
      const int q = static_cast<int>(std::find(begin, begin + other.num_detected, id) - begin);
      person_in_[g - lo] = q < other.num_detected ? q : -1;
    }
    const auto person = frame.persons.Person(p);
    for (int j = 0; j < frame.persons.num_joints; ++j) {
      if (!(person(3, j) > unobserved_score_)) continue;
      observations_.clear();
      int self = -1;
      for (int g = lo; g < hi; ++g) {
        const int q = person_in_[g - lo];
        if (q < 0) continue;
        const auto other = Held(g).persons.Person(q);
        if (!(other(3, j) > unobserved_score_)) continue;
        if (g == i) self = static_cast<int>(observations_.size());
        observations_.push_back(Observation{Held(g).timestamp_s, other.col(j).head<3>()});
      }
      const Eigen::Vector3d fitted = Fit(observations_, self, options_.offline_sigma_s, options_.offline_degree);
      if (fitted == observations_[self].x) continue;
      persons->Person(p).col(j).head<3>() = fitted;
      const std::span<uint8_t> source = persons->PersonProvenance(p);
      if (!source.empty() && source[j] == static_cast<uint8_t>(JointProvenance::kTriangulated)) {
        source[j] = static_cast<uint8_t>(JointProvenance::kSmoothed);  // a lifted joint stays lifted
      }
      ++changed;
    }
  }
  return changed;
}

}  // namespace rpt

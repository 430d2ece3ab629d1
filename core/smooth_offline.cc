// SPDX-License-Identifier: MIT
#include "core/smooth_offline.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace rpt {
namespace {

constexpr int kMaxDegree = 3;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDegree + 1, kMaxDegree + 1>;
using Rhs = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxDegree + 1, 3>;

struct Observation {
  double t;
  Eigen::Vector3d x;
  double* out;  // the joint's coordinates in the frame
};

// Value at t0 of the Gaussian-weighted polynomial fit to obs[begin, end) (t0 = obs[i].t).
Eigen::Vector3d Fit(const std::vector<Observation>& obs, int begin, int end, int i, double sigma, int degree) {
  degree = std::min(degree, end - begin - 1);
  const double t0 = obs[i].t;
  for (; degree >= 1; --degree) {
    const int m = degree + 1;
    Matrix A = Matrix::Zero(m, m);
    Rhs b = Rhs::Zero(m, 3);
    for (int k = begin; k < end; ++k) {
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

long SmoothOffline(const SmoothOptions& options, double max_gap_s, double filled_score,
                   std::span<const double> timestamps_s, std::span<const int> num_detected,
                   std::vector<Poses3D>* frames) {
  if (options.mode != SmoothMode::kOffline) return 0;
  const int num_frames = static_cast<int>(frames->size());
  if (static_cast<int>(timestamps_s.size()) != num_frames ||
      (!num_detected.empty() && static_cast<int>(num_detected.size()) != num_frames)) {
    throw std::invalid_argument("SmoothOffline: one timestamp (and detected count) per frame expected");
  }
  // Continuous segments: a new one starts after a gap or an unknown time.
  std::vector<int> segment(num_frames, 0);
  for (int f = 1; f < num_frames; ++f) {
    const double dt = timestamps_s[f] - timestamps_s[f - 1];
    segment[f] = segment[f - 1] + (dt > 0 && dt <= max_gap_s ? 0 : 1);
  }
  // (segment, track, frame, person) of every detected tracked person, grouped by track.
  std::vector<std::tuple<int, int, int, int>> entries;
  for (int f = 0; f < num_frames; ++f) {
    const Poses3D& persons = (*frames)[f];
    const int detected = num_detected.empty() ? persons.num_persons() : std::min(num_detected[f], persons.num_persons());
    for (int p = 0; p < detected; ++p) {
      if (persons.track_ids[p] >= 0) entries.emplace_back(segment[f], persons.track_ids[p], f, p);
    }
  }
  std::sort(entries.begin(), entries.end());

  const double sigma = options.offline_sigma_s;
  const double reach = 3 * sigma;
  long changed = 0;
  std::vector<Observation> obs;
  std::vector<Eigen::Vector3d> fitted;
  for (size_t begin = 0; begin < entries.size();) {
    size_t end = begin;
    while (end < entries.size() && std::get<0>(entries[end]) == std::get<0>(entries[begin]) &&
           std::get<1>(entries[end]) == std::get<1>(entries[begin])) {
      ++end;
    }
    const int num_joints = (*frames)[std::get<2>(entries[begin])].num_joints;
    for (int j = 0; j < num_joints; ++j) {
      obs.clear();
      for (size_t e = begin; e < end; ++e) {
        const auto [seg, track, f, p] = entries[e];
        Poses3D& persons = (*frames)[f];
        if (persons.num_joints != num_joints) continue;
        auto person = persons.Person(p);
        if (!(person(3, j) > filled_score)) continue;
        obs.push_back(Observation{timestamps_s[f], person.col(j).head<3>(), &person(0, j)});
      }
      // Fit every observation from the unchanged inputs, then write.
      const int n = static_cast<int>(obs.size());
      fitted.resize(n);
      int lo = 0, hi = 0;
      for (int i = 0; i < n; ++i) {
        while (obs[lo].t < obs[i].t - reach) ++lo;
        while (hi < n && obs[hi].t <= obs[i].t + reach) ++hi;
        fitted[i] = Fit(obs, lo, hi, i, sigma, options.offline_degree);
      }
      for (int i = 0; i < n; ++i) {
        if (fitted[i] == obs[i].x) continue;
        Eigen::Map<Eigen::Vector3d>(obs[i].out) = fitted[i];
        ++changed;
      }
    }
    begin = end;
  }
  return changed;
}

}  // namespace rpt

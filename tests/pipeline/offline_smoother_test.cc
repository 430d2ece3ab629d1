// SPDX-License-Identifier: MIT
// Offline smoothing (smooth.mode = offline), streamed by the OfflineSmoother: the same results,
// bit for bit, as smoothing the whole sequence at once (the reference below is the whole-sequence
// implementation the streaming one replaced), frames handed back as soon as their window is
// complete, and the method's properties (exact on linear motion, less noise, nothing mixed
// across tracks, gaps or unobserved joints).
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "core/pipeline/offline_smoother.h"
#include "core/pipeline/triangulator.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

// The whole-sequence smoothing as it was before it streamed (core/smooth_offline.cc at commit
// 826ae86): one pass over all frames, grouped by continuous segment and track.
namespace rpt::reference {
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
    throw std::invalid_argument("one timestamp (and detected count) per frame expected");
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
    const int detected =
        num_detected.empty() ? persons.num_persons() : std::min(num_detected[f], persons.num_persons());
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

}  // namespace rpt::reference

namespace rpt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMaxGap = 1.0;  // TrackOptions default
constexpr int kSmooth = static_cast<int>(Step::kSmooth);

SmoothOptions Offline(int degree = 2) {
  SmoothOptions options;
  options.mode = SmoothMode::kOffline;
  options.offline_degree = degree;
  return options;
}

// One frame of single-joint persons: positions and track ids (score 1).
Poses3D Points(const std::vector<Eigen::Vector3d>& xyz, const std::vector<int>& ids) {
  Poses3D persons;
  persons.Clear(1);
  for (size_t p = 0; p < xyz.size(); ++p) persons.AddPerson(ids[p]).col(0) << xyz[p], 1.0;
  return persons;
}

// Streams `frames` through an OfflineSmoother, taking every frame as soon as it is handed back.
// `waiting[f]`: frames waiting after frame f was pushed and the ready ones taken.
struct Streamed {
  std::vector<Poses3D> frames;
  std::vector<FrameStats> stats;
  std::vector<int> waiting;
};
Streamed Stream(const SmoothOptions& options, double unobserved_score, const std::vector<Poses3D>& frames,
                const std::vector<double>& times, const std::vector<int>& detected = {},
                const std::vector<FrameStats>& stats = {}) {
  OfflineSmoother smoother(options, kMaxGap, unobserved_score);
  Streamed out;
  Poses3D persons;
  FrameStats frame_stats;
  auto take = [&] {
    while (smoother.Pop(&persons, &frame_stats)) {
      out.frames.push_back(persons);
      out.stats.push_back(frame_stats);
    }
  };
  for (size_t f = 0; f < frames.size(); ++f) {
    smoother.Push(times[f], frames[f], detected.empty() ? frames[f].num_persons() : detected[f],
                  stats.empty() ? FrameStats{} : stats[f]);
    take();
    out.waiting.push_back(smoother.num_waiting());
  }
  smoother.Flush();
  take();
  EXPECT_EQ(smoother.num_waiting(), 0);
  EXPECT_EQ(out.frames.size(), frames.size());
  return out;
}

// A tracked synthetic scene through the triangulator, at uneven times with two gaps longer than
// track.max_gap_s and a frame without a time.
struct TrackedScene {
  std::vector<Poses3D> persons;
  std::vector<FrameStats> stats;
  std::vector<double> times;
  std::vector<int> detected;
  double unobserved_score = 0;
};
TrackedScene RunTrackedScene() {
  synthetic::SceneOptions options;
  options.rig.num_cameras = 4;
  options.num_people = 3;
  options.num_frames = 150;
  options.seed = 9;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorSimulator detector(synthetic::DetectorOptions::Realistic(), scene.joint_names, 9);
  TriangulatorOptions tri_options;
  tri_options.room_check.center_m = scene.room_center_m;
  tri_options.room_check.size_m = scene.room_size_m;
  Triangulator tri(scene.cameras, scene.joint_names, tri_options);
  TrackedScene out;
  out.unobserved_score = tri_options.UnobservedScore();
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> jitter(0.02, 0.07);  // 14 to 50 fps
  double t = 0;
  std::vector<Poses2D> views;
  for (int f = 0; f < options.num_frames; ++f) {
    t += f == 50 ? 1.3 : f == 100 ? 2.0 : jitter(rng);  // two gaps over max_gap_s
    out.times.push_back(f == 120 ? kNaN : t);
    detector.Detect(scene.cameras, scene.gt[f], scene.joint_names, f, &views);
    Poses3D& persons = out.persons.emplace_back();
    FrameStats& stats = out.stats.emplace_back();
    tri.Process(views, out.times.back(), &persons, &stats);
    out.detected.push_back(persons.num_persons() - stats.coasting_tracks);
  }
  return out;
}

TEST(OfflineSmoother, StreamedEqualsTheWholeSequenceBitForBit) {
  const TrackedScene scene = RunTrackedScene();
  int coasting = 0;
  for (const FrameStats& s : scene.stats) coasting += s.coasting_tracks;
  ASSERT_GT(coasting, 0) << "the scene must have coasting persons (left as is)";
  for (int degree : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << "degree " << degree);
    std::vector<Poses3D> expected = scene.persons;
    const long changed = reference::SmoothOffline(Offline(degree), kMaxGap, scene.unobserved_score, scene.times,
                                                  scene.detected, &expected);
    ASSERT_GT(changed, 1000) << "not vacuous";
    const Streamed streamed =
        Stream(Offline(degree), scene.unobserved_score, scene.persons, scene.times, scene.detected, scene.stats);
    long streamed_changed = 0;
    for (size_t f = 0; f < expected.size(); ++f) {
      SCOPED_TRACE(testing::Message() << "frame " << f);
      const Poses3D& got = streamed.frames[f];
      ASSERT_EQ(got.num_joints, expected[f].num_joints);
      ASSERT_EQ(got.track_ids, expected[f].track_ids);
      ASSERT_EQ(got.data.size(), expected[f].data.size());
      EXPECT_EQ(0, std::memcmp(got.data.data(), expected[f].data.data(), got.data.size() * sizeof(double)));
      streamed_changed += streamed.stats[f].count[kSmooth];
    }
    EXPECT_EQ(streamed_changed, changed) << "count[smooth]: the joints each frame's fits changed";
  }
}

TEST(OfflineSmoother, HandsEachFrameBackOnceItsWindowIsComplete) {
  // 25 fps, sigma 0.1 s: a frame's window reaches 0.3 s (7.5 frames) ahead, so frame f comes back
  // when frame f + 8 arrives; at a cut (gap, unknown time) or Flush everything held comes back.
  std::vector<Poses3D> frames;
  std::vector<double> times;
  for (int f = 0; f < 40; ++f) {
    const double t = f < 20 ? f * 0.04 : 2.0 + f * 0.04;  // a 1.2 s gap before frame 20
    times.push_back(f == 30 ? kNaN : t);
    frames.push_back(Points({Eigen::Vector3d(t, 0, 1)}, {0}));
  }
  const Streamed out = Stream(Offline(), 0.0, frames, times);
  for (int f = 0; f < 40; ++f) {
    SCOPED_TRACE(testing::Message() << "after frame " << f);
    if (f < 8) {
      EXPECT_EQ(out.waiting[f], f + 1) << "nothing complete yet";
    } else if (f < 20) {
      EXPECT_EQ(out.waiting[f], 8) << "one window: frames f-7 .. f";
    } else if (f < 30) {
      EXPECT_EQ(out.waiting[f], std::min(f - 19, 8)) << "the gap handed back every frame before it";
    } else if (f == 30) {
      EXPECT_EQ(out.waiting[f], 0) << "an unknown time cuts before and after the frame";
    } else if (f > 30 && f < 38) {
      EXPECT_EQ(out.waiting[f], f - 30);
    } else if (f >= 38) {
      EXPECT_EQ(out.waiting[f], 8);
    }
  }
}

TEST(OfflineSmoother, CountsItsTimeInTheSmoothRowOfTheFrameItHandsBack) {
  std::vector<Poses3D> frames;
  std::vector<double> times;
  std::vector<FrameStats> stats(30);
  for (int f = 0; f < 30; ++f) {
    times.push_back(f * 0.04);
    frames.push_back(Points({Eigen::Vector3d(f * 0.04, 0, 1), Eigen::Vector3d(1, f * f * 0.001, 1)}, {0, 1}));
    stats[f].total_us = 100;
    stats[f].count[static_cast<int>(Step::kTrack)] = 2;
  }
  const Streamed out = Stream(Offline(1), 0.0, frames, times, {}, stats);
  long changed = 0;
  for (int f = 0; f < 30; ++f) {
    SCOPED_TRACE(testing::Message() << "frame " << f);
    EXPECT_EQ(out.stats[f].count[static_cast<int>(Step::kTrack)], 2) << "the frame's own stats";
    EXPECT_GT(out.stats[f].time_us[kSmooth], 0);
    EXPECT_NEAR(out.stats[f].total_us, 100 + out.stats[f].time_us[kSmooth], 1e-9);
    int differing = 0;
    for (int p = 0; p < 2; ++p) differing += out.frames[f].Person(p).col(0) != frames[f].Person(p).col(0);
    EXPECT_EQ(out.stats[f].count[kSmooth], differing) << "count: the joints changed";
    changed += differing;
  }
  EXPECT_GE(changed, 30) << "track 1 accelerates: a line does not fit it";
  // Off (or causal, which runs inside the Triangulator): frames pass straight through, untouched
  // and untimed.
  SmoothOptions causal;
  causal.mode = SmoothMode::kCausal;
  for (const SmoothOptions& options : {SmoothOptions{}, causal}) {
    const Streamed off = Stream(options, 0.0, frames, times, {}, stats);
    for (int f = 0; f < 30; ++f) {
      EXPECT_EQ(off.waiting[f], 0);
      EXPECT_EQ(off.frames[f].data, frames[f].data);
      EXPECT_EQ(off.stats[f].time_us, stats[f].time_us);
      EXPECT_EQ(off.stats[f].count, stats[f].count);
      EXPECT_EQ(off.stats[f].total_us, stats[f].total_us);
    }
  }
}

TEST(OfflineSmoother, IsExactOnLinearMotionWithUnevenTimesAndMissingJoints) {
  for (int degree : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << "degree " << degree);
    std::vector<Poses3D> frames;
    std::vector<double> times;
    auto truth = [](double t) { return Eigen::Vector3d(0.3 + 1.2 * t, -0.5 * t, 1.0 + 0.1 * t); };
    double t = 0;
    for (int f = 0; f < 60; ++f) {
      t += f % 7 == 3 ? 0.08 : 0.04;  // a dropped frame now and then
      times.push_back(t);
      frames.push_back(Points({truth(t)}, {0}));
      if (f % 5 == 2) frames.back().Person(0)(3, 0) = 0;  // joint missing
    }
    const Streamed out = Stream(Offline(degree), 0.0, frames, times);
    long changed = 0;
    for (size_t f = 0; f < frames.size(); ++f) {
      changed += out.stats[f].count[kSmooth];
      if (frames[f].Person(0)(3, 0) <= 0) {
        EXPECT_EQ(out.frames[f].data, frames[f].data) << "missing joints stay as they are";
        continue;
      }
      EXPECT_LT((out.frames[f].Person(0).col(0).head<3>() - truth(times[f])).norm(), 1e-9) << "frame " << f;
    }
    EXPECT_GT(changed, 0);
  }
}

TEST(OfflineSmoother, ReducesNoise) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<Poses3D> frames;
  std::vector<double> times;
  std::vector<Eigen::Vector3d> truth;
  for (int f = 0; f < 500; ++f) {
    const double t = f * 0.04;
    truth.emplace_back(std::sin(t), std::cos(0.7 * t), 1.0);  // smooth curved motion, about 1 m/s
    times.push_back(t);
    frames.push_back(Points({truth.back() + Eigen::Vector3d(noise(rng), noise(rng), noise(rng))}, {0}));
  }
  const Streamed out = Stream(Offline(2), 0.0, frames, times);
  double raw = 0, smooth = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    raw += (frames[f].Person(0).col(0).head<3>() - truth[f]).squaredNorm();
    smooth += (out.frames[f].Person(0).col(0).head<3>() - truth[f]).squaredNorm();
  }
  // sigma 0.1 s at 25 fps: about 6 effective frames for a quadratic fit; the error drops to
  // less than half.
  EXPECT_LT(std::sqrt(smooth / raw), 0.5);
}

TEST(OfflineSmoother, NeverMixesTracksCrossesGapsOrUsesCoastingAndFilledJoints) {
  const double filled = 0.05;
  auto a = [](double t) { return Eigen::Vector3d(t, 0, 1); };        // track 0
  auto b = [](double t) { return Eigen::Vector3d(3, 2 * t, 1); };    // track 1
  auto c = [](double t) { return Eigen::Vector3d(-2, -1, 1 + t); };  // track 0 again after the gap
  std::vector<Poses3D> frames;
  std::vector<double> times;
  std::vector<int> detected;
  for (int f = 0; f < 40; ++f) {
    const double t = f < 20 ? f * 0.04 : 2.0 + f * 0.04;  // a 1.2 s gap before frame 20
    times.push_back(f == 30 ? kNaN : t);
    Eigen::Vector3d first = f < 20 ? a(t) : c(t);
    if (f % 2 == 0) {
      frames.push_back(Points({first, b(t)}, {0, 1}));
    } else {
      frames.push_back(Points({b(t), first}, {1, 0}));  // order within a frame does not matter
    }
    detected.push_back(2);
    if (f >= 10 && f < 13) {
      // A coasting copy of a third track with a wild pose.
      frames.back().AddPerson(7).col(0) << 50, 50, 50, 1;
    }
    if (f == 16) {
      frames.back().Person(0)(3, 0) = filled;  // track 0's joint filled: its position is meaningless
      frames.back().Person(0).col(0).head<3>() << 9, 9, 9;
    }
  }
  const Streamed out = Stream(Offline(2), filled, frames, times, detected);
  for (int f = 0; f < 40; ++f) {
    SCOPED_TRACE(testing::Message() << "frame " << f);
    const double t = times[f];
    for (int p = 0; p < out.frames[f].num_persons(); ++p) {
      const auto got = out.frames[f].Person(p).col(0).head<3>();
      const int id = out.frames[f].track_ids[p];
      if (id == 7 || f == 30 || (f == 16 && id == 0)) {
        EXPECT_EQ(Eigen::Vector4d(out.frames[f].Person(p).col(0)), Eigen::Vector4d(frames[f].Person(p).col(0)))
            << "coasting, unknown time or filled: unchanged";
        continue;
      }
      const Eigen::Vector3d expected = id == 1 ? b(t) : f < 20 ? a(t) : c(t);
      EXPECT_LT((got - expected).norm(), 1e-9) << "track " << id;
    }
  }
}

TEST(OfflineSmoother, ASequenceAfterFlushStartsAfresh) {
  // Two sequences with the same track id and times that would be continuous: Flush keeps them
  // apart (each is smoothed as if alone).
  std::vector<Poses3D> first, second;
  std::vector<double> times;
  for (int f = 0; f < 20; ++f) {
    times.push_back(f * 0.04);
    first.push_back(Points({Eigen::Vector3d(0, f * f * 0.002, 1)}, {0}));
    second.push_back(Points({Eigen::Vector3d(5, -f * f * 0.003, 1)}, {0}));
  }
  const Streamed alone = Stream(Offline(1), 0.0, second, times);
  OfflineSmoother smoother(Offline(1), kMaxGap, 0.0);
  Poses3D persons;
  FrameStats stats;
  for (int f = 0; f < 20; ++f) smoother.Push(times[f] - 1.0, first[f], 1, FrameStats{});
  smoother.Flush();
  int handed_back = 0;
  while (smoother.Pop(&persons, &stats)) ++handed_back;
  EXPECT_EQ(handed_back, 20);
  std::vector<Poses3D> after;
  for (int f = 0; f < 20; ++f) {
    smoother.Push(times[f], second[f], 1, FrameStats{});
    while (smoother.Pop(&persons, &stats)) after.push_back(persons);
  }
  smoother.Flush();
  while (smoother.Pop(&persons, &stats)) after.push_back(persons);
  ASSERT_EQ(after.size(), 20u);
  for (int f = 0; f < 20; ++f) EXPECT_EQ(after[f].data, alone.frames[f].data) << "frame " << f;
}

}  // namespace
}  // namespace rpt

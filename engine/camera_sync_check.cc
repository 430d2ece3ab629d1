// SPDX-License-Identifier: MIT
#include "engine/camera_sync_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Dense>

#include "core/printable_text.h"
#include "core/text.h"

namespace rpt::engine {
namespace {

constexpr int kPartners = 4;  // with more than 2 * kPartners + 1 cameras, each is compared with this many each way

Eigen::Matrix3d Skew(const Eigen::Vector3d& t) {
  Eigen::Matrix3d s;
  s << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  return s;
}

// The median distance of detection q's joints to the epipolar lines `lines` (of detection p's
// joints in the other camera; a line (a, b, c) with a^2 + b^2 = 1, or NaN for a joint p lacks),
// over the joints both have (a median: a joint the detector put on the wrong limb does not
// decide), relative to q's box diagonal `diagonal` and at most kSyncCap; infinity when they share
// fewer than kMinSyncJoints joints. `distances` is scratch space.
double Distance(const std::vector<Eigen::Vector3d>& lines, Eigen::Map<const Eigen::Matrix3Xd> q, double diagonal,
                std::vector<double>* distances) {
  distances->clear();
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    const Eigen::Vector3d& line = lines[static_cast<size_t>(j)];
    if (q(2, j) < kMinSyncScore || std::isnan(line.z())) continue;
    distances->push_back(std::abs(line.x() * q(0, j) + line.y() * q(1, j) + line.z()));
  }
  if (static_cast<int>(distances->size()) < kMinSyncJoints || !(diagonal > 0)) {
    return std::numeric_limits<double>::infinity();
  }
  const auto middle = distances->begin() + static_cast<std::ptrdiff_t>(distances->size() / 2);
  std::nth_element(distances->begin(), middle, distances->end());
  return std::min(kSyncCap, *middle / diagonal);
}

// The diagonal of the box of a detection's joints above kMinSyncScore.
double BoxDiagonal(Eigen::Map<const Eigen::Matrix3Xd> q) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    if (q(2, j) < kMinSyncScore) continue;
    min_x = std::min(min_x, q(0, j)), max_x = std::max(max_x, q(0, j));
    min_y = std::min(min_y, q(1, j)), max_y = std::max(max_y, q(1, j));
  }
  return max_x >= min_x ? std::hypot(max_x - min_x, max_y - min_y) : 0.0;
}

}  // namespace

double CameraPairSync::Mean(int shift) const {
  return count > 0 ? sum[static_cast<size_t>(shift + kMaxSyncShift)] / static_cast<double>(count)
                   : std::numeric_limits<double>::infinity();
}

double CameraPairSync::MeanGain(int shift) const { return Mean(0) - Mean(shift); }

double CameraPairSync::GainVariance(int shift) const {
  if (count < 2) return std::numeric_limits<double>::infinity();
  const double n = static_cast<double>(count);
  const double mean = MeanGain(shift);
  const double variance = (difference_squares[static_cast<size_t>(shift + kMaxSyncShift)] / n - mean * mean) * n / (n - 1);
  return std::max(0.0, variance) / n;
}

namespace {

// Whether `gain` (with the variance of its estimate) over a value `at_zero` at k = 0 is an offset.
bool ClearGain(double gain, double variance, double at_zero) {
  return gain > (1.0 - kMaxSyncRatio) * at_zero && gain > kMinSyncZ * std::sqrt(variance);
}

}  // namespace

int CameraPairSync::Offset() const {
  if (count < kMinSyncPersons) return 0;
  int best = 0;
  for (int k = -kMaxSyncShift; k <= kMaxSyncShift; ++k) best = Mean(k) < Mean(best) ? k : best;
  if (std::abs(best) < kMinSyncOffset) return 0;
  return ClearGain(MeanGain(best), GainVariance(best), Mean(0)) ? best : 0;
}

CameraSyncCheck::CameraSyncCheck(const SequenceHeader& header, long num_frames, double max_gap_s)
    : header_(header), max_gap_s_(max_gap_s), ring_(kSyncShifts) {
  const int n = static_cast<int>(header.cameras.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      // Large rigs: each camera with its kPartners neighbours each way in the calibration's order.
      const int apart = std::min(b - a, n - (b - a));
      if (n > 2 * kPartners + 1 && apart > kPartners) continue;
      const Camera& ca = header.cameras[static_cast<size_t>(a)];
      const Camera& cb = header.cameras[static_cast<size_t>(b)];
      const Eigen::Matrix3d rotation = cb.R * ca.R.transpose();
      const Eigen::Vector3d translation = cb.t - rotation * ca.t;
      essential_.push_back(Skew(translation) * rotation);
      pairs_.push_back({a, b, std::vector<double>(kSyncShifts, 0.0), std::vector<double>(kSyncShifts, 0.0), 0});
    }
  }
  const long centres = std::max(30L, kSyncWork / std::max(1L, static_cast<long>(pairs_.size())));
  // A stream of unknown length (--follow, Python process) starts at every frame; the budget below
  // thins it out as it runs (every 5th frame left a 5-frame lag of a 600-frame stream unseen).
  stride_ = num_frames < 0 ? 1 : std::max(1L, num_frames / centres);
  budget_ = kSyncBudget;
  for (Slot& slot : ring_) slot.views.resize(header.cameras.size());
  distances_.reserve(256);
}

void CameraSyncCheck::Add(const SequenceFrame& frame) {
  const long index = frames_++;
  const bool timed = std::isfinite(frame.timestamp_s);
  const double step = timed && run_ > 0 ? frame.timestamp_s - last_time_s_ : 0;
  if (!timed || frame.views.size() != header_.cameras.size()) {
    run_ = 0;
    return;
  }
  if (run_ > 0 && !(step > 0 && step <= max_gap_s_)) run_ = 0;
  if (run_ > 0) {
    step_sum_s_ += step;
    ++steps_;
  }
  last_time_s_ = frame.timestamp_s;
  ++run_;
  Slot& slot = ring_[static_cast<size_t>(index % kSyncShifts)];
  slot.time_s = frame.timestamp_s;
  slot.normalised = false;
  for (size_t c = 0; c < frame.views.size(); ++c) {
    const Poses2D& view = frame.views[c];
    slot.views[c].Clear(view.num_joints);
    if (!view.unavailable) slot.views[c].data.assign(view.data.begin(), view.data.end());
  }
  const long centre = index - kMaxSyncShift;
  if (run_ < kSyncShifts || centre % stride_ != 0) return;
  Compare(centre);
  // Crowded scenes and large rigs: each time the comparisons reach the budget, half as many frames
  // are compared from then on (the work grows with the log of the sequence's length).
  if (measured_ > budget_) {
    stride_ *= 2;
    budget_ *= 2;
  }
}

// The slot's joints in normalised undistorted coordinates and its detections' box diagonals, once
// (the undistortion is iterative: only the frames a comparison looks at pay for it).
void CameraSyncCheck::Normalise(Slot* slot) {
  if (slot->normalised) return;
  slot->normalised = true;
  slot->diagonals.resize(slot->views.size());
  slot->centres.resize(slot->views.size());
  for (size_t c = 0; c < slot->views.size(); ++c) {
    Poses2D& view = slot->views[c];
    for (size_t i = 0; i + 2 < view.data.size(); i += 3) {
      if (view.data[i + 2] < kMinSyncScore) continue;
      const Eigen::Vector2d xy = header_.cameras[c].PixelToNormalized(Eigen::Vector2d(view.data[i], view.data[i + 1]));
      view.data[i] = xy.x();
      view.data[i + 1] = xy.y();
    }
    slot->diagonals[c].clear();
    slot->centres[c].clear();
    for (int p = 0; p < view.num_persons(); ++p) {
      const auto person = std::as_const(view).Person(p);
      slot->diagonals[c].push_back(BoxDiagonal(person));
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      int used = 0;
      for (Eigen::Index j = 0; j < person.cols(); ++j) {
        if (person(2, j) < kMinSyncScore) continue;
        sum += person.col(j).head<2>();
        ++used;
      }
      slot->centres[c].push_back(used > 0 ? Eigen::Vector2d(sum / used)
                                          : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
    }
  }
}

void CameraSyncCheck::Compare(long centre) {
  for (int k = -kMaxSyncShift; k <= kMaxSyncShift; ++k) Normalise(&ring_[static_cast<size_t>((centre + k) % kSyncShifts)]);
  const Slot& middle = ring_[static_cast<size_t>(centre % kSyncShifts)];
  std::array<double, kSyncShifts> best{}, second{};
  for (size_t i = 0; i < pairs_.size(); ++i) {
    CameraPairSync& pair = pairs_[i];
    const Poses2D& from = middle.views[static_cast<size_t>(pair.a)];
    for (int p = 0; p < from.num_persons(); ++p) {
      // The epipolar lines of p's joints in camera b, normalised so that a point's distance is a dot product.
      const auto person = from.Person(p);
      lines_.resize(static_cast<size_t>(person.cols()));
      for (Eigen::Index j = 0; j < person.cols(); ++j) {
        Eigen::Vector3d line = essential_[i] * Eigen::Vector3d(person(0, j), person(1, j), 1.0);
        const double norm = std::hypot(line.x(), line.y());
        if (person(2, j) < kMinSyncScore || !(norm > 0)) line.z() = std::numeric_limits<double>::quiet_NaN();
        lines_[static_cast<size_t>(j)] = line / norm;
      }
      // Per shift, the nearest of b's detections (another person may be nearest at some shifts:
      // the one p is would have to be nearer still). The centre of p's joints gives a line its
      // detections' centres must come near: detections farther than kSyncCap box diagonals from it
      // count as kSyncCap without measuring each joint.
      const Eigen::Vector2d& p_centre = middle.centres[static_cast<size_t>(pair.a)][static_cast<size_t>(p)];
      Eigen::Vector3d centre_line = essential_[i] * Eigen::Vector3d(p_centre.x(), p_centre.y(), 1.0);
      centre_line /= std::hypot(centre_line.x(), centre_line.y());
      bool complete = std::isfinite(centre_line.z());
      int closest = 0;
      for (int k = -kMaxSyncShift; k <= kMaxSyncShift && complete; ++k) {
        const size_t at = static_cast<size_t>(k + kMaxSyncShift);
        const Slot& slot = ring_[static_cast<size_t>((centre + k) % kSyncShifts)];
        const Poses2D& to = slot.views[static_cast<size_t>(pair.b)];
        const std::vector<double>& diagonals = slot.diagonals[static_cast<size_t>(pair.b)];
        const std::vector<Eigen::Vector2d>& centres = slot.centres[static_cast<size_t>(pair.b)];
        best[at] = second[at] = std::numeric_limits<double>::infinity();
        for (int q = 0; q < to.num_persons(); ++q) {
          const Eigen::Vector2d& c = centres[static_cast<size_t>(q)];
          const double far = std::abs(centre_line.x() * c.x() + centre_line.y() * c.y() + centre_line.z());
          ++measured_;
          const double d = far > kSyncCap * diagonals[static_cast<size_t>(q)]
                               ? kSyncCap
                               : Distance(lines_, to.Person(q), diagonals[static_cast<size_t>(q)], &distances_);
          if (d < best[at]) {
            second[at] = best[at];
            best[at] = d;
          } else {
            second[at] = std::min(second[at], d);
          }
        }
        complete = std::isfinite(best[at]);
        if (complete && best[at] < best[static_cast<size_t>(closest + kMaxSyncShift)]) closest = k;
      }
      // The same person at every shift (paired), and only where its match is clear at its best
      // shift: another person near the epipolar lines too (they constrain one direction only)
      // would flatten the curve.
      if (complete && second[static_cast<size_t>(closest + kMaxSyncShift)] <
                          kSyncAmbiguity * best[static_cast<size_t>(closest + kMaxSyncShift)]) {
        continue;
      }
      if (!complete) continue;
      for (size_t s = 0; s < kSyncShifts; ++s) {
        pair.sum[s] += best[s];
        const double gain = best[static_cast<size_t>(kMaxSyncShift)] - best[s];
        pair.difference_squares[s] += gain * gain;
      }
      ++pair.count;
    }
  }
}

std::vector<std::string> CameraSyncWarnings(const std::string& sequence, const std::vector<Camera>& cameras,
                                            const std::vector<CameraPairSync>& pairs, double frame_step_s) {
  const auto frames_text = [frame_step_s](int frames) {
    std::string text = std::to_string(std::abs(frames)) + " frame" + (std::abs(frames) == 1 ? "" : "s");
    if (frame_step_s > 0) text += " (" + FixedText(std::abs(frames) * frame_step_s, 2) + " s)";
    return text;
  };
  std::vector<std::string> lines;
  if (cameras.size() == 2) {
    if (pairs.size() != 1) return lines;
    const int offset = pairs[0].Offset();
    if (offset == 0) return lines;
    lines.push_back(PrintableText(
        sequence + ", cameras " + QuoteName(cameras[0].name) + " and " + QuoteName(cameras[1].name) + ": the detections of " +
        QuoteName(cameras[1].name) + " agree best with those of " + QuoteName(cameras[0].name) + " " +
        frames_text(offset) + (offset > 0 ? " earlier" : " later") + " (their epipolar distance " +
        FixedText(pairs[0].Mean(offset), 3) + " of a person's size there, " + FixedText(pairs[0].Mean(0), 3) +
        " in the same frame): are the two cameras' clocks or frame numbers that far apart? The 3D persons are "
        "off by the motion in between"));
    return lines;
  }
  // More cameras: per camera, its pairs' means summed with the shift as "this camera later by k"
  // (usable pairs only, at least two); the camera whose sum falls most below its value at k = 0 is
  // named when that is an offset, its pairs are set aside (they would make each other camera look
  // off by the same shift), and the rest looked at again.
  std::vector<bool> set_aside(pairs.size(), false), named(cameras.size(), false);
  while (true) {
    int worst = -1, worst_offset = 0;
    double worst_ratio = kMaxSyncRatio;
    long worst_pairs = 0;
    for (size_t c = 0; c < cameras.size(); ++c) {
      if (named[c]) continue;
      std::array<double, kSyncShifts> sum{}, variance{};  // of the pairs' means, and of their gains
      long used = 0;
      for (size_t i = 0; i < pairs.size(); ++i) {
        const CameraPairSync& pair = pairs[i];
        if (set_aside[i] || (pair.a != static_cast<int>(c) && pair.b != static_cast<int>(c))) continue;
        if (pair.count < kMinSyncPersons) continue;
        ++used;
        for (int k = -kMaxSyncShift; k <= kMaxSyncShift; ++k) {
          const int shift = pair.b == static_cast<int>(c) ? k : -k;
          sum[static_cast<size_t>(k + kMaxSyncShift)] += pair.Mean(shift);
          variance[static_cast<size_t>(k + kMaxSyncShift)] += pair.GainVariance(shift);
        }
      }
      if (used < 2) continue;
      int best = 0;
      for (int k = -kMaxSyncShift; k <= kMaxSyncShift; ++k) {
        if (sum[static_cast<size_t>(k + kMaxSyncShift)] < sum[static_cast<size_t>(best + kMaxSyncShift)]) best = k;
      }
      const size_t at = static_cast<size_t>(best + kMaxSyncShift);
      const double ratio = sum[at] / sum[static_cast<size_t>(kMaxSyncShift)];
      if (std::abs(best) >= kMinSyncOffset && ratio < worst_ratio &&
          ClearGain(sum[static_cast<size_t>(kMaxSyncShift)] - sum[at], variance[at], sum[static_cast<size_t>(kMaxSyncShift)])) {
        worst = static_cast<int>(c), worst_offset = best, worst_ratio = ratio, worst_pairs = used;
      }
    }
    if (worst < 0) break;
    named[static_cast<size_t>(worst)] = true;
    for (size_t i = 0; i < pairs.size(); ++i) set_aside[i] = set_aside[i] || pairs[i].a == worst || pairs[i].b == worst;
    lines.push_back(PrintableText(
        sequence + ", camera " + QuoteName(cameras[static_cast<size_t>(worst)].name) +
        ": its detections agree best with the other cameras' of about " + frames_text(worst_offset) +
        (worst_offset > 0 ? " earlier" : " later") + " (epipolar distance to " + std::to_string(worst_pairs) +
        " cameras " + FixedText(100.0 * (1.0 - worst_ratio), 0) +
        " % below that in the same frame): is its clock or frame numbering " + frames_text(worst_offset) +
        (worst_offset > 0 ? " late" : " early") + "? The 3D persons are off by the motion in between"));
  }
  return lines;
}

}  // namespace rpt::engine

// SPDX-License-Identifier: MIT
#include "core/pipeline/refine.h"

#include <algorithm>

#include "core/pipeline/simd_kernels.h"

namespace rpt {
namespace {

// Rays at less than about half a degree from each other (two rays: det / (trace / 3)^3 = 0.84
// sin^2 of their angle) do not fix a point in depth.
constexpr double kMinConditioning = 1e-4;

// The normal equations of one joint, A x = b with A symmetric (a00 .. a22), and the views used:
// simd::kRefineSums arrays of n, in this order.
enum Sum { kA00, kA01, kA02, kA11, kA12, kA22, kB0, kB1, kB2, kUsed, kSums };
static_assert(kSums == simd::kRefineSums);

// simd::RefinePrepareView's reference.
void PrepareViewScalar(const double* rx, const double* ry, const double* rz, const double* confidence,
                       const double* person_score, double min_score, double cx, double cy, double cz, int n,
                       double* weight, double* inv_norm_sq, double* origin_dot) {
  for (int j = 0; j < n; ++j) {
    const bool usable = weight[j] >= min_score && confidence[j] > 0 && person_score[j] > 0;
    const double norm_sq = rx[j] * rx[j] + ry[j] * ry[j] + rz[j] * rz[j];
    inv_norm_sq[j] = usable && norm_sq > 0 ? 1.0 / norm_sq : 0.0;
    weight[j] = inv_norm_sq[j] > 0 ? confidence[j] : 0.0;
    origin_dot[j] = rx[j] * cx + ry[j] * cy + rz[j] * cz;
  }
}

// simd::RefineAccumulate's reference: the same operations in the same order, joint by joint.
void AccumulateScalar(const simd::RefineParams& p, const simd::RefineView& view, const double* x, const double* y,
                      const double* z, int n, double* sums) {
  double* a00 = sums + kA00 * n;
  double* a01 = sums + kA01 * n;
  double* a02 = sums + kA02 * n;
  double* a11 = sums + kA11 * n;
  double* a12 = sums + kA12 * n;
  double* a22 = sums + kA22 * n;
  double* b0 = sums + kB0 * n;
  double* b1 = sums + kB1 * n;
  double* b2 = sums + kB2 * n;
  double* used = sums + kUsed * n;
  for (int j = 0; j < n; ++j) {
    const double rx = view.rx[j], ry = view.ry[j], rz = view.rz[j];
    const double tx = x[j] - view.cx, ty = y[j] - view.cy, tz = z[j] - view.cz;
    const double along = rx * tx + ry * ty + rz * tz;
    const double distance_sq = tx * tx + ty * ty + tz * tz - along * along * view.inv_norm_sq[j];
    const double robust = view.weight[j] / (1.0 + distance_sq * p.inv_scale_sq);
    const double w = distance_sq <= p.cutoff_sq ? robust : 0.0;
    const double u = w * view.inv_norm_sq[j];  // w times the ray's outer product over |ray|^2
    const double urx = u * rx, ury = u * ry, urz = u * rz;
    a00[j] += w - urx * rx;
    a01[j] -= urx * ry;
    a02[j] -= urx * rz;
    a11[j] += w - ury * ry;
    a12[j] -= ury * rz;
    a22[j] += w - urz * rz;
    b0[j] += w * view.cx - urx * view.origin_dot[j];
    b1[j] += w * view.cy - ury * view.origin_dot[j];
    b2[j] += w * view.cz - urz * view.origin_dot[j];
    used[j] += w > 0 ? 1.0 : 0.0;
  }
}

// simd::RefineSolve's reference: A^-1 b by cofactors where the joint is fixed.
void SolveScalar(const double* sums, int n, double min_conditioning, double* x, double* y, double* z, double* changed) {
  for (int j = 0; j < n; ++j) {
    auto at = [&](int k) { return sums[static_cast<size_t>(k) * n + j]; };
    const double a00 = at(kA00), a01 = at(kA01), a02 = at(kA02), a11 = at(kA11), a12 = at(kA12), a22 = at(kA22);
    const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
    const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
    const double det = a00 * c00 + a01 * c01 + a02 * c02;
    const double third = (a00 + a11 + a22) / 3.0;
    if (!(at(kUsed) >= 2 && det > min_conditioning * third * third * third)) continue;
    const double b0 = at(kB0), b1 = at(kB1), b2 = at(kB2);
    const double inv_det = 1.0 / det;
    x[j] = (c00 * b0 + c01 * b1 + c02 * b2) * inv_det;
    y[j] = (c01 * b0 + c11 * b1 + c12 * b2) * inv_det;
    z[j] = (c02 * b0 + c12 * b1 + c22 * b2) * inv_det;
    changed[j] = 1.0;
  }
}

// options.one_view_joints for person p (refine.h): returns the joints placed.
int PlaceOneViewJoints(const steps::RefineInput& in, std::span<const int> poses, int p, Poses3D* persons) {
  const KeypointColumns& columns = in.views.all_columns;
  const int n = persons->num_joints;
  auto person = persons->Person(p);
  const std::span<uint8_t> provenance = persons->PersonProvenance(p);
  const auto triangulated = static_cast<uint8_t>(JointProvenance::kTriangulated);
  int placed = 0;
  for (int j = 0; j < n; ++j) {
    const int nb = in.neighbour[j];
    if (person(3, j) > 0 || nb < 0 || !(person(3, nb) > 0) || provenance[nb] != triangulated) continue;
    int seen = 0;
    size_t at = 0;
    for (const int pose : poses) {
      const size_t k = static_cast<size_t>(pose) * n + j;
      if (!(columns.score[k] > 0)) continue;
      ++seen;
      at = k;
    }
    if (seen != 1) continue;  // none, or views that disagree (no pair kept it)
    const Eigen::Vector3d ray(columns.rx[at], columns.ry[at], columns.rz[at]);
    const Eigen::Vector3d& center = in.geometry[in.views.view_of[at / n]].center;
    const double t = ray.dot(person.col(nb).head<3>() - center) / ray.squaredNorm();
    if (!(t > 0)) continue;
    person.col(j).head<3>() = center + t * ray;
    person(3, j) = 0.5 * columns.score[at];
    provenance[j] = static_cast<uint8_t>(JointProvenance::kLifted);
    ++placed;
  }
  return placed;
}

}  // namespace

int steps::Refine(const RefineOptions& options, const RefineInput& in, RefineScratch* scratch, Poses3D* persons,
                  FrameStats* stats) {
  if (!options.enabled) return 0;
  const Proposals& proposals = in.proposals;
  const Groups& groups = in.groups;
  const KeypointColumns& columns = in.views.all_columns;
  const int n = proposals.num_joints;
  // Person i was merged from group i, over the prepared poses' joints (their columns).
  if (groups.size() != persons->num_persons() || n != persons->num_joints || columns.stride != n) return 0;
  static_assert(simd::kRefineAlign <= KeypointColumns::kSlack + 1, "reads past a pose stay in the columns");
  const double scale = options.scale_factor * in.kernel.scale_m;
  if (!(scale > 0)) return 0;
  const simd::RefineParams params{.inv_scale_sq = 1.0 / (scale * scale),
                                  .cutoff_sq = options.cutoff * options.cutoff * scale * scale};
  const bool use_simd = simd::Enabled();
  const double min_score = std::max(in.min_joint_score, 1e-300);  // as the merge: score 0 = invalid
  // Every per-joint array holds `padded` values, the joints beyond n zero (no view, no change).
  const int padded = (n + simd::kRefineAlign - 1) / simd::kRefineAlign * simd::kRefineAlign;
  const size_t row = static_cast<size_t>(padded);
  // The columns end in their slack (undistort sizes them with KeypointColumns::Resize).
  if (columns.rx.size() < static_cast<size_t>(in.views.num_poses()) * n + (padded - n)) return 0;
  RefineScratch& s = *scratch;
  s.x.assign(row, 0.0);
  s.y.assign(row, 0.0);
  s.z.assign(row, 0.0);
  s.person_score.assign(row, 0.0);
  s.changed.resize(row);
  s.sums.resize(kSums * row);
  int moved = 0;
  for (int p = 0; p < persons->num_persons(); ++p) {
    const int first = groups.begin[p], last = groups.begin[p + 1];
    s.poses.clear();
    for (int k = first; k < last; ++k)
      for (const int pose : {proposals.pairs[k].a, proposals.pairs[k].b})
        if (std::find(s.poses.begin(), s.poses.end(), pose) == s.poses.end()) s.poses.push_back(pose);
    const int num_poses = static_cast<int>(s.poses.size());
    // Per pose and joint the best joint score of its pairs (in `weight` until the preparation
    // below turns it into the weight; padded with zeros: the joints beyond n are never usable).
    s.weight.assign(num_poses * row, 0.0);
    s.inv_norm_sq.resize(num_poses * row);
    s.origin_dot.resize(num_poses * row);
    for (int k = first; k < last; ++k) {
      const double* score = proposals.score.data() + static_cast<size_t>(k) * n;
      for (const int pose : {proposals.pairs[k].a, proposals.pairs[k].b}) {
        const size_t q = std::find(s.poses.begin(), s.poses.end(), pose) - s.poses.begin();
        double* best = s.weight.data() + q * row;
        if (use_simd) {
          simd::RefineBestScore(score, n, best);
        } else {
          for (int j = 0; j < n; ++j) best[j] = std::max(best[j], score[j]);
        }
      }
    }
    auto person = persons->Person(p);
    for (int j = 0; j < n; ++j) s.person_score[j] = person(3, j);
    // The kernels read each pose's columns in place, `padded` values from its first joint: past
    // its last joint they read the next pose's or the columns' slack (KeypointColumns::kSlack),
    // which lanes of weight 0 ignore.
    for (int q = 0; q < num_poses; ++q) {
      const size_t at = static_cast<size_t>(s.poses[q]) * n;
      const Eigen::Vector3d& c = in.geometry[in.views.view_of[s.poses[q]]].center;
      (use_simd ? simd::RefinePrepareView : PrepareViewScalar)(
          columns.rx.data() + at, columns.ry.data() + at, columns.rz.data() + at, columns.score.data() + at,
          s.person_score.data(), min_score, c.x(), c.y(), c.z(), padded, s.weight.data() + q * row,
          s.inv_norm_sq.data() + q * row, s.origin_dot.data() + q * row);
    }
    for (int j = 0; j < n; ++j) {
      s.x[j] = person(0, j);
      s.y[j] = person(1, j);
      s.z[j] = person(2, j);
    }
    std::fill(s.changed.begin(), s.changed.end(), 0.0);
    for (int it = 0; it < options.iterations; ++it) {
      std::fill(s.sums.begin(), s.sums.end(), 0.0);
      for (int q = 0; q < num_poses; ++q) {
        const size_t at = static_cast<size_t>(s.poses[q]) * n;
        const Eigen::Vector3d& c = in.geometry[in.views.view_of[s.poses[q]]].center;
        const simd::RefineView view{.rx = columns.rx.data() + at,
                                    .ry = columns.ry.data() + at,
                                    .rz = columns.rz.data() + at,
                                    .weight = s.weight.data() + q * row,
                                    .inv_norm_sq = s.inv_norm_sq.data() + q * row,
                                    .origin_dot = s.origin_dot.data() + q * row,
                                    .cx = c.x(),
                                    .cy = c.y(),
                                    .cz = c.z()};
        (use_simd ? simd::RefineAccumulate : AccumulateScalar)(params, view, s.x.data(), s.y.data(), s.z.data(),
                                                               padded, s.sums.data());
      }
      (use_simd ? simd::RefineSolve : SolveScalar)(s.sums.data(), padded, kMinConditioning, s.x.data(), s.y.data(),
                                                   s.z.data(), s.changed.data());
    }
    for (int j = 0; j < n; ++j) {
      if (s.changed[j] == 0) continue;
      person(0, j) = s.x[j];
      person(1, j) = s.y[j];
      person(2, j) = s.z[j];
      ++moved;
    }
    if (options.one_view_joints && static_cast<int>(in.neighbour.size()) == n &&
        !persons->PersonProvenance(p).empty()) {
      stats->one_view_joints += PlaceOneViewJoints(in, s.poses, p, persons);
    }
  }
  return moved;
}

}  // namespace rpt

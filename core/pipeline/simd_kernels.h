// SPDX-License-Identifier: MIT
// SIMD kernels of the hot steps, one lane per joint: the undistortion of a pinhole camera's pose
// (before step 1), mid-point triangulation of a pose pair
// (steps 4 and 10), its reprojection residuals, their median and joint scores (steps 6-7 and 10), the pre-filter's
// pixel distance (step 2), the merge of a group (step 11), the multi-view refinement (step 11a),
// and, one lane per limb, limb pruning's length test. (The group step's distance stays scalar:
// docs/algorithm.md.)
// Structure of arrays in (KeypointColumns, pipeline_types.h), the steps' own arrays out.
//
// Each kernel is compiled for several instruction sets (Highway, simd_kernels.cc, private to
// core) and the best one the CPU has is chosen at run time: the default build stays portable.
// The kernels compute every joint independently with the same double-precision operations in the
// same order as the scalar code they replace (no fused multiply-add: the file is compiled with
// -ffp-contract=off; sums over joints are added in joint order), so every instruction set gives
// bit-identical results: a frame's output does not depend on the machine. The scalar reference stays in proposal_scoring.h, pair_triangulation.h
// and fast_math.h, and the tests compare the two on random inputs for every instruction set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/pipeline/pipeline_types.h"

namespace rpt::simd {

// One pose's joints as columns (pointers into KeypointColumns).
struct PoseColumns {
  const double* u;
  const double* v;
  const double* score;  // <= 0: missing
  const double* rx;
  const double* ry;
  const double* rz;  // world ray direction (unnormalised)
};

// Pose g's columns.
inline PoseColumns ColumnsOf(const KeypointColumns& c, int g) {
  const size_t at = static_cast<size_t>(g) * c.stride;
  return {c.u.data() + at, c.v.data() + at, c.score.data() + at, c.rx.data() + at, c.ry.data() + at, c.rz.data() + at};
}

// Mid-point triangulation (TriangulateMidpoint) of joints [0, n) of poses a and b, seen from the
// camera centres ca and cb (3 values each). Writes xyz (n points, x y z interleaved: the layout
// of Eigen::Vector3d), gap (-1 where not triangulated) and score (1 triangulated, 0 not).
void TriangulatePair(const double* ca, const PoseColumns& a, const double* cb, const PoseColumns& b, int n,
                     double* xyz, double* gap, double* score);

// The two views of a pair for the residual (JointResidual): their 3x4 projections (column-major,
// Eigen's layout) and the residual's scale per view.
struct ResidualViews {
  const double* Pa;
  const double* Pb;
  double scale_a;
  double scale_b;
  bool adaptive;
};

// Pass 1 of the adaptive score step: residual[i] = -1 where score[i] <= 0 or geometric[i] >= 0;
// else 0 without the reprojection term, 1e6 where gap[i] > skip_gap, else JointResidual.
void PairResiduals(const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, int n, const double* xyz,
                   const double* gap, const double* score, const double* geometric, bool use_reprojection,
                   double skip_gap, double* residual);

// The kernels of ScoreKernel (proposal_scoring.h) that the joint scores need.
struct JointKernel {
  bool use_reprojection;
  bool use_ray_gap;
  double inv_residual;
  double inv_ray_gap;
};

// The geometric joint scores of ScoreJointsOfProposal before limb pruning: where score[i] > 0,
// score[i] = geometric[i] if geometric[i] >= 0 (scored earlier), else both = exp(-exponent).
// `residual` may be null (computed here).
void ScoreJoints(const JointKernel& kernel, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b,
                 int n, const double* xyz, const double* gap, const double* residual, double* score,
                 double* geometric);

// For each of `persons` rows of n points (uv: u v interleaved, as Eigen::Vector2d, row after row):
// sums[q] = the sum over joints i in [0, n) with c.score[i] > 0 and uv_i seen (x not NaN) of the
// pixel distance |uv_i - (c.u[i], c.v[i])|, added in joint order; counts[q] = the number of such
// joints. The pre-filter's distances of a pose from the previous persons, in one call.
void PixelDistanceSums(const double* uv, int persons, const PoseColumns& c, int n, double* sums, int* counts);

// steps::Merge of one group (merge.h) over joints [0, n), lanes across joints: the group's `members`
// proposals start at xyz (x y z interleaved, n points per proposal) and score (n per proposal).
// Writes the person, x y z score per joint (4 x n, column-major). `dist` is scratch of
// MergeScratchSize(members) doubles. Only for top_k <= 8 (larger: nth_element,
// whose order the kernel does not reproduce).
struct MergeParams {
  double min_score;       // max(merge.min_joint_score, 1e-300)
  double max_distance_m;  // <= 0: no distance filter
  double max_distance_sq;
  int top_k;              // 0: keep all
  bool score_weighted;
  bool keep_best;         // keep_best_when_all_far
};
size_t MergeScratchSize(int members);
void MergeGroup(const MergeParams& p, const double* xyz, const double* score, int members, int n, double* dist,
                double* out);

// The undistort step's keypoints of one pose seen by a pinhole camera (no distortion), lanes across
// joints: joints [0, n) of `uvs` (u v score per joint, interleaved as Poses2D stores them) into the
// arrays of `out`, one per field of Keypoint (pipeline_types.h), n values each. A joint with
// score < min_score or a non-finite number gets all fields 0 (Keypoint{}); a score above 1 is
// taken as 1.
struct PinholeView {
  double fx, fy, cx, cy, skew;
  const double* R_t;  // camera -> world directions, 3x3 column-major (Eigen's layout)
  double min_score;
};
struct KeypointFields {
  double *u, *v, *score, *sqrt_score, *rx, *ry, *rz, *x, *y;
};
// box: the minimum u, minimum v, maximum u and maximum v of the joints written with a score above 0
// (1e300, 1e300, -1e300, -1e300 when none), as std::min / std::max in joint order give them.
void UndistortPinhole(const PinholeView& view, const double* uvs, int n, const KeypointFields& out, double* box);

// Pass 1 of limb pruning (PruneImplausibleLimbs, proposal_scoring.h), lanes across limbs: bit
// l - begin of the result is set where limb l in [begin, end) (at most 64 limbs) has both joints
// scored (score > 0) and a squared length ((dx^2 + dy^2) + dz^2 of xyz, x y z interleaved)
// below min_sq or above max_sq.
uint64_t ImplausibleLimbs(const LimbColumns& limbs, size_t begin, size_t end, const double* xyz, const double* score);

// RankMedianScalar (median.h) of values[0..n), n in [1, kRankMedianMax], with the same comparisons
// (the median of a pair's joint residuals in the score step): bit-identical, NaN included.
inline constexpr int kRankMedianMax = 32;
double RankMedian(const double* values, int n);

// The kernels of steps::Refine (refine.h) run over whole vectors: their n is a multiple of
// kRefineAlign (a multiple of the lane count of every instruction set compiled: 8 doubles with
// AVX-512) and their arrays are padded.
inline constexpr int kRefineAlign = 8;
// One reweighting pass of steps::Refine for one view of a person, lanes across joints:
// for every joint j in [0, n) adds the view's ray to the joint's normal equations at the current
// point (x, y, z)[j]. sums holds kRefineSums arrays of n: a00 a01 a02 a11 a12 a22 (the symmetric
// matrix), b0 b1 b2, and the count of views used. A view with weight 0 adds nothing.
inline constexpr int kRefineSums = 10;
struct RefineParams {
  double inv_scale_sq;  // 1 / s^2
  double cutoff_sq;     // (cutoff x s)^2
};
struct RefineView {
  const double* rx;
  const double* ry;
  const double* rz;           // the view's rays (unnormalised)
  const double* weight;       // 2D confidence where usable, else 0
  const double* inv_norm_sq;  // 1 / |ray|^2 (0 where weight is 0)
  const double* origin_dot;   // ray . camera centre
  double cx, cy, cz;          // camera centre
};
// best[j] = (best[j] < score[j] ? score[j] : best[j]) for j in [0, n) (std::max, NaN included):
// the best joint score of a pose's pairs. Any n (a partial last vector runs lane by lane).
void RefineBestScore(const double* score, int n, double* best);
// Before the passes, per view of the person: where the joint is usable (best >= min_score: a pair
// the merge could use has it; confidence > 0; person_score > 0: the merged joint exists; a ray of
// nonzero length) inv_norm_sq = 1 / |ray|^2 and weight = confidence, else both 0; origin_dot =
// ray . camera centre. `weight` holds `best` on entry (RefineView's arrays, written here).
void RefinePrepareView(const double* rx, const double* ry, const double* rz, const double* confidence,
                       const double* person_score, double min_score, double cx, double cy, double cz, int n,
                       double* weight, double* inv_norm_sq, double* origin_dot);
void RefineAccumulate(const RefineParams& p, const RefineView& view, const double* x, const double* y, const double* z,
                      int n, double* sums);
// Then the solve of every joint: where at least 2 views were used and the matrix is well
// conditioned (det > min_conditioning x (trace / 3)^3), (x, y, z)[j] = A^-1 b and changed[j] = 1.
void RefineSolve(const double* sums, int n, double min_conditioning, double* x, double* y, double* z,
                 double* changed);

// Whether the steps use these kernels (the default) or their scalar code: for comparisons and tests.
// The environment variable RPT_SIMD=off starts a process with the scalar code; RPT_SIMD=<name>
// (scalar, SSE4, AVX2, AVX-512) restricts the kernels to that instruction set.
bool Enabled();
void SetEnabled(bool on);

// The instruction set the kernels run on, e.g. "AVX2" ("AVX-512" for Highway's AVX3, "scalar"
// for its portable fallback).
std::string ActivePath();

// Runs `body` once for every instruction set compiled in and supported by this CPU, with the
// kernels restricted to it (ActivePath() names it), then restores the automatic choice. For tests.
void ForEachPathForTest(const std::function<void()>& body);

}  // namespace rpt::simd

// SPDX-License-Identifier: MIT
// The kernels of simd_kernels.h, written once with Highway and compiled for each instruction set
// below (foreach_target.h re-includes this file per target); HWY_DYNAMIC_DISPATCH picks the best
// one the CPU supports. Every lane is computed with the scalar code's operations in its order
// (see the header), so each target gives the scalar result bit for bit.

// Targets: the portable fallback (EMU128), SSE4, AVX2 and AVX-512 (AVX3). SSSE3 and the newer
// AVX-512 variants add compile time for no gain on double-precision kernels.
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SSSE3 | HWY_AVX3_DL)
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "core/pipeline/simd_kernels.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "core/pipeline/simd_kernels.h"

#include <algorithm>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace rpt::simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The last, partial vector of joints runs as a full vector over copies: `Tail` copies r < N
// values of each input to lanes [0, r) of a buffer (the other lanes 0: a missing joint) and the
// outputs' lanes [0, r) back. Lanes are independent, so the padding changes no result.
template <size_t kMax>
struct Tail {
  explicit Tail(size_t rest) : r(rest) {}
  size_t r;
  double in[16][kMax];
  double out[4][3 * kMax];
  int used_in = 0, used_out = 0;

  const double* In(const double* p, size_t scale = 1) {
    double* b = in[used_in++];
    for (size_t k = 0; k < kMax; ++k) b[k] = 0.0;
    if (p != nullptr) std::copy(p, p + scale * r, b);
    return p != nullptr ? b : nullptr;
  }
  const double* In3(const double* p) {  // x y z interleaved: three rows of `in`
    double* b = in[used_in];
    used_in += 3;
    for (size_t k = 0; k < 3 * kMax; ++k) b[k] = 0.0;
    std::copy(p, p + 3 * r, b);
    return b;
  }
  double* Out() { return out[used_out++]; }
  void Back(const double* b, double* p, size_t scale = 1) { std::copy(b, b + scale * r, p); }
};

PoseColumns TailColumns(Tail<HWY_MAX_BYTES / 8>& t, const PoseColumns& c, size_t i, bool uv, bool rays) {
  PoseColumns out{};
  out.score = t.In(c.score + i);
  if (uv) {
    out.u = t.In(c.u + i);
    out.v = t.In(c.v + i);
  }
  if (rays) {
    out.rx = t.In(c.rx + i);
    out.ry = t.In(c.ry + i);
    out.rz = t.In(c.rz + i);
  }
  return out;
}

// exp(-x), FastExpNeg (fast_math.h) lane by lane.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ExpNeg(D d, V x) {
  const hn::RebindToSigned<D> di;
  const auto in_range = hn::Lt(x, hn::Set(d, 700.0));  // false for NaN too
  const V t = hn::Mul(hn::Neg(x), hn::Set(d, 1.4426950408889634));
  // Round to nearest, ties to even (std::nearbyint in the default rounding mode) by adding 1.5 * 2^52:
  // the sum's low mantissa bits hold n as an integer, which saves the double -> int64 conversion
  // that AVX2 lacks (valid for |t| < 2^51; in range |t| < 1010).
  const V magic = hn::Set(d, 6755399441055744.0);
  const V shifted = hn::Add(t, magic);
  const V n = hn::Sub(shifted, magic);
  const V f = hn::Sub(t, n);
  const V l = hn::Mul(hn::Set(d, 0.6931471805599453), f);
  V p = hn::Set(d, 1.0 / 5040);
  p = hn::Add(hn::Set(d, 1.0 / 720), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 1.0 / 120), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 1.0 / 24), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 1.0 / 6), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 0.5), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 1.0), hn::Mul(l, p));
  p = hn::Add(hn::Set(d, 1.0), hn::Mul(l, p));
  // 2^n from the integer bits: (n + 1023) << 52, the sum's upper bits shifted out. For x < 700,
  // n >= -1010, so n + 1023 >= 13 (FastExpNeg's test for a non-positive exponent never fires);
  // lanes out of range give 0.
  const auto exponent = hn::Add(hn::BitCast(di, shifted), hn::Set(di, int64_t{1023}));
  const V scale = hn::BitCast(d, hn::ShiftLeft<52>(exponent));
  return hn::IfThenElseZero(in_range, hn::Mul(p, scale));
}

// ReprojectionError (proposal_scoring.h) of (x, y, z) against (u, v) in the view of projection P
// (column-major 3x4), and the depth, lane by lane; `times_depth` as there (the error times the
// depth, without a division); behind the camera the caller discards the lane. The sums follow
// Eigen's evaluation of P.leftCols<3>() * point in the scalar code (SSE2 baseline): rows 0-1 as
// one packet, column by column ((a + b) + c), row 2 as an unrolled reduction (a + (b + c)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V ReprojectionError(D d, const double* P, V x, V y, V z, V u, V v, bool times_depth, V* depth) {
  const V hx = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(d, P[0]), x), hn::Mul(hn::Set(d, P[3]), y)),
                               hn::Mul(hn::Set(d, P[6]), z)),
                       hn::Set(d, P[9]));
  const V hy = hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(d, P[1]), x), hn::Mul(hn::Set(d, P[4]), y)),
                               hn::Mul(hn::Set(d, P[7]), z)),
                       hn::Set(d, P[10]));
  const V hz = hn::Add(hn::Add(hn::Mul(hn::Set(d, P[2]), x),
                               hn::Add(hn::Mul(hn::Set(d, P[5]), y), hn::Mul(hn::Set(d, P[8]), z))),
                       hn::Set(d, P[11]));
  *depth = hz;
  V du, dv;
  if (times_depth) {
    du = hn::Sub(hx, hn::Mul(u, hz));
    dv = hn::Sub(hy, hn::Mul(v, hz));
  } else {
    const V inv_z = hn::Div(hn::Set(d, 1.0), hz);
    du = hn::Sub(hn::Mul(hx, inv_z), u);
    dv = hn::Sub(hn::Mul(hy, inv_z), v);
  }
  return hn::Sqrt(hn::Add(hn::Mul(du, du), hn::Mul(dv, dv)));
}

// JointResidual (proposal_scoring.h) of joints [i, i + Lanes(d)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Residual(D d, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, const double* xyz,
                      size_t i) {
  V x, y, z;
  hn::LoadInterleaved3(d, xyz + 3 * i, x, y, z);
  V za, zb;
  const V ea = ReprojectionError(d, rv.Pa, x, y, z, hn::LoadU(d, a.u + i), hn::LoadU(d, a.v + i), rv.adaptive, &za);
  const V eb = ReprojectionError(d, rv.Pb, x, y, z, hn::LoadU(d, b.u + i), hn::LoadU(d, b.v + i), rv.adaptive, &zb);
  const V r = hn::Mul(hn::Set(d, 0.5), hn::Add(hn::Mul(ea, hn::Set(d, rv.scale_a)), hn::Mul(eb, hn::Set(d, rv.scale_b))));
  const auto behind = hn::Or(hn::Le(za, hn::Zero(d)), hn::Le(zb, hn::Zero(d)));
  return hn::IfThenElse(behind, hn::Set(d, 1e6), r);
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE void TriangulateLanes(D d, const double* ca, const PoseColumns& a, const double* cb, const PoseColumns& b,
                                 size_t i, double* xyz, double* gap, double* score) {
  const V zero = hn::Zero(d);
  const V d1x = hn::LoadU(d, a.rx + i), d1y = hn::LoadU(d, a.ry + i), d1z = hn::LoadU(d, a.rz + i);
  const V d2x = hn::LoadU(d, b.rx + i), d2y = hn::LoadU(d, b.ry + i), d2z = hn::LoadU(d, b.rz + i);
  const V w0x = hn::Set(d, ca[0] - cb[0]), w0y = hn::Set(d, ca[1] - cb[1]), w0z = hn::Set(d, ca[2] - cb[2]);
  auto dot = [](V px, V py, V pz, V qx, V qy, V qz) {
    return hn::Add(hn::Add(hn::Mul(px, qx), hn::Mul(py, qy)), hn::Mul(pz, qz));
  };
  const V A = dot(d1x, d1y, d1z, d1x, d1y, d1z), B = dot(d1x, d1y, d1z, d2x, d2y, d2z);
  const V C = dot(d2x, d2y, d2z, d2x, d2y, d2z);
  const V Dd = dot(d1x, d1y, d1z, w0x, w0y, w0z), E = dot(d2x, d2y, d2z, w0x, w0y, w0z);
  const V denom = hn::Sub(hn::Mul(A, C), hn::Mul(B, B));
  auto ok = hn::Gt(denom, hn::Mul(hn::Mul(hn::Set(d, 1e-12), A), C));  // false for NaN
  ok = hn::And(ok, hn::And(hn::Gt(hn::LoadU(d, a.score + i), zero), hn::Gt(hn::LoadU(d, b.score + i), zero)));
  const V inv_denom = hn::Div(hn::Set(d, 1.0), denom);  // one division for both, as TriangulateMidpoint
  const V s = hn::Mul(hn::Sub(hn::Mul(B, E), hn::Mul(C, Dd)), inv_denom);
  const V t = hn::Mul(hn::Sub(hn::Mul(A, E), hn::Mul(B, Dd)), inv_denom);
  ok = hn::And(ok, hn::And(hn::Gt(s, zero), hn::Gt(t, zero)));
  const V p1x = hn::Add(hn::Set(d, ca[0]), hn::Mul(s, d1x)), p2x = hn::Add(hn::Set(d, cb[0]), hn::Mul(t, d2x));
  const V p1y = hn::Add(hn::Set(d, ca[1]), hn::Mul(s, d1y)), p2y = hn::Add(hn::Set(d, cb[1]), hn::Mul(t, d2y));
  const V p1z = hn::Add(hn::Set(d, ca[2]), hn::Mul(s, d1z)), p2z = hn::Add(hn::Set(d, cb[2]), hn::Mul(t, d2z));
  const V half = hn::Set(d, 0.5);
  const V ex = hn::Sub(p1x, p2x), ey = hn::Sub(p1y, p2y), ez = hn::Sub(p1z, p2z);
  const V g = hn::Sqrt(dot(ex, ey, ez, ex, ey, ez));
  hn::StoreInterleaved3(hn::IfThenElseZero(ok, hn::Mul(half, hn::Add(p1x, p2x))),
                        hn::IfThenElseZero(ok, hn::Mul(half, hn::Add(p1y, p2y))),
                        hn::IfThenElseZero(ok, hn::Mul(half, hn::Add(p1z, p2z))), d, xyz + 3 * i);
  hn::StoreU(hn::IfThenElse(ok, g, hn::Set(d, -1.0)), d, gap + i);
  hn::StoreU(hn::IfThenElseZero(ok, hn::Set(d, 1.0)), d, score + i);
}

template <class D>
HWY_INLINE void TriangulatePairJoints(D d, const double* ca, const PoseColumns& a, const double* cb, const PoseColumns& b, int n, double* xyz, double* gap, double* score) {
  const size_t N = hn::Lanes(d), count = static_cast<size_t>(n);
  size_t i = 0;
  for (; i + N <= count; i += N) TriangulateLanes(d, ca, a, cb, b, i, xyz, gap, score);
  if (i < count) {
    Tail<HWY_MAX_BYTES / 8> t(count - i);
    const PoseColumns ta = TailColumns(t, a, i, false, true), tb = TailColumns(t, b, i, false, true);
    double *x = t.Out(), *g = t.Out(), *sc = t.Out();
    TriangulateLanes(d, ca, ta, cb, tb, 0, x, g, sc);
    t.Back(x, xyz + 3 * i, 3);
    t.Back(g, gap + i);
    t.Back(sc, score + i);
  }
}

void TriangulatePairImpl(const double* ca, const PoseColumns& a, const double* cb, const PoseColumns& b, int n,
                         double* xyz, double* gap, double* score) {
  // Fewer than 32 joints (the core joints, a body): 4 lanes at most, so that AVX-512 does not
  // spend most of a short row in its padded last vector.
  if (hn::Lanes(hn::ScalableTag<double>()) > 4 && n < 32) {
    TriangulatePairJoints(hn::CappedTag<double, 4>(), ca, a, cb, b, n, xyz, gap, score);
  } else {
    TriangulatePairJoints(hn::ScalableTag<double>(), ca, a, cb, b, n, xyz, gap, score);
  }
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE void ResidualLanes(D d, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, size_t i,
                              const double* xyz, const double* gap, const double* score, const double* geometric,
                              bool use_reprojection, double skip_gap, double* residual) {
  const auto skipped = hn::Or(hn::Le(hn::LoadU(d, score + i), hn::Zero(d)),
                              hn::Ge(hn::LoadU(d, geometric + i), hn::Zero(d)));
  V r = hn::Zero(d);
  if (use_reprojection) {
    const auto far = hn::Gt(hn::LoadU(d, gap + i), hn::Set(d, skip_gap));
    // Like the scalar code, no projection when no joint needs one (e.g. the pairs of different people).
    r = hn::AllTrue(d, hn::Or(skipped, far)) ? hn::Set(d, 1e6)
                                              : hn::IfThenElse(far, hn::Set(d, 1e6), Residual(d, rv, a, b, xyz, i));
  }
  hn::StoreU(hn::IfThenElse(skipped, hn::Set(d, -1.0), r), d, residual + i);
}

template <class D>
HWY_INLINE void PairResidualsJoints(D d, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, int n, const double* xyz, const double* gap, const double* score, const double* geometric, bool use_reprojection, double skip_gap, double* residual) {
  const size_t N = hn::Lanes(d), count = static_cast<size_t>(n);
  size_t i = 0;
  for (; i + N <= count; i += N)
    ResidualLanes(d, rv, a, b, i, xyz, gap, score, geometric, use_reprojection, skip_gap, residual);
  if (i < count) {
    Tail<HWY_MAX_BYTES / 8> t(count - i);
    const PoseColumns ta = TailColumns(t, a, i, true, false), tb = TailColumns(t, b, i, true, false);
    const double* txyz = t.In3(xyz + 3 * i);
    const double *tg = t.In(gap + i), *ts = t.In(score + i), *tgeo = t.In(geometric + i);
    double* r = t.Out();
    ResidualLanes(d, rv, ta, tb, 0, txyz, tg, ts, tgeo, use_reprojection, skip_gap, r);
    t.Back(r, residual + i);
  }
}

void PairResidualsImpl(const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, int n, const double* xyz,
                       const double* gap, const double* score, const double* geometric, bool use_reprojection,
                       double skip_gap, double* residual) {
  // Fewer than 32 joints (the core joints, a body): 4 lanes at most, so that AVX-512 does not
  // spend most of a short row in its padded last vector.
  if (hn::Lanes(hn::ScalableTag<double>()) > 4 && n < 32) {
    PairResidualsJoints(hn::CappedTag<double, 4>(), rv, a, b, n, xyz, gap, score, geometric, use_reprojection, skip_gap, residual);
  } else {
    PairResidualsJoints(hn::ScalableTag<double>(), rv, a, b, n, xyz, gap, score, geometric, use_reprojection, skip_gap, residual);
  }
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE void ScoreLanes(D d, const JointKernel& kernel, const ResidualViews& rv, const PoseColumns& a,
                           const PoseColumns& b, size_t i, const double* xyz, const double* gap,
                           const double* residual, double* score, double* geometric) {
  const V zero = hn::Zero(d);
  const V old_score = hn::LoadU(d, score + i);
  const V old_geometric = hn::LoadU(d, geometric + i);
  const auto unscored = hn::Le(old_score, zero);
  const auto earlier = hn::Ge(old_geometric, zero);
  V exponent = zero;
  auto negligible = hn::Lt(zero, zero);  // all false
  if (kernel.use_ray_gap) {
    const V r = hn::Mul(hn::LoadU(d, gap + i), hn::Set(d, kernel.inv_ray_gap));
    exponent = hn::Mul(r, r);
    negligible = hn::Gt(exponent, hn::Set(d, 30.0));
  }
  if (hn::AllTrue(d, hn::Or(hn::Or(unscored, earlier), negligible))) {  // nothing to compute
    const V new_geometric = hn::IfThenElse(hn::Or(unscored, earlier), old_geometric, zero);
    hn::StoreU(hn::IfThenElse(unscored, old_score, new_geometric), d, score + i);
    hn::StoreU(new_geometric, d, geometric + i);
    return;
  }
  if (kernel.use_reprojection) {
    const V e = residual != nullptr ? hn::LoadU(d, residual + i) : Residual(d, rv, a, b, xyz, i);
    const V r = hn::Mul(e, hn::Set(d, kernel.inv_residual));
    exponent = hn::Add(exponent, hn::Mul(r, r));
  }
  const V s = hn::IfThenZeroElse(negligible, ExpNeg(d, exponent));
  // unscored: both unchanged; scored earlier: score = geometric; else both = s.
  const V new_geometric = hn::IfThenElse(hn::Or(unscored, earlier), old_geometric, s);
  const V new_score = hn::IfThenElse(unscored, old_score, new_geometric);
  hn::StoreU(new_score, d, score + i);
  hn::StoreU(new_geometric, d, geometric + i);
}

template <class D>
HWY_INLINE void ScoreJointsJoints(D d, const JointKernel& kernel, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, int n, const double* xyz, const double* gap, const double* residual, double* score, double* geometric) {
  const size_t N = hn::Lanes(d), count = static_cast<size_t>(n);
  size_t i = 0;
  for (; i + N <= count; i += N) ScoreLanes(d, kernel, rv, a, b, i, xyz, gap, residual, score, geometric);
  if (i < count) {
    Tail<HWY_MAX_BYTES / 8> t(count - i);
    const PoseColumns ta = TailColumns(t, a, i, true, false), tb = TailColumns(t, b, i, true, false);
    const double* txyz = t.In3(xyz + 3 * i);
    const double *tg = t.In(gap + i), *tr = t.In(residual != nullptr ? residual + i : nullptr);
    double *ts = t.Out(), *tgeo = t.Out();
    std::copy(score + i, score + count, ts);
    std::copy(geometric + i, geometric + count, tgeo);
    std::fill(ts + (count - i), ts + hn::MaxLanes(d), 0.0);
    std::fill(tgeo + (count - i), tgeo + hn::MaxLanes(d), -1.0);
    ScoreLanes(d, kernel, rv, ta, tb, 0, txyz, tg, tr, ts, tgeo);
    t.Back(ts, score + i);
    t.Back(tgeo, geometric + i);
  }
}

void ScoreJointsImpl(const JointKernel& kernel, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b,
                     int n, const double* xyz, const double* gap, const double* residual, double* score,
                     double* geometric) {
  // Fewer than 32 joints (the core joints, a body): 4 lanes at most, so that AVX-512 does not
  // spend most of a short row in its padded last vector.
  if (hn::Lanes(hn::ScalableTag<double>()) > 4 && n < 32) {
    ScoreJointsJoints(hn::CappedTag<double, 4>(), kernel, rv, a, b, n, xyz, gap, residual, score, geometric);
  } else {
    ScoreJointsJoints(hn::ScalableTag<double>(), kernel, rv, a, b, n, xyz, gap, residual, score, geometric);
  }
}

// Merge of joints [j, j + Lanes(d)) of one group: steps::Merge's loop lane by lane (merge.h). `dist`
// holds members x Lanes(d) squared distances (NaN = not, or no longer, a candidate), then members x 3
// x Lanes(d) coordinates (the members' x, y, z de-interleaved by the first pass).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void MergeLanes(D d, const MergeParams& p, const double* xyz, const double* score, int members, size_t n,
                           size_t j, double* dist, double* out) {
  const size_t N = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), nan = hn::Set(d, std::numeric_limits<double>::quiet_NaN());
  const V min_score = hn::Set(d, p.min_score);
  // Candidates (score >= min_score): their count, sum (member order) and the best-scoring one.
  V count = zero, sx = zero, sy = zero, sz = zero, best_score = hn::Set(d, -1.0), bx = zero, by = zero, bz = zero;
  // The members' coordinates de-interleaved once, into `cache` (x, y, z per member): the passes
  // below read them again.
  double* const cache = dist + static_cast<size_t>(members) * N;
  for (int m = 0; m < members; ++m) {
    const size_t at = static_cast<size_t>(m) * n + j;
    const V sc = hn::LoadU(d, score + at);
    V x, y, z;
    hn::LoadInterleaved3(d, xyz + 3 * at, x, y, z);
    double* const c = cache + static_cast<size_t>(m) * 3 * N;
    hn::StoreU(x, d, c);
    hn::StoreU(y, d, c + N);
    hn::StoreU(z, d, c + 2 * N);
    const auto valid = hn::Ge(sc, min_score);
    count = hn::Add(count, hn::IfThenElseZero(valid, one));
    sx = hn::Add(sx, hn::IfThenElseZero(valid, x));
    sy = hn::Add(sy, hn::IfThenElseZero(valid, y));
    sz = hn::Add(sz, hn::IfThenElseZero(valid, z));
    const auto better = hn::And(valid, hn::Gt(sc, best_score));
    best_score = hn::IfThenElse(better, sc, best_score);
    bx = hn::IfThenElse(better, x, bx);
    by = hn::IfThenElse(better, y, by);
    bz = hn::IfThenElse(better, z, bz);
  }
  const auto any = hn::Gt(count, zero);
  const V mx = hn::Div(sx, count), my = hn::Div(sy, count), mz = hn::Div(sz, count);
  // The distance filter; the kept candidates summed in member order.
  const V max_sq = hn::Set(d, p.max_distance_sq);
  V kept_count = zero, ax = zero, ay = zero, az = zero, aw = zero, as = zero;
  for (int m = 0; m < members; ++m) {
    const size_t at = static_cast<size_t>(m) * n + j;
    const V sc = hn::LoadU(d, score + at);
    const double* const c = cache + static_cast<size_t>(m) * 3 * N;
    const V x = hn::LoadU(d, c), y = hn::LoadU(d, c + N), z = hn::LoadU(d, c + 2 * N);
    const V dx = hn::Sub(x, mx), dy = hn::Sub(y, my), dz = hn::Sub(z, mz);
    const V dsq = hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz));
    auto kept = hn::Ge(sc, min_score);
    if (p.max_distance_m > 0) kept = hn::And(kept, hn::Le(dsq, max_sq));
    hn::StoreU(hn::IfThenElse(kept, dsq, nan), d, dist + static_cast<size_t>(m) * N);
    kept_count = hn::Add(kept_count, hn::IfThenElseZero(kept, one));
    const V w = p.score_weighted ? sc : one;
    ax = hn::Add(ax, hn::IfThenElseZero(kept, hn::Mul(w, x)));
    ay = hn::Add(ay, hn::IfThenElseZero(kept, hn::Mul(w, y)));
    az = hn::Add(az, hn::IfThenElseZero(kept, hn::Mul(w, z)));
    aw = hn::Add(aw, hn::IfThenElseZero(kept, w));
    as = hn::Add(as, hn::IfThenElseZero(kept, sc));
  }
  V rx = hn::Div(ax, aw), ry = hn::Div(ay, aw), rz = hn::Div(az, aw), rs = hn::Div(as, kept_count);
  // More than top_k kept: the top_k closest (ties: the earlier member), summed closest first.
  const V top_k = hn::Set(d, static_cast<double>(p.top_k));
  const auto many = hn::Gt(kept_count, top_k);
  if (p.top_k > 0 && !hn::AllFalse(d, many)) {
    V tx = zero, ty = zero, tz = zero, tw = zero, ts = zero;
    for (int t = 0; t < p.top_k; ++t) {
      V low = hn::Set(d, std::numeric_limits<double>::infinity()), low_m = hn::Set(d, -1.0);
      V lx = zero, ly = zero, lz = zero, ls = zero;
      for (int m = 0; m < members; ++m) {
        const size_t at = static_cast<size_t>(m) * n + j;
        const V dm = hn::LoadU(d, dist + static_cast<size_t>(m) * N);
        // No early exit when no lane is less: that branch mispredicted so often that blending
        // every member costs less (merge 9.9 -> 7.5 us on the whole-body frame).
        const auto less = hn::Lt(dm, low);  // false for NaN: not a candidate
        const double* const c = cache + static_cast<size_t>(m) * 3 * N;
        const V x = hn::LoadU(d, c), y = hn::LoadU(d, c + N), z = hn::LoadU(d, c + 2 * N);
        low = hn::IfThenElse(less, dm, low);
        low_m = hn::IfThenElse(less, hn::Set(d, static_cast<double>(m)), low_m);
        lx = hn::IfThenElse(less, x, lx);
        ly = hn::IfThenElse(less, y, ly);
        lz = hn::IfThenElse(less, z, lz);
        ls = hn::IfThenElse(less, hn::LoadU(d, score + at), ls);
      }
      for (int m = 0; m < members; ++m) {  // the chosen one is no longer a candidate
        double* dm = dist + static_cast<size_t>(m) * N;
        hn::StoreU(hn::IfThenElse(hn::Eq(low_m, hn::Set(d, static_cast<double>(m))), nan, hn::LoadU(d, dm)), d, dm);
      }
      const V w = p.score_weighted ? ls : one;
      tx = hn::Add(tx, hn::Mul(w, lx));
      ty = hn::Add(ty, hn::Mul(w, ly));
      tz = hn::Add(tz, hn::Mul(w, lz));
      tw = hn::Add(tw, w);
      ts = hn::Add(ts, ls);
    }
    rx = hn::IfThenElse(many, hn::Div(tx, tw), rx);
    ry = hn::IfThenElse(many, hn::Div(ty, tw), ry);
    rz = hn::IfThenElse(many, hn::Div(tz, tw), rz);
    rs = hn::IfThenElse(many, hn::Div(ts, top_k), rs);
  }
  // None kept: the best-scoring candidate alone (keep_best_when_all_far), else missing.
  const auto none = hn::Eq(kept_count, zero);
  if (p.keep_best) {
    const V w = p.score_weighted ? best_score : one;
    rx = hn::IfThenElse(none, hn::Div(hn::Mul(w, bx), w), rx);
    ry = hn::IfThenElse(none, hn::Div(hn::Mul(w, by), w), ry);
    rz = hn::IfThenElse(none, hn::Div(hn::Mul(w, bz), w), rz);
    rs = hn::IfThenElse(none, best_score, rs);
  }
  const auto missing = p.keep_best ? hn::Not(any) : none;
  hn::StoreInterleaved4(hn::IfThenZeroElse(missing, rx), hn::IfThenZeroElse(missing, ry),
                        hn::IfThenZeroElse(missing, rz), hn::IfThenZeroElse(missing, rs), d, out + 4 * j);
}

void MergeGroupImpl(const MergeParams& p, const double* xyz, const double* score, int members, int n, double* dist,
                    double* out) {
  const hn::ScalableTag<double> d;
  const hn::CappedTag<double, 1> d1;
  const size_t N = hn::Lanes(d), joints = static_cast<size_t>(n);
  size_t j = 0;
  for (; j + N <= joints; j += N) MergeLanes(d, p, xyz, score, members, joints, j, dist, out);
  if (j < joints && joints >= N) {
    // The last joints as one full vector ending at the last joint: its first lanes repeat joints
    // done above, and write the same values again (every lane is computed on its own).
    MergeLanes(d, p, xyz, score, members, joints, joints - N, dist, out);
    return;
  }
  for (; j < joints; ++j) MergeLanes(d1, p, xyz, score, members, joints, j, dist, out);
}

template <class D, class V = hn::Vec<D>>
HWY_INLINE void PixelDistanceLanes(D d, const double* uv, const PoseColumns& c, size_t i, double* sum, int* count) {
  V pu, pv;
  hn::LoadInterleaved2(d, uv + 2 * i, pu, pv);
  const V du = hn::Sub(pu, hn::LoadU(d, c.u + i)), dv = hn::Sub(pv, hn::LoadU(d, c.v + i));
  const auto valid = hn::And(hn::Gt(hn::LoadU(d, c.score + i), hn::Zero(d)), hn::Eq(pu, pu));  // pu NaN: not seen
  const V dist = hn::IfThenElseZero(valid, hn::Sqrt(hn::Add(hn::Mul(du, du), hn::Mul(dv, dv))));
  HWY_ALIGN double lanes[hn::MaxLanes(d)];
  hn::Store(dist, d, lanes);
  for (size_t l = 0; l < hn::Lanes(d); ++l) *sum += lanes[l];  // joint order, as the scalar loop
  *count += static_cast<int>(hn::CountTrue(d, valid));
}

void PixelDistanceSumsImpl(const double* uv, int persons, const PoseColumns& c, int n, double* sums, int* counts) {
  const hn::CappedTag<double, 4> d;  // rows of core joints: short
  const hn::CappedTag<double, 1> d1;
  const size_t N = hn::Lanes(d), joints = static_cast<size_t>(n);
  for (int q = 0; q < persons; ++q, uv += 2 * joints) {
    double sum = 0;
    int count = 0;
    size_t i = 0;
    for (; i + N <= joints; i += N) PixelDistanceLanes(d, uv, c, i, &sum, &count);
    for (; i < joints; ++i) PixelDistanceLanes(d1, uv, c, i, &sum, &count);
    sums[q] = sum;
    counts[q] = count;
  }
}

// ImplausibleLimbs for limbs [l, l + Lanes(d)): the lanes' bits.
template <class D>
HWY_INLINE uint64_t ImplausibleLimbLanes(D d, const LimbColumns& t, size_t l, const double* xyz, const double* score) {
  const hn::RebindToSigned<D> di;
  const auto a = hn::LoadU(di, t.a.data() + l), b = hn::LoadU(di, t.b.data() + l);
  const auto a3 = hn::Add(hn::Add(a, a), a), b3 = hn::Add(hn::Add(b, b), b);
  const auto dx = hn::Sub(hn::GatherIndex(d, xyz, a3), hn::GatherIndex(d, xyz, b3));
  const auto dy = hn::Sub(hn::GatherIndex(d, xyz + 1, a3), hn::GatherIndex(d, xyz + 1, b3));
  const auto dz = hn::Sub(hn::GatherIndex(d, xyz + 2, a3), hn::GatherIndex(d, xyz + 2, b3));
  const auto length_sq = hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz));
  const auto outside =
      hn::Or(hn::Lt(length_sq, hn::LoadU(d, t.min_sq.data() + l)), hn::Gt(length_sq, hn::LoadU(d, t.max_sq.data() + l)));
  const auto zero = hn::Zero(d);
  const auto scored = hn::And(hn::Gt(hn::GatherIndex(d, score, a), zero), hn::Gt(hn::GatherIndex(d, score, b), zero));
  uint8_t bits[8] = {};
  hn::StoreMaskBits(d, hn::And(outside, scored), bits);
  return bits[0];
}

uint64_t ImplausibleLimbsImpl(const LimbColumns& limbs, size_t begin, size_t end, const double* xyz,
                              const double* score) {
  uint64_t bits = 0;
#if HWY_TARGET > HWY_AVX3
  // Below AVX-512 the gathers cost more than loading the joints one by one (whole body, Zen 4 with
  // AVX2: triangulate_full 2.5 us per frame faster, `rpt bench`): the lanes' code, one limb at a time.
  for (size_t l = begin; l < end; ++l) {
    const double* pa = xyz + 3 * static_cast<size_t>(limbs.a[l]);
    const double* pb = xyz + 3 * static_cast<size_t>(limbs.b[l]);
    const double dx = pa[0] - pb[0], dy = pa[1] - pb[1], dz = pa[2] - pb[2];
    const double length_sq = (dx * dx + dy * dy) + dz * dz;
    const bool outside = (length_sq < limbs.min_sq[l]) | (length_sq > limbs.max_sq[l]);
    const bool scored = (score[limbs.a[l]] > 0.0) & (score[limbs.b[l]] > 0.0);
    bits |= static_cast<uint64_t>(outside & scored) << (l - begin);
  }
  return bits;
#else
  const hn::ScalableTag<double> d;
  const hn::CappedTag<double, 1> d1;
  const size_t N = hn::Lanes(d);
  static_assert(HWY_MAX_BYTES / 8 <= 8, "a vector's lanes fit one byte of mask bits");
  size_t l = begin;
  for (; l + N <= end; l += N) bits |= ImplausibleLimbLanes(d, limbs, l, xyz, score) << (l - begin);
  for (; l < end; ++l) bits |= ImplausibleLimbLanes(d1, limbs, l, xyz, score) << (l - begin);
  return bits;
#endif
}

// std::max(best, score) lane by lane for joints [j, j + Lanes(d)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void RefineBestScoreLanes(D d, const double* score, size_t j, double* best) {
  const V b = hn::LoadU(d, best + j), s = hn::LoadU(d, score + j);
  hn::StoreU(hn::IfThenElse(hn::Lt(b, s), s, b), d, best + j);
}

void RefineBestScoreImpl(const double* score, int n, double* best) {
  const hn::ScalableTag<double> d;
  const hn::CappedTag<double, 1> d1;
  const size_t N = hn::Lanes(d), joints = static_cast<size_t>(n);
  size_t j = 0;
  for (; j + N <= joints; j += N) RefineBestScoreLanes(d, score, j, best);
  for (; j < joints; ++j) RefineBestScoreLanes(d1, score, j, best);
}

// steps::Refine's view preparation (refine.cc, PrepareViewScalar) for joints [j, j + Lanes(d)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void RefinePrepareLanes(D d, const double* rx, const double* ry, const double* rz,
                                   const double* confidence, const double* person_score, double min_score, double cx,
                                   double cy, double cz, size_t j, double* weight, double* inv_norm_sq,
                                   double* origin_dot) {
  const V x = hn::LoadU(d, rx + j), y = hn::LoadU(d, ry + j), z = hn::LoadU(d, rz + j);
  const V c = hn::LoadU(d, confidence + j), zero = hn::Zero(d);
  const auto usable = hn::And(hn::And(hn::Ge(hn::LoadU(d, weight + j), hn::Set(d, min_score)), hn::Gt(c, zero)),
                              hn::Gt(hn::LoadU(d, person_score + j), zero));
  const V norm_sq = hn::Add(hn::Add(hn::Mul(x, x), hn::Mul(y, y)), hn::Mul(z, z));
  const auto valid = hn::And(usable, hn::Gt(norm_sq, zero));
  const V inv = hn::IfThenElseZero(valid, hn::Div(hn::Set(d, 1.0), norm_sq));
  hn::StoreU(inv, d, inv_norm_sq + j);
  hn::StoreU(hn::IfThenElseZero(hn::Gt(inv, zero), c), d, weight + j);
  const V dot = hn::Add(hn::Add(hn::Mul(x, hn::Set(d, cx)), hn::Mul(y, hn::Set(d, cy))), hn::Mul(z, hn::Set(d, cz)));
  hn::StoreU(dot, d, origin_dot + j);
}

static_assert(kRefineAlign % (HWY_MAX_BYTES / sizeof(double)) == 0, "whole vectors over the padded joints");

void RefinePrepareViewImpl(const double* rx, const double* ry, const double* rz, const double* confidence,
                           const double* person_score, double min_score, double cx, double cy, double cz, int n,
                           double* weight, double* inv_norm_sq, double* origin_dot) {
  const hn::ScalableTag<double> d;
  for (size_t j = 0; j < static_cast<size_t>(n); j += hn::Lanes(d))  // n: a multiple of kRefineAlign
    RefinePrepareLanes(d, rx, ry, rz, confidence, person_score, min_score, cx, cy, cz, j, weight, inv_norm_sq,
                       origin_dot);
}

// steps::Refine's accumulation (refine.cc, AccumulateScalar) for joints [j, j + Lanes(d)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void RefineAccumulateLanes(D d, const RefineParams& p, const RefineView& view, const double* x,
                                      const double* y, const double* z, size_t n, size_t j, double* sums) {
  auto load = [&](const double* at) { return hn::LoadU(d, at + j); };
  const V rx = load(view.rx), ry = load(view.ry), rz = load(view.rz);
  const V inv_norm_sq = load(view.inv_norm_sq), origin_dot = load(view.origin_dot);
  const V tx = hn::Sub(load(x), hn::Set(d, view.cx));
  const V ty = hn::Sub(load(y), hn::Set(d, view.cy));
  const V tz = hn::Sub(load(z), hn::Set(d, view.cz));
  const V along = hn::Add(hn::Add(hn::Mul(rx, tx), hn::Mul(ry, ty)), hn::Mul(rz, tz));
  const V distance_sq = hn::Sub(hn::Add(hn::Add(hn::Mul(tx, tx), hn::Mul(ty, ty)), hn::Mul(tz, tz)),
                                hn::Mul(hn::Mul(along, along), inv_norm_sq));
  const V robust =
      hn::Div(load(view.weight), hn::Add(hn::Set(d, 1.0), hn::Mul(distance_sq, hn::Set(d, p.inv_scale_sq))));
  const V w = hn::IfThenElseZero(hn::Le(distance_sq, hn::Set(d, p.cutoff_sq)), robust);
  const V u = hn::Mul(w, inv_norm_sq);
  const V urx = hn::Mul(u, rx), ury = hn::Mul(u, ry), urz = hn::Mul(u, rz);
  auto add = [&](int k, V value) {
    double* at = sums + static_cast<size_t>(k) * n + j;
    hn::StoreU(hn::Add(hn::LoadU(d, at), value), d, at);
  };
  auto sub = [&](int k, V value) {
    double* at = sums + static_cast<size_t>(k) * n + j;
    hn::StoreU(hn::Sub(hn::LoadU(d, at), value), d, at);
  };
  add(0, hn::Sub(w, hn::Mul(urx, rx)));
  sub(1, hn::Mul(urx, ry));
  sub(2, hn::Mul(urx, rz));
  add(3, hn::Sub(w, hn::Mul(ury, ry)));
  sub(4, hn::Mul(ury, rz));
  add(5, hn::Sub(w, hn::Mul(urz, rz)));
  add(6, hn::Sub(hn::Mul(w, hn::Set(d, view.cx)), hn::Mul(urx, origin_dot)));
  add(7, hn::Sub(hn::Mul(w, hn::Set(d, view.cy)), hn::Mul(ury, origin_dot)));
  add(8, hn::Sub(hn::Mul(w, hn::Set(d, view.cz)), hn::Mul(urz, origin_dot)));
  add(9, hn::IfThenElseZero(hn::Gt(w, hn::Zero(d)), hn::Set(d, 1.0)));
}

void RefineAccumulateImpl(const RefineParams& p, const RefineView& view, const double* x, const double* y,
                          const double* z, int n, double* sums) {
  const hn::ScalableTag<double> d;
  for (size_t j = 0; j < static_cast<size_t>(n); j += hn::Lanes(d))
    RefineAccumulateLanes(d, p, view, x, y, z, static_cast<size_t>(n), j, sums);
}

// steps::Refine's solve (refine.cc, SolveScalar) for joints [j, j + Lanes(d)).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void RefineSolveLanes(D d, const double* sums, size_t n, size_t j, double min_conditioning, double* x,
                                 double* y, double* z, double* changed) {
  auto at = [&](int k) { return hn::LoadU(d, sums + static_cast<size_t>(k) * n + j); };
  const V a00 = at(0), a01 = at(1), a02 = at(2), a11 = at(3), a12 = at(4), a22 = at(5);
  const V c00 = hn::Sub(hn::Mul(a11, a22), hn::Mul(a12, a12));
  const V c01 = hn::Sub(hn::Mul(a02, a12), hn::Mul(a01, a22));
  const V c02 = hn::Sub(hn::Mul(a01, a12), hn::Mul(a02, a11));
  const V c11 = hn::Sub(hn::Mul(a00, a22), hn::Mul(a02, a02));
  const V c12 = hn::Sub(hn::Mul(a01, a02), hn::Mul(a00, a12));
  const V c22 = hn::Sub(hn::Mul(a00, a11), hn::Mul(a01, a01));
  const V det = hn::Add(hn::Add(hn::Mul(a00, c00), hn::Mul(a01, c01)), hn::Mul(a02, c02));
  const V third = hn::Div(hn::Add(hn::Add(a00, a11), a22), hn::Set(d, 3.0));
  const V bound = hn::Mul(hn::Mul(hn::Mul(hn::Set(d, min_conditioning), third), third), third);
  const auto solve = hn::And(hn::Ge(at(9), hn::Set(d, 2.0)), hn::Gt(det, bound));
  const V b0 = at(6), b1 = at(7), b2 = at(8);
  const V inv_det = hn::Div(hn::Set(d, 1.0), det);
  const V nx = hn::Mul(hn::Add(hn::Add(hn::Mul(c00, b0), hn::Mul(c01, b1)), hn::Mul(c02, b2)), inv_det);
  const V ny = hn::Mul(hn::Add(hn::Add(hn::Mul(c01, b0), hn::Mul(c11, b1)), hn::Mul(c12, b2)), inv_det);
  const V nz = hn::Mul(hn::Add(hn::Add(hn::Mul(c02, b0), hn::Mul(c12, b1)), hn::Mul(c22, b2)), inv_det);
  hn::StoreU(hn::IfThenElse(solve, nx, hn::LoadU(d, x + j)), d, x + j);
  hn::StoreU(hn::IfThenElse(solve, ny, hn::LoadU(d, y + j)), d, y + j);
  hn::StoreU(hn::IfThenElse(solve, nz, hn::LoadU(d, z + j)), d, z + j);
  hn::StoreU(hn::IfThenElse(solve, hn::Set(d, 1.0), hn::LoadU(d, changed + j)), d, changed + j);
}

void RefineSolveImpl(const double* sums, int n, double min_conditioning, double* x, double* y, double* z,
                     double* changed) {
  const hn::ScalableTag<double> d;
  for (size_t j = 0; j < static_cast<size_t>(n); j += hn::Lanes(d))
    RefineSolveLanes(d, sums, static_cast<size_t>(n), j, min_conditioning, x, y, z, changed);
}

// steps::Undistort's pinhole path (undistort.cc: the inverse of K, then SetFromNormalized) for
// joints [i, i + Lanes(d)). R_t * (x, y, 1) follows Eigen's evaluation of a 3x3 matrix times a
// vector on the SSE2 baseline: rows 0-1 column by column ((a + b) + c), row 2 as a + (b + c).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void UndistortPinholeLanes(D d, const PinholeView& g, const double* uvs, size_t i, const KeypointFields& out,
                                      V* box) {
  V u, v, s;
  hn::LoadInterleaved3(d, uvs + 3 * i, u, v, s);
  const auto valid = hn::And(hn::And(hn::Ge(s, hn::Set(d, g.min_score)), hn::IsFinite(s)),
                             hn::And(hn::IsFinite(u), hn::IsFinite(v)));
  const V y = hn::Div(hn::Sub(v, hn::Set(d, g.cy)), hn::Set(d, g.fy));
  const V x = hn::Div(hn::Sub(hn::Sub(u, hn::Set(d, g.cx)), hn::Mul(hn::Set(d, g.skew), y)), hn::Set(d, g.fx));
  const V pu = hn::Add(hn::Add(hn::Mul(hn::Set(d, g.fx), x), hn::Mul(hn::Set(d, g.skew), y)), hn::Set(d, g.cx));
  const V pv = hn::Add(hn::Mul(hn::Set(d, g.fy), y), hn::Set(d, g.cy));
  const V score = hn::Min(s, hn::Set(d, 1.0));
  const V one = hn::Set(d, 1.0);
  const double* R = g.R_t;  // column-major: R(r, c) = R[3 c + r]
  const V rx = hn::Add(hn::Add(hn::Mul(hn::Set(d, R[0]), x), hn::Mul(hn::Set(d, R[3]), y)), hn::Mul(hn::Set(d, R[6]), one));
  const V ry = hn::Add(hn::Add(hn::Mul(hn::Set(d, R[1]), x), hn::Mul(hn::Set(d, R[4]), y)), hn::Mul(hn::Set(d, R[7]), one));
  const V rz = hn::Add(hn::Mul(hn::Set(d, R[2]), x), hn::Add(hn::Mul(hn::Set(d, R[5]), y), hn::Mul(hn::Set(d, R[8]), one)));
  hn::StoreU(hn::IfThenElseZero(valid, pu), d, out.u + i);
  hn::StoreU(hn::IfThenElseZero(valid, pv), d, out.v + i);
  hn::StoreU(hn::IfThenElseZero(valid, score), d, out.score + i);
  hn::StoreU(hn::IfThenElseZero(valid, hn::Sqrt(score)), d, out.sqrt_score + i);
  hn::StoreU(hn::IfThenElseZero(valid, rx), d, out.rx + i);
  hn::StoreU(hn::IfThenElseZero(valid, ry), d, out.ry + i);
  hn::StoreU(hn::IfThenElseZero(valid, rz), d, out.rz + i);
  hn::StoreU(hn::IfThenElseZero(valid, x), d, out.x + i);
  hn::StoreU(hn::IfThenElseZero(valid, y), d, out.y + i);
  // The box of the joints kept with a positive score, as std::min / std::max would update it.
  const auto boxed = hn::And(valid, hn::Gt(score, hn::Zero(d)));
  box[0] = hn::IfThenElse(hn::And(boxed, hn::Lt(pu, box[0])), pu, box[0]);
  box[1] = hn::IfThenElse(hn::And(boxed, hn::Lt(pv, box[1])), pv, box[1]);
  box[2] = hn::IfThenElse(hn::And(boxed, hn::Lt(box[2], pu)), pu, box[2]);
  box[3] = hn::IfThenElse(hn::And(boxed, hn::Lt(box[3], pv)), pv, box[3]);
}

// The box of `lanes` folded into box_out (min u, min v, max u, max v).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void FoldBox(D d, const V* lanes, double* box_out) {
  HWY_ALIGN double values[HWY_MAX_BYTES / 8];
  for (int k = 0; k < 4; ++k) {
    hn::Store(lanes[k], d, values);
    for (size_t lane = 0; lane < hn::Lanes(d); ++lane) {
      const double value = values[lane];
      box_out[k] = k < 2 ? std::min(box_out[k], value) : std::max(box_out[k], value);
    }
  }
}

template <class D>
HWY_INLINE void UndistortPinholeJoints(D d, const PinholeView& g, const double* uvs, size_t n, const KeypointFields& out,
                                       double* box) {
  const hn::CappedTag<double, 1> d1;
  const size_t N = hn::Lanes(d);
  const double empty[4] = {1e300, 1e300, -1e300, -1e300};
  hn::Vec<D> lanes[4];
  hn::Vec<decltype(d1)> lane[4];
  for (int k = 0; k < 4; ++k) {
    lanes[k] = hn::Set(d, empty[k]);
    lane[k] = hn::Set(d1, empty[k]);
    box[k] = empty[k];
  }
  size_t i = 0;
  for (; i + N <= n; i += N) UndistortPinholeLanes(d, g, uvs, i, out, lanes);
  for (; i < n; ++i) UndistortPinholeLanes(d1, g, uvs, i, out, lane);
  FoldBox(d, lanes, box);
  FoldBox(d1, lane, box);
}

void UndistortPinholeImpl(const PinholeView& g, const double* uvs, int n, const KeypointFields& out, double* box) {
  const size_t joints = static_cast<size_t>(n);
  if (hn::Lanes(hn::ScalableTag<double>()) > 4 && n < 32) {  // short rows: see TriangulatePairImpl
    UndistortPinholeJoints(hn::CappedTag<double, 4>(), g, uvs, joints, out, box);
  } else {
    UndistortPinholeJoints(hn::ScalableTag<double>(), g, uvs, joints, out, box);
  }
}

// RankMedianScalar with lanes over i: each lane counts the values below its value, and the equal
// ones earlier in the list, with the scalar code's comparisons; the ranks are then read in list
// order as the scalar code reads them (the last value of a rank wins).
double RankMedianImpl(const double* values, int n) {
  const hn::CappedTag<double, 4> d;  // at most 32 values: short rows
  using V = hn::Vec<decltype(d)>;
  const size_t N = hn::Lanes(d), count = static_cast<size_t>(n);
  HWY_ALIGN double padded[kRankMedianMax + 4];
  HWY_ALIGN double rank[kRankMedianMax + 4];
  std::copy(values, values + count, padded);
  std::fill(padded + count, padded + count + N, 0.0);  // lanes past n: ranked, never read
  const V one = hn::Set(d, 1.0);
  for (size_t i = 0; i < count; i += N) {
    const V vi = hn::Load(d, padded + i);
    const V index = hn::Iota(d, static_cast<double>(i));
    V r = hn::Zero(d);
    for (size_t j = 0; j < count; ++j) {
      const V vj = hn::Set(d, values[j]);
      const auto counted = hn::Or(hn::Lt(vj, vi), hn::And(hn::Eq(vj, vi), hn::Lt(hn::Set(d, static_cast<double>(j)), index)));
      r = hn::Add(r, hn::IfThenElseZero(counted, one));
    }
    hn::Store(r, d, rank + i);
  }
  const double low = static_cast<double>((n - 1) / 2), high = static_cast<double>(n / 2);
  double lower = 0, upper = 0;
  for (size_t i = 0; i < count; ++i) {
    lower = rank[i] == low ? values[i] : lower;
    upper = rank[i] == high ? values[i] : upper;
  }
  return 0.5 * (lower + upper);
}

int64_t TargetImpl() { return HWY_TARGET; }

size_t DoubleLanesImpl() { return hn::Lanes(hn::ScalableTag<double>()); }

}  // namespace HWY_NAMESPACE
}  // namespace rpt::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace rpt::simd {
namespace {

std::atomic<bool> g_simd_enabled{true};

std::string PathName(int64_t target) {
  if (target == HWY_AVX3) return "AVX-512";
  if (target == HWY_EMU128 || target == HWY_SCALAR) return "scalar";
  return hwy::TargetName(target);
}

// RPT_SIMD (read once): "off" = the steps' scalar code; an instruction set's name ("scalar",
// "SSE4", "AVX2", "AVX-512", case-insensitive) = the kernels restricted to it.
bool ReadEnvironment() {
  const char* value = std::getenv("RPT_SIMD");
  if (value == nullptr || *value == 0) return true;
  if (strcasecmp(value, "off") == 0) {
    g_simd_enabled = false;
    return true;
  }
  std::string names;
  for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
    if (strcasecmp(value, PathName(target).c_str()) == 0) {
      hwy::SetSupportedTargetsForTest(target);
      hwy::GetChosenTarget().Update(hwy::SupportedTargets());
      return true;
    }
    names += ' ';
    names += PathName(target);
  }
  std::fprintf(stderr, "warning: RPT_SIMD=%s is not one of off%s (this CPU); the best one is used\n", value,
               names.c_str());
  return true;
}

void EnsureEnvironmentRead() { static const bool read = ReadEnvironment(); (void)read; }

}  // namespace

HWY_EXPORT(TriangulatePairImpl);
HWY_EXPORT(PairResidualsImpl);
HWY_EXPORT(ScoreJointsImpl);
HWY_EXPORT(MergeGroupImpl);
HWY_EXPORT(PixelDistanceSumsImpl);
HWY_EXPORT(RankMedianImpl);
HWY_EXPORT(ImplausibleLimbsImpl);
HWY_EXPORT(UndistortPinholeImpl);
HWY_EXPORT(RefineBestScoreImpl);
HWY_EXPORT(RefinePrepareViewImpl);
HWY_EXPORT(RefineAccumulateImpl);
HWY_EXPORT(RefineSolveImpl);
HWY_EXPORT(TargetImpl);
HWY_EXPORT(DoubleLanesImpl);

void TriangulatePair(const double* ca, const PoseColumns& a, const double* cb, const PoseColumns& b, int n,
                     double* xyz, double* gap, double* score) {
  HWY_DYNAMIC_DISPATCH(TriangulatePairImpl)(ca, a, cb, b, n, xyz, gap, score);
}

void PairResiduals(const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b, int n, const double* xyz,
                   const double* gap, const double* score, const double* geometric, bool use_reprojection,
                   double skip_gap, double* residual) {
  HWY_DYNAMIC_DISPATCH(PairResidualsImpl)(rv, a, b, n, xyz, gap, score, geometric, use_reprojection, skip_gap,
                                          residual);
}

void ScoreJoints(const JointKernel& kernel, const ResidualViews& rv, const PoseColumns& a, const PoseColumns& b,
                 int n, const double* xyz, const double* gap, const double* residual, double* score,
                 double* geometric) {
  HWY_DYNAMIC_DISPATCH(ScoreJointsImpl)(kernel, rv, a, b, n, xyz, gap, residual, score, geometric);
}

void PixelDistanceSums(const double* uv, int persons, const PoseColumns& c, int n, double* sums, int* counts) {
  HWY_DYNAMIC_DISPATCH(PixelDistanceSumsImpl)(uv, persons, c, n, sums, counts);
}

size_t MergeScratchSize(int members) {
  return static_cast<size_t>(members) * 4 * HWY_DYNAMIC_DISPATCH(DoubleLanesImpl)();  // distances, x, y, z
}

void MergeGroup(const MergeParams& p, const double* xyz, const double* score, int members, int n, double* dist,
                double* out) {
  HWY_DYNAMIC_DISPATCH(MergeGroupImpl)(p, xyz, score, members, n, dist, out);
}

uint64_t ImplausibleLimbs(const LimbColumns& limbs, size_t begin, size_t end, const double* xyz, const double* score) {
  return HWY_DYNAMIC_DISPATCH(ImplausibleLimbsImpl)(limbs, begin, end, xyz, score);
}

double RankMedian(const double* values, int n) { return HWY_DYNAMIC_DISPATCH(RankMedianImpl)(values, n); }

void UndistortPinhole(const PinholeView& view, const double* uvs, int n, const KeypointFields& out, double* box) {
  HWY_DYNAMIC_DISPATCH(UndistortPinholeImpl)(view, uvs, n, out, box);
}

void RefineBestScore(const double* score, int n, double* best) { HWY_DYNAMIC_DISPATCH(RefineBestScoreImpl)(score, n, best); }

void RefinePrepareView(const double* rx, const double* ry, const double* rz, const double* confidence,
                       const double* person_score, double min_score, double cx, double cy, double cz, int n,
                       double* weight, double* inv_norm_sq, double* origin_dot) {
  HWY_DYNAMIC_DISPATCH(RefinePrepareViewImpl)(rx, ry, rz, confidence, person_score, min_score, cx, cy, cz, n, weight,
                                              inv_norm_sq, origin_dot);
}

void RefineAccumulate(const RefineParams& p, const RefineView& view, const double* x, const double* y, const double* z,
                      int n, double* sums) {
  HWY_DYNAMIC_DISPATCH(RefineAccumulateImpl)(p, view, x, y, z, n, sums);
}

void RefineSolve(const double* sums, int n, double min_conditioning, double* x, double* y, double* z,
                 double* changed) {
  HWY_DYNAMIC_DISPATCH(RefineSolveImpl)(sums, n, min_conditioning, x, y, z, changed);
}

bool Enabled() {
  EnsureEnvironmentRead();
  return g_simd_enabled.load(std::memory_order_relaxed);
}

void SetEnabled(bool on) {
  EnsureEnvironmentRead();
  g_simd_enabled = on;
}

std::string ActivePath() {
  EnsureEnvironmentRead();
  return PathName(HWY_DYNAMIC_DISPATCH(TargetImpl)());
}

void ForEachPathForTest(const std::function<void()>& body) {
  EnsureEnvironmentRead();
  for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
    body();
  }
  hwy::SetSupportedTargetsForTest(0);
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
}

}  // namespace rpt::simd
#endif  // HWY_ONCE

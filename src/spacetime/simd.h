// SimdD: a number type holding one SIMD vector of doubles (one light ray per lane), for the
// packet integrator (geodesic_packet.h) and the metric templates (g_tmpl, christoffel_tmpl,
// accel_tmpl) evaluated on a packet of rays. Built on Google Highway (Debian libhwy-dev): the
// same source is compiled once per instruction set (AVX-512, AVX2, SSE4, scalar emulation) and
// the best one the machine has is chosen at run time (HWY_DYNAMIC_DISPATCH).
//
// This is a per-target header in Highway's sense: it is included inside a file that is itself
// re-included per target by <hwy/foreach_target.h>, so it has a toggle guard instead of
// #pragma once, and everything lives in geovis::HWY_NAMESPACE (geovis::N_AVX2::SimdD, ...).
//
// Bit-identical to the scalar path: every operator is one IEEE operation per lane (Highway's
// Mul, Add, Div, Sqrt; no fused multiply-add: files that include this header are compiled with
// -ffp-contract=off, CMakeLists.txt), and sin/cos, exp and asin are fast_math.h's polynomials, the
// same templates (sincos_reduced.h, exp_reduced.h, asin_core.h), so a formula written once as a
// template gives the same bits per lane as on doubles.
#if defined(GEOVIS_SPACETIME_SIMD_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GEOVIS_SPACETIME_SIMD_H_
#undef GEOVIS_SPACETIME_SIMD_H_
#else
#define GEOVIS_SPACETIME_SIMD_H_
#endif

#include <hwy/highway.h>

#include "spacetime/fast_math.h"
#include "spacetime/metric_kernel.h"
#include "spacetime/vec.h"

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using SimdTag = hn::ScalableTag<double>;
using SimdVec = hn::Vec<SimdTag>;

/// One double per lane. Implicitly constructible from a double (broadcast), so the metric
/// templates' mixed expressions (1.0 - rs / r) work unchanged.
struct SimdD {
  SimdVec v;
  SimdD() = default;  // uninitialized, as a double (trivial: Vec4T<SimdD> needs no target code to build)
  HWY_INLINE SimdD(double x) : v(hn::Set(SimdTag(), x)) {}  // NOLINT: broadcast, as a double literal
  HWY_INLINE explicit SimdD(SimdVec x) : v(x) {}
  static HWY_INLINE size_t lanes() { return hn::Lanes(SimdTag()); }
  static HWY_INLINE SimdD load(const double* p) { return SimdD(hn::LoadU(SimdTag(), p)); }
  HWY_INLINE void store(double* p) const { hn::StoreU(v, SimdTag(), p); }
  HWY_INLINE SimdD& operator+=(SimdD b) { return v = hn::Add(v, b.v), *this; }
  HWY_INLINE SimdD& operator-=(SimdD b) { return v = hn::Sub(v, b.v), *this; }
  HWY_INLINE SimdD& operator*=(SimdD b) { return v = hn::Mul(v, b.v), *this; }
  HWY_INLINE SimdD& operator/=(SimdD b) { return v = hn::Div(v, b.v), *this; }
};

/// Per-lane truth value (result of a comparison).
struct SimdMask {
  hn::Mask<SimdTag> m;
};

HWY_API SimdD operator+(SimdD a, SimdD b) { return SimdD(hn::Add(a.v, b.v)); }
HWY_API SimdD operator-(SimdD a, SimdD b) { return SimdD(hn::Sub(a.v, b.v)); }
HWY_API SimdD operator*(SimdD a, SimdD b) { return SimdD(hn::Mul(a.v, b.v)); }
HWY_API SimdD operator/(SimdD a, SimdD b) { return SimdD(hn::Div(a.v, b.v)); }
HWY_API SimdD operator-(SimdD a) { return SimdD(hn::Neg(a.v)); }
HWY_API SimdD operator+(SimdD a) { return a; }

HWY_API SimdMask operator<(SimdD a, SimdD b) { return {hn::Lt(a.v, b.v)}; }
HWY_API SimdMask operator<=(SimdD a, SimdD b) { return {hn::Le(a.v, b.v)}; }
HWY_API SimdMask operator>(SimdD a, SimdD b) { return {hn::Gt(a.v, b.v)}; }
HWY_API SimdMask operator>=(SimdD a, SimdD b) { return {hn::Ge(a.v, b.v)}; }
HWY_API SimdMask operator==(SimdD a, SimdD b) { return {hn::Eq(a.v, b.v)}; }
HWY_API SimdMask operator!=(SimdD a, SimdD b) { return {hn::Ne(a.v, b.v)}; }
HWY_API SimdMask operator&&(SimdMask a, SimdMask b) { return {hn::And(a.m, b.m)}; }
HWY_API SimdMask operator||(SimdMask a, SimdMask b) { return {hn::Or(a.m, b.m)}; }
HWY_API SimdMask operator!(SimdMask a) { return {hn::Not(a.m)}; }
HWY_API bool all_of(SimdMask a) { return hn::AllTrue(SimdTag(), a.m); }
HWY_API bool none_of(SimdMask a) { return hn::AllFalse(SimdTag(), a.m); }

/// Lane-wise c ? a : b.
HWY_API SimdD select(SimdMask c, SimdD a, SimdD b) { return SimdD(hn::IfThenElse(c.m, a.v, b.v)); }
HWY_API SimdD sqrt(SimdD a) { return SimdD(hn::Sqrt(a.v)); }
HWY_API SimdD abs(SimdD a) { return SimdD(hn::Abs(a.v)); }
HWY_API SimdD fabs(SimdD a) { return SimdD(hn::Abs(a.v)); }
HWY_API SimdD min(SimdD a, SimdD b) { return SimdD(hn::Min(a.v, b.v)); }
HWY_API SimdD max(SimdD a, SimdD b) { return SimdD(hn::Max(a.v, b.v)); }
HWY_API SimdMask isfinite(SimdD a) { return {hn::IsFinite(a.v)}; }
/// std::copysign lane by lane: |a| with the sign bit of b.
HWY_API SimdD copysign(SimdD a, SimdD b) { return SimdD(hn::CopySign(a.v, b.v)); }
/// The lanes with the low 32 bits of their significands cleared (fast_math.h's clear_low_word).
HWY_API SimdD clear_low_word(SimdD x) {
  const SimdTag d;
  const hn::RebindToUnsigned<SimdTag> du;
  return SimdD(hn::BitCast(d, hn::And(hn::BitCast(du, x.v), hn::Set(du, 0xffffffff00000000ull))));
}

/// The integer n (|n| < 2^51, held in a double) as a 64-bit integer modulo 2^52 — its two's
/// complement bits from bit 0 to bit 51, which are all that the quadrant of sincos_t (n mod 4) and
/// the exponent field of exp_t's 2^n (n + 1023 in [1, 2046], shifted left by 52) read: n + 1.5·2^52
/// is exact and lies in [2^52, 2^53), where the significand holds 2^51 + n, so its bits are
/// 0x4338000000000000 + n (the fdlibm round-to-integer constant's trick). Three instructions
/// where Highway's ConvertTo (double → int64, saturating) emulates the conversion on AVX2 with ~20
/// (callgrind, issue 13); the same values, so the same bits as before.
HWY_API hn::Vec<hn::RebindToSigned<SimdTag>> integer_bits(SimdD n) {
  const hn::RebindToSigned<SimdTag> di;
  return hn::BitCast(di, hn::Add(n.v, hn::Set(SimdTag(), 6755399441055744.0)));
}

#include "spacetime/sincos_reduced.h"  // sincos_reduced: this target's copy

/// fast_sincos (fast_math.h) lane by lane: the same reduction and the same Estrin polynomials
/// (sincos_reduced), operation for operation, so each lane equals fast_sincos of that lane to the bit. Lanes outside
/// |x| < 1e5 (and NaN) take fast_sincos's own route through std::sin/std::cos.
HWY_API void sincos_t(SimdD x, SimdD& s, SimdD& c) {
  const SimdTag d;
  if (HWY_UNLIKELY(!hn::AllTrue(d, hn::Lt(hn::Abs(x.v), hn::Set(d, 1e5))))) {
    HWY_ALIGN double xs[HWY_MAX_BYTES / sizeof(double)], ss[HWY_MAX_BYTES / sizeof(double)],
        cs[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(x.v, d, xs);
    for (size_t i = 0; i < hn::Lanes(d); ++i) fast_sincos(xs[i], ss[i], cs[i]);
    s = SimdD(hn::Load(d, ss));
    c = SimdD(hn::Load(d, cs));
    return;
  }
  SimdD n, sr, cr;
  sincos_reduced(x, n, sr, cr);
  // Quadrant q = n mod 4: q odd swaps sin and cos; sin is negated for q = 2, 3, cos for q = 1, 2.
  const hn::RebindToSigned<SimdTag> di;
  const auto q = integer_bits(n);
  const auto one = hn::Set(di, 1), two = hn::Set(di, 2);
  const auto swap = hn::RebindMask(d, hn::Eq(hn::And(q, one), one));
  const auto neg_s = hn::RebindMask(d, hn::Eq(hn::And(q, two), two));
  const auto neg_c = hn::RebindMask(d, hn::Eq(hn::And(hn::Add(q, one), two), two));
  const SimdVec s0 = hn::IfThenElse(swap, cr.v, sr.v), c0 = hn::IfThenElse(swap, sr.v, cr.v);
  s = SimdD(hn::IfThenElse(neg_s, hn::Neg(s0), s0));
  c = SimdD(hn::IfThenElse(neg_c, hn::Neg(c0), c0));
}

HWY_API SimdD sin_t(SimdD x) {
  SimdD s, c;
  sincos_t(x, s, c);
  return s;
}
HWY_API SimdD sin(SimdD x) { return sin_t(x); }
HWY_API SimdD cos(SimdD x) {
  SimdD s, c;
  sincos_t(x, s, c);
  return c;
}

#include "spacetime/asin_core.h"  // asin_core: this target's copy

/// fast_asin (fast_math.h) lane by lane: the same operations (asin_core), so each lane equals
/// fast_asin of that lane to the bit.
HWY_API SimdD asin_t(SimdD x) { return asin_core(x); }

#include "spacetime/exp_reduced.h"  // exp_reduced: this target's copy

/// fast_exp (fast_math.h) lane by lane: the same reduction and polynomial (exp_reduced) and the
/// same exact scaling by 2^n (the exponent bits n + 1023), so each lane equals fast_exp of that
/// lane to the bit. Lanes outside |x| < 708 (and NaN) take fast_exp's own route through std::exp.
HWY_API SimdD exp_t(SimdD x) {
  const SimdTag d;
  if (HWY_UNLIKELY(!hn::AllTrue(d, hn::Lt(hn::Abs(x.v), hn::Set(d, 708.0))))) {
    HWY_ALIGN double xs[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(x.v, d, xs);
    for (size_t i = 0; i < hn::Lanes(d); ++i) xs[i] = fast_exp(xs[i]);
    return SimdD(hn::Load(d, xs));
  }
  SimdD n, er;
  exp_reduced(x, n, er);
  const hn::RebindToSigned<SimdTag> di;
  const auto bits = hn::ShiftLeft<52>(hn::Add(integer_bits(n), hn::Set(di, 1023)));
  return er * SimdD(hn::BitCast(d, bits));
}

// Dual numbers of lanes: dual_arith.h's Dual compiled for this target (Dual<SimdD, K>: lane l of
// each part is that of a Dual<double, K>) with its first-order functions on this target's sqrt,
// sincos_t and exp_t: the same operations, so a lane equals the scalar dual number to the bit.
#define GEOVIS_DUAL_ATTR HWY_ATTR __attribute__((always_inline))
#include "spacetime/dual_arith.h"  // Dual: this target's copy
#undef GEOVIS_DUAL_ATTR

/// A metric's acceleration template a = accel(x, k) (Vec4T<SimdD>) on a packet of `stride` lanes
/// in structure-of-arrays layout (geodesic_packet.h): y holds x^μ, k^μ (8 rows of `stride`
/// doubles), a receives a^μ (4 rows), one SimdD of lanes at a time.
template <class F>
HWY_INLINE void packet_acceleration_simd(const F& accel, const double* y, double* a, size_t stride) {
  for (size_t l = 0; l < stride; l += SimdD::lanes()) {
    Vec4T<SimdD> x, k, acc;
    for (int i = 0; i < 4; ++i) {
      x[i] = SimdD::load(y + i * stride + l);
      k[i] = SimdD::load(y + (4 + i) * stride + l);
    }
    accel(x, k, acc);
    for (int i = 0; i < 4; ++i) acc[i].store(a + i * stride + l);
  }
}

/// The Jacobi system's terms (JacobiTerms, metric_kernel.h) of a packet's Jacobi states y (the
/// layout of metric_kernel.h's kJacobi… rows, SoA of `stride` lanes) into t (kJacobiTermRows rows:
/// Gk[μ][b] at row 4μ + b, dGkk[f][μ] at row 16 + 4f + μ) from a metric's acceleration template
/// on first-order duals: jacobi_terms_from_accel (jacobi.h, where the derivation is) lane by lane,
/// with the same operations.
template <class F>
HWY_INLINE void packet_jacobi_terms_simd(const F& accel, const double* y, double* t, size_t stride) {
  using D = Dual<SimdD, 6>;
  for (size_t l = 0; l < stride; l += SimdD::lanes()) {
    Vec4T<D> x, k, a;
    for (int i = 0; i < 4; ++i) {
      x[i] = D(SimdD::load(y + (kJacobiX + i) * stride + l));
      x[i].d[0] = SimdD::load(y + (kJacobiY1 + i) * stride + l);
      x[i].d[1] = SimdD::load(y + (kJacobiY2 + i) * stride + l);
      k[i] = D(SimdD::load(y + (kJacobiK + i) * stride + l));
      k[i].d[2 + i] = SimdD(1.0);
    }
    accel(x, k, a);
    for (int mu = 0; mu < 4; ++mu) {
      for (int b = 0; b < 4; ++b) (a[mu].d[2 + b] * SimdD(-0.5)).store(t + (4 * mu + b) * stride + l);
      for (int f = 0; f < 2; ++f) (-a[mu].d[f]).store(t + (16 + 4 * f + mu) * stride + l);
    }
  }
}

/// The lanes of one vector where m holds, as bits (bit i: lane i of the vector); a packet's
/// functions shift them to the vector's first lane.
HWY_API unsigned mask_bits(SimdMask m) {
  uint8_t lane_bits[8] = {};  // StoreMaskBits writes up to 8 bytes
  hn::StoreMaskBits(SimdTag(), m.m, lane_bits);
  return lane_bits[0];
}

/// A metric's condition on the position x (a template over the number type giving a lane mask,
/// e.g. its validity domain) on a packet of `stride` lanes in structure-of-arrays layout (y holds
/// x^μ in its first 4 rows of `stride` doubles): bit l set where it holds on lane l.
template <class Condition>
HWY_INLINE unsigned packet_position_mask_simd(const Condition& condition, const double* y, size_t stride) {
  unsigned bits = 0;
  for (size_t l = 0; l < stride; l += SimdD::lanes()) {
    Vec4T<SimdD> x;
    for (int i = 0; i < 4; ++i) x[i] = SimdD::load(y + i * stride + l);
    bits |= mask_bits(condition(x)) << l;
  }
  return bits;
}

#include "spacetime/geodesic_constraint.h"  // geodesic_constraint: this target's copy

/// MetricSystem::constraint (integrators.h, geodesic_constraint) on a packet of `stride` lanes in
/// structure-of-arrays layout, one SimdD of lanes at a time: y holds x^μ, k^μ (8 rows of `stride`
/// doubles), value and scale receive one double per lane. metric_tensor(x, g) is the metric's
/// g_μν template (Mat4T<SimdD>); no_observer_norm(x, g, k) its own size of k where x^0 is no time
/// coordinate, or abs_quadratic_form's.
template <class MetricTensor, class NoObserverNorm>
HWY_INLINE void packet_constraint_simd(const MetricTensor& metric_tensor, const NoObserverNorm& no_observer_norm,
                                       const double* y, double target, double* value, double* scale, size_t stride) {
  for (size_t l = 0; l < stride; l += SimdD::lanes()) {
    Vec4T<SimdD> x, k;
    for (int i = 0; i < 4; ++i) {
      x[i] = SimdD::load(y + i * stride + l);
      k[i] = SimdD::load(y + (4 + i) * stride + l);
    }
    Mat4T<SimdD> g;
    metric_tensor(x, g);
    SimdD v, s;
    // This target's copy (geovis::geodesic_constraint is the scalar one).
    HWY_NAMESPACE::geodesic_constraint(g, k, target, [&] { return no_observer_norm(x, g, k); }, v, s);
    v.store(value + l);
    s.store(scale + l);
  }
}
/// The same for a metric whose x^0 is a time coordinate wherever its rays go (no size of k of its
/// own: abs_quadratic_form).
template <class MetricTensor>
HWY_INLINE void packet_constraint_simd(const MetricTensor& metric_tensor, const double* y, double target, double* value,
                                       double* scale, size_t stride) {
  packet_constraint_simd(
      metric_tensor,
      [](const Vec4T<SimdD>&, const Mat4T<SimdD>& g, const Vec4T<SimdD>& k) {
        return HWY_NAMESPACE::abs_quadratic_form(g, k);
      },
      y, target, value, scale, stride);
}

/// The same for a diagonal metric, from its template metric_diagonal(x, g) giving g_μμ (SimdD g[4]):
/// diagonal_geodesic_constraint, the bits of geodesic_constraint on the full g_μν without its
/// off-diagonal zeros.
template <class MetricDiagonal>
HWY_INLINE void packet_diagonal_constraint_simd(const MetricDiagonal& metric_diagonal, const double* y, double target,
                                                double* value, double* scale, size_t stride) {
  for (size_t l = 0; l < stride; l += SimdD::lanes()) {
    Vec4T<SimdD> x, k;
    for (int i = 0; i < 4; ++i) {
      x[i] = SimdD::load(y + i * stride + l);
      k[i] = SimdD::load(y + (4 + i) * stride + l);
    }
    SimdD g[4];
    metric_diagonal(x, g);
    SimdD v, s;
    HWY_NAMESPACE::diagonal_geodesic_constraint(g, k, target, v, s);
    v.store(value + l);
    s.store(scale + l);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#endif  // GEOVIS_SPACETIME_SIMD_H_

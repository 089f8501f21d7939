// The packet integrator (geodesic_packet.h). The Runge–Kutta attempt with its error norm and
// controller root (rk_attempt, mino_attempt), the Mino-time right-hand side and tolerance scales
// are compiled once per SIMD instruction set by Highway's foreach_target (this file includes
// itself per target); the per-lane step control and stop logic is compiled once
// (the HWY_ONCE part), as one driver over the system (integrate_lanes): the geodesic system in
// the metric's coordinates (CoordinatePacket), Carter's separated equations in Mino time
// (MinoPacket, kerr_mino.h), or those with their derivatives along two Jacobi fields on dual
// numbers of lanes (MinoJacobiPacket, kerr_jacobi.h: RGBjac's rays that hit), or the Jacobi system
// in the metric's coordinates (CoordinateJacobiPacket, jacobi_system.h: RGBjac's rays elsewhere).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/geodesic_packet.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_
#define GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

#include "core/error.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/integrators.h"
#include "spacetime/jacobi_system.h"
#include "spacetime/kerr_jacobi.h"
#include "spacetime/kerr_mino.h"
#include "spacetime/metric.h"
#include "spacetime/metric_kernel.h"

namespace geovis {
namespace {

constexpr int kDim = 8;  // y = (x^μ, k^μ)

/// dy = f(y) for the lanes in `lanes` (GeodesicRHS: dx/dλ = k, dk/dλ = −Γkk), SoA.
inline void packet_rhs(const MetricKernel& m, const double* y, double* dy, unsigned lanes) {
  std::memcpy(dy, y + 4 * kPacketLanes, 4 * kPacketLanes * sizeof(double));
  m.packet_acceleration(y, dy + 4 * kPacketLanes, lanes);
}

/// The constants of the rays in a packet's lanes (KerrMinoCoeffs, one row per coefficient; the
/// pole ζ is measured from; axis: all bits set where L = 0; the floor of sin²θ in the tolerance
/// scales; 1/r_break, KerrMinoSystem::w_break), for the SIMD right-hand side, tolerance scales
/// and state checks.
struct MinoLaneCoeffs {
  enum { M, A_SPIN, A2, E, L, Q, MU2, C, K, A, B, POLE, AXIS, SIN2_FLOOR, W_BREAK, kRows };
  alignas(64) double v[kRows][kPacketLanes] = {};
  /// Lane l's rows: the ray's constants, the pole of its state and 1/r_break.
  void set_lane(int l, const KerrMinoConstants& c, double pole, double w_break) {
    const double row[kRows] = {
        c.M, c.a, c.a2, c.E, c.L, c.Q, c.mu2, c.c, c.K, c.A, c.B, pole, c.axis ? 1.0 : 0.0, c.sin2_floor, w_break};
    for (int i = 0; i < kRows; ++i) v[i][l] = row[i];
  }
};

/// The coefficients of Carter's equations with their derivatives along the two Jacobi fields of the
/// rays in a packet's lanes (KerrMinoJacobiSystem::kd: value and the two derivative parts of each
/// coefficient, one row of kPacketLanes each) and the pole ζ is measured from, for the right-hand
/// side on dual numbers of SIMD lanes (mino_jacobi_rhs).
struct MinoJacobiLaneCoeffs {
  enum { M, A_SPIN, A2, E, L, Q, MU2, C, K, A, B, kCoeffs };
  alignas(64) double v[kCoeffs][3][kPacketLanes] = {};
  alignas(64) double pole[kPacketLanes] = {};
};

/// Where the Boyer–Lindquist views of the step ends of a packet's lanes go (each lane's
/// KerrMinoRay::EndView: x, k, dk/dλ and the pseudo-Cartesian position; a lane without a step
/// writes to a scratch view) and what they are computed from besides the state: the θ branch
/// (sign, offset) of each lane after its step, and which lanes have a step (active: 1, else 0).
struct MinoEndViews {
  alignas(64) double sign[kPacketLanes] = {}, offset[kPacketLanes] = {}, active[kPacketLanes] = {};
  KerrMinoRay::EndView* dst[kPacketLanes] = {};
  bool position_only = false;  ///< only EndView::p (KerrMinoRay::bl_step_with_position)
};

/// The error tolerance of a packet's lanes (ErrorScale): eps_abs, eps_rel and, for a system with
/// tolerance scales of its own, the 1/D_i of every lane (N rows of kPacketLanes, SoA; else null).
struct LaneTolerance {
  double eps_abs, eps_rel;
  const double* inv;
};

/// What the step control needs of an attempt besides y1, for every lane: the scaled error norm
/// (ErrorScale::norm), its root err^(1/q̂) for the step controller (StepController::next_with_root;
/// meaningful only where err > 0 is finite) and whether y1 is finite (bit l: lane l).
struct AttemptError {
  alignas(64) double err[kPacketLanes];
  alignas(64) double root[kPacketLanes];
  unsigned finite;
};

/// The step state of a packet's lanes (integrate_with's locals of each lane's run, integrators.h),
/// SoA: lane l at index l. Why not one struct per lane: the set-up of the trial steps, the tests
/// after an attempt and the lanes going on after their steps run on SIMD lanes (lane_setup,
/// lane_attempt_tests, lanes_go_on) instead of lane by lane with a branch per test (~250
/// instructions per lane and step in Mino time, ~170 in the metric's coordinates: callgrind of
/// integrate_lanes, issue 13).
struct LaneSteps {
  alignas(64) double lambda[kPacketLanes] = {};      ///< the integration variable
  alignas(64) double h[kPacketLanes] = {};           ///< the step size the control proposes
  alignas(64) double hstep[kPacketLanes] = {};       ///< the attempt's step size (h clipped to λ_max)
  alignas(64) double param1[kPacketLanes] = {};      ///< the integration variable after that step
  alignas(64) double h_cross[kPacketLanes] = {};     ///< the first step that left the domain (0: none)
  alignas(64) double affine0[kPacketLanes] = {};     ///< the affine parameter at the start
  alignas(64) double remaining[kPacketLanes] = {};   ///< λ_max less the affine distance run so far
  alignas(64) int64_t rhs_evals[kPacketLanes] = {};  ///< GeodesicResult::rhs_evals
  alignas(32) int steps[kPacketLanes] = {};          ///< GeodesicResult::steps (PacketSteps::step_index)
};

/// What lane_setup reads besides the lanes' step state.
struct LaneSetupParams {
  const double* affine;      ///< the affine parameter of each lane's state (a row of y), or null: λ
  const double* per_affine;  ///< dσ/dλ of each lane's state, or null: 1 (no affine parameter of its own)
  double lambda_max, lambda_res, hmax_affine, step_min, dir;
  double lambda_end;  ///< 0.0 + dir·λ_max: the integration variable after a step clipped to λ_max
};

/// Calls f.template operator()<Tab>() with the tableau of solver `kind` (one of those
/// packet_solver accepts).
template <class F>
decltype(auto) with_packet_tableau(SolverKind kind, F&& f) {
  switch (kind) {
    case SolverKind::Fehlberg45: return f.template operator()<FehlbergTableau>();
    case SolverKind::DormandPrince54: return f.template operator()<DormandPrince54Tableau>();
    case SolverKind::DormandPrince853: return f.template operator()<DOP853Tableau>();
    default: return f.template operator()<CashKarpTableau>();
  }
}

/// A tableau with DOP853's two embedded estimates (weights e5 and e3, DOP853Tableau) instead of
/// ExplicitRK's one (e).
template <class Tab>
constexpr bool kCombinedEstimate = requires {
  Tab::e5;
  Tab::e3;
};

}  // namespace
}  // namespace geovis
#endif  // GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {
#include "spacetime/kerr_mino_bl.h"
#include "spacetime/kerr_mino_rhs.h"

/// The dual numbers of a packet's Jacobi fields: lane l of each part is that of ray l's DualJ
/// (kerr_jacobi.h), with the same operations (dual_arith.h on SimdD).
using DualLanes = Dual<SimdD, 2>;

/// kerr_mino_rhs's choice of the axis form on dual numbers of lanes; the rays of the Jacobi packet
/// never take it (they are off the axis, L ≠ 0: KerrMinoJacobiRay), so `axis` is false for all
/// lanes, as for one ray (KerrMinoJacobiSystem).
template <int K>
HWY_INLINE Dual<SimdD, K> select(bool axis, const Dual<SimdD, K>& a, const Dual<SimdD, K>& b) {
  return axis ? a : b;
}

/// ExplicitRK<Tab>::attempt (integrators.h; DOP853::attempt for DOP853's tableau) on all lanes
/// at once for a system of N components whose right-hand side reads the first kCoupled
/// (rk_detail::coupled_dim): from y, dy = f(y) and the signed steps h (per lane), the new state y1,
/// the error estimate e (and DOP853's second one e3) and, for a first-same-as-last tableau
/// (Tab::kFsal), f(y1) = the last stage in dy1 (SoA). The same operations in the same order as
/// the scalar stepper's rk_detail::stage/weighted:
///   stage s: tmp_i = y_i + h·(((0 + a_s0 k_0i) + a_s1 k_1i) + …)   (non-zero a, i < kCoupled)
///   y1_i = y_i + h·Σ_j b_j k_ji,   e_i = h·Σ_j e_j k_ji
///   (DOP853: e_i = Σ_j e5_j k_ji, e3_i = Σ_j e3_j k_ji, without h).
/// A system whose first M components have the derivatives dy_i = y_{M+i} (kVelocityRows = M; the
/// geodesic system: dx^μ/dλ = k^μ, M = 4) gets only the other rows from rhs (called with the stage
/// state and the stage's k_j, rows M… to fill); for rows i < M the sums read k_ji = y_{M+i} from
/// the stage state itself (the values rhs would have copied there, so the same bits) — no copy per
/// stage, and one store-to-load round trip less between a stage's velocity and the next stage's
/// position. dy holds all N rows (k_0).
template <class Tab, int N, int kCoupled, int kVelocityRows = 0, class Rhs>
HWY_INLINE void rk_attempt_lanes(const Rhs& rhs, const double* y, const double* dy, const double* h, double* y1,
                                 double* e, double* e3, double* dy1) {
  constexpr int S = Tab::S, W = kPacketLanes, M = kVelocityRows;
  static_assert(M == 0 || (2 * M <= kCoupled && kCoupled == N));
  const SimdTag d;
  const size_t L = hn::Lanes(d);
  HWY_ALIGN double k[S][N * W];
  std::memcpy(k[0], dy, sizeof k[0]);
  // The stage states: one per stage where their velocity rows stand in for k_j's first M rows.
  HWY_ALIGN double tmp[M > 0 ? S : 1][N * W];
  auto stage_state = [&](int st) -> double* { return tmp[M > 0 ? st : 0]; };
  // Row i of k_j.
  auto k_row = [&](int j, int i) -> const double* {
    return M > 0 && j > 0 && i < M ? stage_state(j) + (M + i) * W : k[j] + i * W;
  };
  if constexpr (kCoupled < N) std::memcpy(tmp[0] + kCoupled * W, y + kCoupled * W, (N - kCoupled) * W * sizeof(double));
  // clang-format off
  [&]<int... s>(std::integer_sequence<int, s...>) {
    ([&] {
      constexpr int st = s + 1;
      double* const state = stage_state(st);
      for (size_t l = 0; l < static_cast<size_t>(W); l += L) {
        const SimdD hv = SimdD::load(h + l);
        for (int i = 0; i < kCoupled; ++i) {
          SimdD acc(0.0);
          [&]<int... j>(std::integer_sequence<int, j...>) {
            ([&] {
              if constexpr (Tab::a[st][j] != 0.0) acc = acc + SimdD(Tab::a[st][j]) * SimdD::load(k_row(j, i) + l);
            }(), ...);
          }(std::make_integer_sequence<int, st>{});
          (SimdD::load(y + i * W + l) + hv * acc).store(state + i * W + l);
        }
      }
      rhs(state, k[st]);
    }(), ...);
  }(std::make_integer_sequence<int, S - 1>{});
  for (size_t l = 0; l < static_cast<size_t>(W); l += L) {
    const SimdD hv = SimdD::load(h + l);
    for (int i = 0; i < N; ++i) {
      SimdD ab(0.0), ae(0.0), ae3(0.0);
      [&]<int... j>(std::integer_sequence<int, j...>) {
        ([&] {
          const SimdD kj = SimdD::load(k_row(j, i) + l);
          if constexpr (Tab::b[j] != 0.0) ab = ab + SimdD(Tab::b[j]) * kj;
          if constexpr (kCombinedEstimate<Tab>) {
            if constexpr (Tab::e5[j] != 0.0) ae = ae + SimdD(Tab::e5[j]) * kj;
            if constexpr (Tab::e3[j] != 0.0) ae3 = ae3 + SimdD(Tab::e3[j]) * kj;
          } else {
            if constexpr (Tab::e[j] != 0.0) ae = ae + SimdD(Tab::e[j]) * kj;
          }
        }(), ...);
      }(std::make_integer_sequence<int, S>{});
      // clang-format on
      (SimdD::load(y + i * W + l) + hv * ab).store(y1 + i * W + l);
      if constexpr (kCombinedEstimate<Tab>) {
        ae.store(e + i * W + l);
        ae3.store(e3 + i * W + l);
      } else {
        (hv * ae).store(e + i * W + l);
      }
    }
  }
  if constexpr (Tab::kFsal) {
    std::memcpy(dy1, stage_state(S - 1) + M * W, M * W * sizeof(double));
    std::memcpy(dy1 + M * W, k[S - 1] + M * W, (N - M) * W * sizeof(double));
  }
}

/// ErrorScale::norm of the estimate e on every lane: max_i |e_i|/D_i and NaN where an e_i is NaN,
/// with the same operations per lane as the scalar stepper (std::max(m, v) as the select
/// m < v ? v : m, so a NaN quotient is skipped as there).
template <int N>
HWY_INLINE void error_scale_norm_lanes(const LaneTolerance& tol, const double* y, const double* e, double* err) {
  constexpr int W = kPacketLanes;
  // The maximum over the components of term(i, |e_i|) on lanes l..l+lanes−1.
  auto max_over = [&](size_t l, SimdMask& nan, auto term) {
    SimdD m(0.0);
    for (int i = 0; i < N; ++i) {
      const SimdD a = fabs(SimdD::load(e + i * W + l));
      nan = nan || a != a;
      const SimdD v = term(i, a);
      m = select(m < v, v, m);
    }
    return m;
  };
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    SimdMask nan{hn::FirstN(SimdTag(), 0)};
    SimdD m;
    if (tol.inv) {
      m = max_over(l, nan, [&](int i, SimdD a) { return a * SimdD::load(tol.inv + i * W + l); });
    } else if (tol.eps_rel == 0.0) {
      m = max_over(l, nan, [](int, SimdD a) { return a; }) / SimdD(tol.eps_abs);
    } else {
      m = max_over(l, nan, [&](int i, SimdD a) {
        return a / (SimdD(tol.eps_abs) + SimdD(tol.eps_rel) * fabs(SimdD::load(y + i * W + l)));
      });
    }
    select(nan, SimdD(std::numeric_limits<double>::quiet_NaN()), m).store(err + l);
  }
}

/// The scaled error of the steps h (per lane) from the attempt's estimate(s) at the start states
/// y, on every lane: the stepper's own norm, ExplicitRK's ErrorScale::norm of e = h·Σ e_j k_j, or
/// DOP853's combined norm of e = Σ e5_j k_j and e3 = Σ e3_j k_j (DOP853::combined_error, the
/// scalar stepper's function, lane by lane).
template <class Tab, int N>
HWY_INLINE void step_error_norm_lanes(const LaneTolerance& tol, const double* y, const double* e, const double* e3,
                                      const double* h, double* err) {
  error_scale_norm_lanes<N>(tol, y, e, err);
  if constexpr (kCombinedEstimate<Tab>) {
    HWY_ALIGN double err3[kPacketLanes];
    error_scale_norm_lanes<N>(tol, y, e3, err3);
    for (int l = 0; l < kPacketLanes; ++l) err[l] = DOP853::combined_error(err[l], err3[l], h[l]);
  }
}

/// root_q<q>(x) (integrators.h) on every lane where x > 0 is finite, the same operations per lane
/// (the bit-pattern seed lane by lane: 64-bit integer division has no SIMD instruction).
template <int q>
HWY_INLINE void root_q_lanes(const double* x, double* root) {
  constexpr int W = kPacketLanes;
  if constexpr (q == 5 || q == 7) {
    HWY_ALIGN double seed[W];
    for (int l = 0; l < W; ++l) seed[l] = x[l] > 0.0 && std::isfinite(x[l]) ? root_q_seed<q>(x[l]) : 1.0;
    for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
      const SimdD xv = SimdD::load(x + l);
      SimdD y = SimdD::load(seed + l);
      for (int it = 0; it < 4; ++it) {
        const SimdD y2 = y * y;
        if constexpr (q == 5) {
          y = y * (SimdD(6.0) - xv * (y2 * y2 * y)) * SimdD(0.2);
        } else {
          const SimdD y3 = y2 * y;
          y = y * (SimdD(8.0) - xv * (y3 * y3 * y)) * SimdD(1.0 / 7.0);
        }
      }
      (SimdD(1.0) / y).store(root + l);
    }
  } else if constexpr (q == 1 || q == 2 || q == 4 || q == 8) {
    for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
      SimdD r = SimdD::load(x + l);
      for (int s = 1; s < q; s *= 2) r = sqrt(r);
      r.store(root + l);
    }
  } else {
    for (int l = 0; l < W; ++l) root[l] = x[l] > 0.0 && std::isfinite(x[l]) ? root_q<q>(x[l]) : 0.0;
  }
}

/// The attempt's AttemptError: the error norm of e (and e3), its root and the finiteness of y1
/// per lane.
template <class Tab, int N>
HWY_INLINE void attempt_error_lanes(const LaneTolerance& tol, const double* y, const double* y1, const double* e,
                                    const double* e3, const double* h, AttemptError& out) {
  constexpr int W = kPacketLanes;
  step_error_norm_lanes<Tab, N>(tol, y, e, e3, h, out.err);
  root_q_lanes<Tab::kErrExp>(out.err, out.root);
  HWY_ALIGN double finite[W];
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    SimdMask all{hn::IsFinite(SimdD::load(y1 + l).v)};
    for (int i = 1; i < N; ++i) all = all && SimdMask{hn::IsFinite(SimdD::load(y1 + i * W + l).v)};
    select(all, SimdD(1.0), SimdD(0.0)).store(finite + l);
  }
  out.finite = 0;
  for (int l = 0; l < W; ++l) out.finite |= (finite[l] != 0.0 ? 1u : 0u) << l;
}

/// The attempt of solver `kind` on the geodesic system in the metric's coordinates (lanes: those
/// whose right-hand side is needed, for metrics evaluated lane by lane), with its AttemptError.
void rk_attempt(SolverKind kind, const MetricKernel& m, unsigned lanes, const LaneTolerance& tol, const double* y,
                const double* dy, const double* h, double* y1, double* dy1, AttemptError& err) {
  with_packet_tableau(kind, [&]<class Tab>() {
    HWY_ALIGN double e[kDim * kPacketLanes];
    HWY_ALIGN double e3[kCombinedEstimate<Tab> ? kDim * kPacketLanes : 1];
    // dx/dλ = k: rk_attempt_lanes reads it from the stage states; the metric gives dk/dλ.
    rk_attempt_lanes<Tab, kDim, kDim, 4>(
        [&](const double* yy, double* dyy) { m.packet_acceleration(yy, dyy + 4 * kPacketLanes, lanes); }, y, dy, h, y1,
        e, e3, dy1);
    attempt_error_lanes<Tab, kDim>(tol, y, y1, e, e3, h, err);
  });
}

/// The coefficients of Carter's equations (KerrMinoCoeffs) of the lanes l … l + SimdD::lanes() − 1.
HWY_INLINE KerrMinoCoeffs<SimdD> mino_coeffs_at(const MinoLaneCoeffs& c, size_t l) {
  using R = MinoLaneCoeffs;
  auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
  return {at(R::M), at(R::A_SPIN), at(R::A2), at(R::E), at(R::L), at(R::Q),
          at(R::MU2), at(R::C), at(R::K), at(R::A), at(R::B)};
}

/// The lanes l … l + SimdD::lanes() − 1 whose rays can pass through the polar axis (L = 0).
HWY_INLINE SimdMask mino_axis_at(const MinoLaneCoeffs& c, size_t l) {
  const SimdTag d;
  return {hn::Ne(SimdD::load(c.v[MinoLaneCoeffs::AXIS] + l).v, hn::Zero(d))};
}

/// kerr_mino_rhs (kerr_mino.h) on every lane: the Mino-time right-hand side, SoA (KerrMinoRHS's
/// components, kPacketLanes per row).
HWY_INLINE void mino_rhs_lanes(const MinoLaneCoeffs& c, const double* y, double* dy) {
  using R = MinoLaneCoeffs;
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    const KerrMinoCoeffs<SimdD> k = mino_coeffs_at(c, l);
    const SimdMask axis = mino_axis_at(c, l);
    SimdD ys[N], dys[N];
    for (int i = 0; i < N; ++i) ys[i] = SimdD::load(y + i * W + l);
    HWY_NAMESPACE::kerr_mino_rhs(k, axis, at(R::POLE), ys, dys);  // this target's copy
    for (int i = 0; i < N; ++i) dys[i].store(dy + i * W + l);
  }
}

void mino_rhs(const MinoLaneCoeffs& c, const double* y, double* dy) { mino_rhs_lanes(c, y, dy); }

/// The attempt of solver `kind` on the Mino-time system (t, φ, λ are quadratures:
/// KerrMinoRHS::kCoupled), with its AttemptError.
void mino_attempt(SolverKind kind, const MinoLaneCoeffs& c, const LaneTolerance& tol, const double* y, const double* dy,
                  const double* h, double* y1, double* dy1, AttemptError& err) {
  with_packet_tableau(kind, [&]<class Tab>() {
    constexpr int N = KerrMinoRHS::N;
    HWY_ALIGN double e[N * kPacketLanes];
    HWY_ALIGN double e3[kCombinedEstimate<Tab> ? N * kPacketLanes : 1];
    rk_attempt_lanes<Tab, N, KerrMinoRHS::kCoupled>([&](const double* yy, double* dyy) { mino_rhs_lanes(c, yy, dyy); },
                                                    y, dy, h, y1, e, e3, dy1);
    attempt_error_lanes<Tab, N>(tol, y, y1, e, e3, h, err);
  });
}

/// The coefficients with derivatives (KerrMinoCoeffs<DualLanes>) of the lanes l … l + SimdD::lanes() − 1.
HWY_INLINE KerrMinoCoeffs<DualLanes> mino_jacobi_coeffs_at(const MinoJacobiLaneCoeffs& c, size_t l) {
  using R = MinoJacobiLaneCoeffs;
  auto at = [&](int row) {
    DualLanes x;
    x.v = SimdD::load(c.v[row][0] + l);
    x.d[0] = SimdD::load(c.v[row][1] + l);
    x.d[1] = SimdD::load(c.v[row][2] + l);
    return x;
  };
  return {at(R::M),   at(R::A_SPIN), at(R::A2), at(R::E), at(R::L), at(R::Q),
          at(R::MU2), at(R::C),      at(R::K),  at(R::A), at(R::B)};
}

/// KerrMinoJacobiSystem's right-hand side (kerr_mino_rhs on dual numbers, kerr_jacobi.h) on every
/// lane, SoA in MinoJacobiLayout: lane l equals the scalar system of ray l to the bit.
HWY_INLINE void mino_jacobi_rhs_lanes(const MinoJacobiLaneCoeffs& c, const double* y, double* dy) {
  using J = MinoJacobiLayout;
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const KerrMinoCoeffs<DualLanes> k = mino_jacobi_coeffs_at(c, l);
    DualLanes ys[N], dys[N];
    for (int i = 0; i < KerrMinoRHS::kCoupled; ++i) {  // the right-hand side reads no quadrature
      ys[i].v = SimdD::load(y + J::at(i, -1) * W + l);
      for (int f = 0; f < 2; ++f) ys[i].d[f] = SimdD::load(y + J::at(i, f) * W + l);
    }
    HWY_NAMESPACE::kerr_mino_rhs(k, false, SimdD::load(c.pole + l), ys, dys);  // this target's copy
    for (int i = 0; i < N; ++i) {
      dys[i].v.store(dy + J::at(i, -1) * W + l);
      for (int f = 0; f < 2; ++f) dys[i].d[f].store(dy + J::at(i, f) * W + l);
    }
  }
}

void mino_jacobi_rhs(const MinoJacobiLaneCoeffs& c, const double* y, double* dy) { mino_jacobi_rhs_lanes(c, y, dy); }

/// The attempt of solver `kind` on the Mino-time Jacobi system (the quadratures of the value and of
/// the derivatives last: MinoJacobiLayout::kCoupled), with its AttemptError.
void mino_jacobi_attempt(SolverKind kind, const MinoJacobiLaneCoeffs& c, const LaneTolerance& tol, const double* y,
                         const double* dy, const double* h, double* y1, double* dy1, AttemptError& err) {
  with_packet_tableau(kind, [&]<class Tab>() {
    constexpr int N = MinoJacobiLayout::N;
    HWY_ALIGN double e[N * kPacketLanes];
    HWY_ALIGN double e3[kCombinedEstimate<Tab> ? N * kPacketLanes : 1];
    rk_attempt_lanes<Tab, N, MinoJacobiLayout::kCoupled>(
        [&](const double* yy, double* dyy) { mino_jacobi_rhs_lanes(c, yy, dyy); }, y, dy, h, y1, e, e3, dy1);
    attempt_error_lanes<Tab, N>(tol, y, y1, e, e3, h, err);
  });
}

/// integrate_with's set_tolerance for the Mino-time Jacobi system on every lane (SoA): the 1/D_i
/// of ErrorScale from KerrMinoJacobiSystem::tolerance_inv_scale at state y — the value's scales
/// (kerr_mino_tolerance_inv_scale), each derivative's relative to its own size max(1, max_i
/// |V_f,i|/s_i) — with the scalar function's operations (std::max(a, b) as a < b ? b : a).
void mino_jacobi_tolerance(const MinoLaneCoeffs& c, double eps_abs, double eps_rel, const double* y, double* inv) {
  using R = MinoLaneCoeffs;
  using J = MinoJacobiLayout;
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  const double inv_eps_abs = 1.0 / eps_abs;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    SimdD ys[N], iv[N], is[J::N];
    for (int i = 0; i < N; ++i) ys[i] = SimdD::load(y + J::at(i, -1) * W + l);
    HWY_NAMESPACE::kerr_mino_tolerance_inv_scale(at(R::A2), at(R::SIN2_FLOOR), at(R::POLE), ys, iv);
    for (int i = 0; i < N; ++i) is[J::at(i, -1)] = iv[i];
    for (int f = 0; f < 2; ++f) {
      SimdD size(1.0);
      for (int i = 0; i < N; ++i) {
        const SimdD x = fabs(SimdD::load(y + J::at(i, f) * W + l)) * iv[i];
        size = select(size < x, x, size);
      }
      const SimdD inv_size = SimdD(1.0) / size;
      for (int i = 0; i < N; ++i) is[J::at(i, f)] = iv[i] * inv_size;
    }
    for (int i = 0; i < J::N; ++i) {
      if (eps_rel == 0.0)
        is[i] = is[i] * SimdD(inv_eps_abs);
      else
        is[i] = SimdD(1.0) / (SimdD(eps_abs) / is[i] + SimdD(eps_rel) * fabs(SimdD::load(y + i * W + l)));
      is[i].store(inv + i * W + l);
    }
  }
}

/// JacobiRHS (jacobi.h) from the Jacobi system's terms t of a packet's lanes
/// (MetricKernel::packet_jacobi_terms), with its operations in its order on SIMD lanes: the rows
/// from kJacobiK on of dy (the rows dx/dλ = k are rk_attempt_lanes's velocity rows, or
/// coordinate_jacobi_rhs's copy).
HWY_INLINE void jacobi_rhs_rows_lanes(const double* y, const double* t, double* dy) {
  constexpr size_t W = kPacketLanes;
  for (size_t l = 0; l < W; l += SimdD::lanes()) {
    auto at = [&](const double* p, int row) { return SimdD::load(p + row * W + l); };
    SimdD Gk[4][4];
    for (int mu = 0; mu < 4; ++mu)
      for (int b = 0; b < 4; ++b) Gk[mu][b] = at(t, 4 * mu + b);
    auto contract = [&](int mu, const SimdD (&e)[4]) {
      return Gk[mu][0] * e[0] + Gk[mu][1] * e[1] + Gk[mu][2] * e[2] + Gk[mu][3] * e[3];
    };
    for (int v = 0; v < 3; ++v) {  // k, s1, s2: e' = −Γ(k, e)
      const SimdD e[4] = {at(y, kJacobiK + 4 * v), at(y, kJacobiK + 4 * v + 1), at(y, kJacobiK + 4 * v + 2),
                          at(y, kJacobiK + 4 * v + 3)};
      for (int mu = 0; mu < 4; ++mu) (-contract(mu, e)).store(dy + (kJacobiK + 4 * v + mu) * W + l);
    }
    for (int f = 0; f < 2; ++f) {
      const int dy_row = kJacobiDY1 + 8 * f;
      const SimdD d[4] = {at(y, dy_row), at(y, dy_row + 1), at(y, dy_row + 2), at(y, dy_row + 3)};
      for (int mu = 0; mu < 4; ++mu) {
        d[mu].store(dy + (kJacobiY1 + 8 * f + mu) * W + l);
        (-(SimdD(2.0) * contract(mu, d) + at(t, 16 + 4 * f + mu))).store(dy + (dy_row + mu) * W + l);
      }
    }
  }
}

/// dy = f(y) of the Jacobi system in the metric's coordinates for the lanes in `lanes`; the other
/// lanes' dy are left as they are (they hold f of their states, which the terms t — room for
/// kJacobiTermRows rows — need not have for those lanes).
void coordinate_jacobi_rhs(const MetricKernel& m, unsigned lanes, const double* y, double* dy, double* t) {
  constexpr int W = kPacketLanes;
  m.packet_jacobi_terms(y, t, lanes);
  HWY_ALIGN double f[kJacobiDim * W];
  std::memcpy(f + kJacobiX * W, y + kJacobiK * W, 4 * W * sizeof(double));
  jacobi_rhs_rows_lanes(y, t, f);
  const SimdTag d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const auto on = hn::LoadMaskBits(d, &bits);
    for (int i = 0; i < kJacobiDim; ++i) hn::BlendedStore(hn::LoadU(d, f + i * W + l), on, d, dy + i * W + l);
  }
}

/// The attempt of solver `kind` on the Jacobi system in the metric's coordinates (as rk_attempt:
/// dx/dλ = k read from the stage states, the other rows from coordinate_jacobi_rhs's).
void coordinate_jacobi_attempt(SolverKind kind, const MetricKernel& m, unsigned lanes, const LaneTolerance& tol,
                               const double* y, const double* dy, const double* h, double* y1, double* dy1,
                               AttemptError& err, double* t) {
  with_packet_tableau(kind, [&]<class Tab>() {
    HWY_ALIGN double e[kJacobiDim * kPacketLanes];
    HWY_ALIGN double e3[kCombinedEstimate<Tab> ? kJacobiDim * kPacketLanes : 1];
    rk_attempt_lanes<Tab, kJacobiDim, kJacobiDim, 4>(
        [&](const double* yy, double* dyy) {
          m.packet_jacobi_terms(yy, t, lanes);
          jacobi_rhs_rows_lanes(yy, t, dyy);
        },
        y, dy, h, y1, e, e3, dy1);
    attempt_error_lanes<Tab, kJacobiDim>(tol, y, y1, e, e3, h, err);
  });
}

/// The 1/D_i of integrate_with's set_tolerance for JacobiSystem (jacobi_system.h:
/// tolerance_inv_scale, then eps_abs and eps_rel) on every lane, with its operations
/// (std::max(size, v) as the select size < v ? v : size).
void coordinate_jacobi_tolerance(double eps_abs, double eps_rel, const double* y, double* inv) {
  constexpr int W = kPacketLanes;
  const double inv_eps_abs = 1.0 / eps_abs;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    SimdD is[kJacobiDim];
    for (int i = 0; i < kJacobiY1; ++i) is[i] = SimdD(1.0);
    for (int f = 0; f < 2; ++f) {
      const int row = kJacobiY1 + 8 * f;  // Y_f (4) then Y_f' (4)
      SimdD size(1.0);
      for (int i = 0; i < 8; ++i) {
        const SimdD v = fabs(SimdD::load(y + (row + i) * W + l));
        size = select(size < v, v, size);
      }
      const SimdD inv_size = SimdD(1.0) / size;
      for (int i = 0; i < 8; ++i) is[row + i] = inv_size;
    }
    for (int i = 0; i < kJacobiDim; ++i) {
      if (eps_rel == 0.0)
        is[i] = is[i] * SimdD(inv_eps_abs);
      else
        is[i] = SimdD(1.0) / (SimdD(eps_abs) / is[i] + SimdD(eps_rel) * fabs(SimdD::load(y + i * W + l)));
      is[i].store(inv + i * W + l);
    }
  }
}

/// kerr_mino_bl_view (kerr_mino_bl.h) on every lane: the BL views of the Mino states y with
/// σ-derivatives dy (SoA) on the lanes' θ branches, written to each lane's view (out.dst), or
/// only their pseudo-Cartesian positions (out.position_only: kerr_mino_position). A lane
/// without a step (its y may be a rejected attempt, NaN) is viewed at φ = 0, which keeps sincos_t
/// off its lane-by-lane route for arguments it cannot reduce.
void mino_end_views(const MinoLaneCoeffs& c, const double* y, const double* dy, const MinoEndViews& out) {
  using R = MinoLaneCoeffs;
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  const SimdTag d;
  const size_t L = SimdD::lanes();
  for (size_t l = 0; l < static_cast<size_t>(W); l += L) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    const KerrMinoCoeffs<SimdD> k = mino_coeffs_at(c, l);
    const SimdMask axis = mino_axis_at(c, l);
    const SimdMask active{hn::Ne(SimdD::load(out.active + l).v, hn::Zero(d))};
    SimdD ys[N], dys[N];
    for (int i = 0; i < N; ++i) {
      ys[i] = SimdD::load(y + i * W + l);
      dys[i] = SimdD::load(dy + i * W + l);
    }
    ys[KerrMinoRHS::PHI] = select(active, ys[KerrMinoRHS::PHI], SimdD(0.0));
    if (out.position_only) {
      SimdD p[3];
      HWY_NAMESPACE::kerr_mino_position(at(R::POLE), SimdD::load(out.sign + l), ys, p);  // this target's copy
      HWY_ALIGN double rows[3][HWY_MAX_BYTES / sizeof(double)];
      for (int i = 0; i < 3; ++i) p[i].store(rows[i]);
      for (size_t j = 0; j < L; ++j) {
        double* e = out.dst[l + j]->p;
        for (int i = 0; i < 3; ++i) e[i] = rows[i][j];
      }
      continue;
    }
    // v = (x, k, dk/dλ, p, 0): the rows of the views in EndView's order (xk, then p and its pad).
    SimdD v[16];
    HWY_NAMESPACE::kerr_mino_bl_view(k, axis, at(R::POLE), SimdD::load(out.sign + l), SimdD::load(out.offset + l), ys,
                                     dys, v, v + 4, v + 8, v + 12);  // this target's copy
    v[15] = SimdD(0.0);
#if HWY_TARGET == HWY_AVX2
    // Four lanes: each group of four rows transposed (4×4: two rounds of shuffles) and stored as
    // four consecutive doubles of each lane's view, instead of 16 scalar copies per lane.
    for (int g = 0; g < 4; ++g) {
      const SimdVec r0 = v[4 * g].v, r1 = v[4 * g + 1].v, r2 = v[4 * g + 2].v, r3 = v[4 * g + 3].v;
      const SimdVec t0 = hn::InterleaveLower(d, r0, r1), t1 = hn::InterleaveUpper(d, r0, r1);  // [a0 b0 a2 b2], [a1 b1 a3 b3]
      const SimdVec t2 = hn::InterleaveLower(d, r2, r3), t3 = hn::InterleaveUpper(d, r2, r3);  // [c0 d0 c2 d2], [c1 d1 c3 d3]
      const SimdVec lane_rows[4] = {hn::ConcatLowerLower(d, t2, t0), hn::ConcatLowerLower(d, t3, t1),
                                    hn::ConcatUpperUpper(d, t2, t0), hn::ConcatUpperUpper(d, t3, t1)};
      for (size_t j = 0; j < 4; ++j) {
        KerrMinoRay::EndView& e = *out.dst[l + j];
        hn::StoreU(lane_rows[j], d, g < 3 ? e.xk + 4 * g : e.p);
      }
    }
#else
    HWY_ALIGN double rows[15][HWY_MAX_BYTES / sizeof(double)];
    for (int i = 0; i < 15; ++i) v[i].store(rows[i]);
    for (size_t j = 0; j < L; ++j) {
      KerrMinoRay::EndView& e = *out.dst[l + j];
      for (int i = 0; i < 12; ++i) e.xk[i] = rows[i][j];
      for (int i = 0; i < 3; ++i) e.p[i] = rows[12 + i][j];
    }
#endif
  }
}

/// kerr_mino_position (kerr_mino_bl.h) of the states y (SoA) on every lane, on the θ branches of
/// sign `sign`, to p (SoA, 3 rows of kPacketLanes): the positions of the step ends of the lanes in
/// `lanes` (the others, whose y may be a rejected attempt, NaN, are viewed at φ = 0, as in
/// mino_end_views).
void mino_end_positions(const MinoLaneCoeffs& c, const double* y, const double* sign, unsigned lanes, double* p) {
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  const SimdTag d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const SimdMask active{hn::LoadMaskBits(d, &bits)};
    SimdD ys[N];
    for (int i = 0; i < N; ++i) ys[i] = SimdD::load(y + i * W + l);
    ys[KerrMinoRHS::PHI] = select(active, ys[KerrMinoRHS::PHI], SimdD(0.0));
    SimdD pp[3];
    HWY_NAMESPACE::kerr_mino_position(SimdD::load(c.v[MinoLaneCoeffs::POLE] + l), SimdD::load(sign + l), ys,
                                      pp);  // this target's copy
    for (int i = 0; i < 3; ++i) pp[i].store(p + i * W + l);
  }
}

/// The tests of KerrMinoSystem after a step on the states y (SoA) of every lane, with the scalar
/// tests' comparisons: bit l of the result where lane l's ζ is to be re-based (!(|ζ| <= 1),
/// KerrMinoSystem::rebase), bit 8 + l where its w, t and φ lie in the box (KerrMinoSystem::inside
/// but for θ; box = w_lo, w_hi, t_lo, t_hi, φ_lo, φ_hi, the same for every ray).
unsigned mino_state_tests(const double* box, const double* y) {
  using I = KerrMinoRHS;
  constexpr int W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const SimdD w = SimdD::load(y + I::W * W + l), t = SimdD::load(y + I::T * W + l);
    const SimdD phi = SimdD::load(y + I::PHI * W + l), zeta = SimdD::load(y + I::Z * W + l);
    const SimdMask rebase = !(fabs(zeta) <= SimdD(1.0));
    const SimdMask in = w >= SimdD(box[0]) && w <= SimdD(box[1]) && t >= SimdD(box[2]) && t <= SimdD(box[3]) &&
                        phi >= SimdD(box[4]) && phi <= SimdD(box[5]);
    bits |= mask_bits(rebase) << l | mask_bits(in) << (8 + l);
  }
  return bits;
}

/// KerrMinoSystem::valid of the states y (SoA) on every lane in `lanes`: bit l set where lane l's
/// state is valid — 0 < w < w_break and, on the axis branch (L = 0), |z| <= 1 + 1e-3, else
/// sin²θ > 0 — with the scalar test's operations, all lanes at once.
unsigned mino_valid(const MinoLaneCoeffs& c, const double* y, unsigned lanes) {
  using R = MinoLaneCoeffs;
  using I = KerrMinoRHS;
  constexpr int W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    const SimdD w = SimdD::load(y + I::W * W + l), zeta = SimdD::load(y + I::Z * W + l), pole = at(R::POLE);
    const SimdMask axis = mino_axis_at(c, l);
    const SimdMask near_pole = fabs(pole + zeta) <= SimdD(1.0 + 1e-3);  // PolarOffset::z
    const SimdMask off_axis = -zeta * (2.0 * pole + zeta) > SimdD(0.0);  // PolarOffset::sin2
    const SimdMask ok =
        w > SimdD(0.0) && w < at(R::W_BREAK) && ((axis && near_pole) || (!axis && off_axis));
    bits |= mask_bits(ok) << l;
  }
  return bits & lanes;
}

/// KerrMinoSystem::constraint of the states y (SoA) on every lane (kerr_mino_constraint, the
/// scalar system's formula): value and scale, one double per lane. Returns the lanes past the
/// first tests of KerrMinoSystem::escaped (bit l: beyond escape_radius, w·r_esc < 1, moving
/// outward) and captured (bit 8 + l: below capture_radius, w·r_cap > 1, moving inward), with
/// their expressions; `outward` is −1 for integration forward in λ, +1 backward (the sign
/// of w' that escaped takes for outward).
unsigned mino_constraint(const MinoLaneCoeffs& c, const double* y, double escape_radius, double capture_radius,
                         double outward, double* value, double* scale) {
  using R = MinoLaneCoeffs;
  using I = KerrMinoRHS;
  constexpr int W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    const KerrMinoCoeffs<SimdD> k = mino_coeffs_at(c, l);
    SimdD ys[4];
    for (int i = 0; i < 4; ++i) ys[i] = SimdD::load(y + i * W + l);
    SimdD v, s;
    HWY_NAMESPACE::kerr_mino_constraint(k, at(R::POLE), ys, v, s);  // this target's copy
    v.store(value + l);
    s.store(scale + l);
    const SimdD w = ys[I::W], dw = ys[I::DW];
    const SimdMask may_escape = w * SimdD(escape_radius) < SimdD(1.0) && SimdD(outward) * dw > SimdD(0.0);
    const SimdMask may_be_captured = w * SimdD(capture_radius) > SimdD(1.0) && SimdD(-outward) * dw > SimdD(0.0);
    bits |= mask_bits(may_escape) << l | mask_bits(may_be_captured) << (8 + l);
  }
  return bits;
}

/// KerrMinoSystem::param_per_affine (kerr_mino_param_per_affine) of the states y (SoA) on every
/// lane, the scalar function's template, so its bits. Why: the scalar division of each lane
/// before each attempt stalled the driver (perf annotate of kerrAccretionDisk.scm, issue 13).
void mino_param_per_affine(const MinoLaneCoeffs& c, const double* y, double* out) {
  using R = MinoLaneCoeffs;
  using I = KerrMinoRHS;
  constexpr int W = kPacketLanes;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const SimdD w = SimdD::load(y + I::W * W + l);
    const SimdD z = SimdD::load(c.v[R::POLE] + l) + SimdD::load(y + I::Z * W + l);  // PolarOffset::z
    HWY_NAMESPACE::kerr_mino_param_per_affine(SimdD::load(c.v[R::A2] + l), w, z).store(out + l);
  }
}

/// integrate_with's set_tolerance (integrators.h) for the Mino-time system on every lane: the 1/D_i
/// of ErrorScale from the system's scales (kerr_mino_tolerance_inv_scale) at state y, SoA.
void mino_tolerance(const MinoLaneCoeffs& c, double eps_abs, double eps_rel, const double* y, double* inv) {
  using R = MinoLaneCoeffs;
  constexpr int N = KerrMinoRHS::N, W = kPacketLanes;
  const double inv_eps_abs = 1.0 / eps_abs;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    auto at = [&](int row) { return SimdD::load(c.v[row] + l); };
    SimdD ys[N], is[N];
    for (int i = 0; i < N; ++i) ys[i] = SimdD::load(y + i * W + l);
    HWY_NAMESPACE::kerr_mino_tolerance_inv_scale(at(R::A2), at(R::SIN2_FLOOR), at(R::POLE), ys, is);
    for (int i = 0; i < N; ++i) {
      if (eps_rel == 0.0)
        is[i] = is[i] * SimdD(inv_eps_abs);
      else
        is[i] = SimdD(1.0) / (SimdD(eps_abs) / is[i] + SimdD(eps_rel) * fabs(ys[i]));
      is[i].store(inv + i * W + l);
    }
  }
}

/// packet_accepted_step_control (geodesic_packet.h) on SIMD lanes: StepController::next_with_root
/// (integrators.h) for an accepted step, each branch as a select and every std::min/max/clamp as
/// the select its libstdc++ definition is (min(a, b): b < a ? b : a; max(a, b): a < b ? b : a;
/// clamp(v, lo, hi): v < lo ? lo : hi < v ? hi : v), so NaNs go the same way; the divisions and
/// products are single IEEE operations in the scalar order, so every lane equals the scalar
/// controller to the bit (test GeodesicPacket.AcceptedStepControlIsTheScalarController). Why:
/// three dependent divisions per lane and step, scalar, were a third of the driver's cycles
/// (perf annotate of integrate_lanes on fallEddFinkIn, issue 13); here one division serves a
/// vector of lanes. Its inputs are all stored well before the call (vector loads of fresh scalar
/// stores would stall on store forwarding: a first version that gathered them per lane in the
/// accept loop was 4 % slower than the scalar controller).
void accepted_step_control(unsigned lanes, const double* hs, const double* err, const double* root,
                           PacketStepControl& c) {
  using Ctl = StepController<5>;  // the constants do not depend on the exponent
  constexpr int W = kPacketLanes;
  const SimdTag d;
  const SimdD zero(0.0), one(1.0), grow(Ctl::kMaxGrow), shrink(Ctl::kMaxShrink);
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const SimdMask on{hn::LoadMaskBits(d, &bits)};
    const SimdD h = fabs(SimdD::load(hs + l)), e = SimdD::load(err + l), q_root = SimdD::load(root + l);
    const SimdD h_old = SimdD::load(c.h_old + l), q_old = SimdD::load(c.q_old + l);
    const SimdMask positive = e > zero;
    const SimdMask finite = positive && SimdMask{hn::IsFinite(e.v)};
    // err > 0 finite: fac = kSafety/q, Gustafsson's proposal where there is an old step, clamped.
    SimdD fac = SimdD(Ctl::kSafety) / q_root;
    const SimdD predictive = fac * (h / h_old) * (q_old / q_root);
    fac = select(h_old > zero && q_old > zero && predictive < fac, predictive, fac);
    fac = select(fac < shrink, shrink, select(grow < fac, grow, fac));
    // err <= 0 or NaN: ×kMaxGrow; err = inf: ×kMaxShrink.
    fac = select(!positive, grow, select(finite, fac, shrink));
    const SimdD q = select(finite, q_root, zero);
    const SimdMask after_reject = SimdD::load(c.after_reject + l) != zero;
    fac = select(after_reject && one < fac, one, fac);
    const SimdD proposal = h * fac;
    const SimdD hmin = SimdD::load(c.hmin + l), hmax = SimdD::load(c.hmax + l);
    const SimdD at_least = select(proposal < hmin, hmin, proposal);
    select(at_least < hmax, at_least, hmax).store(c.h_next + l);
    select(on, h, h_old).store(c.h_old + l);
    select(on, q, q_old).store(c.q_old + l);
  }
}

/// MetricSystem::inside (integrators.h: ll_i <= x^i <= ur_i for i = 0..3, false where x^i is NaN)
/// of the states y (SoA) of all lanes at once, bit l: lane l. The same comparisons as the scalar
/// test, so the same answer; the scalar test of each lane cost ~20 instructions per step in the
/// driver's accept loop (callgrind, issue 13).
unsigned inside_box_lanes(const double* box, const double* y) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  unsigned bits = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    SimdMask in{hn::Not(hn::FirstN(d, 0))};
    for (int i = 0; i < 4; ++i) {
      const SimdD x = SimdD::load(y + i * W + l);
      in = in && x >= SimdD(box[i]) && x <= SimdD(box[4 + i]);
    }
    bits |= mask_bits(in) << l;
  }
  return bits;
}

/// y = y1 and dy = dy1 on the lanes in `lanes` (bit l: lane l) of `rows` rows of kPacketLanes
/// doubles each (SoA), the other lanes kept: the accepted steps' ends become the lanes' states,
/// a vector at a time (masked stores) instead of lane by lane (8 scalar copies per row, ~130
/// instructions per lane and step for y and dy in the driver's accept loop: callgrind on
/// fallEddFinkIn, issue 13).
void take_step_ends(unsigned lanes, const double* y1, const double* dy1, double* y, double* dy, int rows) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const auto on = hn::LoadMaskBits(d, &bits);
    for (int i = 0; i < rows; ++i) {
      hn::BlendedStore(hn::LoadU(d, y1 + i * W + l), on, d, y + i * W + l);
      hn::BlendedStore(hn::LoadU(d, dy1 + i * W + l), on, d, dy + i * W + l);
    }
  }
}

/// integrate_with's set-up of a trial step (the top of its loop, integrators.h) on the lanes in
/// `lanes`, with its operations: remaining = λ_max − |λ_affine − λ_affine,0|; with an affine
/// parameter of its own (p.per_affine) hmax and hmin from dσ/dλ (into c); hstep = h, clipped to
/// remaining·dσ/dλ where h reaches it; hv = dir·hstep, and the integration variable after the
/// step (param1: λ + dir·hstep, or the end λ_max for a clipped step without an affine parameter of
/// its own). The other lanes keep their values. Returns the lanes whose λ_max is reached
/// (!(remaining > lambda_res): they stop before the step) in bits 0–7, the clipped ones in 8–15.
unsigned lane_setup(unsigned lanes, const LaneSetupParams& p, LaneSteps& s, PacketStepControl& c, double* hv) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  unsigned out = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const auto on = hn::LoadMaskBits(d, &bits);
    const SimdD lambda = SimdD::load(s.lambda + l);
    const SimdD affine = p.affine ? SimdD::load(p.affine + l) : lambda;
    const SimdD remaining = SimdD(p.lambda_max) - fabs(affine - SimdD::load(s.affine0 + l));
    SimdD ppa(1.0);
    if (p.per_affine) {
      ppa = SimdD::load(p.per_affine + l);
      hn::BlendedStore((SimdD(p.hmax_affine) * ppa).v, on, d, c.hmax + l);
      hn::BlendedStore((SimdD(p.step_min) * ppa).v, on, d, c.hmin + l);
    }
    const SimdD h = SimdD::load(s.h + l), limit = remaining * ppa;
    const SimdMask clip = h >= limit;
    const SimdD hstep = select(clip, limit, h);
    SimdD param1 = lambda + SimdD(p.dir) * hstep;
    if (!p.affine) param1 = select(clip, SimdD(p.lambda_end), param1);
    hn::BlendedStore(remaining.v, on, d, s.remaining + l);
    hn::BlendedStore(hstep.v, on, d, s.hstep + l);
    hn::BlendedStore(param1.v, on, d, s.param1 + l);
    hn::BlendedStore((SimdD(p.dir) * hstep).v, on, d, hv + l);
    out |= mask_bits(!(remaining > SimdD(p.lambda_res))) << l | mask_bits(clip) << (8 + l);
  }
  return out;
}

/// n more on the counts of the lanes in `lanes` (SoA, e.g. LaneSteps::rhs_evals).
template <class T>
HWY_INLINE void add_on_lanes(unsigned lanes, T n, T* count) {
  constexpr int W = kPacketLanes;
  const hn::Rebind<T, SimdTag> d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += hn::Lanes(d)) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const auto v = hn::Load(d, count + l);
    hn::Store(hn::IfThenElse(hn::LoadMaskBits(d, &bits), hn::Add(v, hn::Set(d, n)), v), d, count + l);
  }
}

/// integrate_with's tests of the attempts of the lanes in `ready` (integrators.h), with its
/// comparisons, after their S − 1 evaluations of the right-hand side (s.rhs_evals). The bits,
/// of all lanes: 0–7 the lanes whose step is rejected (not in `valid`, the lanes whose y1 is
/// finite and in the domain, or adaptive and !(err <= 1)). With an affine parameter of its own
/// (affine0, affine1: its rows in y and y1; else null, and bits 8–23 are 0), for the step's length
/// dl = |λ1 − λ0| in it:
/// bits 8–15 where dl exceeds remaining·(1 + 1e-12) (λ_max finite) or hmax_affine·(1 + 1e-12)
/// (the step is retried shorter), bits 16–23 where dl >= remaining·(1 − 1e-12) (it ends at λ_max).
unsigned lane_attempt_tests(unsigned ready, int64_t stage_evals, unsigned valid, const double* err, bool adaptive,
                            const double* affine0, const double* affine1, LaneSteps& s, bool lambda_max_finite,
                            double hmax_affine) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  add_on_lanes(ready, stage_evals, s.rhs_evals);
  unsigned out = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(valid >> l);
    SimdMask accept{hn::LoadMaskBits(d, &bits)};
    if (adaptive) accept = accept && SimdD::load(err + l) <= SimdD(1.0);
    out |= mask_bits(!accept) << l;
    if (!affine0) continue;
    const SimdD dl = fabs(SimdD::load(affine1 + l) - SimdD::load(affine0 + l));
    const SimdD rem = SimdD::load(s.remaining + l);
    SimdMask longer = dl > SimdD(hmax_affine) * SimdD(1.0 + 1e-12);
    if (lambda_max_finite) longer = longer || dl > rem * SimdD(1.0 + 1e-12);
    out |= mask_bits(longer) << (8 + l) | mask_bits(dl >= rem * SimdD(1.0 - 1e-12)) << (16 + l);
  }
  return out;
}

/// integrate_with's tests and counts after the accepted attempts of the lanes in `accepted`: one
/// more evaluation of the right-hand side on the lanes in need_dy1 (s.rhs_evals); bits 0–7 the
/// lanes whose accepted state keeps the constraint, |C| <= tol·scale (its comparison; NaN fails),
/// which take their step (one more in s.steps); bits 8–15 those of them that reach max_steps.
unsigned lane_step_tests(unsigned accepted, unsigned need_dy1, const double* constraint, const double* scale,
                         double tol, int max_steps, LaneSteps& s) {
  constexpr int W = kPacketLanes;
  add_on_lanes(need_dy1, int64_t{1}, s.rhs_evals);
  unsigned stepping = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes())
    stepping |= mask_bits(fabs(SimdD::load(constraint + l)) <= SimdD(tol) * SimdD::load(scale + l)) << l;
  stepping &= accepted;
  add_on_lanes(stepping, 1, s.steps);
  const hn::Rebind<int, SimdTag> di;
  unsigned at_max = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += hn::Lanes(di)) {
    uint8_t bits[8] = {};  // StoreMaskBits writes up to 8 bytes
    hn::StoreMaskBits(di, hn::Not(hn::Lt(hn::Load(di, s.steps + l), hn::Set(di, max_steps))), bits);
    at_max |= unsigned{bits[0]} << l;
  }
  return stepping | (at_max & stepping) << 8;
}

/// After the steps of the lanes in `stepped`: their integration variable λ = param1; the lanes in
/// `go` go on (integrate_with after an accepted step): h = the control's h_next where adaptive, a
/// fresh boundary search (h_cross = 0) unless the step followed a rejection, after_reject = 0.
void lanes_go_on(unsigned stepped, unsigned go, bool adaptive, LaneSteps& s, PacketStepControl& c) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t stepped_bits = static_cast<uint8_t>(stepped >> l), go_bits = static_cast<uint8_t>(go >> l);
    const auto on = hn::LoadMaskBits(d, &go_bits);
    hn::BlendedStore(hn::Load(d, s.param1 + l), hn::LoadMaskBits(d, &stepped_bits), d, s.lambda + l);
    if (adaptive) hn::BlendedStore(hn::Load(d, c.h_next + l), on, d, s.h + l);
    const auto after_reject = hn::Ne(hn::Load(d, c.after_reject + l), hn::Zero(d));
    hn::BlendedStore(hn::Zero(d), hn::AndNot(after_reject, on), d, s.h_cross + l);
    hn::BlendedStore(hn::Zero(d), on, d, c.after_reject + l);
  }
}

/// KerrMinoSystem::project_invariants' first tests (!axis and sin²θ < kAxisProjectionSin2,
/// PolarOffset::sin2) of the states y (SoA) of all lanes, with their operations: bit l where lane
/// l's accepted state may be projected onto the polar first integral.
unsigned mino_may_project(const MinoLaneCoeffs& c, const double* y) {
  constexpr int W = kPacketLanes;
  unsigned bits = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const SimdD zeta = SimdD::load(y + KerrMinoRHS::Z * W + l), pole = SimdD::load(c.v[MinoLaneCoeffs::POLE] + l);
    const SimdMask near = -zeta * (SimdD(2.0) * pole + zeta) < SimdD(KerrMinoSystem::kAxisProjectionSin2);
    bits |= mask_bits(!mino_axis_at(c, l) && near) << l;
  }
  return bits;
}

/// dst = src on the lanes in `lanes` of each of `rows` pairs (src[i], dst[i]), one row of
/// kPacketLanes doubles each; the other lanes kept.
void copy_lanes(unsigned lanes, const double* const* src, double* const* dst, int rows) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const auto on = hn::LoadMaskBits(d, &bits);
    for (int i = 0; i < rows; ++i) hn::BlendedStore(hn::LoadU(d, src[i] + l), on, d, dst[i] + l);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {

HWY_EXPORT(rk_attempt);
HWY_EXPORT(mino_rhs);
HWY_EXPORT(mino_attempt);
HWY_EXPORT(mino_tolerance);
HWY_EXPORT(mino_end_views);
HWY_EXPORT(mino_end_positions);
HWY_EXPORT(mino_state_tests);
HWY_EXPORT(accepted_step_control);
HWY_EXPORT(inside_box_lanes);
HWY_EXPORT(take_step_ends);
HWY_EXPORT(mino_valid);
HWY_EXPORT(mino_constraint);
HWY_EXPORT(mino_param_per_affine);
HWY_EXPORT(lane_setup);
HWY_EXPORT(lane_attempt_tests);
HWY_EXPORT(lane_step_tests);
HWY_EXPORT(lanes_go_on);
HWY_EXPORT(mino_may_project);
HWY_EXPORT(copy_lanes);
HWY_EXPORT(mino_jacobi_rhs);
HWY_EXPORT(mino_jacobi_attempt);
HWY_EXPORT(mino_jacobi_tolerance);
HWY_EXPORT(coordinate_jacobi_rhs);
HWY_EXPORT(coordinate_jacobi_attempt);
HWY_EXPORT(coordinate_jacobi_tolerance);

namespace {

/// The index of the SIMD target Highway chose (hwy::ChosenTarget) in the tables of HWY_EXPORT:
/// the entry HWY_DYNAMIC_DISPATCH calls, looked up once per packet run (the packet systems'
/// `target`, GEOVIS_PACKET_DISPATCH). Why: HWY_DYNAMIC_DISPATCH looks it up in every call (a call
/// into Highway and a few instructions; ~17 calls per round of a packet, ~8 instructions each:
/// callgrind, issue 13).
size_t packet_target() {
  hwy::ChosenTarget& chosen = hwy::GetChosenTarget();
  if (!chosen.IsInitialized()) chosen.Update(hwy::SupportedTargets());  // as the first HWY_DYNAMIC_DISPATCH does
  return chosen.GetIndex();
}

/// Entry `target` (packet_target) of a table of HWY_EXPORT; a table of one entry (a build for one
/// target, where HWY_DYNAMIC_DISPATCH is the static call) has only that one.
template <class F, size_t n>
F packet_table_entry(F const (&table)[n], size_t target) {
  return table[n == 1 ? 0 : target];
}

}  // namespace

/// HWY_DYNAMIC_DISPATCH(FUNC) for the target index `target` (packet_target).
#define GEOVIS_PACKET_DISPATCH(FUNC, target) (*packet_table_entry(HWY_DISPATCH_TABLE(FUNC), target))

namespace {

/// Integrates the rays of `rays` on the lanes of packet system PS, each lane exactly as
/// integrate_with<ExplicitRK<Tab>> (integrators.h, Tab: the tableau of cfg.kind; DOP853 for its
/// tableau, step_error_norm_lanes) integrates PS's scalar system of the lane from λ = 0: the same
/// steps, checks and stops in the same order (the optional parts — own affine parameter, scaled
/// tolerance, projection, re-basing — chosen by the same `requires`). The per-lane state is SoA
/// (LaneSteps, PacketStepControl) and the common path of every lane — the set-up of its trial
/// step, the tests of its attempt, the hand-over of its step and going on — runs on SIMD lanes
/// with the scalar loop's operations (lane_setup, lane_attempt_tests, lane_step_tests,
/// lanes_go_on); only the lanes that leave it (a rejected or retried step, a state to project, a
/// ray that ends) are handled one by one, in lane order, as the scalar loop handles them.
/// PS provides
///   N                                   the state's dimension;
///   system(l)                           the scalar system of lane l (integrators.h concept);
///   start(l, y_start, y)                the ray's state from its start (8 components: x, k);
///                                       false when it handled the ray itself (done already called);
///   rhs(y, dy, lanes), attempt(kind, lanes, tol, y, dy, h, y1, dy1, err)   SoA right-hand side
///                                       and the attempt of solver `kind` (rk_attempt_lanes) with
///                                       its error norm, root and finiteness (AttemptError);
///   tolerance_inv(eps_abs, eps_rel, y, inv)   for a system with tolerance scales of its own: the
///                                       1/D_i of set_tolerance at state y on every lane (SoA);
///   step(l, StepView), done(l, y, res)  the accepted steps and the end, in the system's variables;
///   steps(PacketSteps), batch_steps() (optional)   the accepted steps of a round at once instead of
///                                       step, where batch_steps() (returns the lanes to stop);
///   after_steps(cfg, lanes, y) (optional)   with steps: after the batched steps of the lanes in
///                                       `lanes` became their states y, the system's re-basing and
///                                       its box test (returns the lanes inside);
///   accepted_states_may_change(cfg, y1, lanes) (optional)   the lanes of `lanes` whose accepted
///                                       states y1 may be changed (reproject, project_invariants,
///                                       rescale); else all where accepted_states_change;
///   before_steps(lanes, y, y1, dy1) (optional)   once per round, before the steps of the accepted
///                                       lanes (bits of `lanes`: y → y1) are handed to step;
///   rebase(l, y) (optional)             the system's re-basing, kept in the packet's own copies;
///   valid_lanes(y, lanes), step_checks(cfg, y, lanes, out)   the scalar system's valid,
///                                       and its constraint, escaped and captured (PacketStepChecks),
///                                       of all lanes' states at once;
///   accepted_states_change(cfg) (optional)   false where the system never changes an accepted state;
///   param_per_affine_lanes(y, out)      with an affine parameter of its own: Sys::param_per_affine
///                                       of all lanes' states at once.
template <class Tab, class PS>
void integrate_lanes(PS& ps, const SolverConfig& cfg, const PacketRays& rays) {
  constexpr int W = kPacketLanes, N = PS::N;
  using Sys = std::remove_cvref_t<decltype(ps.system(0))>;
  constexpr bool kOwnAffine = requires(const Sys& s, const double* p) {
    s.affine(p);
    s.param_per_affine(p);
  };
  constexpr bool kScaledTol = requires(const Sys& s, const double* p, double* q) { s.tolerance_inv_scale(p, q); };
  // A packet system tests the states of its lanes at once (PS::valid_lanes, PS::step_checks).
  static_assert(requires(PS & p, const double* yy, PacketStepChecks& out) {
    p.valid_lanes(yy, 0u);
    p.step_checks(cfg, yy, 0u, out);
  });
  // A packet system that tests Sys::inside of all lanes' accepted states at once
  // (PS::inside_lanes); it must not change a state between the test and the step (rebase).
  constexpr bool kLaneInside = requires(PS & p, const double* yy) { p.inside_lanes(cfg, yy); };
  static_assert(!kLaneInside || !requires(double* yy) { ps.rebase(0, yy); });
  // A packet system that can hand the accepted steps of a round on at once (PS::steps, where its
  // caller takes them so: PS::batch_steps), without a StepView per lane. Its states need no
  // re-basing and it tests them against the box before the steps (PS::inside_lanes), or it does
  // both after the steps have become the lanes' states (PS::after_steps); an affine parameter of
  // its own is a component of the state (Sys::kAffineIndex): the batched steps keep no rows
  // (y_row).
  constexpr bool kBatch = requires(PS & p, const PacketSteps& s) { p.steps(s); };
  constexpr bool kAfterSteps = requires(PS & p, double* yy) { p.after_steps(cfg, 0u, yy); };
  static_assert(!kBatch || kAfterSteps || (kLaneInside && !requires(double* yy) { ps.rebase(0, yy); }));
  bool batch_steps = false;
  if constexpr (kBatch) batch_steps = ps.batch_steps();
  // Whether an accepted state may change before it is taken (reproject, project_invariants,
  // rescale below); where it cannot (PS::accepted_states_change), y1 stays as the attempt gave it,
  // and where PS tells which lanes' states may change (PS::accepted_states_may_change) only those
  // are taken as rows to be changed.
  bool accepted_states_change = true;
  if constexpr (requires { ps.accepted_states_change(cfg); }) accepted_states_change = ps.accepted_states_change(cfg);
  auto affine = [](const Sys& s, const double* yy, double sv) {
    if constexpr (kOwnAffine) return s.affine(yy);
    return sv;
  };
  auto per_affine = [](const Sys& s, const double* yy) {
    if constexpr (kOwnAffine) return s.param_per_affine(yy);
    return 1.0;
  };
  // An affine parameter of its own is a component of the state, read in place (Sys::kAffineIndex),
  // and its dσ/dλ is given for all lanes at once (PS::param_per_affine_lanes).
  static_assert(!kOwnAffine || requires(PS & p, const double* yy, double* o) {
    Sys::kAffineIndex;
    p.param_per_affine_lanes(yy, o);
  });
  alignas(64) double per_affine_lanes[kOwnAffine ? W : 1];  // PS::param_per_affine_lanes of y
  // The row of the affine parameter in a state (y or y1), or null without one of its own.
  auto affine_row = [](double* soa) -> double* {
    if constexpr (kOwnAffine) return soa + Sys::kAffineIndex * W;
    return nullptr;
  };

  // integrate_with's constants (λ0 = 0).
  const double dir = cfg.direction >= 0 ? 1.0 : -1.0;
  const bool adaptive = cfg.step_ctrl;
  const double hmax_affine = std::max(cfg.step_max, cfg.step_min);
  const double lambda_res = kOwnAffine && std::isfinite(cfg.lambda_max) ? 1e-12 * cfg.lambda_max : 0.0;
  constexpr double kBoundaryRes = 1.0 / 1024;

  // alignas(64), not HWY_ALIGN: this part is compiled once, where HWY_ALIGN is the last target's
  // (16 bytes), and the per-target functions may load a whole AVX-512 vector from these rows.
  alignas(64) double y[N * W] = {}, dy[N * W] = {}, y1[N * W] = {}, dy1[N * W] = {}, hv[W] = {};
  alignas(64) double f1[Tab::kFsal ? N * W : 1];  // f(y1) of the lanes whose last stage is not it
  // ErrorScale::inv of every lane (SoA) for systems with their own tolerance scales.
  alignas(64) double inv_tol[kScaledTol ? N * W : 1] = {};
  const LaneTolerance tol{cfg.eps_abs, cfg.eps_rel, kScaledTol ? inv_tol : nullptr};
  AttemptError attempt_err;
  // Each lane's run of integrate_with: its step state (s), its step controller (ExplicitRK::
  // control: h_old, q_old in ctl) and the inputs of the step control after accepted steps
  // (after_reject, hmin, hmax), done for all accepted lanes at once before their steps are handed
  // on (packet_accepted_step_control); its result with the counts apart (in s) and its retries of
  // steps too long in λ.
  LaneSteps s;
  PacketStepControl ctl{};
  GeodesicResult res[W];
  int affine_retries[W] = {};
  const LaneSetupParams setup{affine_row(y),
                              kOwnAffine ? per_affine_lanes : nullptr,
                              cfg.lambda_max,
                              lambda_res,
                              hmax_affine,
                              cfg.step_min,
                              dir,
                              0.0 + dir * cfg.lambda_max};
  bool exhausted = false;
  unsigned live = 0;     // lanes with a ray
  unsigned need_dy = 0;  // lanes whose dy = f(y) is still to be evaluated (fresh rays)
  unsigned ready = 0;    // lanes whose next trial step is set up (hv)
  unsigned clipped = 0;  // lanes whose trial step ends at λ_max
  unsigned at_max = 0;   // lanes whose ray has cfg.max_steps steps
  unsigned retried = 0;  // lanes with affine_retries > 0

  auto get = [](const double* soa, int l, double* out) {
    for (int i = 0; i < N; ++i) out[i] = soa[i * W + l];
  };
  auto put = [](double* soa, int l, const double* in) {
    for (int i = 0; i < N; ++i) soa[i * W + l] = in[i];
  };
  // Each lane's y and dy also as one row (AoS), kept equal to the lane's column of y and dy, for
  // the steps handed on lane by lane (PS::step), in rows. Why: gathering the columns again for
  // every use (the step's start and its derivative) was a ninth of kerrAccretionDisk.scm's tracing
  // instructions when its steps were handed on so (callgrind, issue 13). The batched steps
  // (take_steps) read neither and do not keep the rows.
  alignas(64) double y_row[W][N], dy_row[W][N];
  // integrate_with's set_tolerance: the lane's 1/D_i at the start of its step, for the lanes in
  // need_tol at once before the next attempt (PS::tolerance_inv, all lanes: a lane whose state
  // did not change gets the same values again).
  unsigned need_tol = 0;
  auto set_tolerance = [&](unsigned lanes) {
    if constexpr (kScaledTol) need_tol |= lanes;
  };
  // integrate_with's finish(): the result with the state where the ray stopped.
  auto finish = [&](int l, StopReason r) {
    double yl[N];
    get(y, l, yl);
    GeodesicResult& rl = res[l];
    rl.reason = r;
    rl.steps = s.steps[l];
    rl.rhs_evals = s.rhs_evals[l];
    rl.lambda = affine(ps.system(l), yl, s.lambda[l]);
    double scale;
    ps.system(l).constraint(yl, cfg.type, rl.constraint_drift, scale);
    live &= ~(1u << l);
    ps.done(l, yl, rl);
  };
  // Fills lane l with the next ray (integrate_with's set-up); rays that stop before their first
  // step are finished at once.
  auto refill = [&](int l) {
    const unsigned bit = 1u << l;
    ready &= ~bit;
    while (!exhausted) {
      double ys[kDim], yl[N];
      if (!rays.next(l, ys)) {
        exhausted = true;
        break;
      }
      if (!ps.start(l, ys, yl)) continue;
      put(y, l, yl);
      if (!batch_steps) std::memcpy(y_row[l], yl, sizeof yl);
      res[l] = GeodesicResult{};
      s.steps[l] = affine_retries[l] = 0;
      s.rhs_evals[l] = 0;
      retried &= ~bit;
      at_max = (at_max & ~bit) | (cfg.max_steps <= 0 ? bit : 0u);
      s.lambda[l] = s.h_cross[l] = 0.0;
      ctl.h_old[l] = ctl.q_old[l] = ctl.after_reject[l] = 0.0;  // a fresh StepController
      live |= bit;
      const Sys& sys = ps.system(l);
      set_tolerance(bit);
      const double ppa = per_affine(sys, yl);
      ctl.hmax[l] = hmax_affine * ppa;
      ctl.hmin[l] = cfg.step_min * ppa;
      s.h[l] = std::max(std::min(std::fabs(cfg.step_size), hmax_affine) * ppa, ctl.hmin[l]);
      s.affine0[l] = affine(sys, yl, 0.0);
      if (!sys.valid(yl)) {
        finish(l, StopReason::Invalid);
        continue;
      }
      if (!sys.inside(cfg, yl)) {
        finish(l, StopReason::BoundingBox);
        continue;
      }
      need_dy |= bit;
      return;
    }
  };

  // integrate_with's tests after lane l's step was taken, in its order: why the ray stops there
  // (StopReason::None: it goes on); `callback_stop`: the step's callback stopped it, `in_box`: the
  // new state is inside the bounding box. Sets the escape radius where the ray escaped.
  auto stop_after_step = [&](int l, bool callback_stop, bool in_box, const PacketStepChecks& checks) {
    if (callback_stop) return StopReason::Callback;
    if (!in_box) return StopReason::BoundingBox;
    if (clipped >> l & 1u) return StopReason::LambdaMax;
    if (checks.escaped >> l & 1u) {
      res[l].escape_radius = checks.escape_radius[l];
      return StopReason::Escaped;
    }
    if (checks.captured >> l & 1u) return StopReason::Invalid;
    return StopReason::None;
  };
  // Lane l goes on after its step (lanes_go_on for one lane): the step size the control gave
  // (adaptive), a fresh boundary search, the controller told that the step was accepted.
  auto go_on = [&](int l) {
    if (adaptive) s.h[l] = ctl.h_next[l];
    if (ctl.after_reject[l] == 0.0) s.h_cross[l] = 0.0;
    ctl.after_reject[l] = 0.0;
  };

  // The accepted steps of a round (bits of `accepted`; `need_dy1`, `checks`, `inside` as the
  // round's loop below has them) where PS hands them on at once (kBatch, batch_steps): the same
  // constraint test, step, stop tests and step size per lane as that loop, on SIMD lanes; the
  // steps handed on (PS::steps) and their ends taken as the lanes' states on SIMD lanes
  // (take_step_ends) between the constraint and the other tests, with no lane's view gathered
  // (~200 instructions per lane and step of gathers, copies and the per-lane callback on
  // fallEddFinkIn: callgrind, issue 13). The rays that end are handed back (done, next) lane
  // after lane, as there.
  auto take_steps = [&](unsigned accepted, unsigned need_dy1, const PacketStepChecks& checks, unsigned inside) {
    if constexpr (kBatch) {
      ready &= ~accepted;
      // The accepted lanes whose constraint holds: they take their step.
      const unsigned counted = GEOVIS_PACKET_DISPATCH(lane_step_tests, ps.target)(
          accepted, need_dy1, checks.constraint, checks.constraint_scale, cfg.constraint_tol, cfg.max_steps, s);
      const unsigned stepping = counted & 0xffu;
      at_max |= counted >> 8;
      // The affine parameter at both ends: the states' own, or the integration variable before
      // and after the step.
      const double* lambda0 = kOwnAffine ? affine_row(y) : s.lambda;
      const double* lambda1 = kOwnAffine ? affine_row(y1) : s.param1;
      PacketSteps round{stepping, y, y1, dy, dy1, lambda0, lambda1, s.steps};
      round.dim = N;
      const unsigned stopped = ps.steps(round);
      GEOVIS_PACKET_DISPATCH(take_step_ends, ps.target)(stepping, y1, dy1, y, dy, N);
      if constexpr (kAfterSteps) inside = ps.after_steps(cfg, stepping, y);
      set_tolerance(stepping);
      // stop_after_step's reasons, all lanes at once.
      const unsigned go = stepping & ~(stopped | ~inside | clipped | checks.escaped | checks.captured);
      GEOVIS_PACKET_DISPATCH(lanes_go_on, ps.target)(stepping, go, adaptive, s, ctl);
      if (!adaptive && kOwnAffine) {
        for (unsigned todo = go; todo != 0; todo &= todo - 1) {
          const int l = std::countr_zero(todo);
          double yl[N];
          get(y, l, yl);
          s.h[l] = std::fabs(cfg.step_size) * per_affine(ps.system(l), yl);
        }
      }
      for (unsigned todo = accepted & ~go; todo != 0; todo &= todo - 1) {
        const int l = std::countr_zero(todo);
        finish(l, stepping >> l & 1u ? stop_after_step(l, stopped >> l & 1u, inside >> l & 1u, checks)
                                     : StopReason::Constraint);
        refill(l);
      }
    }
  };

  for (int l = 0; l < W; ++l) refill(l);
  while (true) {
    // Every live lane set up for a trial step (the top of integrate_with's loop).
    do {
      if (need_dy) {
        ps.rhs(y, dy, need_dy);
        for (unsigned todo = need_dy; todo != 0; todo &= todo - 1) {
          const int l = std::countr_zero(todo);
          ++s.rhs_evals[l];
          if (!batch_steps) get(dy, l, dy_row[l]);
        }
        need_dy = 0;
      }
      const unsigned todo = live & ~ready;
      if (!todo) break;
      if constexpr (kOwnAffine) ps.param_per_affine_lanes(y, per_affine_lanes);
      const unsigned set = GEOVIS_PACKET_DISPATCH(lane_setup, ps.target)(todo, setup, s, ctl, hv);
      clipped = (clipped & ~todo) | (set >> 8 & todo);
      // The lanes that stop before the step (max_steps, then λ_max, as integrate_with tests them).
      const unsigned stop = todo & (at_max | set);
      ready |= todo & ~stop;
      for (unsigned left = stop; left != 0; left &= left - 1) {
        const int l = std::countr_zero(left);
        finish(l, at_max >> l & 1u ? StopReason::MaxSteps : StopReason::LambdaMax);
        refill(l);
      }
    } while (need_dy);
    if (!ready) return;

    if constexpr (kScaledTol) {
      if (need_tol) ps.tolerance_inv(cfg.eps_abs, cfg.eps_rel, y, inv_tol);
      need_tol = 0;
    }
    ps.attempt(cfg.kind, ready, tol, y, dy, hv, y1, dy1, attempt_err);
    const unsigned valid = ps.valid_lanes(y1, ready & attempt_err.finite);
    const unsigned tests = GEOVIS_PACKET_DISPATCH(lane_attempt_tests, ps.target)(
        ready, Tab::S - 1, valid, attempt_err.err, adaptive, affine_row(y), affine_row(y1), s,
        std::isfinite(cfg.lambda_max), hmax_affine);
    // The rejected steps, lane by lane (integrate_with's step control after a rejection).
    for (unsigned todo = tests & ready; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      const double err = attempt_err.err[l];
      const bool finite = attempt_err.finite >> l & 1u;
      const bool in_domain = valid >> l & 1u;
      const bool after_reject = ctl.after_reject[l] != 0.0;
      ready &= ~(1u << l);
      if (!adaptive) {
        finish(l, finite ? StopReason::Invalid : StopReason::NotFinite);
        refill(l);
        continue;
      }
      ++res[l].rejected;
      if (finite && !in_domain) {
        if (s.h_cross[l] == 0.0) s.h_cross[l] = s.hstep[l];
        if (s.hstep[l] <= kBoundaryRes * s.h_cross[l]) {
          finish(l, StopReason::Invalid);
          refill(l);
          continue;
        }
      }
      s.h[l] = in_domain ? StepController<Tab::kErrExp>{ctl.h_old[l], ctl.q_old[l]}.next_with_root(
                               s.hstep[l], err, attempt_err.root[l], false, after_reject)  // leaves h_old, q_old
                         : 0.5 * s.hstep[l];
      ctl.after_reject[l] = 1.0;
      if (s.h[l] < ctl.hmin[l] || s.h[l] <= 4 * DBL_EPSILON * std::fabs(s.lambda[l])) {
        finish(l, !finite ? StopReason::NotFinite : (!in_domain ? StopReason::Invalid : StopReason::StepUnderflow));
        refill(l);
      }
    }
    if constexpr (kOwnAffine) {
      // λ_max overshot, or a step longer than step_max in λ: retried shorter (integrate_with).
      for (unsigned todo = tests >> 8 & ready; todo != 0; todo &= todo - 1) {
        const int l = std::countr_zero(todo);
        if (affine_retries[l] >= 50) continue;
        const double dl = std::fabs(y1[Sys::kAffineIndex * W + l] - y[Sys::kAffineIndex * W + l]);
        if (std::isfinite(cfg.lambda_max) && dl > s.remaining[l] * (1.0 + 1e-12))
          s.h[l] = s.hstep[l] * s.remaining[l] / dl;
        else
          s.h[l] = s.hstep[l] * hmax_affine / dl * (1.0 - 1e-9);
        ++affine_retries[l];
        retried |= 1u << l;
        ready &= ~(1u << l);
      }
    }
    const unsigned accepted = ready;
    if constexpr (kOwnAffine) {
      for (unsigned todo = retried & accepted; todo != 0; todo &= todo - 1) affine_retries[std::countr_zero(todo)] = 0;
      retried &= ~accepted;
      clipped = (clipped & ~accepted) | (tests >> 16 & accepted);
    }
    // The accepted states that may change, lane by lane.
    unsigned changed = 0;
    if (accepted_states_change) {
      unsigned may_change = accepted;
      if constexpr (requires { ps.accepted_states_may_change(cfg, y1, accepted); })
        may_change = ps.accepted_states_may_change(cfg, y1, accepted);
      for (unsigned todo = may_change; todo != 0; todo &= todo - 1) {
        const int l = std::countr_zero(todo);
        auto& sys = ps.system(l);
        double yl1[N];
        get(y1, l, yl1);
        bool lane_changed = false;
        if (cfg.reproject) sys.reproject(yl1, cfg.type);
        if constexpr (requires { sys.project_invariants(yl1); }) lane_changed = sys.project_invariants(yl1);
        if constexpr (requires { sys.rescale(yl1, cfg.type); })
          lane_changed = sys.rescale(yl1, cfg.type) || lane_changed;
        if (cfg.reproject || lane_changed) put(y1, l, yl1);
        if (lane_changed) changed |= 1u << l;
      }
    }
    if (!accepted) continue;
    const unsigned need_dy1 = !Tab::kFsal || cfg.reproject ? accepted : changed;

    // f at the accepted states the last stage did not give (integrate_with); a first-same-as-last
    // tableau's dy1 of the other lanes is kept.
    if constexpr (Tab::kFsal) {
      if (need_dy1) {
        ps.rhs(y1, f1, need_dy1);
        for (int l = 0; l < W; ++l)
          if (need_dy1 >> l & 1u)
            for (int i = 0; i < N; ++i) dy1[i * W + l] = f1[i * W + l];
      }
    } else {
      ps.rhs(y1, dy1, need_dy1);
    }
    PacketStepChecks checks;
    ps.step_checks(cfg, y1, accepted, checks);
    unsigned inside = 0;  // bit l: lane l's y1 (as the step hands it on) inside the box
    if constexpr (kLaneInside) inside = ps.inside_lanes(cfg, y1);
    if constexpr (requires { ps.before_steps(accepted, y, y1, dy1); }) ps.before_steps(accepted, y, y1, dy1);
    // ln.h = min(hmax, max(control.next_with_root(hstep, err, root, true, after_reject), hmin)) of
    // every accepted lane (err and root: attempt_err's; hstep = |hv|), taken below
    // by those that go on. A lane that stops here is refilled with a fresh controller or stays idle.
    if (adaptive)
      GEOVIS_PACKET_DISPATCH(accepted_step_control, ps.target)(accepted, hv, attempt_err.err, attempt_err.root, ctl);
    if constexpr (kBatch) {
      if (batch_steps) {
        take_steps(accepted, need_dy1, checks, inside);
        continue;
      }
    }
    // Else each step handed on lane by lane (PS::step, its view gathered).
    for (unsigned todo = accepted; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      auto& sys = ps.system(l);
      ready &= ~(1u << l);
      if (need_dy1 >> l & 1u) ++s.rhs_evals[l];
      const double* yl = y_row[l];
      const double* dyl = dy_row[l];
      double yl1[N], dyl1[N];
      get(y1, l, yl1);
      get(dy1, l, dyl1);
      if (!(std::fabs(checks.constraint[l]) <= cfg.constraint_tol * checks.constraint_scale[l])) {
        finish(l, StopReason::Constraint);
        refill(l);
        continue;
      }
      if (++s.steps[l] >= cfg.max_steps) at_max |= 1u << l;
      const double lambda1 = s.param1[l];
      const StepAction act = ps.step(
          l, StepView{affine(sys, yl, s.lambda[l]), affine(sys, yl1, lambda1), yl, yl1, dyl, dyl1, N, s.steps[l]});
      if constexpr (requires { ps.rebase(l, yl1); }) ps.rebase(l, yl1);
      put(y, l, yl1);
      put(dy, l, dyl1);
      std::memcpy(y_row[l], yl1, sizeof y_row[l]);
      std::memcpy(dy_row[l], dyl1, sizeof dyl1);
      s.lambda[l] = lambda1;
      set_tolerance(1u << l);
      const bool in_box = kLaneInside ? (inside >> l & 1u) != 0 : sys.inside(cfg, yl1);
      if (const StopReason stop = stop_after_step(l, act == StepAction::Stop, in_box, checks);
          stop != StopReason::None) {
        finish(l, stop);
        refill(l);
        continue;
      }
      if (!adaptive && kOwnAffine) s.h[l] = std::fabs(cfg.step_size) * per_affine(sys, yl1);
      go_on(l);
    }
  }
}

/// MetricSystem::inside of all lanes' states y (their first four rows x) at once (inside_box_lanes).
unsigned inside_box(const SolverConfig& c, const double* y, size_t target) {
  const double box[8] = {c.box_ll[0], c.box_ll[1], c.box_ll[2], c.box_ll[3],
                         c.box_ur[0], c.box_ur[1], c.box_ur[2], c.box_ur[3]};
  return GEOVIS_PACKET_DISPATCH(inside_box_lanes, target)(box, y);
}

/// The tests and the hand-over of the packets in the metric's coordinates (CoordinatePacket,
/// CoordinateJacobiPacket), all lanes at once: P has `metric` (MetricKernel), `rays` (PacketRays or
/// JacobiPacketRays) and `target`; the first eight rows of its states are x and k, which
/// MetricSystem's tests read (MetricKernel::packet_valid, packet_step_checks: the metric's functions
/// inlined).
template <class P>
struct CoordinateStateTests {
  unsigned valid_lanes(const double* y, unsigned lanes) const { return self().metric.packet_valid(y, lanes); }
  /// MetricSystem::inside of all lanes' states at once (inside_box_lanes).
  unsigned inside_lanes(const SolverConfig& c, const double* y) const { return inside_box(c, y, self().target); }
  void step_checks(const SolverConfig& c, const double* y, unsigned lanes, PacketStepChecks& out) const {
    self().metric.packet_step_checks(c, y, lanes, out);
  }
  StepAction step(int l, const StepView& s) const {
    return self().rays.on_step ? self().rays.on_step(l, s) : StepAction::Continue;
  }
  /// The steps go to the rays' on_steps a round at a time where it is set.
  bool batch_steps() const { return static_cast<bool>(self().rays.on_steps); }
  unsigned steps(const PacketSteps& s) const { return self().rays.on_steps(s); }
  void done(int l, const double* y, const GeodesicResult& res) const { self().rays.done(l, y, res); }

 private:
  const P& self() const { return static_cast<const P&>(*this); }
};

/// The geodesic system y = (x, k) in the metric's coordinates (MetricSystem), the same for all
/// lanes.
struct CoordinatePacket : CoordinateStateTests<CoordinatePacket> {
  static constexpr int N = kDim;
  const MetricKernel& metric;
  const PacketRays& rays;
  size_t target = packet_target();  ///< the SIMD functions' (GEOVIS_PACKET_DISPATCH)
  GeodesicRHS<MetricKernel> f{metric};
  MetricSystem<MetricKernel, GeodesicRHS<MetricKernel>> sys{metric, f};

  const MetricSystem<MetricKernel, GeodesicRHS<MetricKernel>>& system(int) const { return sys; }
  bool start(int, const double* ys, double* y) const {
    std::memcpy(y, ys, N * sizeof(double));
    return true;
  }
  void rhs(const double* y, double* dy, unsigned lanes) const { packet_rhs(metric, y, dy, lanes); }
  void attempt(SolverKind kind, unsigned lanes, const LaneTolerance& tol, const double* y, const double* dy,
               const double* h, double* y1, double* dy1, AttemptError& err) const {
    GEOVIS_PACKET_DISPATCH(rk_attempt, target)(kind, metric, lanes, tol, y, dy, h, y1, dy1, err);
  }
  /// MetricSystem::reproject and rescale (the only ones that change an accepted state here).
  bool accepted_states_change(const SolverConfig& c) const {
    return c.reproject || (c.type == GeodesicType::Lightlike && metric.rescales_null_direction());
  }
};

/// The Jacobi system in the metric's coordinates (JacobiSystem, jacobi_system.h), the same for all
/// lanes: the Jacobi system's terms from the metric (MetricKernel::packet_jacobi_terms), the rest on
/// SIMD lanes; the state's first eight rows are the geodesic's x and k, which the metric's packet
/// tests read (CoordinateStateTests). Its steps (32 components per state) go to
/// JacobiPacketRays::on_steps a round at a time where that is set: gathering and handing on each
/// lane's step was a fifth of morristhorne.scm's RGBjac Jacobi pass (callgrind).
struct CoordinateJacobiPacket : CoordinateStateTests<CoordinateJacobiPacket> {
  static constexpr int N = kJacobiDim;
  const MetricKernel& metric;
  const JacobiPacketRays& rays;
  size_t target = packet_target();  ///< the SIMD functions' (GEOVIS_PACKET_DISPATCH)
  JacobiRHS<MetricKernel> f{metric};
  JacobiSystem sys{{metric, f}};
  /// Each lane's start state as rays.next gave it (the driver's start sees x and k only).
  double start_state[kPacketLanes][kJacobiDim] = {};
  /// The Jacobi system's terms of the stage being evaluated (coordinate_jacobi_rhs).
  alignas(64) double terms[kJacobiTermRows * kPacketLanes] = {};

  const JacobiSystem& system(int) const { return sys; }
  /// PacketRays::next of the driver: the next ray's whole start state kept for start().
  bool next(int l, double* y) {
    if (!rays.next(l, start_state[l])) return false;
    std::memcpy(y, start_state[l], kDim * sizeof(double));
    return true;
  }
  bool start(int l, const double*, double* y) const {
    std::memcpy(y, start_state[l], N * sizeof(double));
    return true;
  }
  void rhs(const double* y, double* dy, unsigned lanes) {
    GEOVIS_PACKET_DISPATCH(coordinate_jacobi_rhs, target)(metric, lanes, y, dy, terms);
  }
  void attempt(SolverKind kind, unsigned lanes, const LaneTolerance& tol, const double* y, const double* dy,
               const double* h, double* y1, double* dy1, AttemptError& err) {
    GEOVIS_PACKET_DISPATCH(coordinate_jacobi_attempt, target)(kind, metric, lanes, tol, y, dy, h, y1, dy1, err, terms);
  }
  void tolerance_inv(double eps_abs, double eps_rel, const double* y, double* inv) const {
    GEOVIS_PACKET_DISPATCH(coordinate_jacobi_tolerance, target)(eps_abs, eps_rel, y, inv);
  }
  /// MetricSystem::reproject (its rescale is the geodesic system's only).
  bool accepted_states_change(const SolverConfig& c) const { return c.reproject; }
};

/// The tests of the Mino state shared by MinoPacket and MinoJacobiPacket, all lanes at once: P's
/// states have N rows whose first four are the Mino state's w, ζ, w', z' (KerrMinoRHS,
/// MinoJacobiLayout: the SIMD tests read only those), P has `coeffs`, `target` and system(l), lane
/// l's scalar system (its escaped and captured read the state's N components).
template <class P>
struct MinoStateTests {
  /// KerrMinoSystem::param_per_affine of all lanes' states at once (mino_param_per_affine, SIMD).
  void param_per_affine_lanes(const double* y, double* out) const {
    GEOVIS_PACKET_DISPATCH(mino_param_per_affine, self().target)(self().coeffs, y, out);
  }
  /// KerrMinoSystem::valid of all lanes' states at once (mino_valid, SIMD).
  unsigned valid_lanes(const double* y, unsigned lanes) const {
    return GEOVIS_PACKET_DISPATCH(mino_valid, self().target)(self().coeffs, y, lanes);
  }
  /// KerrMinoSystem's constraint (on SIMD lanes: mino_constraint, kerr_mino_constraint's bits),
  /// escaped and captured of the accepted states y (SoA) of the lanes in `lanes`. Escape and
  /// capture are tested lane by lane, and the costly part of each (the turning-point and Bernstein
  /// tests of the radial potential) only where its radius and direction admit it.
  void step_checks(const SolverConfig& c, const double* y, unsigned lanes, PacketStepChecks& out) {
    constexpr int W = kPacketLanes;
    static_assert(W <= 8, "mino_constraint's candidate bits: 8 per test");
    // The lanes past the first tests of escaped and captured, which most steps fail (SIMD, with
    // their expressions); only those are gathered and tested here.
    const unsigned candidates = GEOVIS_PACKET_DISPATCH(mino_constraint, self().target)(
        self().coeffs, y, c.escape_radius, c.capture_radius, c.direction >= 0 ? -1.0 : 1.0, out.constraint,
        out.constraint_scale);
    const unsigned may_escape = candidates & lanes, may_be_captured = candidates >> 8 & lanes;
    out.escaped = out.captured = 0;
    for (unsigned todo = may_escape | may_be_captured; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      double yl[P::N];
      for (int i = 0; i < P::N; ++i) yl[i] = y[i * W + l];
      const auto& sys = static_cast<P&>(*this).system(l);
      if ((may_escape >> l & 1u) && sys.escaped(c, yl, out.escape_radius[l])) out.escaped |= 1u << l;
      if ((may_be_captured >> l & 1u) && sys.captured(c, yl)) out.captured |= 1u << l;
    }
  }
  /// The lanes of `lanes` whose accepted states (y1, SoA) may be changed: all where they are
  /// re-projected (c.reproject), else those that may be projected onto the polar first integral
  /// near the axis — KerrMinoSystem::project_invariants' first tests, on ζ alone, all lanes at once
  /// (mino_may_project). Why: the other states need not be gathered (~25 instructions per lane and
  /// attempt on kerrAccretionDisk.scm, callgrind, issue 13).
  unsigned accepted_states_may_change(const SolverConfig& c, const double* y1, unsigned lanes) const {
    if (c.reproject) return lanes;
    return GEOVIS_PACKET_DISPATCH(mino_may_project, self().target)(self().coeffs, y1) & lanes;
  }

 private:
  const P& self() const { return static_cast<const P&>(*this); }
};

/// Carter's separated equations in Mino time (kerr_mino.h), one ray (KerrMinoRay) per lane.
struct MinoPacket : MinoStateTests<MinoPacket> {
  static constexpr int N = KerrMinoRHS::N;
  const Metric& metric;
  const KerrMinoParams hole;
  const SolverConfig& cfg_in;  ///< the caller's settings (for rays handed to metric.integrate)
  const SolverConfig& cfg;     ///< KerrMinoRay::config(cfg_in)
  const PacketRays& rays;
  std::optional<KerrMinoRay> ray[kPacketLanes];
  MinoLaneCoeffs coeffs;
  MinoEndViews ends;
  KerrMinoRay::EndView scratch_end;  ///< where the views of lanes without a step go
  // The steps handed on a round at a time (steps): the lanes whose rays can pass through the axis
  // (L = 0: their θ branch can change); the polar offset and ζ of each lane's state as the end of
  // its last step, before a re-basing (the view of the next step's start,
  // KerrMinoRay::bl_step_viewed); the positions of the step ends (SoA); the round's steps and the
  // Mino states of the lane whose view was asked for last (lane_view).
  unsigned axis_lanes = 0;
  alignas(64) double start_pole[kPacketLanes] = {}, start_zeta[kPacketLanes] = {};
  alignas(64) double end_p[3][kPacketLanes] = {};
  const PacketSteps* round = nullptr;
  double view_states[4][KerrMinoRHS::N] = {};
  size_t target = packet_target();  ///< the SIMD functions' (GEOVIS_PACKET_DISPATCH)

  KerrMinoSystem& system(int l) { return ray[l]->sys; }
  /// The ray from BL (x, k); one that starts outside the metric's validity domain goes to
  /// metric.integrate, as in MetricCRTP::integrate.
  bool start(int l, const double* ys, double* y) {
    if (!metric.is_valid(Vec4{{ys[0], ys[1], ys[2], ys[3]}})) {
      double yy[kMaxSystemDim] = {};
      std::memcpy(yy, ys, kDim * sizeof(double));
      auto cb = [&](const StepView& s) { return rays.on_step ? rays.on_step(l, s) : StepAction::Continue; };
      const GeodesicResult res = metric.integrate(cfg_in, GeodesicSystem::Geodesic, yy, 0.0, cb);
      rays.done(l, yy, res);
      return false;
    }
    const KerrMinoRay& r = ray[l].emplace(hole.mass, hole.a, hole.r_break, cfg, ys, 0.0, y);
    const KerrMinoConstants& c = r.c;
    coeffs.set_lane(l, c, r.sys.f.polar.pole, r.sys.w_break);
    axis_lanes = (axis_lanes & ~(1u << l)) | (c.axis ? 1u << l : 0u);
    ends.sign[l] = r.branch.sign;
    start_pole[l] = r.sys.f.polar.pole;
    start_zeta[l] = y[KerrMinoRHS::Z];
    return true;
  }
  void rhs(const double* y, double* dy, unsigned) const { GEOVIS_PACKET_DISPATCH(mino_rhs, target)(coeffs, y, dy); }
  void tolerance_inv(double eps_abs, double eps_rel, const double* y, double* inv) const {
    GEOVIS_PACKET_DISPATCH(mino_tolerance, target)(coeffs, eps_abs, eps_rel, y, inv);
  }
  void attempt(SolverKind kind, unsigned, const LaneTolerance& tol, const double* y, const double* dy, const double* h,
               double* y1, double* dy1, AttemptError& err) const {
    GEOVIS_PACKET_DISPATCH(mino_attempt, target)(kind, coeffs, tol, y, dy, h, y1, dy1, err);
  }
  /// The BL views of the accepted steps' ends (y1, dy1: SoA), all lanes at once on SIMD lanes
  /// (kerr_mino_bl_view, the function KerrMinoRay::step evaluates per ray), on the branch each ray
  /// has after its step, written straight into each ray's next_end() (mino_end_views), which step
  /// then reports. Without a step callback none are needed.
  void before_steps(unsigned lanes, const double* y, const double* y1, const double* dy1) {
    if (!rays.on_step || batch_steps()) return;
    using I = KerrMinoRHS;
    constexpr int W = kPacketLanes;
    for (int l = 0; l < W; ++l) {
      const bool active = lanes >> l & 1u;
      ends.active[l] = active ? 1.0 : 0.0;
      // The view of the step's end goes to the slot bl_step_with_end reports (next_end).
      ends.dst[l] = active ? &ray[l]->next_end() : &scratch_end;
      if (!active) continue;
      const ThetaBranch b = ray[l]->branch_after(y[I::DZ * W + l], y1[I::Z * W + l], y1[I::DZ * W + l]);
      ends.sign[l] = b.sign;
      ends.offset[l] = b.offset;
    }
    ends.position_only = rays.states_on_request;
    GEOVIS_PACKET_DISPATCH(mino_end_views, target)(coeffs, y1, dy1, ends);
  }
  /// The accepted step of lane l in BL terms, the view of its end (or its position alone, where
  /// the caller asks for the states: PacketRays::states_on_request) written by before_steps.
  StepAction step(int l, const StepView& s) {
    if (!rays.on_step) return ray[l]->step(s, {});
    if (rays.states_on_request) return rays.on_step(l, ray[l]->bl_step_with_position(s));
    return rays.on_step(l, ray[l]->bl_step_with_end(s));
  }
  void rebase(int l, double* y) {
    ray[l]->sys.rebase(y);
    coeffs.v[MinoLaneCoeffs::POLE][l] = ray[l]->sys.f.polar.pole;
  }
  /// The steps go to PacketRays::on_steps a round at a time where it is set.
  bool batch_steps() const { return static_cast<bool>(rays.on_steps); }
  /// The accepted steps of a round (s: Mino states, SoA) handed on at once: the positions of their
  /// ends on all lanes at once (mino_end_positions, on the θ branch after the step) as
  /// PacketSteps::p1, each lane's BL view only where the caller asks for it (lane_view); then each
  /// lane's θ branch and the offset and ζ of its new state are kept for its next step. Why: the
  /// lane-by-lane hand-over (the gathered rows, the ray's view bookkeeping, a call per lane and
  /// step) was ~200 instructions per step on kerrAccretionDisk.scm, whose chords are nearly all
  /// culled from their ends' positions alone (callgrind, issue 13).
  unsigned steps(const PacketSteps& s) {
    using I = KerrMinoRHS;
    constexpr int W = kPacketLanes;
    // Only a ray through the axis changes its θ branch (KerrMinoRay::branch_after).
    for (unsigned todo = s.lanes & axis_lanes; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      ends.sign[l] = ray[l]->branch_after(s.y0[I::DZ * W + l], s.y1[I::Z * W + l], s.y1[I::DZ * W + l]).sign;
    }
    GEOVIS_PACKET_DISPATCH(mino_end_positions, target)(coeffs, s.y1, ends.sign, s.lanes, end_p[0]);
    PacketSteps bl = s;
    bl.p1 = end_p[0];
    bl.lane_view = &MinoPacket::lane_view;
    bl.lane_view_context = this;
    round = &bl;
    const unsigned stopped = rays.on_steps(bl);
    round = nullptr;
    for (unsigned todo = s.lanes & axis_lanes; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      ray[l]->branch = ray[l]->branch_after(s.y0[I::DZ * W + l], s.y1[I::Z * W + l], s.y1[I::DZ * W + l]);
    }
    const double* const from[2] = {coeffs.v[MinoLaneCoeffs::POLE], s.y1 + I::Z * W};
    double* const to[2] = {start_pole, start_zeta};
    GEOVIS_PACKET_DISPATCH(copy_lanes, target)(s.lanes, from, to, 2);
    return stopped;
  }
  /// PacketSteps::lane_view of the round being handed on: lane l's step in BL terms
  /// (KerrMinoRay::bl_step_viewed), its states converted on request where the caller reads them
  /// so (PacketRays::states_on_request).
  static StepView lane_view(void* context, int l) {
    MinoPacket& p = *static_cast<MinoPacket*>(context);
    constexpr int W = kPacketLanes, N = KerrMinoRHS::N;
    const PacketSteps& s = *p.round;
    for (int i = 0; i < N; ++i) {
      p.view_states[0][i] = s.y0[i * W + l];
      p.view_states[1][i] = s.y1[i * W + l];
      p.view_states[2][i] = s.dy0[i * W + l];
      p.view_states[3][i] = s.dy1[i * W + l];
    }
    const double p1[3] = {p.end_p[0][l], p.end_p[1][l], p.end_p[2][l]};
    const StepView mino{
        s.lambda0[l],   s.lambda1[l], p.view_states[0], p.view_states[1], p.view_states[2], p.view_states[3], N,
        s.step_index[l]};
    return p.ray[l]->bl_step_viewed(mino, p.start_pole[l], p.start_zeta[l], p1, p.rays.states_on_request);
  }
  /// After the steps of the lanes in `lanes` became their states y (SoA): the re-basing of those
  /// that crossed the equator (rebase), then KerrMinoSystem::inside of each (bit l: lane l), in the
  /// order of the lane-by-lane steps.
  unsigned after_steps(const SolverConfig& c, unsigned lanes, double* y) {
    using I = KerrMinoRHS;
    constexpr int W = kPacketLanes;
    if (!lanes) return 0;
    // The box in w, t and φ is the same for every ray (KerrMinoSystem::set_box).
    const KerrMinoSystem& any = system(std::countr_zero(lanes));
    const double box[6] = {any.w_lo, any.w_hi, c.box_ll[0], c.box_ur[0], c.box_ll[3], c.box_ur[3]};
    const unsigned bits = GEOVIS_PACKET_DISPATCH(mino_state_tests, target)(box, y);
    for (unsigned todo = bits & lanes; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      double yl[I::N] = {};
      yl[I::Z] = y[I::Z * W + l];
      rebase(l, yl);  // reads and changes ζ alone
      y[I::Z * W + l] = yl[I::Z];
    }
    unsigned inside = bits >> 8 & lanes;
    if (!any.theta_boxed) return inside;
    for (unsigned todo = inside; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      double yl[I::N] = {};  // the components inside reads
      for (const int i : {I::W, I::Z, I::T, I::PHI}) yl[i] = y[i * W + l];
      if (!system(l).inside(c, yl)) inside &= ~(1u << l);
    }
    return inside;
  }
  void done(int l, const double* y, const GeodesicResult& res) {
    double ys[kDim];
    ray[l]->to_bl_state(y, ys);
    rays.done(l, ys, res);
  }
};

/// The Jacobi system of light rays through the Mino-time flow and its derivatives (kerr_jacobi.h),
/// one ray (KerrMinoJacobiRay) per lane: the right-hand side, the attempt and the tolerance scales
/// on dual numbers of SIMD lanes, the ray's own tests (validity, constraint, escape, capture) on
/// its value rows with the Mino packet's functions (the value's w, ζ, w', z' are the layout's rows
/// 0-3, as KerrMinoRHS's), the steps handed on lane by lane in BL Jacobi terms (bl_step, or
/// bl_step_with_position where the caller reads the states on request).
struct MinoJacobiPacket : MinoStateTests<MinoJacobiPacket> {
  using J = MinoJacobiLayout;
  static constexpr int N = J::N;
  const Metric& metric;
  const KerrMinoParams hole;
  const SolverConfig& cfg_in;  ///< the caller's settings (for rays handed to metric.integrate)
  const SolverConfig& cfg;     ///< KerrMinoRay::config(cfg_in)
  const JacobiPacketRays& rays;
  std::optional<KerrMinoJacobiRay> ray[kPacketLanes];
  MinoLaneCoeffs coeffs;      ///< the value's (each ray's KerrMinoSystem): its tests and scales
  MinoJacobiLaneCoeffs dual;  ///< with the derivatives: the right-hand side
  /// Each lane's start state as rays.next gave it (the driver's start sees x and k only).
  double start_state[kPacketLanes][kJacobiDim] = {};
  size_t target = packet_target();  ///< the SIMD functions' (GEOVIS_PACKET_DISPATCH)

  KerrMinoJacobiSystem& system(int l) { return ray[l]->sys; }
  /// PacketRays::next of the driver: the next ray's whole start state kept for start().
  bool next(int l, double* y) {
    if (!rays.next(l, start_state[l])) return false;
    std::memcpy(y, start_state[l], kDim * sizeof(double));
    return true;
  }
  /// The ray from its start state (next); one that this path does not take (outside the metric's
  /// validity domain, through the polar axis: KerrMinoJacobiRay::integrable) goes to
  /// metric.integrate, as in MetricCRTP::integrate.
  bool start(int l, const double*, double* y) {
    const double* ys = start_state[l];
    if (metric.is_valid(Vec4{{ys[0], ys[1], ys[2], ys[3]}})) {
      const KerrMinoJacobiRay& r = ray[l].emplace(hole.mass, hole.a, hole.r_break, cfg, ys, 0.0, y);
      if (r.integrable) {
        const double pole = r.sys.ray.f.polar.pole;
        coeffs.set_lane(l, r.c, pole, r.sys.ray.w_break);
        const KerrMinoCoeffs<DualJ>& kd = r.sys.kd;
        const DualJ* rows[MinoJacobiLaneCoeffs::kCoeffs] = {&kd.M,   &kd.a, &kd.a2, &kd.E, &kd.L, &kd.Q,
                                                            &kd.mu2, &kd.c, &kd.K,  &kd.A, &kd.B};
        for (int i = 0; i < MinoJacobiLaneCoeffs::kCoeffs; ++i) {
          dual.v[i][0][l] = rows[i]->v;
          dual.v[i][1][l] = rows[i]->d[0];
          dual.v[i][2][l] = rows[i]->d[1];
        }
        dual.pole[l] = pole;
        return true;
      }
    }
    double yy[kMaxSystemDim] = {};
    std::memcpy(yy, ys, kJacobiDim * sizeof(double));
    auto cb = [&](const StepView& s) { return rays.on_step ? rays.on_step(l, s) : StepAction::Continue; };
    const GeodesicResult res = metric.integrate(cfg_in, GeodesicSystem::Jacobi, yy, 0.0, cb);
    rays.done(l, yy, res);
    return false;
  }
  void rhs(const double* y, double* dy, unsigned) const {
    GEOVIS_PACKET_DISPATCH(mino_jacobi_rhs, target)(dual, y, dy);
  }
  void tolerance_inv(double eps_abs, double eps_rel, const double* y, double* inv) const {
    GEOVIS_PACKET_DISPATCH(mino_jacobi_tolerance, target)(coeffs, eps_abs, eps_rel, y, inv);
  }
  void attempt(SolverKind kind, unsigned, const LaneTolerance& tol, const double* y, const double* dy, const double* h,
               double* y1, double* dy1, AttemptError& err) const {
    GEOVIS_PACKET_DISPATCH(mino_jacobi_attempt, target)(kind, dual, tol, y, dy, h, y1, dy1, err);
  }
  // The value's dσ/dλ, validity, checks and may-project tests: MinoStateTests, on the value's rows,
  // which are the Mino state's where those tests read them.
  static_assert(J::at(KerrMinoRHS::W, -1) == KerrMinoRHS::W && J::at(KerrMinoRHS::Z, -1) == KerrMinoRHS::Z &&
                J::at(KerrMinoRHS::DW, -1) == KerrMinoRHS::DW && J::at(KerrMinoRHS::DZ, -1) == KerrMinoRHS::DZ);
  void rebase(int l, double* y) {
    system(l).rebase(y);
    coeffs.v[MinoLaneCoeffs::POLE][l] = dual.pole[l] = system(l).ray.f.polar.pole;
  }
  StepAction step(int l, const StepView& s) {
    if (!rays.on_step) return StepAction::Continue;
    if (rays.states_on_request) return rays.on_step(l, ray[l]->bl_step_with_position(s));
    return rays.on_step(l, ray[l]->bl_step(s));
  }
  void done(int l, const double* y, const GeodesicResult& res) {
    double ys[kJacobiDim];
    ray[l]->to_bl_state(y, ys);
    rays.done(l, ys, res);
  }
};

void require_packet_solver(const SolverConfig& cfg) {
  validate_solver_config(cfg);
  if (!packet_solver(cfg.kind))
    throw Error("packet integrator: only the CashKarp45, Fehlberg45, DormandPrince54 and DormandPrince853 solvers");
}

}  // namespace

void packet_accepted_step_control(unsigned lanes, const double* h, const double* err, const double* root,
                                  PacketStepControl& c) {
  HWY_DYNAMIC_DISPATCH(accepted_step_control)(lanes, h, err, root, c);
}

bool packet_solver(SolverKind kind) {
  return kind == SolverKind::CashKarp45 || kind == SolverKind::Fehlberg45 || kind == SolverKind::DormandPrince54 ||
         kind == SolverKind::DormandPrince853;
}

void integrate_geodesic_packet(const MetricKernel& metric, const SolverConfig& cfg, const PacketRays& rays) {
  require_packet_solver(cfg);
  CoordinatePacket ps{{}, metric, rays};
  with_packet_tableau(cfg.kind, [&]<class Tab>() { integrate_lanes<Tab>(ps, cfg, rays); });
}

void integrate_kerr_mino_packet(const Metric& metric, const KerrMinoParams& hole, const SolverConfig& cfg,
                                const PacketRays& rays) {
  require_packet_solver(cfg);
  const SolverConfig mino_cfg = KerrMinoRay::config(cfg);
  MinoPacket ps{{}, metric, hole, cfg, mino_cfg, rays, {}, {}, {}, {}};
  with_packet_tableau(cfg.kind, [&]<class Tab>() { integrate_lanes<Tab>(ps, mino_cfg, rays); });
}

void integrate_jacobi_packet_on_kernel(const MetricKernel& metric, const SolverConfig& cfg,
                                       const JacobiPacketRays& rays) {
  require_packet_solver(cfg);
  CoordinateJacobiPacket ps{{}, metric, rays};
  auto next = [&ps](int l, double* y) { return ps.next(l, y); };
  const PacketRays lane_rays{next, {}, {}, {}, false};
  with_packet_tableau(cfg.kind, [&]<class Tab>() { integrate_lanes<Tab>(ps, cfg, lane_rays); });
}

void integrate_kerr_mino_jacobi_packet(const Metric& metric, const KerrMinoParams& hole, const SolverConfig& cfg,
                                       const JacobiPacketRays& rays) {
  require_packet_solver(cfg);
  const SolverConfig mino_cfg = KerrMinoRay::config(cfg);
  MinoJacobiPacket ps{{}, metric, hole, cfg, mino_cfg, rays, {}, {}, {}, {}};
  auto next = [&ps](int l, double* y) { return ps.next(l, y); };
  const PacketRays lane_rays{next, {}, {}, {}, false};
  with_packet_tableau(cfg.kind, [&]<class Tab>() { integrate_lanes<Tab>(ps, mino_cfg, lane_rays); });
}

}  // namespace geovis
#endif  // HWY_ONCE

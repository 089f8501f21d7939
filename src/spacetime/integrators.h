// Integrator templates: the ODE systems along a geodesic, the explicit steppers and the step-size
// driver. Everything here is a template instantiated per concrete metric (metric_crtp.h), so a
// Runge-Kutta stage is straight-line code with the metric's Christoffel symbols inlined: no heap
// allocation and no virtual call per stage; the solver kind is dispatched once per geodesic.
//
// Steppers (tableaux from the original papers, as reprinted in Hairer, Nørsett & Wanner, "Solving
// Ordinary Differential Equations I", 2nd ed., Springer 1993 — "HNW" below):
//   RK2        Heun–Euler embedded 2(1) (trapezoidal Heun / explicit Euler; HNW I §II.4)
//   RK4        classical Runge–Kutta, fixed step (HNW I §II.1)
//   CashKarp45 Cash & Karp, ACM TOMS 16 (1990) 201; 5th order propagated (as GSL rkck)
//   Fehlberg45 Fehlberg, NASA TR R-315 (1969), HNW I §II.5; 4th order propagated (classical RKF45)
//   DP54       Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19; HNW I §II.5, FSAL
//   DOP853     Hairer's DOP853 (HNW I §II.10, code dop853.f): 8th order with the combined 5th/3rd
//              order error estimator err = e5² / sqrt(e5² + 0.01 e3²)
//   RKN86      Runge–Kutta–Nyström 8(6) of Dormand, El-Mikkawy & Prince (IMA J. Numer. Anal. 7
//              (1987) 423; HNW I §II.14): for y'' = f(y) with quadratures q' = g(y) only
//              (Carter's equations in Mino time, kerr_mino.h); 9 stages, the last one FSAL
//   BS         Gragg–Bulirsch–Stoer: modified midpoint rule with Gragg's smoothing step, polynomial
//              (Aitken–Neville) extrapolation in h², error from the last two entries of the
//              extrapolation table, order and step size selection by work per unit step (HNW I
//              §II.9, Hairer's code ODEX).
//
// Stepper concept (an object, constructed per geodesic from the SolverConfig):
//   static constexpr bool kHasErrorEstimate;
//   template <int N, class F> bool attempt(F& f, const double* y, const double* dy, double h,
//                                          double* yout, double* dyout, const ErrorScale& tol,
//                                          long& evals, double& err);
//     one trial step of signed size h from (y, dy = f(y)); writes the new state and the scaled
//     error norm err (≤ 1: acceptable; 0 when the stepper has no estimate); returns true when it
//     also wrote dyout = f(yout) (first-same-as-last methods).
//   double next_step(double h, double err, bool accepted, bool after_reject);
//     the |h| proposed for the next attempt.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "core/error.h"
#include "spacetime/geodesic.h"
#include "spacetime/vec.h"

namespace geovis {

#include "spacetime/geodesic_constraint.h"  // geodesic_constraint: in namespace geovis

// ---- ODE systems -------------------------------------------------------------------------------

/// Geodesic equation in coordinates, d²x^μ/dλ² = −Γ^μ_{ab} k^a k^b (y = x, k). Uses the metric's
/// hand-written acceleration when it has one, else contracts the Christoffel symbols.
template <class M>
struct GeodesicRHS {
  static constexpr int N = 8;
  const M& m;
  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    const Vec4 k{{y[4], y[5], y[6], y[7]}};
    Vec4 a;
    m.geodesic_acceleration(x, k, a);
    for (int i = 0; i < 4; ++i) {
      dy[i] = k[i];
      dy[4 + i] = a[i];
    }
  }
};

/// Geodesic plus parallel transport of four vectors (paper §2.3): de^μ/dλ = −Γ^μ_{ab} k^a e^b.
template <class M>
struct TransportRHS {
  static constexpr int N = 24;
  const M& m;
  void operator()(const double* y, double* dy) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    Christoffel G;
    m.christoffel_inline(x, G);
    const double* k = y + 4;
    for (int i = 0; i < 4; ++i) dy[i] = k[i];
    for (int v = 0; v < 5; ++v) {  // v = 0: k itself; 1..4: transported vectors
      const double* e = y + 4 + 4 * v;
      for (int mu = 0; mu < 4; ++mu) {
        double s = 0;
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * k[a] * e[b];
        dy[4 + 4 * v + mu] = -s;
      }
    }
  }
};

// The Jacobi system (Sachs basis + Jacobi matrix) lives in spacetime/jacobi.h.

// ---- error norm ----------------------------------------------------------------------------------

/// GSL's "y" control (gsl_odeiv2_control_y_new, as GeoViS uses it): component i may carry the
/// local error D_i = eps_abs + eps_rel·|y_i|. The scaled error is the maximum over components of
/// |err_i| / D_i. |y_i| is taken at the start of the step, not at its end as in GSL and HNW I
/// §II.4: a trial step that jumps across a singularity produces a huge y_new and must not
/// inflate its own tolerance with it (test BlowUpStopsBeforeTheSingularity).
///
/// A system whose variables are not the coordinates (Mino state, kerr_mino.h) gives per-component
/// scales s_i (as 1/s_i) so that the tolerance keeps its meaning in coordinates, D_i =
/// eps_abs·s_i + eps_rel·|y0_i|; the driver then sets `inv` to the N values 1/D_i at the start
/// of the step. The packet integrator runs the same norm on SIMD lanes (geodesic_packet.cpp
/// error_scale_norm_lanes): any change here goes there too.
struct ErrorScale {
  double eps_abs = 0, eps_rel = 0;
  const double* inv = nullptr;  ///< per-component 1/D_i, or null: D_i = eps_abs + eps_rel·|y0_i|
  /// max_i |err_i| / D_i; NaN when an error component is NaN. With eps_rel = 0 (GeoViS's default)
  /// this is one division per step instead of one per component.
  template <int N>
  double norm(const double* err, const double* y0) const {
    double m = 0;
    bool nan = false;
    if (inv) {
      for (int i = 0; i < N; ++i) {
        const double a = std::fabs(err[i]);
        nan |= a != a;
        m = std::max(m, a * inv[i]);
      }
    } else if (eps_rel == 0.0) {
      for (int i = 0; i < N; ++i) {
        const double a = std::fabs(err[i]);
        nan |= a != a;
        m = std::max(m, a);
      }
      m /= eps_abs;
    } else {
      for (int i = 0; i < N; ++i) {
        const double a = std::fabs(err[i]);
        nan |= a != a;
        m = std::max(m, a / (eps_abs + eps_rel * std::fabs(y0[i])));
      }
    }
    return nan ? std::numeric_limits<double>::quiet_NaN() : m;
  }
};

// ---- explicit Runge-Kutta ------------------------------------------------------------------------

namespace rk_detail {

/// acc += a·k[j][i] for the compile-time coefficient a = Tab::a[s][j] (skipped when zero, so the
/// unrolled stage is exactly the tableau's non-zero pattern).
template <class Tab, int s, int j, int S, int N>
inline void add_a(double& acc, const double (&k)[S][N], int i) {
  if constexpr (Tab::a[s][j] != 0.0) acc += Tab::a[s][j] * k[j][i];
}
template <class Tab, int S, int N, const double (&w)[S], int j>
inline void add_w(double& acc, const double (&k)[S][N], int i) {
  if constexpr (w[j] != 0.0) acc += w[j] * k[j][i];
}
/// Σ_j w[j] k[j][i] over the non-zero weights.
// clang-format 14 splits an immediately invoked template lambda from its call: not formatted.
// clang-format off
template <class Tab, int S, int N, const double (&w)[S]>
inline double weighted(const double (&k)[S][N], int i) {
  double acc = 0.0;
  [&]<int... j>(std::integer_sequence<int, j...>) {
    (add_w<Tab, S, N, w, j>(acc, k, i), ...);
  }(std::make_integer_sequence<int, S>{});
  return acc;
}

/// Number of leading state components the right-hand side of F reads (F::kCoupled when given,
/// else all): the remaining ones are quadratures (y_i' = f_i(coupled part)) whose stage values
/// are never needed.
template <class F, int N>
constexpr int coupled_dim() {
  if constexpr (requires { F::kCoupled; }) {
    static_assert(F::kCoupled <= N);
    return F::kCoupled;
  }
  return N;
}

/// Stage s (≥ 1): tmp = y + h Σ_{j<s} a[s][j] k_j (coupled components only), then k_s = f(tmp).
template <class Tab, int s, int S, int N, class F>
GEOVIS_HOT_INLINE void stage(F& f, const double* y, double h, double (&k)[S][N]) {
  double tmp[N];
  for (int i = 0; i < coupled_dim<F, N>(); ++i) {
    double acc = 0.0;
    [&]<int... j>(std::integer_sequence<int, j...>) {
      (add_a<Tab, s, j, S, N>(acc, k, i), ...);
    }(std::make_integer_sequence<int, s>{});
    tmp[i] = y[i] + h * acc;
  }
  f(tmp, k[s]);
}

template <class Tab, int S, int N, class F>
inline void all_stages(F& f, const double* y, double h, double (&k)[S][N]) {
  [&]<int... s>(std::integer_sequence<int, s...>) {
    (stage<Tab, s + 1, S, N>(f, y, h, k), ...);
  }(std::make_integer_sequence<int, S - 1>{});
}
// clang-format on

}  // namespace rk_detail

/// The start of root_q's Newton iteration for q = 5, 7: 2^(−log2(x)/q) from x's bit pattern
/// (exponent and mantissa read as a linear approximation of log2).
template <int q>
GEOVIS_HOT_INLINE double root_q_seed(double x) {
  constexpr std::int64_t kOne = 0x3FF0000000000000;  // bits of 1.0
  std::int64_t i;
  std::memcpy(&i, &x, sizeof i);
  i = kOne - (i - kOne) / q;
  double y;
  std::memcpy(&y, &i, sizeof y);
  return y;
}

/// x^(1/q) (x > 0 finite) for the step-size controllers: square roots for q = 2, 4, 8 (DOP853),
/// a division-free Newton iteration for q = 5 and 7, std::pow otherwise (a libm call per step).
/// Always inlined, like StepController::next below. The packet integrator (geodesic_packet.cpp
/// root_q_lanes) runs the same operations on SIMD lanes: any change here goes there too (test
/// GeodesicPacket, bit identity).
///
/// q = 5, 7: y = x^(−1/q) by Newton's iteration y ← y (q + 1 − x y^q)/q (no division) from the
/// bit-pattern estimate 2^(−log2(x)/q) of root_q_seed (within 9 %; the error e goes to ~3e² per
/// iteration); four iterations leave < 1e-9 relative error, far below what a step-size proposal
/// needs (test FastMath.StepControllerRootsMatchPow).
template <int q>
GEOVIS_HOT_INLINE double root_q(double x) {
  if constexpr (q == 5) {
    double y = root_q_seed<5>(x);
    for (int it = 0; it < 4; ++it) {
      const double y2 = y * y;
      y = y * (6.0 - x * (y2 * y2 * y)) * 0.2;
    }
    return 1.0 / y;
  } else if constexpr (q == 7) {
    double y = root_q_seed<7>(x);
    for (int it = 0; it < 4; ++it) {
      const double y2 = y * y, y3 = y2 * y;
      y = y * (8.0 - x * (y3 * y3 * y)) * (1.0 / 7.0);
    }
    return 1.0 / y;
  } else if constexpr (q == 1) {
    return x;
  } else if constexpr (q == 2) {
    return std::sqrt(x);
  } else if constexpr (q == 4) {
    return std::sqrt(std::sqrt(x));
  } else if constexpr (q == 8) {
    return std::sqrt(std::sqrt(std::sqrt(x)));
  } else {
    return std::pow(x, 1.0 / q);
  }
}

/// Step-size control of the embedded pairs. Standard rule (HNW I §II.4):
///   h_new = h·0.9·err^(−1/q̂),  q̂ = kErrExp (the error estimate behaves like h^q̂),
/// growth limited to ×5 and shrink to ×0.2 (GSL's standard control), no growth right after a
/// rejection (HNW I §II.4). After two accepted steps in a row it also applies Gustafsson's
/// predictive rule (Gustafsson, ACM TOMS 20 (1994) 496; HNW II §IV.8, as in Hairer's RADAU5)
///   h_new = h·0.9·err^(−1/q̂) · (h/h_old) · (err_old/err)^(1/q̂)
/// and takes the smaller proposal: when the error grows steadily from step to step (a ray falling
/// towards a black hole), the standard rule keeps proposing steps that are then rejected.
template <int kErrExp>
struct StepController {
  static constexpr double kSafety = 0.9, kMaxGrow = 5.0, kMaxShrink = 0.2;
  double h_old = 0, q_old = 0;  ///< last accepted step and its err^(1/q̂); h_old = 0: none yet

  // Always inlined: the per-metric integrator (metric_crtp.h) is its only caller in a metric file,
  // but in a unity unit of several metrics (CMakeLists.txt) GCC stopped inlining it.
  GEOVIS_HOT_INLINE double next(double h, double err, bool accepted, bool after_reject) {
    return next_with_root(h, err, err > 0.0 && std::isfinite(err) ? root_q<kErrExp>(err) : 0.0, accepted, after_reject);
  }
  /// next() with root = root_q<kErrExp>(err) given (used only where err > 0 is finite): the packet
  /// integrator takes the roots of all its lanes at once (geodesic_packet.cpp).
  GEOVIS_HOT_INLINE double next_with_root(double h, double err, double root, bool accepted, bool after_reject) {
    h = std::fabs(h);
    double fac, q = 0;
    if (!(err > 0.0)) {
      fac = kMaxGrow;
    } else if (std::isfinite(err)) {
      q = root;
      fac = kSafety / q;
      if (accepted && h_old > 0 && q_old > 0) fac = std::min(fac, fac * (h / h_old) * (q_old / q));
      fac = std::clamp(fac, kMaxShrink, kMaxGrow);
    } else {
      fac = kMaxShrink;
    }
    if (!accepted) {
      fac = std::min(fac, kSafety);
    } else {
      if (after_reject) fac = std::min(fac, 1.0);
      h_old = h;
      q_old = q;
    }
    return h * fac;
  }
};

/// Explicit embedded Runge-Kutta step from a tableau with static members S (stages), a[S][S],
/// b[S] (propagated solution), e[S] = b − b̂ (error weights), kErrExp (0: no estimate), kFsal.
template <class Tab>
struct ExplicitRK {
  static constexpr bool kHasErrorEstimate = Tab::kErrExp > 0;
  explicit ExplicitRK(const SolverConfig&) {}
  StepController<(Tab::kErrExp > 0 ? Tab::kErrExp : 1)> control;

  template <int N, class F>
  bool attempt(F& f, const double* y, const double* dy, double h, double* yout, double* dyout, const ErrorScale& tol,
               long& evals, double& err) {
    constexpr int S = Tab::S;
    double k[S][N];
    for (int i = 0; i < N; ++i) k[0][i] = dy[i];
    rk_detail::all_stages<Tab>(f, y, h, k);
    evals += S - 1;
    double e[N];
    for (int i = 0; i < N; ++i) {
      yout[i] = y[i] + h * rk_detail::weighted<Tab, S, N, Tab::b>(k, i);
      if constexpr (kHasErrorEstimate) e[i] = h * rk_detail::weighted<Tab, S, N, Tab::e>(k, i);
    }
    err = 0.0;
    if constexpr (kHasErrorEstimate) err = tol.norm<N>(e, y);
    if constexpr (Tab::kFsal) {
      // The last stage was evaluated at yout itself (c_S = 1, a[S-1] = b).
      for (int i = 0; i < N; ++i) dyout[i] = k[S - 1][i];
      return true;
    }
    return false;
  }
  GEOVIS_HOT_INLINE double next_step(double h, double err, bool accepted, bool after_reject) {
    if constexpr (kHasErrorEstimate) return control.next(h, err, accepted, after_reject);
    return std::fabs(h);
  }
};

/// Heun–Euler embedded pair 2(1): Heun's trapezoidal method (order 2) is propagated, explicit Euler
/// (order 1) is the comparison; the estimate behaves like h².
struct HeunEulerTableau {
  static constexpr int S = 2, kErrExp = 2;
  static constexpr bool kFsal = false;
  static constexpr double c[2] = {0, 1};
  static constexpr double a[2][2] = {{0, 0}, {1, 0}};
  static constexpr double b[2] = {0.5, 0.5};
  static constexpr double e[2] = {0.5 - 1.0, 0.5};
};

/// Classical fourth-order Runge-Kutta (fixed step; no error estimate).
struct RK4Tableau {
  static constexpr int S = 4, kErrExp = 0;
  static constexpr bool kFsal = false;
  static constexpr double c[4] = {0, 0.5, 0.5, 1};
  static constexpr double a[4][4] = {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}};
  static constexpr double b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  static constexpr double e[4] = {0, 0, 0, 0};
};

/// Cash & Karp (1990): embedded 4(5); the 5th-order solution is propagated (as GSL's rkck
/// and Numerical Recipes), the estimate is the 4th-order local error, ~h⁵.
struct CashKarpTableau {
  static constexpr int S = 6, kErrExp = 5;
  static constexpr bool kFsal = false;
  static constexpr double c[6] = {0, 1.0 / 5, 3.0 / 10, 3.0 / 5, 1, 7.0 / 8};
  static constexpr double a[6][6] = {{0, 0, 0, 0, 0, 0},
                                     {1.0 / 5, 0, 0, 0, 0, 0},
                                     {3.0 / 40, 9.0 / 40, 0, 0, 0, 0},
                                     {3.0 / 10, -9.0 / 10, 6.0 / 5, 0, 0, 0},
                                     {-11.0 / 54, 5.0 / 2, -70.0 / 27, 35.0 / 27, 0, 0},
                                     {1631.0 / 55296, 175.0 / 512, 575.0 / 13824, 44275.0 / 110592, 253.0 / 4096, 0}};
  static constexpr double b[6] = {37.0 / 378, 0, 250.0 / 621, 125.0 / 594, 0, 512.0 / 1771};
  static constexpr double e[6] = {
      37.0 / 378 - 2825.0 / 27648, 0, 250.0 / 621 - 18575.0 / 48384, 125.0 / 594 - 13525.0 / 55296, -277.0 / 14336,
      512.0 / 1771 - 0.25};
};

/// Runge–Kutta–Fehlberg 4(5) (Fehlberg 1969; HNW I §II.5): the 4th-order
/// solution is propagated as in Fehlberg's original method, the 5th-order one estimates its
/// error, ~h⁵.
struct FehlbergTableau {
  static constexpr int S = 6, kErrExp = 5;
  static constexpr bool kFsal = false;
  static constexpr double c[6] = {0, 1.0 / 4, 3.0 / 8, 12.0 / 13, 1, 1.0 / 2};
  static constexpr double a[6][6] = {{0, 0, 0, 0, 0, 0},
                                     {1.0 / 4, 0, 0, 0, 0, 0},
                                     {3.0 / 32, 9.0 / 32, 0, 0, 0, 0},
                                     {1932.0 / 2197, -7200.0 / 2197, 7296.0 / 2197, 0, 0, 0},
                                     {439.0 / 216, -8.0, 3680.0 / 513, -845.0 / 4104, 0, 0},
                                     {-8.0 / 27, 2.0, -3544.0 / 2565, 1859.0 / 4104, -11.0 / 40, 0}};
  static constexpr double b[6] = {25.0 / 216, 0, 1408.0 / 2565, 2197.0 / 4104, -1.0 / 5, 0};
  static constexpr double e[6] = {
      25.0 / 216 - 16.0 / 135, 0,        1408.0 / 2565 - 6656.0 / 12825, 2197.0 / 4104 - 28561.0 / 56430,
      -1.0 / 5 + 9.0 / 50,     -2.0 / 55};
};

/// Dormand & Prince (1980) RK5(4)7M (HNW I §II.5): 5th order propagated, FSAL (the 7th
/// stage is f at the new point), estimate ~h⁵.
struct DormandPrince54Tableau {
  static constexpr int S = 7, kErrExp = 5;
  static constexpr bool kFsal = true;
  static constexpr double c[7] = {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
  static constexpr double a[7][7] = {{0, 0, 0, 0, 0, 0, 0},
                                     {1.0 / 5, 0, 0, 0, 0, 0, 0},
                                     {3.0 / 40, 9.0 / 40, 0, 0, 0, 0, 0},
                                     {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0, 0},
                                     {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0, 0},
                                     {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0, 0},
                                     {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0}};
  static constexpr double b[7] = {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0};
  static constexpr double e[7] = {71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                                  -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
};

/// Hairer's DOP853 (HNW I §II.10; coefficients of dop853.f, Dormand & Prince 1981 8(7)13M
/// re-optimized with a 5th- and 3rd-order embedded pair). 12 stages, 8th-order propagated.
struct DOP853Tableau {
  static constexpr int S = 12, kErrExp = 8;  ///< the combined estimate (DOP853) behaves like h⁸
  static constexpr bool kFsal = false;
  static constexpr double c[12] = {0.0,
                                   0.526001519587677318785587544488e-01,
                                   0.789002279381515978178381316732e-01,
                                   0.118350341907227396726757197510e+00,
                                   0.281649658092772603273242802490e+00,
                                   0.333333333333333333333333333333e+00,
                                   0.25e+00,
                                   0.307692307692307692307692307692e+00,
                                   0.651282051282051282051282051282e+00,
                                   0.6e+00,
                                   0.857142857142857142857142857142e+00,
                                   1.0};
  static constexpr double a[12][12] = {
      {},
      {5.26001519587677318785587544488e-2},
      {1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2},
      {2.95875854768068491816892993775e-2, 0, 8.87627564304205475450678981324e-2},
      {2.41365134159266685502369798665e-1, 0, -8.84549479328286085344864962717e-1, 9.24834003261792003115737966543e-1},
      {3.7037037037037037037037037037e-2, 0, 0, 1.70828608729473871279604482173e-1, 1.25467687566822425016691814123e-1},
      {3.7109375e-2, 0, 0, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2, -1.7578125e-2},
      {3.70920001185047927108779319836e-2, 0, 0, 1.70383925712239993810214054705e-1, 1.07262030446373284651809199168e-1,
       -1.53194377486244017527936158236e-2, 8.27378916381402288758473766002e-3},
      {6.24110958716075717114429577812e-1, 0, 0, -3.36089262944694129406857109825e0,
       -8.68219346841726006818189891453e-1, 2.75920996994467083049415600797e1, 2.01540675504778934086186788979e1,
       -4.34898841810699588477366255144e1},
      {4.77662536438264365890433908527e-1, 0, 0, -2.48811461997166764192642586468e0,
       -5.90290826836842996371446475743e-1, 2.12300514481811942347288949897e1, 1.52792336328824235832596922938e1,
       -3.32882109689848629194453265587e1, -2.03312017085086261358222928593e-2},
      {-9.3714243008598732571704021658e-1, 0, 0, 5.18637242884406370830023853209e0, 1.09143734899672957818500254654e0,
       -8.14978701074692612513997267357e0, -1.85200656599969598641566180701e1, 2.27394870993505042818970056734e1,
       2.49360555267965238987089396762e0, -3.0467644718982195003823669022e0},
      {2.27331014751653820792359768449e0, 0, 0, -1.05344954667372501984066689879e1, -2.00087205822486249909675718444e0,
       -1.79589318631187989172765950534e1, 2.79488845294199600508499808837e1, -2.85899827713502369474065508674e0,
       -8.87285693353062954433549289258e0, 1.23605671757943030647266201528e1, 6.43392746015763530355970484046e-1}};
  static constexpr double b[12] = {5.42937341165687622380535766363e-2,
                                   0,
                                   0,
                                   0,
                                   0,
                                   4.45031289275240888144113950566e0,
                                   1.89151789931450038304281599044e0,
                                   -5.8012039600105847814672114227e0,
                                   3.1116436695781989440891606237e-1,
                                   -1.52160949662516078556178806805e-1,
                                   2.01365400804030348374776537501e-1,
                                   4.47106157277725905176885569043e-2};
  /// 5th-order error weights (b − b̂₅), dop853.f ER1..ER12.
  static constexpr double e5[12] = {0.1312004499419488073250102996e-01,
                                    0,
                                    0,
                                    0,
                                    0,
                                    -0.1225156446376204440720569753e+01,
                                    -0.4957589496572501915214079952e+00,
                                    0.1664377182454986536961530415e+01,
                                    -0.3503288487499736816886487290e+00,
                                    0.3341791187130174790297318841e+00,
                                    0.8192320648511571246570742613e-01,
                                    -0.2235530786388629525884427845e-01};
  /// 3rd-order comparison weights b̂₃ (dop853.f BHH1..3 on stages 1, 9, 12); e3 = b − b̂₃.
  static constexpr double bhh1 = 0.244094488188976377952755905512e+00;
  static constexpr double bhh2 = 0.733846688281611857341361741547e+00;
  static constexpr double bhh3 = 0.220588235294117647058823529412e-01;
  static constexpr double e3[12] = {b[0] - bhh1, 0, 0, 0, 0, b[5], b[6], b[7], b[8] - bhh2, b[9], b[10], b[11] - bhh3};
};

/// DOP853 step: the general stage machinery with Hairer's combined error estimator
/// err = |h|·e5² / sqrt(e5² + 0.01·e3²) (dop853.f, label 'ERROR ESTIMATION'), here with the max
/// norm of ErrorScale instead of dop853's RMS norm. It behaves like h⁸ (HNW I §II.10).
struct DOP853 {
  using Tab = DOP853Tableau;
  static constexpr bool kHasErrorEstimate = true;
  static constexpr int kErrExp = Tab::kErrExp;
  explicit DOP853(const SolverConfig&) {}

  template <int N, class F>
  bool attempt(F& f, const double* y, const double* dy, double h, double* yout, double* /*dyout*/,
               const ErrorScale& tol, long& evals, double& err) {
    constexpr int S = Tab::S;
    double k[S][N];
    for (int i = 0; i < N; ++i) k[0][i] = dy[i];
    rk_detail::all_stages<Tab>(f, y, h, k);
    evals += S - 1;
    double e5[N], e3[N];
    for (int i = 0; i < N; ++i) {
      yout[i] = y[i] + h * rk_detail::weighted<Tab, S, N, Tab::b>(k, i);
      e5[i] = rk_detail::weighted<Tab, S, N, Tab::e5>(k, i);
      e3[i] = rk_detail::weighted<Tab, S, N, Tab::e3>(k, i);
    }
    err = combined_error(tol.norm<N>(e5, y), tol.norm<N>(e3, y), h);
    return false;
  }
  /// The combined estimate from the scaled norms of Σ e5_j k_j and Σ e3_j k_j (without the
  /// factor h) and the step h; also the packet integrator's (geodesic_packet.cpp), for the same
  /// bits.
  static double combined_error(double err5, double err3, double h) {
    const double deno = err5 * err5 + 0.01 * err3 * err3;
    return deno > 0 ? std::fabs(h) * err5 * err5 / std::sqrt(deno) : (deno == 0 ? 0.0 : deno);
  }
  double next_step(double h, double err, bool accepted, bool after_reject) {
    return control.next(h, err, accepted, after_reject);
  }
  StepController<kErrExp> control;
};

// ---- Runge–Kutta–Nyström -------------------------------------------------------------------------

/// Number P of position components of a system with Nyström structure — state (q[P], q'[P],
/// quadratures), f giving q'' and the quadratures' derivatives from q alone — declared as
/// `static constexpr int kNystromPositions`; 0 when the system has none.
template <class F>
constexpr int nystrom_positions() {
  if constexpr (requires { F::kNystromPositions; }) return F::kNystromPositions;
  return 0;
}

/// Dormand, El-Mikkawy & Prince RKN 8(6) (IMA J. Numer. Anal. 7 (1987) 423; the coefficients as
/// tabulated in GMAT's DormandElMikkawyPrince68): nodes c, position matrix ā (row sums c²/2),
/// position weights b̄ (8th order), velocity weights b (8th order; a symmetric quadrature on the
/// nodes 0, .1, .3, .5, .7, .9, 1, exact to degree 7), and the differences to the embedded 6th-order weights, ep = b̄ −
/// b̄̂, ev = b − b̂. The last stage is evaluated at the new position (ā[8] = b̄): first same as last.
struct RKN86Tableau {
  static constexpr int S = 9;
  static constexpr double c[9] = {0.0, 1.0 / 20, 1.0 / 10, 3.0 / 10, 1.0 / 2, 7.0 / 10, 9.0 / 10, 1.0, 1.0};
  static constexpr double bp[9] = {
      223.0 / 7938, 0.0, 1175.0 / 8064, 925.0 / 6048, 41.0 / 448, 925.0 / 14112, 1175.0 / 72576, 0.0, 0.0};
  static constexpr double a[9][9] = {
      {},
      {1.0 / 800},
      {1.0 / 600, 1.0 / 300},
      {9.0 / 200, -9.0 / 100, 9.0 / 100},
      {-66701.0 / 197352, 28325.0 / 32892, -2665.0 / 5482, 2170.0 / 24669},
      {227015747.0 / 304251000, -54897451.0 / 30425100, 12942349.0 / 10141700, -9499.0 / 304251, 539.0 / 9250},
      {-1131891597.0 / 901789000, 41964921.0 / 12882700, -6663147.0 / 3220675, 270954.0 / 644135, -108.0 / 5875,
       114.0 / 1645},
      {13836959.0 / 3667458, -17731450.0 / 1833729, 1063919505.0 / 156478208, -33213845.0 / 39119552, 13335.0 / 28544,
       -705.0 / 14272, 1645.0 / 57088},
      {bp[0], bp[1], bp[2], bp[3], bp[4], bp[5], bp[6], bp[7]}};
  static constexpr double bv[9] = {
      223.0 / 7938, 0.0, 5875.0 / 36288, 4625.0 / 21168, 41.0 / 224, 4625.0 / 21168, 5875.0 / 36288, 223.0 / 7938, 0.0};
  static constexpr double ep[9] = {bp[0] - 7987313.0 / 109941300,
                                   0.0,
                                   bp[2] - 1610737.0 / 44674560,
                                   bp[3] - 10023263.0 / 33505920,
                                   bp[4] + 497221.0 / 12409600,
                                   bp[5] - 10023263.0 / 78180480,
                                   bp[6] - 1610737.0 / 402071040,
                                   0.0,
                                   0.0};
  static constexpr double ev[9] = {bv[0] - 7987313.0 / 109941300,
                                   0.0,
                                   bv[2] - 1610737.0 / 40207104,
                                   bv[3] - 10023263.0 / 23454144,
                                   bv[4] + 497221.0 / 6204800,
                                   bv[5] - 10023263.0 / 23454144,
                                   bv[6] - 1610737.0 / 40207104,
                                   bv[7] + 4251941.0 / 54970650,
                                   -3.0 / 20};
};

/// One RKN86 step on a system with Nyström structure (nystrom_positions): per stage only the P
/// positions are formed, q_s = q + c_s h q' + h² Σ ā_sj q''_j; then q_new = q + h q' + h² Σ b̄_j q''_j,
/// q'_new = q' + h Σ b_j q''_j and every quadrature Q_new = Q + h Σ b_j Q'_j (Q' depends on q only,
/// exactly like q''). The error estimate compares with the embedded 6th-order weights (~h⁷).
struct RKN86 {
  using Tab = RKN86Tableau;
  static constexpr bool kHasErrorEstimate = true;
  static constexpr int kErrExp = 7;
  explicit RKN86(const SolverConfig&) {}

  template <int N, class F>
  bool attempt(F& f, const double* y, const double* dy, double h, double* yout, double* dyout, const ErrorScale& tol,
               long& evals, double& err) {
    constexpr int P = nystrom_positions<F>();
    static_assert(P > 0 && 2 * P <= N, "RKN86 needs a system with Nyström structure");
    constexpr int S = Tab::S;
    double k[S][N];
    for (int i = 0; i < N; ++i) k[0][i] = dy[i];
    const double h2 = h * h;
    // clang-format 14 splits an immediately invoked template lambda from its call: not formatted.
    // clang-format off
    auto positions = [&]<int s>(double* tmp) {
      for (int i = 0; i < P; ++i) {
        double acc = 0.0;
        [&]<int... j>(std::integer_sequence<int, j...>) {
          ((Tab::a[s][j] != 0.0 ? (acc += Tab::a[s][j] * k[j][P + i]) : acc), ...);
        }(std::make_integer_sequence<int, s>{});
        tmp[i] = y[i] + Tab::c[s] * h * y[P + i] + h2 * acc;
        tmp[P + i] = y[P + i];  // not read by f; keeps the stage state defined
      }
    };
    [&]<int... s>(std::integer_sequence<int, s...>) {
      (
          [&] {
            double tmp[N];
            positions.template operator()<s + 1>(tmp);
            f(tmp, k[s + 1]);
          }(),
          ...);
    }(std::make_integer_sequence<int, S - 1>{});
    // clang-format on
    evals += S - 1;
    double e[N];
    for (int i = 0; i < P; ++i) {
      // Positions: the last stage was evaluated there (ā[8] = b̄).
      double acc = 0.0, ea = 0.0;
      for (int j = 0; j < S; ++j) {
        acc += Tab::bp[j] * k[j][P + i];
        ea += Tab::ep[j] * k[j][P + i];
      }
      yout[i] = y[i] + h * y[P + i] + h2 * acc;
      e[i] = h2 * ea;
    }
    for (int i = P; i < N; ++i) {  // velocities and quadratures
      double acc = 0.0, ea = 0.0;
      for (int j = 0; j < S; ++j) {
        acc += Tab::bv[j] * k[j][i];
        ea += Tab::ev[j] * k[j][i];
      }
      yout[i] = y[i] + h * acc;
      e[i] = h * ea;
    }
    err = tol.norm<N>(e, y);
    // FSAL: the last stage is f at the new positions; dq/dσ there is the new velocity.
    for (int i = 0; i < N; ++i) dyout[i] = k[S - 1][i];
    for (int i = 0; i < P; ++i) dyout[i] = yout[P + i];
    return true;
  }
  double next_step(double h, double err, bool accepted, bool after_reject) {
    return control.next(h, err, accepted, after_reject);
  }
  StepController<kErrExp> control;
};

// ---- Bulirsch–Stoer ------------------------------------------------------------------------------

/// Gragg–Bulirsch–Stoer extrapolation (HNW I §II.9). Row j of the extrapolation table starts with
/// Gragg's modified midpoint rule over the big step H with n_j = 2(j+1) substeps (Deuflhard's
/// sequence 2, 4, 6, ...) including Gragg's smoothing step, whose error expands in even powers of
/// H (Gragg 1965; HNW I §II.9); Aitken–Neville extrapolation (HNW I §II.9)
///   T_{j,k+1} = T_{j,k} + (T_{j,k} − T_{j−1,k}) / ((n_j / n_{j−k})² − 1)
/// gives T_{j,j} of order 2(j+1). The error of T_{j,j−1} (order 2j, local error ~H^{2j+1}) is
/// estimated by |T_{j,j} − T_{j,j−1}|; T_{j,j} is propagated. Order (number of rows) and step
/// size are chosen to minimize the work per unit step A_j/H_j (HNW I §II.9, code ODEX).
/// With step control off, kFixedRows rows are used (order 2·kFixedRows = 8).
struct BulirschStoer {
  static constexpr bool kHasErrorEstimate = true;
  static constexpr int kMaxRows = 9;    ///< n = 2 ... 18; highest order 18
  static constexpr int kFixedRows = 4;  ///< order 8 with fixed steps
  static constexpr int n(int j) { return 2 * (j + 1); }
  /// Work (f evaluations) for rows 0..j, including the evaluation at the start of the step.
  static constexpr double work(int j) {
    double w = 1;
    for (int l = 0; l <= j; ++l) w += n(l);
    return w;
  }

  explicit BulirschStoer(const SolverConfig& cfg) : adaptive_(cfg.step_ctrl) {}

  template <int N, class F>
  bool attempt(F& f, const double* y, const double* dy, double H, double* yout, double* /*dyout*/,
               const ErrorScale& tol, long& evals, double& err) {
    double T[kMaxRows][N];  // T[k] = T_{j,k} of the latest row j
    const int last_row = adaptive_ ? std::min(kopt_ + 1, kMaxRows - 1) : kFixedRows - 1;
    err = 0.0;
    int j = 0;
    for (;; ++j) {
      double base[N], diff[N];
      modified_midpoint<N>(f, y, dy, H, n(j), base, evals);
      double e = 0.0;
      for (int i = 0; i < N; ++i) {
        double cur = base[i];
        for (int k = 0; k < j; ++k) {
          const double old = T[k][i];
          T[k][i] = cur;
          const double r = static_cast<double>(n(j)) / n(j - k - 1);
          cur = cur + (cur - old) / (r * r - 1.0);
        }
        if (j > 0) diff[i] = cur - T[j - 1][i];
        T[j][i] = cur;
      }
      if (j > 0) e = tol.norm<N>(diff, y);
      if (j == last_row && !adaptive_) break;
      if (j == 0) continue;
      // Step proposal from this row: H_j = H·0.94·(0.65/err)^(1/(2j+1)) (ODEX safety factors).
      const double expo = 1.0 / (2 * j + 1);
      double fac = 0.02;  // NaN or infinite error
      if (e == 0)
        fac = 4.0;
      else if (e > 0 && std::isfinite(e))
        fac = 0.94 * std::pow(0.65 / e, expo);
      h_row_[j] = std::fabs(H) * std::clamp(fac, 0.02, 4.0);
      err = e;
      if (j == last_row || (j >= kopt_ - 1 && e <= 1.0)) break;
      // Early rejection (ODEX's convergence monitor): with the error dropping like (n_0/n_l)² per row, it
      // cannot be expected to fall below 1 by row kopt+1.
      if (j >= kopt_ - 1) {
        double expect = 1.0;
        for (int l = j + 1; l <= last_row; ++l) {
          const double r = static_cast<double>(n(l)) / n(0);
          expect *= r * r;
        }
        if (e > expect) break;
      }
    }
    last_row_ = j;
    for (int i = 0; i < N; ++i) yout[i] = T[j][i];
    if (!adaptive_) err = 0.0;
    return false;
  }

  double next_step(double h, double err, bool accepted, bool after_reject) {
    if (!adaptive_) return std::fabs(h);
    const int j = std::max(1, last_row_);
    if (!accepted) {
      // Reduce the step with the proposal of the last row computed; lower the order if possible.
      kopt_ = std::clamp(std::min(kopt_, j), 2, kMaxRows - 2);
      const double hr = h_row_[j] > 0 ? h_row_[j] : 0.25 * std::fabs(h);
      return std::min(hr, 0.9 * std::fabs(h));
    }
    (void)err;
    // Order selection by work per unit step W_j = A_j / H_j.
    double hnew;
    const double w_j = work(j) / h_row_[j];
    const double w_jm = j >= 2 ? work(j - 1) / h_row_[j - 1] : INFINITY;
    if (j >= 2 && w_jm < 0.8 * w_j) {
      kopt_ = j - 1;
      hnew = h_row_[j - 1];
    } else if (w_j < 0.9 * w_jm && j + 1 <= kMaxRows - 1) {
      kopt_ = j + 1;
      hnew = h_row_[j] * work(j + 1) / work(j);
    } else {
      kopt_ = j;
      hnew = h_row_[j];
    }
    kopt_ = std::clamp(kopt_, 2, kMaxRows - 2);
    if (after_reject) hnew = std::min(hnew, std::fabs(h));
    return hnew;
  }

 private:
  /// Gragg's modified midpoint rule with smoothing (HNW I §II.9): z_0 = y,
  /// z_1 = y + h f(y), z_{m+1} = z_{m−1} + 2h f(z_m), result ½(z_{n−1} + z_n + h f(z_n)), h = H/n.
  template <int N, class F>
  static void modified_midpoint(F& f, const double* y, const double* dy, double H, int nsub, double* out, long& evals) {
    const double h = H / nsub;
    double zprev[N], z[N], fz[N];
    for (int i = 0; i < N; ++i) {
      zprev[i] = y[i];
      z[i] = y[i] + h * dy[i];
    }
    for (int m = 1; m < nsub; ++m) {
      f(z, fz);
      for (int i = 0; i < N; ++i) {
        const double znew = zprev[i] + 2.0 * h * fz[i];
        zprev[i] = z[i];
        z[i] = znew;
      }
    }
    f(z, fz);
    evals += nsub;
    for (int i = 0; i < N; ++i) out[i] = 0.5 * (zprev[i] + z[i] + h * fz[i]);
  }
  bool adaptive_;
  int kopt_ = 4;      ///< target row: accept at kopt−1, kopt or kopt+1
  int last_row_ = 1;  ///< row at which the last attempt ended
  double h_row_[kMaxRows] = {};
};

// ---- systems as seen by the driver ---------------------------------------------------------------

/// A geodesic system (GeodesicRHS, TransportRHS, JacobiRHS) on metric M: the state starts with
/// x^μ, k^μ; the metric's validity domain and the normalization constraint g(k,k) = target apply.
template <class M, class F>
struct MetricSystem {
  static constexpr int N = F::N;
  static constexpr bool kHasConstraint = true;
  const M& m;
  F& f;
  GEOVIS_HOT_INLINE void operator()(const double* y, double* dy) const { f(y, dy); }
  /// In the metric's validity domain; a metric may also break a ray by its direction with
  /// `bool leaves_chart(const Vec4& x, const Vec4& k) const` (a ray that can only leave the chart
  /// asymptotically, e.g. towards the region that ingoing Eddington–Finkelstein does not cover).
  bool valid(const double* y) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    if (!m.is_valid_inline(x)) return false;
    if constexpr (requires { m.leaves_chart(x, x); }) return !m.leaves_chart(x, Vec4{{y[4], y[5], y[6], y[7]}});
    return true;
  }
  /// Inside the scene's bounding box (GeoViS boundBoxLL/UR, in the metric's coordinates).
  static bool inside(const SolverConfig& c, const double* y) {
    for (int i = 0; i < 4; ++i)
      if (!(y[i] >= c.box_ll[i] && y[i] <= c.box_ur[i])) return false;
    return true;
  }
  /// Escape of a light ray (geodesic.h StopReason::Escaped): an asymptotically flat metric
  /// provides `bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const`
  /// (spacetime/escape.h), true when x lies beyond radius r_min (radius = its |p|) and the light
  /// ray there, moving along k, can no longer turn back. The ray moves along direction·k.
  bool escaped(const SolverConfig& c, const double* y, double& radius) const {
    if constexpr (requires(const Vec4& v, double& r) { m.escapes(v, v, 0.0, r); }) {
      if (c.type != GeodesicType::Lightlike || !(c.escape_radius < INFINITY)) return false;
      const double s = c.direction >= 0 ? 1.0 : -1.0;
      return m.escapes(Vec4{{y[0], y[1], y[2], y[3]}}, Vec4{{s * y[4], s * y[5], s * y[6], s * y[7]}}, c.escape_radius,
                       radius);
    }
    return false;
  }
  /// Capture of a light ray (capture.h): a metric with a horizon provides `bool captures(const
  /// Vec4& x, const Vec4& k, const SolverConfig& c) const`, true when x lies below
  /// c.capture_radius and the light ray there, moving along k, falls to the break radius without
  /// turning back or meeting another stop. The ray moves along direction·k.
  bool captured(const SolverConfig& c, const double* y) const {
    if constexpr (requires(const Vec4& v) { m.captures(v, v, c); }) {
      if (c.type != GeodesicType::Lightlike || !(c.capture_radius > 0.0)) return false;
      const double s = c.direction >= 0 ? 1.0 : -1.0;
      return m.captures(Vec4{{y[0], y[1], y[2], y[3]}}, Vec4{{s * y[4], s * y[5], s * y[6], s * y[7]}}, c);
    }
    return false;
  }
  /// value = g(k,k) − target and its scale (geodesic_constraint.h, which says why); where x^0 is
  /// no time coordinate the metric may provide `double constraint_norm(const Vec4& x, const Mat4& g,
  /// const Vec4& k) const` (h for an observer of its own); otherwise Σ_{μν} |g_μν k^μ k^ν| is used.
  void constraint(const double* y, GeodesicType type, double& value, double& scale) const {
    const Vec4 x{{y[0], y[1], y[2], y[3]}};
    Mat4 g;
    m.metric_tensor_inline(x, g);
    const Vec4 k{{y[4], y[5], y[6], y[7]}};
    auto no_observer_norm = [&] {
      if constexpr (requires { m.constraint_norm(x, g, k); })
        return m.constraint_norm(x, g, k);
      else
        return abs_quadratic_form(g, k);
    };
    geodesic_constraint(g, k, constraint_target(type), no_observer_norm, value, scale);
  }
  /// Motion4D's Metric::resize, called after every accepted step: a metric may rescale the
  /// direction of a light ray with `void rescale_null_direction(double* k) const`
  /// (AlcubierreWarpSimple: |k^t| = 1). A null geodesic stays the same curve under k -> c k (only
  /// its affine parameter changes), so this applies to plain lightlike geodesics only: a timelike
  /// k is normalized and Jacobi fields and transported frames are tied to the affine parameter.
  /// Returns true when y changed.
  bool rescale(double* y, GeodesicType type) const {
    if constexpr (std::is_same_v<F, GeodesicRHS<M>> && requires(double* k) { m.rescale_null_direction(k); }) {
      if (type == GeodesicType::Lightlike) {
        if constexpr (std::is_same_v<decltype(m.rescale_null_direction(y)), bool>) {
          return m.rescale_null_direction(y + 4);  // MetricKernel: only when the metric has the rule
        } else {
          m.rescale_null_direction(y + 4);
          return true;
        }
      }
    }
    return false;
  }
  /// Re-projects k onto g(k,k) = target by solving the quadratic in k^0 (root closest to the
  /// current k^0); leaves k unchanged when no real root exists.
  void reproject(double* y, GeodesicType type) const {
    Mat4 g;
    m.metric_tensor_inline(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    const double* k = y + 4;
    const double A = g[0][0];
    double B = 0, C = -constraint_target(type);
    for (int i = 1; i < 4; ++i) {
      B += 2 * g[0][i] * k[i];
      for (int j = 1; j < 4; ++j) C += g[i][j] * k[i] * k[j];
    }
    if (std::fabs(A) < 1e-300) {
      if (std::fabs(B) > 1e-300) y[4] = -C / B;
      return;
    }
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return;
    // Numerically stable roots (Numerical Recipes §5.6): q = −½(B + sign(B)·√disc).
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    const double r1 = q / A, r2 = q != 0 ? C / q : r1;
    y[4] = std::fabs(r1 - k[0]) < std::fabs(r2 - k[0]) ? r1 : r2;
  }
};

/// A plain autonomous ODE y' = f(y) (tests, other layers): valid while finite, no constraint.
template <class F>
struct PlainSystem {
  static constexpr int N = F::N;
  static constexpr int kNystromPositions = nystrom_positions<F>();
  static constexpr bool kHasConstraint = false;
  F& f;
  void operator()(const double* y, double* dy) const { f(y, dy); }
  bool valid(const double* y) const {
    for (int i = 0; i < N; ++i)
      if (!std::isfinite(y[i])) return false;
    return true;
  }
  static bool inside(const SolverConfig&, const double*) { return true; }
  void constraint(const double*, GeodesicType, double& value, double& scale) const { value = 0, scale = 1; }
  void reproject(double*, GeodesicType) const {}
};

// ---- driver --------------------------------------------------------------------------------------

/// Checks the solver configuration once per geodesic (throws Error with the offending value).
void validate_solver_config(const SolverConfig& cfg);

/// Integrates y' = f(y) with stepper St. Per attempt: a trial state that is not finite or lies
/// outside the validity domain is rejected like a step with too large an error (adaptive: the
/// step shrinks; fixed step: the integration stops). Per accepted step, in this order: constraint
/// test (a step that broke the constraint is not reported; before it, a system may project the
/// state onto its first integrals: `bool project_invariants(double* y) const`, kerr_mino.h),
/// callback, re-basing of the state
/// (`void rebase(double* y)`, systems whose variables are relative to a moving origin, kerr_mino.h),
/// bounding box, λ_max, escape (`bool escaped(const SolverConfig&, const double* y, double&
/// radius) const`, systems that can tell; geodesic.h SolverConfig::escape_radius), capture
/// (`bool captured(const SolverConfig&, const double* y) const`: stops with Invalid, the reason
/// of the break radius the ray is certain to reach; SolverConfig::capture_radius). Before
/// each attempt: max_steps. A ray that runs into the edge of the validity domain stops with
/// Invalid once the edge is located to 1/1024 of the first step that crossed it. Step underflow (|h| < step_min or |h|
/// below the resolution of λ) stops with StepUnderflow, or with Invalid / NotFinite when the rejected trials were
/// leaving the validity domain / not finite.
///
/// A system integrated in a parameter σ other than the affine one (Mino time, kerr_mino.h) carries
/// λ in its state and provides `double affine(const double* y) const` (λ at y) and `double
/// param_per_affine(const double* y) const` (dσ/dλ at y). Then step_size and step_max are
/// converted from λ to σ at the current state, StepView and the result report λ, and λ_max is
/// reached by shortening the overshooting step with the secant on λ(σ) until |λ − λ_max| ≤
/// 1e-12 λ_max (the step that lands there is accepted; λ_max stays a bound, never exceeded).
template <class St, class Sys>
GeodesicResult integrate_with(Sys& sys, const SolverConfig& cfg, double* y_io, double lambda0, StepCallback cb) {
  constexpr int N = Sys::N;
  constexpr bool kOwnAffine = requires(const Sys& s, const double* p) {
    s.affine(p);
    s.param_per_affine(p);
  };
  auto affine = [&sys](const double* yy, double s) {
    if constexpr (kOwnAffine) return sys.affine(yy);
    return s;
  };
  auto per_affine = [&sys](const double* yy) {
    if constexpr (kOwnAffine) return sys.param_per_affine(yy);
    return 1.0;
  };
  GeodesicResult res;
  double y[N], dy[N], y1[N], dy1[N];
  for (int i = 0; i < N; ++i) y[i] = y_io[i];
  double lambda = lambda0;  // the independent variable (σ when kOwnAffine)
  const double dir = cfg.direction >= 0 ? 1.0 : -1.0;
  St stepper(cfg);
  const bool adaptive = cfg.step_ctrl && St::kHasErrorEstimate;
  ErrorScale tol{cfg.eps_abs, cfg.eps_rel};
  constexpr bool kScaledTol = requires(const Sys& s, const double* p, double* q) { s.tolerance_inv_scale(p, q); };
  double inv_tol[N];
  const double inv_eps_abs = 1.0 / cfg.eps_abs;
  auto set_tolerance = [&] {
    if constexpr (kScaledTol) {
      sys.tolerance_inv_scale(y, inv_tol);
      if (cfg.eps_rel == 0.0) {
        for (int i = 0; i < N; ++i) inv_tol[i] *= inv_eps_abs;
      } else {
        for (int i = 0; i < N; ++i) inv_tol[i] = 1.0 / (cfg.eps_abs / inv_tol[i] + cfg.eps_rel * std::fabs(y[i]));
      }
      tol.inv = inv_tol;
    }
  };
  set_tolerance();
  const double hmax_affine = std::max(cfg.step_max, cfg.step_min);
  double hmax = hmax_affine * per_affine(y), hmin = cfg.step_min * per_affine(y);
  double h = std::max(std::min(std::fabs(cfg.step_size), hmax_affine) * per_affine(y), hmin);
  const double affine0 = affine(y, lambda0);
  int affine_retries = 0;  // consecutive step retries to meet λ_max / step_max in λ (kOwnAffine)
  bool after_reject = false;
  // Boundary location: |h| of the first trial that left the validity domain (0: none pending).
  constexpr double kBoundaryRes = 1.0 / 1024;
  double h_cross = 0.0;

  auto finish = [&](StopReason r) {
    for (int i = 0; i < N; ++i) y_io[i] = y[i];
    res.reason = r;
    res.lambda = affine(y, lambda);
    if constexpr (Sys::kHasConstraint) {
      double scale;
      sys.constraint(y, cfg.type, res.constraint_drift, scale);
    }
    return res;
  };

  if (!sys.valid(y)) return finish(StopReason::Invalid);
  if (!sys.inside(cfg, y)) return finish(StopReason::BoundingBox);
  sys(y, dy);
  ++res.rhs_evals;

  while (true) {
    if (res.steps >= cfg.max_steps) return finish(StopReason::MaxSteps);
    const double remaining = cfg.lambda_max - std::fabs(affine(y, lambda) - affine0);
    const double lambda_res = kOwnAffine && std::isfinite(cfg.lambda_max) ? 1e-12 * cfg.lambda_max : 0.0;
    if (!(remaining > lambda_res)) return finish(StopReason::LambdaMax);
    double hstep = h;
    bool clipped = false;
    const double ppa = per_affine(y);
    if constexpr (kOwnAffine) {
      hmax = hmax_affine * ppa;
      hmin = cfg.step_min * ppa;
    }
    if (hstep >= remaining * ppa) {
      hstep = remaining * ppa;
      clipped = true;
    }
    double err = 0;
    const bool have_dy1 = stepper.template attempt<N>(sys, y, dy, dir * hstep, y1, dy1, tol, res.rhs_evals, err);
    bool finite = true;
    for (int i = 0; i < N; ++i) finite = finite && std::isfinite(y1[i]);
    const bool in_domain = finite && sys.valid(y1);
    if (!in_domain || (adaptive && !(err <= 1.0))) {
      if (!adaptive) return finish(finite ? StopReason::Invalid : StopReason::NotFinite);
      ++res.rejected;
      if (finite && !in_domain) {
        // The trial left the validity domain (horizon break radius, chart edge): halve the step
        // until the boundary is located to kBoundaryRes of the first step that crossed it, then
        // stop. Without this limit the ray creeps towards the boundary in ever smaller accepted
        // steps (each one halving the distance) until the step underflows: ~2·log2(h/step_min)
        // wasted steps per ray that ends there.
        if (h_cross == 0.0) h_cross = hstep;
        if (hstep <= kBoundaryRes * h_cross) return finish(StopReason::Invalid);
      }
      h = in_domain ? stepper.next_step(hstep, err, false, after_reject) : 0.5 * hstep;
      after_reject = true;
      if (h < hmin || h <= 4 * DBL_EPSILON * std::fabs(lambda)) {
        const StopReason r =
            !finite ? StopReason::NotFinite : (!in_domain ? StopReason::Invalid : StopReason::StepUnderflow);
        return finish(r);
      }
      continue;
    }
    if constexpr (kOwnAffine) {
      // λ_max overshot: retry with the step shortened by the secant on λ(σ) (not a rejection;
      // the secant converges in a few retries, the cap only guards against a pathological λ(σ)).
      const double dl = std::fabs(sys.affine(y1) - sys.affine(y));
      if (affine_retries < 50) {
        if (std::isfinite(cfg.lambda_max) && dl > remaining * (1.0 + 1e-12)) {
          h = hstep * remaining / dl;
          ++affine_retries;
          continue;
        }
        // Likewise a step longer than step_max in λ (Σ grew inside it).
        if (dl > hmax_affine * (1.0 + 1e-12)) {
          h = hstep * hmax_affine / dl * (1.0 - 1e-9);
          ++affine_retries;
          continue;
        }
      }
      affine_retries = 0;
      clipped = dl >= remaining * (1.0 - 1e-12);
    }
    // Accepted.
    if (cfg.reproject) sys.reproject(y1, cfg.type);
    bool changed = false;
    if constexpr (requires { sys.project_invariants(y1); }) changed = sys.project_invariants(y1);
    if constexpr (requires { sys.rescale(y1, cfg.type); }) changed = sys.rescale(y1, cfg.type) || changed;
    if (!have_dy1 || cfg.reproject || changed) {
      sys(y1, dy1);
      ++res.rhs_evals;
    }
    if constexpr (Sys::kHasConstraint) {
      double c, scale;
      sys.constraint(y1, cfg.type, c, scale);
      if (!(std::fabs(c) <= cfg.constraint_tol * scale)) return finish(StopReason::Constraint);
    }
    ++res.steps;
    const double lambda1 = !kOwnAffine && clipped ? lambda0 + dir * cfg.lambda_max : lambda + dir * hstep;
    StepAction act = StepAction::Continue;
    if (cb) act = cb(StepView{affine(y, lambda), affine(y1, lambda1), y, y1, dy, dy1, N, res.steps});
    for (int i = 0; i < N; ++i) {
      y[i] = y1[i];
      dy[i] = dy1[i];
    }
    lambda = lambda1;
    if constexpr (requires { sys.rebase(y); }) sys.rebase(y);
    set_tolerance();
    if (act == StepAction::Stop) return finish(StopReason::Callback);
    if (!sys.inside(cfg, y)) return finish(StopReason::BoundingBox);
    if (clipped) return finish(StopReason::LambdaMax);
    if constexpr (requires { sys.escaped(cfg, y, res.escape_radius); }) {
      if (sys.escaped(cfg, y, res.escape_radius)) return finish(StopReason::Escaped);
    }
    if constexpr (requires { sys.captured(cfg, y); }) {
      if (sys.captured(cfg, y)) return finish(StopReason::Invalid);
    }
    if (adaptive) h = std::min(hmax, std::max(stepper.next_step(hstep, err, true, after_reject), hmin));
    if (!adaptive && kOwnAffine) h = std::fabs(cfg.step_size) * per_affine(y);
    if (!after_reject) h_cross = 0.0;  // two clean steps in a row: away from any boundary
    after_reject = false;
  }
}

/// Chooses the stepper for cfg.kind (dispatch once per geodesic).
template <class Sys>
GeodesicResult integrate_dispatch(Sys& sys, const SolverConfig& cfg, double* y, double lambda0, StepCallback cb) {
  validate_solver_config(cfg);
  switch (cfg.kind) {
    case SolverKind::RK2: return integrate_with<ExplicitRK<HeunEulerTableau>>(sys, cfg, y, lambda0, cb);
    case SolverKind::RK4: return integrate_with<ExplicitRK<RK4Tableau>>(sys, cfg, y, lambda0, cb);
    case SolverKind::CashKarp45: return integrate_with<ExplicitRK<CashKarpTableau>>(sys, cfg, y, lambda0, cb);
    case SolverKind::Fehlberg45: return integrate_with<ExplicitRK<FehlbergTableau>>(sys, cfg, y, lambda0, cb);
    case SolverKind::DormandPrince54:
      return integrate_with<ExplicitRK<DormandPrince54Tableau>>(sys, cfg, y, lambda0, cb);
    case SolverKind::DormandPrince853: return integrate_with<DOP853>(sys, cfg, y, lambda0, cb);
    case SolverKind::BulirschStoer: return integrate_with<BulirschStoer>(sys, cfg, y, lambda0, cb);
    case SolverKind::RungeKuttaNystrom86:
      if constexpr (nystrom_positions<Sys>() > 0) {
        return integrate_with<RKN86>(sys, cfg, y, lambda0, cb);
      } else {
        throw Error(
            "solver RKN86 (Runge-Kutta-Nystrom) needs equations of the form y'' = f(y): the separated "
            "(Carter/Mino-time) geodesic equations of KerrBL and Schwarzschild; this integration has none "
            "(another metric, the transport or Jacobi system, or separable equations switched off) - use "
            "DOP853");
      }
  }
  return integrate_with<ExplicitRK<CashKarpTableau>>(sys, cfg, y, lambda0, cb);
}

/// Integrates geodesic system f (GeodesicRHS/TransportRHS/JacobiRHS) on metric m (used by
/// MetricCRTP::integrate).
template <class M, class F>
GeodesicResult integrate_system(const M& m, F& f, const SolverConfig& cfg, double* y, double lambda0, StepCallback cb) {
  MetricSystem<M, F> sys{m, f};
  return integrate_dispatch(sys, cfg, y, lambda0, cb);
}

/// Integrates a plain autonomous system y' = f(y): F has `static constexpr int N` and
/// `void operator()(const double* y, double* dy) const`. cfg.type and the constraint settings are
/// ignored; the validity domain is "finite".
template <class F>
GeodesicResult integrate_ode(F& f, const SolverConfig& cfg, double* y, double t0, StepCallback cb = {}) {
  PlainSystem<F> sys{f};
  return integrate_dispatch(sys, cfg, y, t0, cb);
}

}  // namespace geovis

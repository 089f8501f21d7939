// The packet integrator (geodesic_packet.h). The Runge–Kutta attempt (rk_attempt) is compiled once
// per SIMD instruction set by Highway's foreach_target (this file includes itself per target);
// the per-lane step control and stop logic is compiled once (the HWY_ONCE part).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "spacetime/geodesic_packet.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_
#define GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_
#include <cfloat>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/integrators.h"
#include "spacetime/metric_kernel.h"

namespace geovis {
namespace {

constexpr int kDim = 8;  // y = (x^μ, k^μ)

/// dy = f(y) for the lanes in `lanes` (GeodesicRHS: dx/dλ = k, dk/dλ = −Γkk), SoA.
inline void packet_rhs(const MetricKernel& m, const double* y, double* dy, unsigned lanes) {
  std::memcpy(dy, y + 4 * kPacketLanes, 4 * kPacketLanes * sizeof(double));
  m.packet_acceleration(y, dy + 4 * kPacketLanes, lanes);
}

}  // namespace
}  // namespace geovis
#endif  // GEOVIS_SPACETIME_GEODESIC_PACKET_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {

/// ExplicitRK<CashKarpTableau>::attempt (integrators.h) on all lanes at once: from y, dy = f(y)
/// and the signed steps h (per lane), the new state y1 and the error estimate e (SoA). The same
/// operations in the same order as the scalar stepper's rk_detail::stage/weighted:
///   stage s: tmp_i = y_i + h·(((0 + a_s0 k_0i) + a_s1 k_1i) + …)   (non-zero a only)
///   y1_i = y_i + h·Σ_j b_j k_ji,   e_i = h·Σ_j e_j k_ji.
void rk_attempt(const MetricKernel& m, unsigned lanes, const double* y, const double* dy, const double* h, double* y1,
                double* e) {
  using Tab = CashKarpTableau;
  constexpr int S = Tab::S, W = kPacketLanes;
  const SimdTag d;
  const size_t L = hn::Lanes(d);
  HWY_ALIGN double k[S][kDim * W];
  std::memcpy(k[0], dy, sizeof k[0]);
  HWY_ALIGN double tmp[kDim * W];
  // clang-format off
  [&]<int... s>(std::integer_sequence<int, s...>) {
    ([&] {
      constexpr int st = s + 1;
      for (size_t l = 0; l < static_cast<size_t>(W); l += L) {
        const SimdD hv = SimdD::load(h + l);
        for (int i = 0; i < kDim; ++i) {
          SimdD acc(0.0);
          [&]<int... j>(std::integer_sequence<int, j...>) {
            ([&] {
              if constexpr (Tab::a[st][j] != 0.0) acc = acc + SimdD(Tab::a[st][j]) * SimdD::load(k[j] + i * W + l);
            }(), ...);
          }(std::make_integer_sequence<int, st>{});
          (SimdD::load(y + i * W + l) + hv * acc).store(tmp + i * W + l);
        }
      }
      packet_rhs(m, tmp, k[st], lanes);
    }(), ...);
  }(std::make_integer_sequence<int, S - 1>{});
  for (size_t l = 0; l < static_cast<size_t>(W); l += L) {
    const SimdD hv = SimdD::load(h + l);
    for (int i = 0; i < kDim; ++i) {
      SimdD ab(0.0), ae(0.0);
      [&]<int... j>(std::integer_sequence<int, j...>) {
        ([&] {
          const SimdD kj = SimdD::load(k[j] + i * W + l);
          if constexpr (Tab::b[j] != 0.0) ab = ab + SimdD(Tab::b[j]) * kj;
          if constexpr (Tab::e[j] != 0.0) ae = ae + SimdD(Tab::e[j]) * kj;
        }(), ...);
      }(std::make_integer_sequence<int, S>{});
      // clang-format on
      (SimdD::load(y + i * W + l) + hv * ab).store(y1 + i * W + l);
      (hv * ae).store(e + i * W + l);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {

HWY_EXPORT(rk_attempt);

namespace {

/// One lane's run of integrate_with<ExplicitRK<CashKarpTableau>> (its local variables there).
struct Lane {
  bool live = false;
  double lambda = 0, h = 0, hstep = 0, h_cross = 0, err = 0;
  bool after_reject = false, clipped = false;
  StepController<CashKarpTableau::kErrExp> control;  ///< ExplicitRK::control
  GeodesicResult res;
};

}  // namespace

void integrate_geodesic_packet(const MetricKernel& metric, const SolverConfig& cfg, const PacketRays& rays) {
  validate_solver_config(cfg);
  if (cfg.kind != SolverKind::CashKarp45) throw Error("packet integrator: only the CashKarp45 solver");
  constexpr int W = kPacketLanes, N = kDim;
  GeodesicRHS<MetricKernel> f{metric};
  const MetricSystem<MetricKernel, GeodesicRHS<MetricKernel>> sys{metric, f};

  // integrate_with's constants (no own affine parameter, no scaled tolerance, λ0 = 0).
  const double dir = cfg.direction >= 0 ? 1.0 : -1.0;
  const bool adaptive = cfg.step_ctrl;
  const ErrorScale tol{cfg.eps_abs, cfg.eps_rel};
  const double hmax = std::max(cfg.step_max, cfg.step_min), hmin = cfg.step_min;
  const double h_first = std::max(std::min(std::fabs(cfg.step_size), hmax), hmin);
  constexpr double kBoundaryRes = 1.0 / 1024;

  HWY_ALIGN double y[N * W] = {}, dy[N * W] = {}, y1[N * W] = {}, dy1[N * W] = {}, e[N * W] = {}, hv[W] = {};
  Lane lane[W];
  bool exhausted = false;
  unsigned need_dy = 0;  // lanes whose dy = f(y) is still to be evaluated (fresh rays)
  unsigned ready = 0;    // lanes whose next trial step is set up (hv)

  auto get = [](const double* soa, int l, double* out) {
    for (int i = 0; i < N; ++i) out[i] = soa[i * W + l];
  };
  auto put = [](double* soa, int l, const double* in) {
    for (int i = 0; i < N; ++i) soa[i * W + l] = in[i];
  };
  // integrate_with's finish(): the result with the state where the ray stopped.
  auto finish = [&](int l, StopReason r) {
    Lane& ln = lane[l];
    double yl[N];
    get(y, l, yl);
    ln.res.reason = r;
    ln.res.lambda = ln.lambda;
    double scale;
    sys.constraint(yl, cfg.type, ln.res.constraint_drift, scale);
    ln.live = false;
    rays.done(l, yl, ln.res);
  };
  // Fills lane l with the next ray (integrate_with's set-up); rays that stop before their first
  // step are finished at once.
  auto refill = [&](int l) {
    const unsigned bit = 1u << l;
    ready &= ~bit;
    while (!exhausted) {
      double yl[N];
      if (!rays.next(l, yl)) {
        exhausted = true;
        break;
      }
      put(y, l, yl);
      lane[l] = Lane{};
      lane[l].live = true;
      lane[l].h = h_first;
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

  for (int l = 0; l < W; ++l) refill(l);
  while (true) {
    // Every live lane set up for a trial step (the top of integrate_with's loop).
    do {
      if (need_dy) {
        packet_rhs(metric, y, dy, need_dy);
        for (int l = 0; l < W; ++l)
          if (need_dy >> l & 1u) ++lane[l].res.rhs_evals;
        need_dy = 0;
      }
      for (int l = 0; l < W; ++l) {
        Lane& ln = lane[l];
        if (!ln.live || (ready >> l & 1u)) continue;
        if (ln.res.steps >= cfg.max_steps) {
          finish(l, StopReason::MaxSteps);
          refill(l);
          continue;
        }
        const double remaining = cfg.lambda_max - std::fabs(ln.lambda - 0.0);
        if (!(remaining > 0.0)) {
          finish(l, StopReason::LambdaMax);
          refill(l);
          continue;
        }
        ln.hstep = ln.h;
        ln.clipped = false;
        if (ln.hstep >= remaining) {
          ln.hstep = remaining;
          ln.clipped = true;
        }
        hv[l] = dir * ln.hstep;
        ready |= 1u << l;
      }
    } while (need_dy);
    if (!ready) return;

    // Looked up per call: before the first dispatch the table entry is Highway's target chooser.
    HWY_DYNAMIC_DISPATCH(rk_attempt)(metric, ready, y, dy, hv, y1, e);
    unsigned accepted = 0;
    for (int l = 0; l < W; ++l) {
      if (!(ready >> l & 1u)) continue;
      Lane& ln = lane[l];
      ln.res.rhs_evals += CashKarpTableau::S - 1;
      double yl[N], yl1[N], el[N];
      get(y, l, yl);
      get(y1, l, yl1);
      get(e, l, el);
      ln.err = tol.norm<N>(el, yl);
      bool finite = true;
      for (int i = 0; i < N; ++i) finite = finite && std::isfinite(yl1[i]);
      const bool in_domain = finite && sys.valid(yl1);
      if (!in_domain || (adaptive && !(ln.err <= 1.0))) {
        ready &= ~(1u << l);
        if (!adaptive) {
          finish(l, finite ? StopReason::Invalid : StopReason::NotFinite);
          refill(l);
          continue;
        }
        ++ln.res.rejected;
        if (finite && !in_domain) {
          if (ln.h_cross == 0.0) ln.h_cross = ln.hstep;
          if (ln.hstep <= kBoundaryRes * ln.h_cross) {
            finish(l, StopReason::Invalid);
            refill(l);
            continue;
          }
        }
        ln.h = in_domain ? ln.control.next(ln.hstep, ln.err, false, ln.after_reject) : 0.5 * ln.hstep;
        ln.after_reject = true;
        if (ln.h < hmin || ln.h <= 4 * DBL_EPSILON * std::fabs(ln.lambda)) {
          finish(l, !finite ? StopReason::NotFinite : (!in_domain ? StopReason::Invalid : StopReason::StepUnderflow));
          refill(l);
        }
        continue;
      }
      if (cfg.reproject) sys.reproject(yl1, cfg.type);
      sys.rescale(yl1, cfg.type);
      put(y1, l, yl1);
      accepted |= 1u << l;
    }
    if (!accepted) continue;

    packet_rhs(metric, y1, dy1, accepted);
    for (int l = 0; l < W; ++l) {
      if (!(accepted >> l & 1u)) continue;
      Lane& ln = lane[l];
      ready &= ~(1u << l);
      ++ln.res.rhs_evals;
      double yl[N], yl1[N], dyl[N], dyl1[N];
      get(y, l, yl);
      get(y1, l, yl1);
      get(dy, l, dyl);
      get(dy1, l, dyl1);
      double c, scale;
      sys.constraint(yl1, cfg.type, c, scale);
      if (!(std::fabs(c) <= cfg.constraint_tol * scale)) {
        finish(l, StopReason::Constraint);
        refill(l);
        continue;
      }
      ++ln.res.steps;
      const double lambda1 = ln.clipped ? 0.0 + dir * cfg.lambda_max : ln.lambda + dir * ln.hstep;
      StepAction act = StepAction::Continue;
      if (rays.on_step) act = rays.on_step(l, StepView{ln.lambda, lambda1, yl, yl1, dyl, dyl1, N, ln.res.steps});
      put(y, l, yl1);
      put(dy, l, dyl1);
      ln.lambda = lambda1;
      StopReason stop = StopReason::None;
      if (act == StepAction::Stop)
        stop = StopReason::Callback;
      else if (!sys.inside(cfg, yl1))
        stop = StopReason::BoundingBox;
      else if (ln.clipped)
        stop = StopReason::LambdaMax;
      else if (sys.escaped(cfg, yl1, ln.res.escape_radius))
        stop = StopReason::Escaped;
      else if (sys.captured(cfg, yl1))
        stop = StopReason::Invalid;
      if (stop != StopReason::None) {
        finish(l, stop);
        refill(l);
        continue;
      }
      if (adaptive) ln.h = std::min(hmax, std::max(ln.control.next(ln.hstep, ln.err, true, ln.after_reject), hmin));
      if (!ln.after_reject) ln.h_cross = 0.0;
      ln.after_reject = false;
    }
  }
}

}  // namespace geovis
#endif  // HWY_ONCE

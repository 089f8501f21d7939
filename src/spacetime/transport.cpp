#include "spacetime/transport.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "spacetime/integrators.h"
#include "spacetime/metric_kernel.h"

namespace geovis {

void pack_transport_state(const Vec4& x, const Vec4& u, const Tetrad& e, double y[kTransportDim]) {
  for (int i = 0; i < 4; ++i) {
    y[i] = x[i];
    y[4 + i] = u[i];
    for (int a = 0; a < 4; ++a) y[8 + 4 * a + i] = e[a][i];
  }
}

void unpack_transport_state(const double* y, Vec4& x, Vec4& u, Tetrad& e) {
  for (int i = 0; i < 4; ++i) {
    x[i] = y[i];
    u[i] = y[4 + i];
    for (int a = 0; a < 4; ++a) e[a][i] = y[8 + 4 * a + i];
  }
}

void transport_rhs(const Metric& m, const double* y, double* dy) {
  // Same system as TransportRHS (integrators.h): dx/dτ = u, dv^μ/dτ = −Γ^μ_{ab} u^a v^b for
  // v = u and the four tetrad vectors (parallel transport, paper §2.3).
  const Vec4 x{{y[0], y[1], y[2], y[3]}};
  Christoffel G;
  m.christoffel(x, G);
  const double* u = y + 4;
  for (int i = 0; i < 4; ++i) dy[i] = u[i];
  for (int v = 0; v < 5; ++v) {
    const double* e = y + 4 + 4 * v;
    for (int mu = 0; mu < 4; ++mu) {
      double s = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * u[a] * e[b];
      dy[4 + 4 * v + mu] = -s;
    }
  }
}

GeodesicResult parallel_transport(const Metric& m, const SolverConfig& cfg_in, Vec4& x, Tetrad& e, double tau0,
                                  StepCallback cb) {
  SolverConfig cfg = cfg_in;
  cfg.type = GeodesicType::Timelike;
  double y[kTransportDim];
  pack_transport_state(x, e[0], e, y);
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Transport, y, tau0, cb);
  Vec4 u;
  unpack_transport_state(y, x, u, e);
  return r;
}

void fermi_walker_rhs(const Metric& m, const WorldlineState& w, const Tetrad& e, Tetrad& de) {
  Christoffel G;
  m.christoffel(w.x, G);
  Mat4 g;
  m.metric_tensor(w.x, g);
  for (int v = 0; v < 4; ++v) {
    // MTW eq. (6.19) in coordinates: de/dτ = −Γ(u,e) + g(e,a) u − g(e,u) a.
    const double ea = dot(g, e[v], w.a), eu = dot(g, e[v], w.u);
    for (int mu = 0; mu < 4; ++mu) {
      double s = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * w.u[a] * e[v][b];
      de[v][mu] = -s + ea * w.u[mu] - eu * w.a[mu];
    }
  }
}

namespace {

/// The Fermi-Walker system for the generic Runge-Kutta stepper: state = τ (0) and the 16 tetrad
/// components (1-16); τ is carried in the state so every stage evaluates the worldline at its
/// own proper time.
struct FermiWalkerSystem {
  static constexpr int N = 17;
  const Metric& m;
  WorldlineFn wl;
  double dir;  // dτ/ds: the integration variable s runs forward, τ = tau0 + dir·s
  void operator()(const double* y, double* dy) const {
    const WorldlineState w = wl(y[0]);
    Tetrad e, de;
    for (int a = 0; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) e[a][mu] = y[1 + 4 * a + mu];
    fermi_walker_rhs(m, w, e, de);
    dy[0] = dir;
    for (int a = 0; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) dy[1 + 4 * a + mu] = dir * de[a][mu];
  }
};

}  // namespace

Tetrad fermi_walker_transport(const Metric& m, WorldlineFn worldline, double tau0, double tau1, const Tetrad& e0,
                              const FermiWalkerConfig& cfg, FunctionRef<void(double, const Tetrad&)> cb) {
  constexpr int N = FermiWalkerSystem::N;
  const double dir = tau1 >= tau0 ? 1.0 : -1.0;
  const double span = std::fabs(tau1 - tau0);
  FermiWalkerSystem f{m, worldline, dir};
  double y[N], dy[N], y1[N], dy1[N];
  y[0] = tau0;
  for (int a = 0; a < 4; ++a)
    for (int mu = 0; mu < 4; ++mu) y[1 + 4 * a + mu] = e0[a][mu];
  auto unpack = [](const double* s) {
    Tetrad e;
    for (int a = 0; a < 4; ++a)
      for (int mu = 0; mu < 4; ++mu) e[a][mu] = s[1 + 4 * a + mu];
    return e;
  };
  if (span == 0.0) return e0;
  f(y, dy);
  double s = 0, h = std::min(std::max(cfg.step_size, cfg.step_min), span);
  long evals = 0;
  // The integrators' Cash–Karp stepper and step-size control (integrators.h) with GSL's "y"
  // error norm; the loop only adds the exact landing on tau1 and the error messages.
  SolverConfig scfg;
  scfg.kind = SolverKind::CashKarp45;
  ExplicitRK<CashKarpTableau> stepper(scfg);
  const ErrorScale tol{cfg.eps_abs, 0.0};
  bool after_reject = false;
  for (int steps = 0; s < span;) {
    if (steps >= cfg.max_steps)
      throw Error("Fermi-Walker transport: more than " + std::to_string(cfg.max_steps) + " steps needed");
    const bool last = h >= span - s;
    const double hs = last ? span - s : h;
    double err = 0;
    stepper.attempt<N>(f, y, dy, hs, y1, dy1, tol, evals, err);
    bool finite = true;
    for (int i = 0; i < N; ++i) finite = finite && std::isfinite(y1[i]);
    if (!finite || !(err <= 1.0)) {
      h = finite ? stepper.next_step(hs, err, false, after_reject) : 0.25 * hs;
      after_reject = true;
      if (h < cfg.step_min)
        throw Error("Fermi-Walker transport: step size underflow at tau = " + std::to_string(y[0]) +
                    (finite ? "" : " (non-finite state: is the worldline valid there?)"));
      continue;
    }
    s = last ? span : s + hs;
    y1[0] = tau0 + dir * s;  // avoid accumulating round-off in τ
    f(y1, dy1);              // Cash–Karp is not first-same-as-last
    std::copy(y1, y1 + N, y);
    std::copy(dy1, dy1 + N, dy);
    ++steps;
    if (cb) cb(y[0], unpack(y));
    if (!last) h = std::min(cfg.step_max, stepper.next_step(hs, err, true, after_reject));
    after_reject = false;
  }
  return unpack(y);
}

GeodesicResult integrate_transport_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                             StepCallback cb) {
  TransportRHS<MetricKernel> f{k};
  return integrate_system(k, f, cfg, y, lambda0, cb);
}

}  // namespace geovis

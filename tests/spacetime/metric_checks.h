// Shared checks for the metric tests (test_kerr.cpp, test_metrics_other.cpp; usable by any metric test): closed-form
// Christoffel symbols against automatic differentiation, the integrator's geodesic acceleration
// against −Γ_AD k k, and natural tetrads against g(e_a, e_b) = η_ab.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "spacetime/metric.h"

namespace geovis::metric_checks {

/// Compares closed-form Γ with the AD Γ at x. A component passes when
/// |Γ_closed − Γ_AD| <= rel · max(|Γ_AD|, floor_frac · max_all|Γ_AD|): relative per component,
/// with an absolute floor (a fraction of the largest symbol) for symbols that vanish here.
/// Returns the worst ratio |Δ| / max(|Γ_AD|, floor) for reporting.
inline double expect_christoffel_matches_ad(const Metric& m, const Vec4& x, double rel = 1e-10,
                                            double floor_frac = 1e-6) {
  EXPECT_TRUE(m.has_closed_form_christoffel()) << m.name();
  Christoffel closed, ad;
  m.christoffel(x, closed);
  m.christoffel_ad(x, ad);
  double scale = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) scale = std::max(scale, std::fabs(ad.G[i][j][k]));
  const double floor = std::max(floor_frac * scale, 1e-300);
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double ref = std::max(std::fabs(ad.G[i][j][k]), floor);
        const double d = std::fabs(closed.G[i][j][k] - ad.G[i][j][k]);
        worst = std::max(worst, d / ref);
        EXPECT_LE(d, rel * ref) << m.name() << " Gamma^" << i << "_" << j << k << " at (" << x[0] << ", "
                                << x[1] << ", " << x[2] << ", " << x[3] << "): closed " << closed.G[i][j][k]
                                << " AD " << ad.G[i][j][k];
      }
  return worst;
}

/// The acceleration the integrator uses (first derivative handed to the step callback) equals
/// −Γ^μ_ab k^a k^b with the AD symbols, relative to Σ_ab |Γ^μ_ab k^a k^b| (the rounding scale of
/// the sum), with a floor of floor_frac times the largest of these sums over μ for components that
/// vanish analytically. Returns the worst ratio.
inline double expect_accel_matches_ad(const Metric& m, const Vec4& x, const Vec4& k, double rel = 1e-10,
                                      double floor_frac = 0.0) {
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  SolverConfig cfg;
  cfg.kind = SolverKind::RK4;
  cfg.step_ctrl = false;
  cfg.step_size = 1e-9;
  cfg.max_steps = 1;
  cfg.constraint_tol = 1e300;
  // The coordinate form's hot-path acceleration, for any k (the separated equations of KerrBL and
  // Schwarzschild assume g(k,k) = −μ² and are checked in test_kerr_mino.cpp).
  cfg.separable = false;
  double acc[4] = {NAN, NAN, NAN, NAN};
  auto cb = [&](const StepView& s) {
    for (int i = 0; i < 4; ++i) acc[i] = s.dy0[4 + i];
    return StepAction::Stop;
  };
  m.integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);
  Christoffel G;
  m.christoffel_ad(x, G);
  double scale = 0;  // the largest Σ_ab |Γ^μ_ab k^a k^b| over μ
  for (int mu = 0; mu < 4; ++mu) {
    double sabs = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) sabs += std::fabs(G.G[mu][a][b] * k[a] * k[b]);
    scale = std::max(scale, sabs);
  }
  double worst = 0;
  for (int mu = 0; mu < 4; ++mu) {
    double s = 0, sabs = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        s += G.G[mu][a][b] * k[a] * k[b];
        sabs += std::fabs(G.G[mu][a][b] * k[a] * k[b]);
      }
    const double ref = std::max({sabs, floor_frac * scale, 1e-300});
    const double d = std::fabs(acc[mu] + s);
    worst = std::max(worst, d / ref);
    EXPECT_LE(d, rel * ref) << m.name() << " accel^" << mu << ": integrator " << acc[mu] << " AD " << -s;
  }
  return worst;
}

/// The one tolerance rule of the tests generated from the registry (test_metrics_registry.cpp,
/// test_metrics_catalogue.cpp) for closed-form against AD Christoffel symbols and accelerations:
/// relative 1e-10 per component, and for components that vanish analytically an absolute floor of
/// 1e-4 of the largest one, i.e. 1e-14 of the scale (a few ulp: closed forms that invert g or take
/// differences of O(1) terms leave rounding noise there).
constexpr double kRuleRel = 1e-10;
constexpr double kRuleFloorFrac = 1e-4;

/// g(e_a, e_b) = η_ab = diag(−1, 1, 1, 1) to `tol`, and e_(0) future-directed (e_(0)^t > 0).
inline void expect_orthonormal(const Metric& m, const Vec4& x, TetradKind kind, double tol = 1e-12) {
  const Tetrad e = m.natural_tetrad(x, kind);
  Mat4 g;
  m.metric_tensor(x, g);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double eta = a == b ? (a == 0 ? -1.0 : 1.0) : 0.0;
      EXPECT_NEAR(dot(g, e[a], e[b]), eta, tol)
          << m.name() << " " << tetrad_kind_name(kind) << " tetrad, g(e" << a << ", e" << b << ") at (" << x[0]
          << ", " << x[1] << ", " << x[2] << ", " << x[3] << ")";
    }
  EXPECT_GT(e[0][0], 0.0) << m.name() << " " << tetrad_kind_name(kind) << ": e_(0) not future-directed";
}

/// Ricci tensor R_bd = R^a_{bad} from the AD Riemann tensor.
inline Mat4 ricci(const Metric& m, const Vec4& x, double* riemann_scale = nullptr) {
  Riemann R;
  m.riemann(x, R);
  Mat4 ric{};
  double scale = 0;
  for (int b = 0; b < 4; ++b)
    for (int d = 0; d < 4; ++d) {
      double s = 0;
      for (int a = 0; a < 4; ++a) s += R.R[a][b][a][d];
      ric[b][d] = s;
    }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        for (int d = 0; d < 4; ++d) scale = std::max(scale, std::fabs(R.R[a][b][c][d]));
  if (riemann_scale) *riemann_scale = scale;
  return ric;
}

}  // namespace geovis::metric_checks

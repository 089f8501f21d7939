// Shared checks for the metric tests (test_kerr.cpp, test_metrics_other.cpp; usable by any metric test): closed-form
// Christoffel symbols against automatic differentiation, the integrator's geodesic acceleration
// against −Γ_AD k k, and natural tetrads against g(e_a, e_b) = η_ab.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "spacetime/jacobi.h"
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
        EXPECT_LE(d, rel * ref) << m.name() << " Gamma^" << i << "_" << j << k << " at (" << x[0] << ", " << x[1]
                                << ", " << x[2] << ", " << x[3] << "): closed " << closed.G[i][j][k] << " AD "
                                << ad.G[i][j][k];
      }
  return worst;
}

/// The acceleration the integrator uses (first derivative handed to the step callback) equals
/// −Γ^μ_ab k^a k^b with the symbols G (what = their source, for messages), relative to
/// Σ_ab |Γ^μ_ab k^a k^b| (the rounding scale of the sum), with a floor of floor_frac times the
/// largest of these sums over μ for components that vanish analytically. Returns the worst ratio.
inline double expect_accel_matches_symbols(const Metric& m, const Vec4& x, const Vec4& k, const Christoffel& G,
                                           const char* what, double rel, double floor_frac) {
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
    EXPECT_LE(d, rel * ref) << m.name() << " accel^" << mu << ": integrator " << acc[mu] << " " << what << " " << -s;
  }
  return worst;
}

/// expect_accel_matches_symbols with the AD symbols.
inline double expect_accel_matches_ad(const Metric& m, const Vec4& x, const Vec4& k, double rel = 1e-10,
                                      double floor_frac = 0.0) {
  Christoffel G;
  m.christoffel_ad(x, G);
  return expect_accel_matches_symbols(m, x, k, G, "AD", rel, floor_frac);
}

/// The one tolerance rule of the tests generated from the registry (test_metrics_registry.cpp,
/// test_metrics_catalogue.cpp) for closed-form against AD Christoffel symbols and accelerations:
/// relative 1e-10 per component, and for components that vanish analytically an absolute floor of
/// 1e-4 of the largest one, i.e. 1e-14 of the scale (a few ulp: closed forms that invert g or take
/// differences of O(1) terms leave rounding noise there).
constexpr double kRuleRel = 1e-10;
constexpr double kRuleFloorFrac = 1e-4;

/// The right-hand side of the Jacobi system the integrator uses (first derivative handed to the
/// step callback) against the full AD Riemann tensor (Metric::riemann), for the ray leaving x in
/// local direction d of tetrad e. Jacobi fields Y1 = s1 and Y2 = e_(0) + 0.3 s2 (any vector
/// will do) start with DY/dλ = Y' + Γ(k, Y) = 0 (AD Γ); then the coordinate right-hand side Y''
/// must give the covariant acceleration
///   D²Y^μ/dλ² = Y''^μ + ∂_ν Γ^μ_{ab} k^ν k^a Y^b + Γ^μ_{ab} k'^a Y^b + Γ^μ_{ab} k^a Y'^b
///            = −R^μ_{βγδ} k^β Y^γ k^δ   (geodesic deviation, MTW eq. 11.10),
/// with k' = −Γ(k, k) (AD). Also the transport of k, s1, s2 against −Γ^μ_{ab} k^a e^b (AD). Each
/// comparison is relative to the sum of the absolute values of all terms that make up both sides
/// (for R: the four terms of MTW eq. 11.12 of each component), the scale of their rounding errors,
/// so components that vanish analytically are checked as strictly as the others. Returns the
/// worst ratio |Δ| / scale.
inline double expect_jacobi_rhs_matches_riemann(const Metric& m, const Vec4& x, const Tetrad& e, const Vec3& d,
                                                double rel) {
  double y[kJacobiDim];
  jacobi_initial_state(x, e, d, y);
  Christoffel G;
  double dG[4][4][4][4];
  m.christoffel_derivs_ad(x, G, dG);
  const Vec4 k{{y[kJacobiK], y[kJacobiK + 1], y[kJacobiK + 2], y[kJacobiK + 3]}};
  auto gamma = [&G](int mu, const Vec4& a, const Vec4& b, double* abs_sum) {
    double t = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        t += G.G[mu][i][j] * a[i] * b[j];
        if (abs_sum) *abs_sum += std::fabs(G.G[mu][i][j] * a[i] * b[j]);
      }
    return t;
  };
  Vec4 Y[2], dY[2];
  for (int mu = 0; mu < 4; ++mu) {
    Y[0][mu] = y[kJacobiS1 + mu];
    Y[1][mu] = e[0][mu] + 0.3 * y[kJacobiS2 + mu];
  }
  for (int f = 0; f < 2; ++f)
    for (int mu = 0; mu < 4; ++mu) {
      dY[f][mu] = -gamma(mu, k, Y[f], nullptr);
      y[kJacobiY1 + 8 * f + mu] = Y[f][mu];
      y[kJacobiDY1 + 8 * f + mu] = dY[f][mu];
    }
  SolverConfig cfg;
  cfg.kind = SolverKind::RK4;
  cfg.step_ctrl = false;
  cfg.step_size = 1e-9;
  cfg.max_steps = 1;
  cfg.constraint_tol = 1e300;
  double dy[kJacobiDim];
  for (double& v : dy) v = NAN;
  auto cb = [&](const StepView& st) {
    for (int i = 0; i < kJacobiDim; ++i) dy[i] = st.dy0[i];
    return StepAction::Stop;
  };
  double y_end[kJacobiDim];
  for (int i = 0; i < kJacobiDim; ++i) y_end[i] = y[i];
  m.integrate(cfg, GeodesicSystem::Jacobi, y_end, 0.0, cb);

  Riemann R;
  m.riemann(x, R);
  Vec4 kdot;
  for (int mu = 0; mu < 4; ++mu) kdot[mu] = -gamma(mu, k, k, nullptr);
  double worst = 0;
  for (int f = 0; f < 2; ++f)
    for (int mu = 0; mu < 4; ++mu) {
      const double Ydd = dy[kJacobiDY1 + 8 * f + mu];
      double scale = 0;
      // Rounding scale of the right-hand side: |2 Γ k Y'| + |∂Γ k k Y| term by term.
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          scale += 2.0 * std::fabs(G.G[mu][a][b] * k[a] * dY[f][b]);
          for (int n = 0; n < 4; ++n) scale += std::fabs(dG[n][mu][a][b] * k[a] * k[b] * Y[f][n]);
        }
      double acc = Ydd + gamma(mu, kdot, Y[f], &scale) + gamma(mu, k, dY[f], &scale);
      for (int n = 0; n < 4; ++n)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            acc += dG[n][mu][a][b] * k[n] * k[a] * Y[f][b];
            scale += std::fabs(dG[n][mu][a][b] * k[n] * k[a] * Y[f][b]);
          }
      double W = 0;
      for (int be = 0; be < 4; ++be)
        for (int ga = 0; ga < 4; ++ga)
          for (int de = 0; de < 4; ++de) {
            const double v = k[be] * Y[f][ga] * k[de];
            W += R.R[mu][be][ga][de] * v;
            double r_abs = std::fabs(dG[ga][mu][de][be]) + std::fabs(dG[de][mu][ga][be]);
            for (int ep = 0; ep < 4; ++ep)
              r_abs += std::fabs(G.G[mu][ga][ep] * G.G[ep][de][be]) + std::fabs(G.G[mu][de][ep] * G.G[ep][ga][be]);
            scale += r_abs * std::fabs(v);
          }
      scale = std::max(scale, 1e-300);
      const double diff = std::fabs(acc + W);
      worst = std::max(worst, diff / scale);
      EXPECT_LE(diff, rel * scale) << m.name() << " field " << f + 1 << ", D2Y^" << mu << " at (" << x[0] << ", "
                                   << x[1] << ", " << x[2] << ", " << x[3] << "): from the Jacobi RHS " << acc
                                   << ", -R(k,Y,k) " << -W << " (scale " << scale << ")";
      EXPECT_EQ(dy[kJacobiY1 + 8 * f + mu], dY[f][mu]);
    }
  for (int v = 0; v < 3; ++v) {
    const double* ev = y + kJacobiK + 4 * v;
    const Vec4 ve{{ev[0], ev[1], ev[2], ev[3]}};
    for (int mu = 0; mu < 4; ++mu) {
      double t_abs = 0;
      const double t = -gamma(mu, k, ve, &t_abs);
      const double diff = std::fabs(dy[kJacobiK + 4 * v + mu] - t);
      EXPECT_LE(diff, rel * std::max(t_abs, 1e-300)) << m.name() << " transport of vector " << v << ", component " << mu
                                                     << ": " << dy[kJacobiK + 4 * v + mu] << " vs " << t;
    }
  }
  for (int i = 0; i < 4; ++i) EXPECT_EQ(dy[i], k[i]);
  return worst;
}

/// g(e_a, e_b) = η_ab = diag(−1, 1, 1, 1) to `tol`, and e_(0) future-directed (e_(0)^t > 0).
inline void expect_orthonormal(const Metric& m, const Vec4& x, TetradKind kind, double tol = 1e-12) {
  const Tetrad e = m.natural_tetrad(x, kind);
  Mat4 g;
  m.metric_tensor(x, g);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double eta = a == b ? (a == 0 ? -1.0 : 1.0) : 0.0;
      EXPECT_NEAR(dot(g, e[a], e[b]), eta, tol)
          << m.name() << " " << tetrad_kind_name(kind) << " tetrad, g(e" << a << ", e" << b << ") at (" << x[0] << ", "
          << x[1] << ", " << x[2] << ", " << x[3] << ")";
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

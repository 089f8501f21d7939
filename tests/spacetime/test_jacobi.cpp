// Jacobi (geodesic deviation) fields along null geodesics against analytic results:
//  * Minkowski: J = λ·1 (d+ = d− = λ, μ = 1, ellipticity 0);
//  * a conformally flat spacetime g = t² η (radiation-dominated FLRW in conformal time): null
//    geodesics are straight lines x = x0 + k_f λ_f with dλ = Ω² dλ_f, and the Jacobi field of a
//    bundle with vertex at the observer is J = Ω(x0) Ω(x) λ_f · 1 (conformal invariance of null
//    geodesics; Perlick, Living Rev. Relativ. 7 (2004) 9, §4.5), which tests the Ricci focusing
//    term of the optical tidal matrix including its sign;
//  * Schwarzschild: the optical tidal matrix of a photon moving tangentially at radius r through a
//    static observer's position is diag(−3ML²/r⁵, +3ML²/r⁵) in the (ê_θ, ê_r) screen (vacuum: no
//    trace; radial stretching, transverse compression), from the static-frame Riemann components
//    R_t̂r̂t̂r̂ = −2M/r³, R_t̂θ̂t̂θ̂ = R_t̂φ̂t̂φ̂ = M/r³, R_θ̂φ̂θ̂φ̂ = 2M/r³, R_r̂θ̂r̂θ̂ = R_r̂φ̂r̂φ̂ = −M/r³
//    (MTW eq. 31.4).
#include <gtest/gtest.h>

#include <cmath>

#include "metric_checks.h"
#include "spacetime/jacobi.h"
#include "spacetime/metric_crtp.h"
#include "spacetime/metric_registry.h"
#include "spacetime/tetrad.h"

using namespace geovis;

namespace {

/// ds² = t² (−dt² + dx² + dy² + dz²), t > 0 (a(η) = η: radiation-dominated FLRW).
class ConformalRadiationFLRW final : public MetricCRTP<ConformalRadiationFLRW> {
 public:
  ConformalRadiationFLRW()
      : MetricCRTP({"TestConformalFLRW",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {},
                    {TetradKind::Default},
                    "test metric t^2 eta",
                    Vec4{{1.0, 0.0, 0.0, 0.0}},
                    {}}) {}
  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T a2 = x[0] * x[0];
    g[0][0] = -a2;
    g[1][1] = a2;
    g[2][2] = a2;
    g[3][3] = a2;
  }
  bool is_valid(const Vec4& x) const override { return x[0] > 0 && Metric::is_valid(x); }
  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Tetrad e{};
    for (int a = 0; a < 4; ++a) e[a][a] = 1.0 / x[0];
    return e;
  }
};

}  // namespace

TEST(Jacobi, MinkowskiGivesLambdaTimesIdentity) {
  auto m = make_metric("Minkowski");
  const Vec4 x{{0, 1, 2, 3}};
  const Tetrad e = m->natural_tetrad(x);
  SolverConfig cfg;
  cfg.eps_abs = 1e-12;
  double y[kJacobiDim];
  GeodesicResult r;
  const JacobiParams p = trace_jacobi(*m, cfg, x, e, Vec3{0.3, -0.5, 0.8}, 7.5, y, &r);
  EXPECT_EQ(r.reason, StopReason::LambdaMax);
  EXPECT_NEAR(r.lambda, 7.5, 1e-12);
  double J[4];
  jacobi_matrix(*m, y, J);
  EXPECT_NEAR(J[0], 7.5, 1e-10);
  EXPECT_NEAR(J[1], 0, 1e-10);
  EXPECT_NEAR(J[2], 0, 1e-10);
  EXPECT_NEAR(J[3], 7.5, 1e-10);
  EXPECT_NEAR(p.d_plus, 7.5, 1e-10);
  EXPECT_NEAR(p.d_minus, 7.5, 1e-10);
  EXPECT_NEAR(p.mu, 1.0, 1e-10);
  EXPECT_NEAR(p.ellipticity, 0.0, 1e-10);
}

TEST(Jacobi, SachsBasisIsOrthonormalAndInTheScreen) {
  auto m = make_metric("Schwarzschild");
  const Vec4 x{{0, 7, 1.1, 0.4}};
  const Tetrad e = boost_tetrad(m->natural_tetrad(x), Vec3{0.2, 0.1, -0.3});
  Mat4 g;
  m->metric_tensor(x, g);
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -2}, Vec3{0.3, -0.4, 0.2}}) {
    Vec4 s1, s2;
    sachs_basis(e, d, s1, s2);
    const Vec4 k = local_null_direction(e, d, true);
    EXPECT_NEAR(dot(g, s1, s1), 1, 1e-13);
    EXPECT_NEAR(dot(g, s2, s2), 1, 1e-13);
    EXPECT_NEAR(dot(g, s1, s2), 0, 1e-13);
    EXPECT_NEAR(dot(g, s1, k), 0, 1e-13);
    EXPECT_NEAR(dot(g, s2, k), 0, 1e-13);
    EXPECT_NEAR(dot(g, s1, e[0]), 0, 1e-13);
    EXPECT_NEAR(dot(g, s2, e[0]), 0, 1e-13);
  }
}

TEST(Jacobi, ParamsOfAKnownMatrix) {
  // J = R(φ) diag(3, 1) R(θ): semi-axes 3 and 1, major axis at angle φ.
  const double phi = 0.7, th = -0.4;
  auto rot = [](double a, double M[4]) {
    M[0] = std::cos(a), M[1] = -std::sin(a), M[2] = std::sin(a), M[3] = std::cos(a);
  };
  double R1[4], R2[4];
  rot(phi, R1);
  rot(th, R2);
  const double D[4] = {3, 0, 0, 1};
  auto mul = [](const double A[4], const double B[4], double C[4]) {
    C[0] = A[0] * B[0] + A[1] * B[2];
    C[1] = A[0] * B[1] + A[1] * B[3];
    C[2] = A[2] * B[0] + A[3] * B[2];
    C[3] = A[2] * B[1] + A[3] * B[3];
  };
  double T[4], J[4];
  mul(R1, D, T);
  mul(T, R2, J);
  const JacobiParams p = jacobi_params(J, 2.0);
  EXPECT_NEAR(p.d_plus, 3, 1e-14);
  EXPECT_NEAR(p.d_minus, 1, 1e-14);
  EXPECT_NEAR(p.angle, phi, 1e-14);
  EXPECT_NEAR(p.ellipticity, 0.5, 1e-14);
  EXPECT_NEAR(p.mu, 4.0 / 3.0, 1e-14);
  // major axis along φ + π/2 modulo π gives an angle in (−π/2, π/2]
  rot(phi + 1.2, R1);
  mul(R1, D, T);
  mul(T, R2, J);
  EXPECT_NEAR(jacobi_params(J, 2.0).angle, phi + 1.2 - M_PI, 1e-14);
  const double zero[4] = {0, 0, 0, 0};
  EXPECT_EQ(jacobi_params(zero, 0.0).mu, 1.0);
}

TEST(Jacobi, RicciFocusingInAConformallyFlatUniverse) {
  const ConformalRadiationFLRW m;
  const double t0 = 10;
  const Vec4 x{{t0, 0, 0, 0}};
  const Tetrad e = m.natural_tetrad(x, TetradKind::Default);
  double y[kJacobiDim];
  jacobi_initial_state(x, e, Vec3{1, 0, 0}, y);
  SolverConfig cfg;
  cfg.eps_abs = 1e-11;
  cfg.max_steps = 100000;
  // k = (−1, 1, 0, 0)/t0, so k_f = t0² k = t0 (−1, 1, 0, 0): t = t0 (1 − λ_f),
  // λ = t0² (1 − (1 − λ_f)³)/3, J = t0 · t · λ_f. Integrate to t = 2 (λ_f = 0.8).
  cfg.lambda_max = t0 * t0 * (1 - std::pow(0.2, 3)) / 3;
  double worst = 0, worst_offdiag = 0, min_ratio = 1;
  int checked = 0;
  auto cb = [&](const StepView& st) {
    const double lam = st.lambda1;
    const double lf = 1 - std::cbrt(1 - 3 * lam / (t0 * t0));
    const double J = t0 * t0 * (1 - lf) * lf;
    double Jm[4];
    jacobi_matrix(m, st.y1, Jm);
    worst = std::max({worst, std::fabs(Jm[0] - J) / J, std::fabs(Jm[3] - J) / J});
    worst_offdiag = std::max({worst_offdiag, std::fabs(Jm[1]) / J, std::fabs(Jm[2]) / J});
    min_ratio = std::min(min_ratio, J / lam);
    EXPECT_NEAR(st.y1[0], t0 * (1 - lf), 1e-8);
    ++checked;
    return StepAction::Continue;
  };
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, cb);
  EXPECT_EQ(r.reason, StopReason::LambdaMax);
  EXPECT_GT(checked, 10);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_offdiag, 1e-10);
  EXPECT_LT(min_ratio, 0.5);  // strong focusing: J is far below the flat-space λ
  const JacobiParams p = jacobi_params_from_state(m, y, r.lambda);
  EXPECT_NEAR(p.d_plus, t0 * t0 * 0.2 * 0.8, 1e-6);
  EXPECT_NEAR(p.ellipticity, 0, 1e-10);
}

TEST(Jacobi, SchwarzschildTidalMatrixOfATangentialPhoton) {
  auto m = make_metric("Schwarzschild");
  const double r = 10, M = 1;
  const Vec4 x{{0, r, M_PI / 2, 0}};
  const Tetrad e = m->natural_tetrad(x);  // e1 = ê_r, e2 = ê_θ, e3 = ê_φ
  double y[kJacobiDim];
  jacobi_initial_state(x, e, Vec3{0, 0, 1}, y);  // along ê_φ: s1 = ê_θ, s2 = ê_r
  const Vec4 k{{y[4], y[5], y[6], y[7]}}, s1{{y[8], y[9], y[10], y[11]}}, s2{{y[12], y[13], y[14], y[15]}};
  EXPECT_NEAR(s1[2], 1 / r, 1e-15);
  EXPECT_NEAR(s2[1], std::sqrt(1 - 2 * M / r), 1e-15);
  double T[4];
  optical_tidal_matrix(*m, x, k, s1, s2, T);
  const double L = r * r * k[3];  // angular momentum g_φφ k^φ = r (local energy 1)
  const double w = 3 * M * L * L / std::pow(r, 5);
  EXPECT_NEAR(T[0], -w, 1e-12);
  EXPECT_NEAR(T[3], w, 1e-12);
  EXPECT_NEAR(T[1], 0, 1e-12);
  EXPECT_NEAR(T[2], 0, 1e-12);
  // a radial photon feels no tidal shear (L = 0) and no Ricci focusing (vacuum)
  const Vec4 kr = local_null_direction(e, Vec3{1, 0, 0}, true);
  Vec4 a1, a2;
  sachs_basis(e, Vec3{1, 0, 0}, a1, a2);
  optical_tidal_matrix(*m, x, kr, a1, a2, T);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(T[i], 0, 1e-12);
}

TEST(Jacobi, RightHandSideFromTheMetricTensorMatchesTheRiemannTensor) {
  // A metric without closed-form Christoffel symbols: the Jacobi right-hand side differentiates
  // g_{μν} twice (jacobi.h christoffel_with_derivs) and must agree with Metric::riemann.
  const ConformalRadiationFLRW m;
  const Vec4 x{{3.0, 0.1, -0.2, 0.3}};
  const Tetrad e = m.natural_tetrad(x, TetradKind::Default);
  for (const Vec3& d : {Vec3{1, 0, 0}, Vec3{0.3, -0.5, 0.8}, Vec3{0, 0, 1}})
    geovis::metric_checks::expect_jacobi_rhs_matches_riemann(m, x, e, d, 1e-12);
}

TEST(Jacobi, FieldToleranceIsRelativeToTheFieldsSize) {
  // The Jacobi equation is linear, so fields started with Y' = c s_b are c times the fields of
  // Y' = s_b. The step control holds each field to eps_abs relative to its own size
  // (jacobi.cpp JacobiSystem), so the scale c must change neither the steps nor J/c; with powers
  // of two every operation scales exactly. (An absolute tolerance takes more steps for larger c.)
  auto m = make_metric("KerrBL", {{"angmom", 0.9}, {"mass", 1.0}});
  const Vec4 x{{0, 30, 1.2, 0}};
  const Tetrad e = m->natural_tetrad(x);
  SolverConfig cfg;
  cfg.eps_abs = 1e-8;
  cfg.lambda_max = 60;  // past the hole at a few M and out again
  auto run = [&](double c, double J[4]) {
    double y[kJacobiDim];
    jacobi_initial_state(x, e, Vec3{-1, 0.2, 0.15}, y);
    for (int i = 0; i < 4; ++i) {
      y[kJacobiDY1 + i] *= c;
      y[kJacobiDY2 + i] *= c;
    }
    const GeodesicResult r = m->integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, {});
    EXPECT_EQ(r.reason, StopReason::LambdaMax);
    jacobi_matrix(*m, y, J);
    for (int i = 0; i < 4; ++i) J[i] /= c;
    return r.steps;
  };
  double J1[4], J2[4];
  const int steps1 = run(128.0, J1);
  const int steps2 = run(131072.0, J2);
  EXPECT_EQ(steps1, steps2);
  EXPECT_GT(steps1, 20);
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(J1[i], J2[i]) << i;
}

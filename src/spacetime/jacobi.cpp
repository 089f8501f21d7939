#include "spacetime/jacobi.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "spacetime/integrators.h"
#include "spacetime/jacobi_system.h"
#include "spacetime/metric.h"
#include "spacetime/metric_kernel.h"

namespace geovis {

namespace {

/// T_ab = −g(s_a, W_b), W_b^α = R^α_{νρσ} k^ν s_b^ρ k^σ (see the header comment).
void tidal_from_riemann(const Riemann& R, const Mat4& g, const Vec4& k, const Vec4& s1, const Vec4& s2, double T[4]) {
  const Vec4* s[2] = {&s1, &s2};
  for (int b = 0; b < 2; ++b) {
    Vec4 W{{0, 0, 0, 0}};
    for (int al = 0; al < 4; ++al)
      for (int nu = 0; nu < 4; ++nu) {
        if (k[nu] == 0.0) continue;
        for (int rho = 0; rho < 4; ++rho)
          for (int sg = 0; sg < 4; ++sg) W[al] += R.R[al][nu][rho][sg] * k[nu] * (*s[b])[rho] * k[sg];
      }
    for (int a = 0; a < 2; ++a) T[2 * a + b] = -dot(g, *s[a], W);
  }
}

}  // namespace

void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1, const Vec4& s2, double T[4]) {
  Riemann R;
  m.riemann(x, R);
  Mat4 g;
  m.metric_tensor(x, g);
  tidal_from_riemann(R, g, k, s1, s2, T);
}

JacobiParams jacobi_params(const double J[4], double lambda) {
  // Singular value decomposition of the 2x2 matrix J = R(φ) diag(d+, ±d-) R(θ) in closed form
  // (J. Blinn, "Consider the lowly 2x2 matrix", IEEE CG&A 16 (1996) 82): with
  // E = (J11+J22)/2, F = (J11−J22)/2, G = (J21+J12)/2, H = (J21−J12)/2,
  // d± = √(E²+H²) ± √(F²+G²), φ = (atan2(G,F) + atan2(H,E))/2. The unit circle maps to the
  // ellipse with semi-axes d+, |d-| whose major axis points along R(φ) s1.
  const double E = 0.5 * (J[0] + J[3]), F = 0.5 * (J[0] - J[3]);
  const double G = 0.5 * (J[2] + J[1]), H = 0.5 * (J[2] - J[1]);
  const double Q = std::sqrt(E * E + H * H), Rr = std::sqrt(F * F + G * G);
  JacobiParams p;
  p.d_plus = Q + Rr;
  p.d_minus = std::fabs(Q - Rr);
  double angle = 0.5 * (std::atan2(G, F) + std::atan2(H, E));
  // An axis direction is defined modulo π.
  while (angle > M_PI / 2) angle -= M_PI;
  while (angle <= -M_PI / 2) angle += M_PI;
  p.angle = angle;
  const double prod = p.d_plus * p.d_minus;
  if (lambda == 0.0)
    p.mu = 1.0;  // J ≈ λ·1 near the vertex in every spacetime
  else
    p.mu = prod > 0 ? lambda * lambda / prod : std::numeric_limits<double>::infinity();
  const double sum = p.d_plus + p.d_minus;
  p.ellipticity = sum > 0 ? std::fabs(p.d_plus - p.d_minus) / sum : 0.0;
  return p;
}

void sachs_basis(const Tetrad& e, const Vec3& d, Vec4& s1, Vec4& s2) {
  const Vec3 n = normalize(d);
  const Vec3 z{0, 0, 1};
  Vec3 b1, b2;
  const Vec3 zn = cross(z, n);
  if (norm(zn) < 1e-12) {
    b1 = Vec3{0, 1, 0};
    b2 = Vec3{1, 0, 0};
  } else {
    b1 = normalize(zn);
    b2 = normalize(cross(b1, n));
  }
  s1 = local_to_coord(e, Vec4{{0, b1.x, b1.y, b1.z}});
  s2 = local_to_coord(e, Vec4{{0, b2.x, b2.y, b2.z}});
}

void jacobi_initial_state(const Vec4& x, const Tetrad& e, const Vec3& d, double y[kJacobiDim]) {
  const Vec4 k = local_null_direction(e, d, true);
  Vec4 s1, s2;
  sachs_basis(e, d, s1, s2);
  for (int i = 0; i < 4; ++i) {
    y[kJacobiX + i] = x[i];
    y[kJacobiK + i] = k[i];
    y[kJacobiS1 + i] = s1[i];
    y[kJacobiS2 + i] = s2[i];
  }
  // Y_b = 0, Y_b' = s_b (J = 0, dJ/dλ = 1).
  for (int i = 0; i < 4; ++i) {
    y[kJacobiY1 + i] = 0.0;
    y[kJacobiDY1 + i] = s1[i];
    y[kJacobiY2 + i] = 0.0;
    y[kJacobiDY2 + i] = s2[i];
  }
}

void jacobi_matrix(const Metric& m, const double* y, double J[4]) {
  Mat4 g;
  m.metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
  const Vec4 s[2] = {Vec4{{y[kJacobiS1], y[kJacobiS1 + 1], y[kJacobiS1 + 2], y[kJacobiS1 + 3]}},
                     Vec4{{y[kJacobiS2], y[kJacobiS2 + 1], y[kJacobiS2 + 2], y[kJacobiS2 + 3]}}};
  const Vec4 Y[2] = {Vec4{{y[kJacobiY1], y[kJacobiY1 + 1], y[kJacobiY1 + 2], y[kJacobiY1 + 3]}},
                     Vec4{{y[kJacobiY2], y[kJacobiY2 + 1], y[kJacobiY2 + 2], y[kJacobiY2 + 3]}}};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) J[2 * a + b] = dot(g, s[a], Y[b]);
}

JacobiParams trace_jacobi(const Metric& m, const SolverConfig& cfg_in, const Vec4& x, const Tetrad& e, const Vec3& d,
                          double lambda_end, double* y_out, GeodesicResult* result) {
  SolverConfig cfg = cfg_in;
  cfg.type = GeodesicType::Lightlike;
  cfg.direction = 1.0;
  cfg.lambda_max = lambda_end;
  double y[kJacobiDim];
  jacobi_initial_state(x, e, d, y);
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, {});
  if (y_out)
    for (int i = 0; i < kJacobiDim; ++i) y_out[i] = y[i];
  if (result) *result = r;
  return jacobi_params_from_state(m, y, r.lambda);
}

GeodesicResult integrate_jacobi_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                          StepCallback cb) {
  JacobiRHS<MetricKernel> f{k};
  JacobiSystem sys{{k, f}};
  return integrate_dispatch(sys, cfg, y, lambda0, cb);
}

}  // namespace geovis

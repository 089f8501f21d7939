#include "spacetime/jacobi.h"

#include <limits>

#include "spacetime/metric.h"

namespace geovis {

void optical_tidal_matrix(const Metric& m, const Vec4& x, const Vec4& k, const Vec4& s1, const Vec4& s2,
                          double T[4]) {
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

void jacobi_initial_state(const Vec4& x, const Tetrad& e, const Vec3& d, double y[24]) {
  const Vec4 k = local_null_direction(e, d, true);
  Vec4 s1, s2;
  sachs_basis(e, d, s1, s2);
  for (int i = 0; i < 4; ++i) {
    y[kJacobiX + i] = x[i];
    y[kJacobiK + i] = k[i];
    y[kJacobiS1 + i] = s1[i];
    y[kJacobiS2 + i] = s2[i];
  }
  // J = 0, dJ/dλ = identity.
  const double J0[4] = {0, 0, 0, 0}, dJ0[4] = {1, 0, 0, 1};
  for (int i = 0; i < 4; ++i) {
    y[kJacobiJ + i] = J0[i];
    y[kJacobiDJ + i] = dJ0[i];
  }
}

JacobiParams trace_jacobi(const Metric& m, const SolverConfig& cfg_in, const Vec4& x, const Tetrad& e, const Vec3& d,
                          double lambda_end, double* y_out, GeodesicResult* result) {
  SolverConfig cfg = cfg_in;
  cfg.type = GeodesicType::Lightlike;
  cfg.direction = 1.0;
  cfg.lambda_max = lambda_end;
  double y[24];
  jacobi_initial_state(x, e, d, y);
  const GeodesicResult r = m.integrate(cfg, GeodesicSystem::Jacobi, y, 0.0, {});
  if (y_out)
    for (int i = 0; i < 24; ++i) y_out[i] = y[i];
  if (result) *result = r;
  return jacobi_params_from_state(y, r.lambda);
}

}  // namespace geovis

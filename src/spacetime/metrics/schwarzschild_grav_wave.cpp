// Schwarzschild black hole with a linear monopole (l = 0) perturbation oscillating in time
// (Motion4D "SchwarzschildGravWave", T. Müller 2017), coordinates (t, r, θ, φ):
//   ds² = −f (1 + ε X c) dt² + (1 + ε Y c)/f dr² + r² (1 + ε Z c) (dθ² + sin²θ dφ²),
//   f = 1 − 2M/r,  c = cos σt,  q = √f/r²,  P = M − (M² + σ² r⁴)/(r − 2M),
//   X = P q,  Y = 3M q,  Z = (r − 3M) q,
// i.e. g = g_Schwarzschild + ε h with Motion4D's h_tt = −f X c, h_rr = Y c/f, h_θθ = r² Z c,
// h_φφ = r² sin²θ Z c (its Legendre factor P_0 = 1). The perturbation solves the vacuum equations
// linearised about Schwarzschild (R_μν = O(ε²), checked in the tests; at l = 0 a time-dependent
// vacuum perturbation can only be a gauge mode, by Birkhoff's theorem, so the wave is a coordinate
// ripple of Schwarzschild to first order).
// The metric is diagonal; the Christoffel symbols follow from diagonal_metric.h with the
// derivatives (′ = d/dr):
//   f′ = 2M/r²,  q′ = f′/(2√f r²) − 2√f/r³,  P′ = −4σ²r³/(r − 2M) + (M² + σ²r⁴)/(r − 2M)²,
//   X′ = P′q + Pq′,  Y′ = 3M q′,  Z′ = q + (r − 3M) q′,  ∂_t c = −σ sin σt,
//   ∂_r g_tt = −f′(1 + εXc) − fεX′c,  ∂_t g_tt = −fεX ∂_t c,
//   ∂_r g_rr = εY′c/f − (1 + εYc) f′/f²,  ∂_t g_rr = εY ∂_t c/f,
//   ∂_r g_θθ = 2r(1 + εZc) + r²εZ′c,  ∂_t g_θθ = r²εZ ∂_t c,  g_φφ = sin²θ g_θθ.
// (Motion4D's own Christoffel symbols drop the ε terms from Γ^θ_φφ and Γ^φ_θφ; these are derived
// from the line element and checked against automatic differentiation.)
// Natural tetrad: static observers e_(μ) = ∂_μ/√|g_μμ| (Motion4D's only one).
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class SchwarzschildGravWave final : public MetricCRTP<SchwarzschildGravWave> {
 public:
  SchwarzschildGravWave()
      : MetricCRTP({"SchwarzschildGravWave",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"epsilon", 0.1, -1e300, 1e300, false, false, "amplitude epsilon of the perturbation"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M of the black hole (r_s = 2M)"},
                     {"sigma", 1.0, -1e300, 1e300, false, false, "angular frequency sigma of the perturbation"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild with an oscillating linear l = 0 perturbation (Motion4D SchwarzschildGravWave, "
                    "T. Mueller 2017)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}, {"epsilon", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T f = 1.0 - 2.0 * M_ / r;
    const T q = sqrt(f) / (r * r);
    const T P = M_ - (M_ * M_ + sigma_ * sigma_ * r * r * r * r) / (r - 2.0 * M_);
    const T c = cos(sigma_ * x[0]);
    const T st = sin(x[2]);
    g[0][0] = -f * (1.0 + eps_ * P * q * c);
    g[1][1] = (1.0 + eps_ * 3.0 * M_ * q * c) / f;
    g[2][2] = r * r * (1.0 + eps_ * (r - 3.0 * M_) * q * c);
    g[3][3] = g[2][2] * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1], r2 = r * r;
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double c = std::cos(sigma_ * x[0]), ct_t = -sigma_ * std::sin(sigma_ * x[0]);
    const double f = 1.0 - 2.0 * M_ / r, df = 2.0 * M_ / r2, sf = std::sqrt(f);
    const double q = sf / r2, dq = df / (2.0 * sf * r2) - 2.0 * sf / (r2 * r);
    const double rm = r - 2.0 * M_, N = M_ * M_ + sigma_ * sigma_ * r2 * r2;
    const double P = M_ - N / rm, dP = -4.0 * sigma_ * sigma_ * r2 * r / rm + N / (rm * rm);
    const double X = P * q, dX = dP * q + P * dq;
    const double Y = 3.0 * M_ * q, dY = 3.0 * M_ * dq;
    const double Z = (r - 3.0 * M_) * q, dZ = q + (r - 3.0 * M_) * dq;
    const double s2 = st * st;
    d.h[0] = -f * (1.0 + eps_ * X * c);
    d.h[1] = (1.0 + eps_ * Y * c) / f;
    d.h[2] = r2 * (1.0 + eps_ * Z * c);
    d.h[3] = d.h[2] * s2;
    d.dh[0][0] = -f * eps_ * X * ct_t;
    d.dh[0][1] = eps_ * Y * ct_t / f;
    d.dh[0][2] = r2 * eps_ * Z * ct_t;
    d.dh[0][3] = d.dh[0][2] * s2;
    d.dh[1][0] = -df * (1.0 + eps_ * X * c) - f * eps_ * dX * c;
    d.dh[1][1] = eps_ * dY * c / f - (1.0 + eps_ * Y * c) * df / (f * f);
    d.dh[1][2] = 2.0 * r * (1.0 + eps_ * Z * c) + r2 * eps_ * dZ * c;
    d.dh[1][3] = d.dh[1][2] * s2;
    d.dh[2][3] = 2.0 * st * ct * d.h[2];
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_accel(d, k, a);
  }

  /// Outside the horizon break radius r_s (1 + horizon_eps), where X ∝ 1/√f still is finite, and
  /// off the polar axis (Motion4D stops at r² <= (1 + 1e-6) r_s²). The perturbation grows like
  /// X ~ −σ²r far out, so the chart also ends where a factor 1 + εXc, 1 + εYc or 1 + εZc of the
  /// line element falls to horizon_eps (beyond, g is degenerate or has the wrong signature; the
  /// linearised wave has long stopped being small there).
  bool is_valid(const Vec4& x) const override {
    if (!(x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0 &&
          std::sin(x[2]) != 0.0))
      return false;
    const double r = x[1], r2 = r * r;
    const double f = 1.0 - 2.0 * M_ / r, q = std::sqrt(f) / r2;
    const double P = M_ - (M_ * M_ + sigma_ * sigma_ * r2 * r2) / (r - 2.0 * M_);
    const double ec = eps_ * std::cos(sigma_ * x[0]) * q;
    return 1.0 + ec * P > horizon_eps_ && 1.0 + ec * 3.0 * M_ > horizon_eps_ &&
           1.0 + ec * (r - 3.0 * M_) > horizon_eps_;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (is_valid(x)) diagonal(x, d);
    if (!is_valid(x) || !diagonal_static_tetrad(d.h, e)) {
      std::ostringstream os;
      os << "SchwarzschildGravWave: no static observer at (t, r, theta) = (" << x[0] << ", " << x[1] << ", " << x[2]
         << ") (needs r > r_s and a timelike d/dt)";
      throw Error(os.str());
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    eps_ = p(0);
    M_ = p(1);
    sigma_ = p(2);
    r_break_ = M_ > 0.0 ? 2.0 * M_ * (1.0 + horizon_eps_) : 1e-300;
  }

 private:
  double eps_ = 0.1, M_ = 1.0, sigma_ = 1.0, r_break_ = 2.0;
};

std::unique_ptr<Metric> make_metric_SchwarzschildGravWave() { return std::make_unique<SchwarzschildGravWave>(); }

}  // namespace geovis

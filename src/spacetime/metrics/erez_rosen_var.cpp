// Erez–Rosen spacetime, the static vacuum of a mass m with quadrupole parameter q, in
// Schwarzschild-like coordinates (t, r, θ, φ) (Motion4D "ErezRosenVar"; G. Erez & N. Rosen,
// Bull. Res. Council Israel 8F (1959) 47; D. Bini et al., "The Erez–Rosen metric and the role of
// the quadrupole on light propagation", arXiv:1408.5264). In Weyl's
// prolate spheroidal form with x = r/m − 1, y = cos θ:
//   ds² = −e^(2ψ) dt² + m² e^(−2ψ) [e^(2γ) (x² − y²)(dx²/(x² − 1) + dy²/(1 − y²)) + (x² − 1)(1 − y²) dφ²],
//   ψ = ½ L + ½ q (3y² − 1) [(3x² − 1) L/4 + 3x/2],  L = ln((x − 1)/(x + 1)),
//   γ = ½ (1 + q)² ln((x² − 1)/(x² − y²)) − (3/2) q (1 − y²)(xL + 2) + q² (1 − y²) Q,
//   Q = (9/64) L² (x⁴(1 − 9y²) − 2x²(1 − 5y²) + 1 − y²) + (3/16) L x (x²(3 − 27y²) + 21y² − 5)
//       + (9/16) x² (1 − 9y²) + (3/4)(3y² − 1),
// i.e. g_tt = −e^(2ψ), g_rr = e^(2γ−2ψ)(x² − y²)/(x² − 1), g_θθ = m² e^(2γ−2ψ)(x² − y²),
// g_φφ = m² e^(−2ψ)(x² − 1) sin²θ (m²(x² − 1) = r² − 2mr, m²(x² − y²) = r² − 2mr + m² sin²θ:
// Motion4D's Δ). ψ solves Laplace's equation (it is P0 Q0 + q P2(y) Q2(x)-type, far field
// ψ ≈ ½ ln(1 − 2m/r) − (2/15) q (m/r)³ P2(cos θ), the quadrupole term of Motion4D's variant), and
// γ was integrated here from Weyl's equations
//   γ_x = (1 − y²)/(x² − y²) [x(x² − 1)ψ_x² − x(1 − y²)ψ_y² − 2y(x² − 1)ψ_x ψ_y],
//   γ_y = (x² − 1)/(x² − y²) [y(x² − 1)ψ_x² − y(1 − y²)ψ_y² + 2x(1 − y²)ψ_x ψ_y]
// with γ = 0 on the axis (elementary flatness); the tests check R_ab = 0. q = 0 is Schwarzschild,
// which is all that Motion4D's compiled ErezRosenVar evaluates (its quadrupole branch is switched
// off and keeps γ of Schwarzschild); here q enters both ψ and γ.
// Christoffel symbols: the metric is diagonal (diagonal_metric.h); with ∂_r = ∂_x/m, ∂_θ = −sinθ ∂_y,
//   ψ_x = 1/(x² − 1) + ½ q (3y² − 1)[3xL/2 + (3x² − 1)/(2(x² − 1)) + 3/2],
//   ψ_y = 3qy [(3x² − 1) L/4 + 3x/2],  γ_x, γ_y from Weyl's equations above,
// and logarithmic derivatives of the components (W = x² − y², X = x² − 1):
//   g_tt: 2ψ_μ;  g_rr: 2γ_μ − 2ψ_μ + ∂_μ ln(W/X);  g_θθ: 2γ_μ − 2ψ_μ + ∂_μ ln W;
//   g_φφ: −2ψ_μ + ∂_μ ln(X sin²θ).
// Natural tetrad (Motion4D's, static): e_(μ) = ∂_μ/√|g_μμ|.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class ErezRosenVar final : public MetricCRTP<ErezRosenVar> {
 public:
  ErezRosenVar()
      : MetricCRTP({"ErezRosenVar",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, true, false, "mass m > 0"},
                     {"q", 0.1, -1e300, 1e300, false, false, "quadrupole parameter q (0: Schwarzschild)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Erez-Rosen static vacuum with quadrupole (Erez & Rosen, Bull. Res. Council Israel 8F (1959) 47; "
                    "Bini et al., arXiv:1408.5264)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  /// ψ and γ as functions of x, y (file comment), for any scalar type.
  template <class T>
  void potentials(const T& x, const T& y, T& psi, T& gam) const {
    using std::log;
    const T L = log((x - 1.0) / (x + 1.0));
    const T x2 = x * x, y2 = y * y, Y = 1.0 - y2;
    psi = 0.5 * L + 0.5 * q_ * (3.0 * y2 - 1.0) * ((3.0 * x2 - 1.0) * L / 4.0 + 1.5 * x);
    const T Q = (9.0 / 64.0) * L * L * (x2 * x2 * (1.0 - 9.0 * y2) - 2.0 * x2 * (1.0 - 5.0 * y2) + Y) +
                (3.0 / 16.0) * L * x * (x2 * (3.0 - 27.0 * y2) + 21.0 * y2 - 5.0) +
                (9.0 / 16.0) * x2 * (1.0 - 9.0 * y2) + 0.75 * (3.0 * y2 - 1.0);
    gam = 0.5 * (1.0 + q_) * (1.0 + q_) * log((x2 - 1.0) / (x2 - y2)) - 1.5 * q_ * Y * (x * L + 2.0) + q_ * q_ * Y * Q;
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& X, Mat4T<T>& g) const {
    using std::cos;
    using std::exp;
    using std::sin;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T x = X[1] / m_ - 1.0, y = cos(X[2]), s = sin(X[2]);
    T psi, gam;
    potentials(x, y, psi, gam);
    const T W = x * x - y * y, Xq = x * x - 1.0;
    const T e2gp = exp(2.0 * (gam - psi));
    g[0][0] = -exp(2.0 * psi);
    g[1][1] = e2gp * W / Xq;
    g[2][2] = m_ * m_ * e2gp * W;
    g[3][3] = m_ * m_ * exp(-2.0 * psi) * Xq * s * s;
  }

  void diagonal(const Vec4& X, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    double s, y;
    fast_sincos(X[2], s, y);
    const double x = X[1] / m_ - 1.0;
    double psi, gam;
    potentials(x, y, psi, gam);
    const double x2 = x * x, y2 = y * y, Y = 1.0 - y2, W = x2 - y2, Xq = x2 - 1.0;
    const double L = std::log((x - 1.0) / (x + 1.0));
    const double px = 1.0 / Xq + 0.5 * q_ * (3.0 * y2 - 1.0) * (1.5 * x * L + (3.0 * x2 - 1.0) / (2.0 * Xq) + 1.5);
    const double py = 3.0 * q_ * y * ((3.0 * x2 - 1.0) * L / 4.0 + 1.5 * x);
    const double gx = Y / W * (x * Xq * px * px - x * Y * py * py - 2.0 * y * Xq * px * py);
    const double gy = Xq / W * (y * Xq * px * px - y * Y * py * py + 2.0 * x * Y * px * py);
    const double e2gp = std::exp(2.0 * (gam - psi)), m2 = m_ * m_;
    d.h[0] = -std::exp(2.0 * psi);
    d.h[1] = e2gp * W / Xq;
    d.h[2] = m2 * e2gp * W;
    d.h[3] = m2 * std::exp(-2.0 * psi) * Xq * s * s;
    // ∂_x and ∂_y of the logarithms of h_μ, then ∂_r = ∂_x/m, ∂_θ = −sinθ ∂_y.
    const double lx[4] = {2.0 * px, 2.0 * gx - 2.0 * px + 2.0 * x / W - 2.0 * x / Xq, 2.0 * gx - 2.0 * px + 2.0 * x / W,
                          -2.0 * px + 2.0 * x / Xq};
    const double ly[3] = {2.0 * py, 2.0 * gy - 2.0 * py - 2.0 * y / W, 2.0 * gy - 2.0 * py - 2.0 * y / W};
    for (int mu = 0; mu < 4; ++mu) d.dh[1][mu] = d.h[mu] * lx[mu] / m_;
    for (int mu = 0; mu < 3; ++mu) d.dh[2][mu] = -s * d.h[mu] * ly[mu];
    d.dh[2][3] = d.h[3] * (2.0 * s * py + 2.0 * y / s);  // −2ψ_θ + 2 cotθ, ψ_θ = −sinθ ψ_y
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

  /// Outside r = 2m (x = 1, where L diverges; with the horizon_eps margin; Motion4D has no break
  /// condition here) and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           std::sin(x[2]) != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (is_valid(x)) diagonal(x, d);
    if (!is_valid(x) || !diagonal_static_tetrad(d.h, e)) {
      std::ostringstream os;
      os << "ErezRosenVar: no static observer at (r, theta) = (" << x[1] << ", " << x[2]
         << ") (needs r > 2m and theta off the axis)";
      throw Error(os.str());
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    m_ = p(0);
    q_ = p(1);
    r_break_ = 2.0 * m_ * (1.0 + horizon_eps_);
  }

 private:
  double m_ = 1.0, q_ = 0.1, r_break_ = 2.0002;
};

std::unique_ptr<Metric> make_metric_ErezRosenVar() { return std::make_unique<ErezRosenVar>(); }

}  // namespace geovis

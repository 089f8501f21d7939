// Rotating Chazy–Curzon spacetime in Weyl–Papapetrou coordinates (t, ρ, φ, z) (Motion4D
// "ChazyCurzonRot"): the stationary vacuum obtained from the static Curzon particle by an Ehlers
// transformation (Ehlers, Colloques Internationaux CNRS 91 (1962) 275; Stephani et al., Exact
// Solutions of Einstein's Field Equations (2003), ch. 34):
//   ds² = −e^(2U) (dt + A dφ)² + e^(−2U) [e^(2k) (dρ² + dz²) + ρ² dφ²],
//   e^(−2U) = cosh(2m/r) − p sinh(2m/r),  k = −m²ρ²/(2r⁴),  A = 2 q m z/r,
//   r² = ρ² + z²,  q = √(1 − p²),  |p| <= 1.
// p = −1 (q = 0) is the Curzon particle of mass m (e^(2U) = e^(−2m/r), "Curzon" metric); the
// Ehlers transformation leaves k unchanged.
// Derivatives for metric_derivs.h (W = e^(−2U), x = 2m/r, μ ∈ {ρ, z}):
//   x_ρ = −2mρ/r³,  x_z = −2mz/r³,  W_μ = (sinh x − p cosh x) x_μ,
//   k_ρ = m²ρ(ρ² − z²)/r⁶,  k_z = 2m²ρ²z/r⁶,  A_ρ = −2qmρz/r³,  A_z = 2qmρ²/r³,
//   ∂g_tt = W_μ/W²,  ∂g_tφ = A W_μ/W² − A_μ/W,
//   ∂g_φφ = 2ρW δ_μρ + ρ² W_μ − 2A A_μ/W + A² W_μ/W²,  ∂g_ρρ = ∂g_zz = (W_μ + 2W k_μ) e^(2k).
// Natural tetrads (Motion4D's): static, e_(0) = e^(−U) ∂_t, e_(2) = e^U (∂_φ − A ∂_t)/ρ; and the
// default/comoving one of the locally non-rotating observer, e_(0) = (∂_t + ω ∂_φ)/α with
// ω = −g_tφ/g_φφ, α = √((g_tφ² − g_tt g_φφ)/g_φφ), e_(2) = ∂_φ/√g_φφ; both with
// e_(1) = e^(U−k) ∂_ρ, e_(3) = e^(U−k) ∂_z. Near the axis, where A does not vanish (a Misner
// string), g_φφ = ρ² e^(−2U) − e^(2U) A² turns negative and only the static tetrad exists.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class ChazyCurzonRot final : public MetricCRTP<ChazyCurzonRot> {
 public:
  ChazyCurzonRot()
      : MetricCRTP({"ChazyCurzonRot",
                    {"t", "rho", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass m >= 0"},
                     {"p", 0.5, -1.0, 1.0, false, false, "Ehlers parameter p, |p| <= 1 (p = -1: static Curzon)"}},
                    {TetradKind::Default, TetradKind::Comoving, TetradKind::Static},
                    "Rotating Chazy-Curzon vacuum, Ehlers transform of the Curzon particle (Stephani et al., "
                    "Exact Solutions (2003); Motion4D ChazyCurzonRot)",
                    Vec4{{0, 6, 0, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cosh;
    using std::exp;
    using std::sinh;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& rho = x[1];
    const T r2 = rho * rho + x[3] * x[3];
    const T r = sqrt(r2);
    const T X = 2.0 * m_ / r;
    const T W = cosh(X) - p_ * sinh(X);
    const T k = -0.5 * m_ * m_ * rho * rho / (r2 * r2);
    const T A = 2.0 * q_ * m_ * x[3] / r;
    g[0][0] = -1.0 / W;
    g[0][2] = g[2][0] = -A / W;
    g[2][2] = rho * rho * W - A * A / W;
    g[1][1] = W * exp(2.0 * k);
    g[3][3] = g[1][1];
  }

  void derivs(const Vec4& x, MetricDerivs& d) const {
    d = MetricDerivs{};
    const double rho = x[1], z = x[3];
    const double r2 = rho * rho + z * z, r = std::sqrt(r2), r3 = r2 * r, r6 = r3 * r3;
    const double X = 2.0 * m_ / r, ch = std::cosh(X), sh = std::sinh(X);
    const double W = ch - p_ * sh, iW = 1.0 / W, iW2 = iW * iW;
    const double k = -0.5 * m_ * m_ * rho * rho / (r2 * r2), e2k = std::exp(2.0 * k);
    const double A = 2.0 * q_ * m_ * z / r;
    const double dWdX = sh - p_ * ch;
    // index 0: ∂_ρ (coordinate 1), 1: ∂_z (coordinate 3)
    const double W_d[2] = {dWdX * (-2.0 * m_ * rho / r3), dWdX * (-2.0 * m_ * z / r3)};
    const double k_d[2] = {m_ * m_ * rho * (rho * rho - z * z) / r6, 2.0 * m_ * m_ * rho * rho * z / r6};
    const double A_d[2] = {-2.0 * q_ * m_ * rho * z / r3, 2.0 * q_ * m_ * rho * rho / r3};
    d.g[0][0] = -iW;
    d.g[0][2] = d.g[2][0] = -A * iW;
    d.g[2][2] = rho * rho * W - A * A * iW;
    d.g[1][1] = d.g[3][3] = W * e2k;
    const int coord[2] = {1, 3};
    for (int i = 0; i < 2; ++i) {
      const int c = coord[i];
      d.dg[c][0][0] = W_d[i] * iW2;
      d.dg[c][0][2] = d.dg[c][2][0] = A * W_d[i] * iW2 - A_d[i] * iW;
      d.dg[c][2][2] =
          (i == 0 ? 2.0 * rho * W : 0.0) + rho * rho * W_d[i] - 2.0 * A * A_d[i] * iW + A * A * W_d[i] * iW2;
      d.dg[c][1][1] = d.dg[c][3][3] = (W_d[i] + 2.0 * W * k_d[i]) * e2k;
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    derivs(x, d);
    christoffel_from_derivs(d, G);
  }

  /// Off the axis ρ = 0 (a coordinate singularity of the chart) and away from the singularity
  /// r = 0: r > m·1e-3, where cosh(2m/r) ~ e^2000 has long overflowed the step control (Motion4D
  /// has no break condition).
  bool is_valid(const Vec4& x) const override {
    return x[1] > 0.0 && x[1] * x[1] + x[3] * x[3] > r2_min_ && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "ChazyCurzonRot: no tetrad at (rho, z) = (" << x[1] << ", " << x[3] << ") (needs rho > 0 and r > 0)";
      throw Error(os.str());
    }
    Mat4 g;
    g_tmpl(x, g);
    const double rho = x[1];
    const double eU = std::sqrt(-g[0][0]), A = g[0][2] / g[0][0];
    Tetrad e{};
    e[1][1] = 1.0 / std::sqrt(g[1][1]);
    e[3][3] = e[1][1];
    if (kind == TetradKind::Static) {
      e[0][0] = 1.0 / eU;
      e[2][0] = -A * eU / rho;
      e[2][2] = eU / rho;
    } else {
      if (!(g[2][2] > 0.0)) {
        std::ostringstream os;
        os << "ChazyCurzonRot: no locally non-rotating observer at (rho, z) = (" << rho << ", " << x[3]
           << "): g_phiphi = " << g[2][2] << " <= 0 (d/dphi is not spacelike near the axis); use the static frame";
        throw Error(os.str());
      }
      const double omega = -g[0][2] / g[2][2];
      const double alpha = std::sqrt((g[0][2] * g[0][2] - g[0][0] * g[2][2]) / g[2][2]);
      e[0][0] = 1.0 / alpha;
      e[0][2] = omega / alpha;
      e[2][2] = 1.0 / std::sqrt(g[2][2]);
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    m_ = p(0);
    p_ = p(1);
    q_ = std::sqrt(std::max(0.0, 1.0 - p_ * p_));
    const double rmin = m_ > 0.0 ? 1e-3 * m_ : 0.0;
    r2_min_ = rmin * rmin;
  }

 private:
  double m_ = 1.0, p_ = 0.5, q_ = 0.8660254037844386, r2_min_ = 1e-6;
};

std::unique_ptr<Metric> make_metric_ChazyCurzonRot() { return std::make_unique<ChazyCurzonRot>(); }

}  // namespace geovis

// Schwarzschild spacetime in pseudo-Cartesian coordinates (t, x, y, z), G = c = 1: the line
// element in Schwarzschild coordinates (paper eq. 1) with x = r sinθ cosφ, y = r sinθ sinφ,
// z = r cosθ, r = sqrt(x² + y² + z²), n = (x, y, z)/r:
//   ds² = −f dt² + δ_ij dx^i dx^j + a(r) (n·dx)²,   f = 1 − r_s/r,  a = 1/f − 1 = r_s/(r − r_s)
// (Catalogue of Spacetimes, arXiv:0904.4184, section "Schwarzschild spacetime / Schwarzschild in
// pseudo-Cartesian coordinates"). Not in the Motion4D database (GeoViS's cartSchwarzschild.scm
// asks for it); it avoids the polar-axis singularity of the spherical chart.
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"

namespace geovis {

class SchwarzschildCart final : public MetricCRTP<SchwarzschildCart> {
 public:
  SchwarzschildCart()
      : MetricCRTP({"SchwarzschildCart",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild black hole in pseudo-Cartesian coordinates (Mueller & Grave, Catalogue of "
                    "Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, 0, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sqrt;
    const T r2 = x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    const T r = sqrt(r2);
    const T a = rs_ / (r - rs_);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    g[0][0] = -(1.0 - rs_ / r);
    for (int i = 1; i < 4; ++i)
      for (int j = 1; j < 4; ++j) g[i][j] = (i == j ? T(1.0) : T(0.0)) + a * x[i] * x[j] / r2;
  }

  /// Derived from g_ij = δ_ij + a n_i n_j with ∂_j n_l = (δ_jl − n_j n_l)/r and the inverse
  /// g^ij = δ_ij − (r_s/r) n_i n_j (so g^{-1} n = f n):
  ///   Γ^t_{tj} = r_s/(2r(r − r_s)) n_j,   Γ^i_{tt} = r_s f/(2r²) n_i,
  ///   Γ^i_{jk} = n_i [−r_s/(2r(r − r_s)) n_j n_k + (r_s/r²)(δ_jk − n_j n_k)].
  /// Projected on n these are Schwarzschild's Γ^t_{tr}, Γ^r_{tt}, Γ^r_{rr} and the r_s parts of
  /// Γ^r_{θθ}, Γ^r_{φφ} (Catalogue of Spacetimes, Schwarzschild coordinates).
  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    const double n[4] = {0.0, x[1] / r, x[2] / r, x[3] / r};
    const double c_ttr = rs_ / (2.0 * r * (r - rs_));
    const double c_rtt = rs_ * (r - rs_) / (2.0 * r * r * r);
    const double c_perp = rs_ / (r * r);
    for (int i = 1; i < 4; ++i) {
      G.G[0][0][i] = G.G[0][i][0] = c_ttr * n[i];
      G.G[i][0][0] = c_rtt * n[i];
      for (int j = 1; j < 4; ++j)
        for (int k = 1; k < 4; ++k) G.G[i][j][k] = n[i] * (-(c_ttr + c_perp) * n[j] * n[k] + (j == k ? c_perp : 0.0));
    }
  }

  /// −Γ^μ_{ab} k^a k^b with the symbols above: with κ = n·k and |k|² the Euclidean norm of the
  /// spatial part, a^t = −2 Γ^t_{tr} k^t κ and
  /// a^i = −n_i [c_rtt (k^t)² − c_ttr κ² + (r_s/r²)(|k|² − κ²)].
  void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    const double nx = x[1] / r, ny = x[2] / r, nz = x[3] / r;
    const double c_ttr = rs_ / (2.0 * r * (r - rs_));
    const double c_rtt = rs_ * (r - rs_) / (2.0 * r * r * r);
    const double c_perp = rs_ / (r * r);
    const double kappa = nx * k[1] + ny * k[2] + nz * k[3];
    const double k2 = k[1] * k[1] + k[2] * k[2] + k[3] * k[3];
    const double s = c_rtt * k[0] * k[0] - c_ttr * kappa * kappa + c_perp * (k2 - kappa * kappa);
    a[0] = -2.0 * c_ttr * k[0] * kappa;
    a[1] = -nx * s;
    a[2] = -ny * s;
    a[3] = -nz * s;
  }

  /// Outside the horizon (same margin as Schwarzschild).
  bool is_valid(const Vec4& x) const override {
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    return r > r_min_ && std::isfinite(x[0]) && std::isfinite(r);
  }

  /// Static observer e_(0) = ∂_t/sqrt(f); spatial legs aligned with the coordinate axes as far as
  /// possible: e_(i) = ∂_i + (sqrt(f) − 1) n_i n^j ∂_j (orthonormal because
  /// (I + (s − 1) n nᵀ)(I + a n nᵀ)(I + (s − 1) n nᵀ) = I for s² = f = 1/(1 + a)).
  /// Escape (escape.h): Schwarzschild's photon sphere r = 1.5 r_s with r = |x| = |p| and
  /// dr/dλ = n·k.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    return escapes_spherical(r, x[1] * k[1] + x[2] * k[2] + x[3] * k[3], 1.5 * rs_, r_min, r, radius);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    if (!(r > rs_) || !(r > 0.0))
      throw Error("SchwarzschildCart: no static observer at r = " + std::to_string(r) +
                  " (needs r > r_s = " + std::to_string(rs_) + ")");
    const double s = std::sqrt(1.0 - rs_ / r);
    const double n[4] = {0.0, x[1] / r, x[2] / r, x[3] / r};
    Tetrad e{};
    e[0][0] = 1.0 / s;
    for (int i = 1; i < 4; ++i)
      for (int j = 1; j < 4; ++j) e[i][j] = (i == j ? 1.0 : 0.0) + (s - 1.0) * n[i] * n[j];
    return e;
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    r_min_ = rs_ > 0.0 ? rs_ * (1.0 + horizon_eps_) : 1e-300;  // Metric::horizon_eps
  }

 private:
  double rs_ = 2.0, r_min_ = 2.0;
};

std::unique_ptr<Metric> make_metric_SchwarzschildCart() { return std::make_unique<SchwarzschildCart>(); }

}  // namespace geovis

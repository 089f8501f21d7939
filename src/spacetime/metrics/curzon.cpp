// Curzon(-Chazy) particle in Weyl's cylindrical coordinates (t, r, φ, z) (Motion4D "Curzon";
// Curzon, Proc. London Math. Soc. 23 (1925) 477; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, "Curzon"):
//   ds² = −e^(2λ) dt² + e^(2ν − 2λ) (dr² + dz²) + r² e^(−2λ) dφ²,
//   λ = −m/R,  ν = −m² r²/(2 R⁴),  R = √(r² + z²),
// the static vacuum field of a point mass in Weyl's formalism (λ is the Newtonian potential). The
// singularity R = 0 is directional: it is a ring at infinity approached along some directions and
// a point along others (Gautreau & Anderson, Phys. Lett. A 25 (1967) 291).
// Derivatives for the diagonal Christoffel symbols (diagonal_metric.h):
//   ∂_r λ = m r/R³,  ∂_z λ = m z/R³,  ∂_r ν = −m² r/R⁴ + 2 m² r³/R⁶,  ∂_z ν = 2 m² r² z/R⁶;
//   ∂ e^(2λ) = 2 e^(2λ) ∂λ,  ∂ e^(2ν−2λ) = 2 (∂ν − ∂λ) e^(2ν−2λ),
//   ∂_r (r² e^(−2λ)) = (2r − 2r² ∂_r λ) e^(−2λ),  ∂_z (r² e^(−2λ)) = −2 r² ∂_z λ e^(−2λ).
// Natural tetrad: static observers, e_(μ) = ∂_μ/√|g_μμ|.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class Curzon final : public MetricCRTP<Curzon> {
 public:
  Curzon()
      : MetricCRTP({"Curzon",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"mass", 1.0, 0.0, 1e300, false, false, "mass m >= 0 of the Curzon particle"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Curzon-Chazy point mass, a static Weyl vacuum (Curzon, Proc. LMS 23 (1925) 477; Mueller & "
                    "Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, 0, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    using std::sqrt;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T R2 = r * r + x[3] * x[3];
    const T lambda = -m_ / sqrt(R2);
    const T nu = -0.5 * m_ * m_ * r * r / (R2 * R2);
    const T e2l = exp(2.0 * lambda);
    g[0][0] = -e2l;
    g[1][1] = exp(2.0 * nu) / e2l;
    g[2][2] = r * r / e2l;
    g[3][3] = g[1][1];
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1], z = x[3];
    const double R2 = r * r + z * z, R = std::sqrt(R2), R4 = R2 * R2, R6 = R4 * R2;
    const double lambda = -m_ / R, nu = -0.5 * m_ * m_ * r * r / R4;
    const double lr = m_ * r / (R2 * R), lz = m_ * z / (R2 * R);
    const double m2 = m_ * m_;
    const double nr = -m2 * r / R4 + 2.0 * m2 * r * r * r / R6, nz = 2.0 * m2 * r * r * z / R6;
    const double e2l = std::exp(2.0 * lambda), em2l = 1.0 / e2l, e2nl = std::exp(2.0 * nu) * em2l;
    d.h[0] = -e2l;
    d.h[1] = d.h[3] = e2nl;
    d.h[2] = r * r * em2l;
    d.dh[1][0] = -2.0 * e2l * lr;
    d.dh[3][0] = -2.0 * e2l * lz;
    d.dh[1][1] = d.dh[1][3] = 2.0 * (nr - lr) * e2nl;
    d.dh[3][1] = d.dh[3][3] = 2.0 * (nz - lz) * e2nl;
    d.dh[1][2] = (2.0 * r - 2.0 * r * r * lr) * em2l;
    d.dh[3][2] = -2.0 * r * r * lz * em2l;
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

  /// Off the axis r = 0 (polar coordinates) and away from the singularity R = 0: R > m·1e-3, where
  /// e^(2m/R) ~ e^2000 has long overflowed the step control anyway.
  bool is_valid(const Vec4& x) const override {
    const double R2 = x[1] * x[1] + x[3] * x[3];
    return x[1] != 0.0 && R2 > R2_min_ && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (is_valid(x)) diagonal(x, d);
    if (!is_valid(x) || !diagonal_static_tetrad(d.h, e))
      throw Error("Curzon: no static observer at (r, z) = (" + std::to_string(x[1]) + ", " + std::to_string(x[3]) +
                  ") (needs r != 0 and R > 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    m_ = p(0);
    const double rmin = m_ > 0.0 ? 1e-3 * m_ : 0.0;
    R2_min_ = rmin * rmin;
  }

 private:
  double m_ = 1.0, R2_min_ = 1e-6;
};

std::unique_ptr<Metric> make_metric_Curzon() { return std::make_unique<Curzon>(); }

}  // namespace geovis

// Bertotti–Kasner spacetime in (t, r, θ, φ) (Motion4D "BertottiKasner", getMetricName
// "MetricBertottiKasner"; Bertotti, Phys. Rev. 116 (1959) 1331; Rindler, Relativity: Special,
// General, and Cosmological (2006) §16.6; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, "Bertotti-Kasner"):
//   ds² = −dt² + e^(2√Λ t) dr² + Λ⁻¹ (dθ² + sin²θ dφ²),
// the product of a two-dimensional de Sitter space (curvature Λ) and a sphere of radius 1/√Λ, a
// homogeneous solution with cosmological constant Λ > 0. Christoffel symbols: diagonal metric
// (diagonal_metric.h) with ∂_t g_rr = 2√Λ e^(2√Λ t), ∂_θ g_φφ = 2 sin θ cos θ/Λ.
// Natural tetrad (Motion4D localToCoord): e_(0) = ∂_t, e_(1) = e^(−√Λ t) ∂_r, e_(2) = √Λ ∂_θ,
// e_(3) = √Λ ∂_φ/sin θ. No break condition in Motion4D; the chart is regular off the polar axis.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class BertottiKasner final : public MetricCRTP<BertottiKasner> {
 public:
  BertottiKasner()
      : MetricCRTP({"BertottiKasner",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"lambda", 1.0, 0.0, 1e300, true, false, "cosmological constant Lambda > 0"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Bertotti-Kasner: 2d de Sitter times a sphere (Bertotti, Phys. Rev. 116 (1959) 1331; Mueller "
                    "& Grave, arXiv:0904.4184)",
                    Vec4{{-1, 1, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T st = sin_t(x[2]);
    g[0][0] = T(-1.0);
    g[1][1] = exp(2.0 * sl_ * x[0]);
    g[2][2] = T(1.0 / L_);
    g[3][3] = st * st / L_;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double e = std::exp(2.0 * sl_ * x[0]);
    d.h[0] = -1.0;
    d.h[1] = e;
    d.h[2] = 1.0 / L_;
    d.h[3] = st * st / L_;
    d.dh[0][1] = 2.0 * sl_ * e;
    d.dh[2][3] = 2.0 * st * ct / L_;
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

  /// Off the polar axis (for a finite double θ, sin θ == 0 exactly iff θ == 0).
  bool is_valid(const Vec4& x) const override {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double st = std::sin(x[2]);
    if (st == 0.0) throw Error("BertottiKasner: no tetrad on the polar axis");
    Tetrad e{};
    e[0][0] = 1.0;
    e[1][1] = std::exp(-sl_ * x[0]);
    e[2][2] = sl_;
    e[3][3] = sl_ / st;
    return e;
  }

 protected:
  void on_params_changed() override {
    L_ = p(0);
    sl_ = std::sqrt(L_);
  }

 private:
  double L_ = 1.0, sl_ = 1.0;
};

std::unique_ptr<Metric> make_metric_BertottiKasner() { return std::make_unique<BertottiKasner>(); }

}  // namespace geovis

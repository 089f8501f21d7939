// "Conformal Minkowski" (Motion4D "MinkowskiConformal") in (ψ, ξ, θ, φ):
//   ds² = −dψ² + dξ² + sin²ξ (dθ² + sin²θ dφ²),
// the Einstein static universe R × S³ onto which Minkowski spacetime is conformally mapped by
// t ± r = tan((ψ ± ξ)/2), ds²_Minkowski = ds²/(4 cos²((ψ+ξ)/2) cos²((ψ−ξ)/2)) (Penrose diagram;
// Hawking & Ellis, The Large Scale Structure of Space-Time (1973) §5.1; Müller & Grave, Catalogue
// of Spacetimes, arXiv:0904.4184, "Minkowski: conformally compactified coordinates"). Motion4D
// integrates the conformally rescaled metric above, whose null geodesics are those of Minkowski
// (null geodesics are conformally invariant up to their affine parameter), while its curvature is
// that of the unit S³ (K = 12, not zero). Minkowski is the diamond |ψ| + ξ < π; the chart is
// Motion4D's 1e-8 <= ξ < π, −π < ψ < π (breakCondition).
// Christoffel symbols: diagonal metric (diagonal_metric.h) with h = (−1, 1, sin²ξ, sin²ξ sin²θ).
// Natural tetrad: e_(0) = ∂_ψ, e_(1) = ∂_ξ, e_(2) = ∂_θ/sin ξ, e_(3) = ∂_φ/(sin ξ sin θ).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class MinkowskiConformal final : public MetricCRTP<MinkowskiConformal> {
 public:
  MinkowskiConformal()
      : MetricCRTP({"MinkowskiConformal",
                    {"psi", "xi", "theta", "phi"},
                    CoordType::Spherical,
                    {},
                    {TetradKind::Default},
                    "Minkowski conformally compactified: the Einstein static universe (Hawking & Ellis (1973) "
                    "5.1; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 1, M_PI / 2, 0}},
                    {}}) {}

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T sx = sin_t(x[1]), st = sin_t(x[2]);
    g[0][0] = T(-1.0);
    g[1][1] = T(1.0);
    g[2][2] = sx * sx;
    g[3][3] = sx * sx * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    double sx, cx;
    fast_sincos(x[1], sx, cx);
    spherical_diagonal(-1.0, 0.0, 1.0, 0.0, sx * sx, 2.0 * sx * cx, x[2], d);
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

  /// Motion4D's chart 1e-8 <= ξ < π, −π < ψ < π, off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] >= 1e-8 && x[1] < M_PI && x[0] > -M_PI && x[0] < M_PI && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double sx = std::sin(x[1]), st = std::sin(x[2]);
    if (!(sx > 0.0) || st == 0.0)
      throw Error("MinkowskiConformal: no tetrad at xi = " + std::to_string(x[1]) +
                  ", theta = " + std::to_string(x[2]) + " (needs 0 < xi < pi, off the axis)");
    Tetrad e{};
    e[0][0] = 1.0;
    e[1][1] = 1.0;
    e[2][2] = 1.0 / sx;
    e[3][3] = 1.0 / (sx * st);
    return e;
  }
};

std::unique_ptr<Metric> make_metric_MinkowskiConformal() { return std::make_unique<MinkowskiConformal>(); }

}  // namespace geovis

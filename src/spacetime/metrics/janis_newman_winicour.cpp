// Janis-Newman-Winicour spacetime (static, spherically symmetric, massless scalar field) in
// (t, r, θ, φ), G = c = 1:
//   ds² = −α^γ dt² + α^(−γ) dr² + α^(1−γ) r² (dθ² + sin²θ dφ²),   α = 1 − r_s/(γ r),  r_s = 2M
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Janis-Newman-Winicour";
// A. I. Janis, E. T. Newman, J. Winicour, Phys. Rev. Lett. 20 (1968) 878. γ = 1 is
// Schwarzschild; for γ < 1 the surface r = r_s/γ is a naked (curvature) singularity.
// Photon sphere r = (1 + 2γ) M / γ from d/dr (g_φφ/(−g_tt)) = 0 (outside r_s/γ only for γ > 1/2;
// Virbhadra, Narasimha & Chitre, Astron. Astrophys. 337 (1998) 1).
#include <algorithm>
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/static_spherical.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class JanisNewmanWinicour final : public MetricCRTP<JanisNewmanWinicour> {
 public:
  JanisNewmanWinicour()
      : MetricCRTP({"JanisNewmanWinicour",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"gamma", 1.0, 0.0, 1.0, true, false,
                      "scalar-field parameter gamma in (0, 1] (gamma = 1: Schwarzschild; gamma < 1: "
                      "naked singularity at r = 2M/gamma)"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0"}},
                    {TetradKind::Default},
                    "Janis-Newman-Winicour naked singularity (Janis, Newman & Winicour, PRL 20 (1968) 878; Mueller & "
                    "Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::pow;
    using std::sin;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T alpha = 1.0 - b_ / r;
    const T ag = pow(alpha, gamma_);
    const T st = sin_t(x[2]);
    const T c = alpha / ag * r * r;  // α^(1−γ) r²
    g[0][0] = -ag;
    g[1][1] = 1.0 / ag;
    g[2][2] = c;
    g[3][3] = c * st * st;
  }

  /// With b = r_s/γ, α' = b/r²:
  ///   A = α^γ,  A' = γ α^(γ−1) b/r²;   B = α^(−γ),  B' = −γ α^(−γ−1) b/r²;
  ///   C = α^(1−γ) r²,  C' = (1−γ) α^(−γ) b + 2r α^(1−γ).
  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    const double r = x[1];
    const double alpha = 1.0 - b_ / r;
    const double dalpha = b_ / (r * r);
    const double ag = std::pow(alpha, gamma_);  // α^γ
    const double A = ag, dA = gamma_ * ag / alpha * dalpha;
    const double B = 1.0 / ag, dB = -gamma_ / (ag * alpha) * dalpha;
    const double C = alpha / ag * r * r;
    const double dC = (1.0 - gamma_) / ag * dalpha * r * r + 2.0 * r * alpha / ag;
    spherical_diagonal(A, dA, B, dB, C, dC, x[2], d);
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

  /// Outside Motion4D's break radius r_c = r_s (1 + γ)²/(4γ²) (m4dMetricJaNeWi::breakCondition:
  /// the innermost radius of its embedding diagram, where dz/dr² = r_s (4 r γ² − r_s (1 + γ)²) /
  /// (4 r² γ² α^(γ+1)) changes sign), and off the axis. r_c >= r_s/γ since (1 + γ)² >= 4γ; at
  /// γ = 1 both are the horizon r_s, where the break margin horizon_eps applies as in
  /// Schwarzschild: r_break = max(r_c, (r_s/γ)(1 + horizon_eps)).
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_min_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
           x[2] != 0.0;  // sin θ == 0 iff θ == 0 (double θ)
  }

  /// Escape (escape.h): h² = α^(1−2γ) r², (ln h²)' = (2r − (1 + 2γ) b)/(r (r − b)) with
  /// b = r_s/γ: h grows beyond the photon sphere (1 + 2γ) b/2 = (1 + 2γ) M/γ, which lies outside
  /// the singularity r = b only for γ > 1/2 (else h grows everywhere). r is |p|.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    return escapes_spherical(x[1], k[1], std::max(b_, 0.5 * (1.0 + 2.0 * gamma_) * b_), r_min, x[1], radius);
  }

  /// Effective potential, circular orbits and embedding (static_spherical.h) from Motion4D's break
  /// radius (the inner edge of its embedding diagram) outwards.
  std::vector<MetricFunction> functions() const override {
    return static_spherical_functions_of(*this, r_min_, r_min_ + 20.0 * std::max(p(1), 0.5));
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    DiagonalMetric d;
    Tetrad e;
    if (x[1] > b_ && x[1] > 0.0) diagonal(x, d);
    if (!(x[1] > b_ && x[1] > 0.0) || !diagonal_static_tetrad(d.h, e))
      throw Error("JanisNewmanWinicour: no static observer at r = " + std::to_string(x[1]) +
                  " (needs r > 2M/gamma = " + std::to_string(b_) + " and sin(theta) != 0)");
    return e;
  }

 protected:
  void on_params_changed() override {
    gamma_ = p(0);
    b_ = 2.0 * p(1) / gamma_;
    const double f = 0.5 * (1.0 + gamma_) / gamma_;
    r_min_ = b_ > 0.0 ? std::max(2.0 * p(1) * f * f, b_ * (1.0 + horizon_eps_)) : 1e-300;
  }

 private:
  double gamma_ = 1.0, b_ = 2.0, r_min_ = 2.0;
};

std::unique_ptr<Metric> make_metric_JanisNewmanWinicour() { return std::make_unique<JanisNewmanWinicour>(); }

}  // namespace geovis

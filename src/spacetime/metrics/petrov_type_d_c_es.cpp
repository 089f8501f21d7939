// Ehlers–Kundt class C of the static vacuum Petrov type D metrics (Motion4D "Petrov_Type_D_C_ES";
// Stephani et al., Exact Solutions of Einstein's Field Equations (2003) §18.6; Müller & Grave,
// Catalogue of Spacetimes, arXiv:0904.4184, "Petrov type D – Levi-Civita spacetimes"), the C-metric
// in (t, φ, x, y):
//   ds² = [−G(y) dt² + f(x) dφ² + dx²/f(x) + dy²/G(y)]/(x + y)²,
//   f(x) = x³ + a x + b,  G(y) = y³ + a y − b = −f(−y),
// static where f(x) > 0 and G(y) > 0, with x + y > 0 (Motion4D report). Vacuum requires
// G(y) = −f(−y) (Kinnersley & Walker, Phys. Rev. D 2 (1970) 1359; Griffiths & Podolský, Exact
// Space-Times (2009) §14.1). Motion4D's m4dMetricPTD_C writes +G dt² − dy²/G, i.e. uses f(−y)
// instead of −f(−y); that line element has R_ab != 0 (e.g. R_tt = 10 at Motion4D's initial
// position (x, y) = (1, −0.5), where this metric is not static), so here the vacuum form is used,
// with the initial position (x, y) = (1, 1.5) in its static region.
// Christoffel symbols: diagonal (diagonal_metric.h) with q = 1/(x + y)², ∂_x q = ∂_y q = −2/(x + y)³:
// h = (−G q, f q, q/f, q/G), ∂_x h = (−G q_x, f' q + f q_x, q_x/f − q f'/f², q_x/G),
// ∂_y h = (−G' q − G q_y, f q_y, q_y/f, q_y/G − q G'/G²), f' = 3x² + a, G' = 3y² + a.
// Natural tetrad (Motion4D localToCoord, with G → −G): e_(0) = (x + y) ∂_t/√G,
// e_(1) = (x + y) ∂_φ/√f, e_(2) = (x + y) √f ∂_x, e_(3) = (x + y) √G ∂_y. The ray stops at conformal
// infinity x + y = 0 and before the horizon G = 0 (g_tt = 0) and the axis f = 0 (g_φφ = 0, where
// Γ^x_xx = −f'/(2f) diverges), where f or G falls below horizon_eps: the break margin of the horizon
// metrics (metric.h, Metric::horizon_eps), as for Pravda_C-Metric (pravda_c_metric.cpp), since
// k^t ∝ 1/G diverges at the horizon as at a Schwarzschild horizon. Motion4D has no break condition.
// Pseudo-Cartesian coordinates (x, y, φ) as Motion4D's transToPseudoCart.
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PetrovTypeD_C final : public MetricCRTP<PetrovTypeD_C> {
 public:
  PetrovTypeD_C()
      : MetricCRTP({"Petrov_Type_D_C_ES",
                    {"t", "phi", "x", "y"},
                    CoordType::Custom,
                    {{"a", -1.0, -1e300, 1e300, false, false, "linear coefficient a of f(x) = x^3 + a x + b"},
                     {"b", 1.0, -1e300, 1e300, false, false, "constant b of f(x) = x^3 + a x + b"}},
                    {TetradKind::Default},
                    "Ehlers-Kundt static type D vacuum C (C-metric) (Stephani et al., Exact Solutions (2003) 18.6; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 0, 1, 1.5}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& X = x[2];
    const T& Y = x[3];
    const T f = X * X * X + a_ * X + b_;
    const T G = Y * Y * Y + a_ * Y - b_;
    const T s = X + Y;
    const T q = 1.0 / (s * s);
    g[0][0] = -G * q;
    g[1][1] = f * q;
    g[2][2] = q / f;
    g[3][3] = q / G;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double X = x[2], Y = x[3];
    const double f = X * X * X + a_ * X + b_, df = 3.0 * X * X + a_;
    const double G = Y * Y * Y + a_ * Y - b_, dG = 3.0 * Y * Y + a_;
    const double s = X + Y, q = 1.0 / (s * s), dq = -2.0 * q / s;
    d.h[0] = -G * q;
    d.h[1] = f * q;
    d.h[2] = q / f;
    d.h[3] = q / G;
    d.dh[2][0] = -G * dq;
    d.dh[2][1] = df * q + f * dq;
    d.dh[2][2] = dq / f - q * df / (f * f);
    d.dh[2][3] = dq / G;
    d.dh[3][0] = -dG * q - G * dq;
    d.dh[3][1] = f * dq;
    d.dh[3][2] = dq / f;
    d.dh[3][3] = dq / G - q * dG / (G * G);
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

  /// The static region x + y > 0, f(x), G(y) > horizon_eps (file comment).
  bool is_valid(const Vec4& x) const override {
    const double X = x[2], Y = x[3];
    return X + Y > 0.0 && X * X * X + a_ * X + b_ > horizon_eps_ && Y * Y * Y + a_ * Y - b_ > horizon_eps_ &&
           std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(X) && std::isfinite(Y);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x))
      throw Error("Petrov_Type_D_C_ES: no static observer at (x, y) = (" + std::to_string(x[2]) + ", " +
                  std::to_string(x[3]) + ") (needs x + y > 0, f(x) > 0, G(y) > 0)");
    const double X = x[2], Y = x[3], s = X + Y;
    const double sf = std::sqrt(X * X * X + a_ * X + b_), sG = std::sqrt(Y * Y * Y + a_ * Y - b_);
    Tetrad e{};
    e[0][0] = s / sG;
    e[1][1] = s / sf;
    e[2][2] = s * sf;
    e[3][3] = s * sG;
    return e;
  }

  int to_pseudo_cartesian(const Vec4& x, Vec3& p) const override {
    p = {x[2], x[3], x[1]};
    return 0;
  }
  Vec4 from_pseudo_cartesian(double t, const Vec3& p, int) const override { return {{t, p.z, p.x, p.y}}; }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    b_ = p(1);
  }

 private:
  double a_ = -1.0, b_ = 1.0;
};

std::unique_ptr<Metric> make_metric_PetrovTypeD_C() { return std::make_unique<PetrovTypeD_C>(); }

}  // namespace geovis

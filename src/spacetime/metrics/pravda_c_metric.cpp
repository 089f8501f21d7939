// C-metric of a uniformly accelerated black hole in the coordinates of Pravda & Pravdová (Motion4D
// "Pravda_C-Metric"; Kinnersley & Walker, Phys. Rev. D 2 (1970) 1359; Pravda & Pravdová, Czech. J.
// Phys. 50 (2000) 333; Griffiths & Podolský, Exact Space-Times (2009) §14.1), coordinates (q, x, y, p):
//   ds² = [−F(y) dq² + dx²/G(x) + dy²/F(y) + G(x) dp²]/(A² (x + y)²),
//   G(x) = 1 − x² − 2mA x³,  F(y) = −1 + y² − 2mA y³ = −G(−y),
// a vacuum solution (F = −G(−y)) with mass m and acceleration A; r = 1/(A (x + y)), and m = 0 is
// flat (Minkowski seen by uniformly accelerated observers). Static where F > 0 and G > 0.
// Christoffel symbols: diagonal (diagonal_metric.h) with c = 1/(A² (x + y)²),
// ∂_x c = ∂_y c = −2c/(x + y): h = (−F c, c/G, c/F, G c),
// ∂_x h = (−F c_x, c_x/G − c G'/G², c_x/F, G' c + G c_x),
// ∂_y h = (−F' c − F c_y, c_y/G, c_y/F − c F'/F², G c_y), G' = −2x − 6mA x², F' = 2y − 6mA y².
// Natural tetrad (Motion4D localToCoord, with |A (x + y)| so that e_(0) points along +∂_q):
// e_(0) = |A (x + y)| ∂_q/√F, e_(1) = |A (x + y)| √G ∂_x, e_(2) = |A (x + y)| √F ∂_y,
// e_(3) = |A (x + y)| ∂_p/√G. The ray stops before the horizons F = 0 and the axes G = 0 (where the
// chart is singular: Γ^x_xx = −G'/(2G) diverges also for rays with k^p = 0), where F or G falls below
// horizon_eps, and at conformal infinity x + y = 0 (Motion4D has no break condition).
// Pseudo-Cartesian coordinates (x, y, p), as Motion4D's transToPseudoCart (the identity of a
// Cartesian chart).
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PravdaCMetric final : public MetricCRTP<PravdaCMetric> {
 public:
  PravdaCMetric()
      : MetricCRTP({"Pravda_C-Metric",
                    {"q", "x", "y", "p"},
                    CoordType::Cartesian,
                    {{"a", 0.1, -1e300, 1e300, false, false, "acceleration A of the black hole (A != 0)"},
                     {"m", 1.0, -1e300, 1e300, false, false, "mass m of the black hole (m = 0: flat)"}},
                    {TetradKind::Default},
                    "C-metric of an accelerated black hole (Kinnersley & Walker, PRD 2 (1970) 1359; Pravda & "
                    "Pravdova, Czech. J. Phys. 50 (2000) 333)",
                    Vec4{{0, -5, -5, 0}},
                    {{"m", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& X = x[1];
    const T& Y = x[2];
    const T G = 1.0 - X * X - ma2_ * X * X * X;
    const T F = -1.0 + Y * Y - ma2_ * Y * Y * Y;
    const T s = X + Y;
    const T c = 1.0 / (a2_ * s * s);
    g[0][0] = -F * c;
    g[1][1] = c / G;
    g[2][2] = c / F;
    g[3][3] = G * c;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double X = x[1], Y = x[2];
    const double G = 1.0 - X * X - ma2_ * X * X * X, dG = -2.0 * X - 3.0 * ma2_ * X * X;
    const double F = -1.0 + Y * Y - ma2_ * Y * Y * Y, dF = 2.0 * Y - 3.0 * ma2_ * Y * Y;
    const double s = X + Y, c = 1.0 / (a2_ * s * s), dc = -2.0 * c / s;
    d.h[0] = -F * c;
    d.h[1] = c / G;
    d.h[2] = c / F;
    d.h[3] = G * c;
    d.dh[1][0] = -F * dc;
    d.dh[1][1] = dc / G - c * dG / (G * G);
    d.dh[1][2] = dc / F;
    d.dh[1][3] = dG * c + G * dc;
    d.dh[2][0] = -dF * c - F * dc;
    d.dh[2][1] = dc / G;
    d.dh[2][2] = dc / F - c * dF / (F * F);
    d.dh[2][3] = G * dc;
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

  /// The static region F(y), G(x) > horizon_eps, off conformal infinity x + y = 0 (file comment).
  bool is_valid(const Vec4& x) const override {
    const double X = x[1], Y = x[2];
    return 1.0 - X * X - ma2_ * X * X * X > horizon_eps_ && -1.0 + Y * Y - ma2_ * Y * Y * Y > horizon_eps_ &&
           X + Y != 0.0 && std::isfinite(x[0]) && std::isfinite(X) && std::isfinite(Y) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x))
      throw Error("Pravda_C-Metric: no static observer at (x, y) = (" + std::to_string(x[1]) + ", " +
                  std::to_string(x[2]) + ") (needs G(x) > 0, F(y) > 0, x + y != 0)");
    const double X = x[1], Y = x[2];
    const double sG = std::sqrt(1.0 - X * X - ma2_ * X * X * X), sF = std::sqrt(-1.0 + Y * Y - ma2_ * Y * Y * Y);
    const double w = std::fabs(a_ * (X + Y));
    Tetrad e{};
    e[0][0] = w / sF;
    e[1][1] = w * sG;
    e[2][2] = w * sF;
    e[3][3] = w / sG;
    return e;
  }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    if (a_ == 0.0) throw Error("Pravda_C-Metric: the acceleration a must not be 0 (r = 1/(a (x + y)))");
    a2_ = a_ * a_;
    ma2_ = 2.0 * p(1) * a_;
  }

 private:
  double a_ = 0.1, a2_ = 0.01, ma2_ = 0.2;
};

std::unique_ptr<Metric> make_metric_PravdaCMetric() { return std::make_unique<PravdaCMetric>(); }

}  // namespace geovis

// Bonnor's massive magnetic dipole, a static axisymmetric Einstein–Maxwell solution, coordinates
// (t, r, θ, φ) (Motion4D "Bonnor"; W. B. Bonnor, Z. Phys. 190 (1966) 444; Müller & Grave,
// Catalogue of Spacetimes, arXiv:0904.4184):
//   ds² = −(P/Y)² dt² + Y²P²/(Q³Z) (dr² + Z dθ²) + Z (Y/P)² sin²θ dφ²,
//   P = r² − 2mr − b² cos²θ,  Q = (r − m)² − (b² + m²) cos²θ,  Y = r² − b² cos²θ,
//   Z = r² − 2mr − b²,
// with mass m and magnetic dipole moment ∝ m b. For b = 0 it is the static vacuum of Zipoy and
// Voorhees with δ = 2 (g_tt = −(1 − 2m/r)²), for m = b = 0 Minkowski in spherical coordinates.
// The chart ends at Z = 0, r = m + √(m² + b²) (Motion4D's break radius); there Q >= Z and
// P >= Z, so P, Q, Y, Z > 0 outside.
// The metric is diagonal (diagonal_metric.h); with the logarithmic derivatives
//   P_r = Q_r = Z_r = 2(r − m),  Y_r = 2r,  P_θ = Y_θ = 2b² cosθ sinθ,  Q_θ = 2(b² + m²) cosθ sinθ:
//   ∂g_tt = g_tt (2P_μ/P − 2Y_μ/Y),  ∂g_rr = g_rr (2Y_μ/Y + 2P_μ/P − 3Q_μ/Q − Z_μ/Z),
//   ∂g_θθ = g_θθ (2Y_μ/Y + 2P_μ/P − 3Q_μ/Q),
//   ∂g_φφ = g_φφ (Z_μ/Z + 2Y_μ/Y − 2P_μ/P + 2 δ_μθ cotθ).
// Natural tetrad (static, Motion4D's): e_(μ) = ∂_μ/√|g_μμ|.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class Bonnor final : public MetricCRTP<Bonnor> {
 public:
  Bonnor()
      : MetricCRTP({"Bonnor",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"b", 0.1, -1e300, 1e300, false, false, "dipole parameter b (magnetic moment m b)"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass m"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Bonnor massive magnetic dipole (Bonnor, Z. Phys. 190 (1966) 444; Mueller & Grave, "
                    "arXiv:0904.4184)",
                    Vec4{{0, 10, M_PI / 2, 0}},
                    {{"mass", 0.0}, {"b", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cos;
    using std::sin;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    const T c = cos(x[2]), s = sin(x[2]);
    const T c2 = c * c;
    const T P = r * r - 2.0 * m_ * r - b2_ * c2;
    const T Q = (r - m_) * (r - m_) - (b2_ + m_ * m_) * c2;
    const T Y = r * r - b2_ * c2;
    const T Z = r * r - 2.0 * m_ * r - b2_;
    const T YP2 = Y * Y * P * P;
    g[0][0] = -(P * P) / (Y * Y);
    g[2][2] = YP2 / (Q * Q * Q);
    g[1][1] = g[2][2] / Z;
    g[3][3] = Z * Y * Y / (P * P) * s * s;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double r = x[1];
    double s, c;
    fast_sincos(x[2], s, c);
    const double c2 = c * c, cs = c * s;
    const double P = r * r - 2.0 * m_ * r - b2_ * c2;
    const double Q = (r - m_) * (r - m_) - (b2_ + m_ * m_) * c2;
    const double Y = r * r - b2_ * c2;
    const double Z = r * r - 2.0 * m_ * r - b2_;
    d.h[0] = -(P * P) / (Y * Y);
    d.h[2] = Y * Y * P * P / (Q * Q * Q);
    d.h[1] = d.h[2] / Z;
    d.h[3] = Z * Y * Y / (P * P) * s * s;
    // logarithmic derivatives: index 1 = r, 2 = θ
    const double lP[3] = {0.0, 2.0 * (r - m_) / P, 2.0 * b2_ * cs / P};
    const double lQ[3] = {0.0, 2.0 * (r - m_) / Q, 2.0 * (b2_ + m_ * m_) * cs / Q};
    const double lY[3] = {0.0, 2.0 * r / Y, 2.0 * b2_ * cs / Y};
    const double lZ[3] = {0.0, 2.0 * (r - m_) / Z, 0.0};
    const double lS[3] = {0.0, 0.0, 2.0 * c / s};
    for (int m = 1; m <= 2; ++m) {
      d.dh[m][0] = d.h[0] * (2.0 * lP[m] - 2.0 * lY[m]);
      d.dh[m][1] = d.h[1] * (2.0 * lY[m] + 2.0 * lP[m] - 3.0 * lQ[m] - lZ[m]);
      d.dh[m][2] = d.h[2] * (2.0 * lY[m] + 2.0 * lP[m] - 3.0 * lQ[m]);
      d.dh[m][3] = d.h[3] * (lZ[m] + 2.0 * lY[m] - 2.0 * lP[m] + lS[m]);
    }
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

  /// Outside r_b = m + √(m² + b²) (Z > 0; Motion4D's break condition r <= r_b, with the common
  /// horizon_eps margin) and off the polar axis.
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
      os << "Bonnor: no static observer at (r, theta) = (" << x[1] << ", " << x[2]
         << ") (needs r > m + sqrt(m^2 + b^2) = " << r_break_ << " and theta off the axis)";
      throw Error(os.str());
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    b2_ = p(0) * p(0);
    m_ = p(1);
    const double rb = m_ + std::sqrt(m_ * m_ + b2_);
    r_break_ = rb > 0.0 ? rb * (1.0 + horizon_eps_) : 0.0;
  }

 private:
  double b2_ = 0.01, m_ = 1.0, r_break_ = 2.0;
};

std::unique_ptr<Metric> make_metric_Bonnor() { return std::make_unique<Bonnor>(); }

}  // namespace geovis

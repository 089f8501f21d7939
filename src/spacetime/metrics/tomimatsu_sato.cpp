// Tomimatsu–Sato δ = 2 spacetime in prolate spheroidal coordinates (t, x, y, φ) (Motion4D
// "TomimatsuSato"; Tomimatsu & Sato, Phys. Rev. Lett. 29 (1972) 1344; in the form of V. S. Manko,
// Prog. Theor. Phys. 127 (2012) 1057):
//   ds² = −f (dt − ω dφ)² + (k²/f) [e^(2γ) (x² − y²) (dx²/(x² − 1) + dy²/(1 − y²))
//         + (x² − 1)(1 − y²) dφ²],
//   f = A/B,  e^(2γ) = A/(p⁴ (x² − y²)⁴),  ω = −k (1 − y²) C/A,
//   A = μ² − (x² − 1)(1 − y²) σ²,  B = μ² + μν − (1 − y²)((x² − 1) σ² − στ),  C = (x² − 1) σν + μτ,
//   μ = p²(x² − 1)² + q²(1 − y²)²,  σ = 2pq (x² − y²),  ν = 4x (px² + 2x + p),
//   τ = −4q (1 − y²)(px + 1)/p,  p² + q² = 1,
// with mass M = 2k/p (f -> 1 − 4/(px) = 1 − 2M/(kx) for x -> ∞, kx -> the distance); p = 1,
// q = 0 is the static Zipoy–Voorhees δ = 2 solution f = ((x − 1)/(x + 1))². Written out with A and
// B cancelled where they can (so that g_tt, g_tφ, g_xx, g_yy are regular where A = 0, the
// ergosurface):
//   g_tt = −A/B,  g_tφ = −k (1 − y²) C/B,  g_xx = k² B/(p⁴ S³ (x² − 1)),  g_yy = k² B/(p⁴ S³ (1 − y²)),
//   g_φφ = k² (1 − y²) H,  H = (x² − 1) B/A − (1 − y²) C²/(AB),  S = x² − y².
// (g_φφ is finite at A = 0 as well, but this form cancels there.)
// Derivatives (hand-written below, chain rule through μ, σ, ν, τ, A, B, C; μ_x = 4p²(x² − 1)x,
// μ_y = −4q²(1 − y²)y, σ_x = 4pqx, σ_y = −4pqy, ν_x = 12px² + 16x + 4p, τ_x = −4q(1 − y²),
// τ_y = 8qy(px + 1)/p) give the Christoffel symbols through metric_derivs.h.
// Natural tetrad (Motion4D's localToCoord, static): e_(0) = ∂_t/√(−g_tt),
// e_(3) = (g_tφ ∂_t − g_tt ∂_φ)/√(−g_tt D), D = g_tφ² − g_tt g_φφ, e_(1,2) = ∂_(x,y)/√g_(xx,yy)
// (outside the ergoregion only; the same as quasi_kerr.h's static tetrad).
// Pseudo-Cartesian: ρ = k √((x² − 1)(1 − y²)), z = k x y (prolate spheroidal with foci z = ±k).
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class TomimatsuSato final : public MetricCRTP<TomimatsuSato> {
 public:
  TomimatsuSato()
      : MetricCRTP({"TomimatsuSato",
                    {"t", "x", "y", "phi"},
                    CoordType::ProlateSpheroidal,
                    {{"k", 0.4330127019, 0.0, 1e300, true, false,
                      "scale k > 0 of the prolate spheroidal coordinates (M = 2k/p)"},
                     {"p", 0.5, 0.0, 1.0, true, false, "parameter p in (0, 1]"},
                     {"q", 0.8660254038, -1.0, 1.0, false, false, "parameter q, p^2 + q^2 = 1 (rotation)"}},
                    {TetradKind::Default},
                    "Tomimatsu-Sato delta = 2 (Tomimatsu & Sato, PRL 29 (1972) 1344; Manko, PTP 127 (2012) 1057)",
                    Vec4{{0, 5, 0.5, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& X, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& x = X[1];
    const T& y = X[2];
    const T X2 = x * x - 1.0, Y2 = 1.0 - y * y, S = x * x - y * y;
    const T mu = p_ * p_ * X2 * X2 + q_ * q_ * Y2 * Y2;
    const T sg = 2.0 * p_ * q_ * S;
    const T nu = 4.0 * x * (p_ * x * x + 2.0 * x + p_);
    const T tau = -4.0 * q_ * Y2 * (p_ * x + 1.0) / p_;
    const T A = mu * mu - X2 * Y2 * sg * sg;
    const T B = mu * mu + mu * nu - Y2 * (X2 * sg * sg - sg * tau);
    const T C = X2 * sg * nu + mu * tau;
    const T S3 = S * S * S;
    g[0][0] = -A / B;
    g[0][3] = g[3][0] = -k_ * Y2 * C / B;
    g[1][1] = k2_ * B / (p4_ * S3 * X2);
    g[2][2] = k2_ * B / (p4_ * S3 * Y2);
    g[3][3] = k2_ * Y2 * (X2 * B / A - Y2 * (C / A) * (C / B));
  }

  void derivs(const Vec4& X, MetricDerivs& d) const {
    d = MetricDerivs{};
    const double x = X[1], y = X[2];
    const double p = p_, q = q_;
    const double X2 = x * x - 1.0, Y2 = 1.0 - y * y, S = x * x - y * y;
    const double mu = p * p * X2 * X2 + q * q * Y2 * Y2;
    const double sg = 2.0 * p * q * S;
    const double nu = 4.0 * x * (p * x * x + 2.0 * x + p);
    const double tau = -4.0 * q * Y2 * (p * x + 1.0) / p;
    const double A = mu * mu - X2 * Y2 * sg * sg;
    const double B = mu * mu + mu * nu - Y2 * (X2 * sg * sg - sg * tau);
    const double C = X2 * sg * nu + mu * tau;
    // derivatives: index 0 = ∂_x, 1 = ∂_y
    const double X2d[2] = {2.0 * x, 0.0}, Y2d[2] = {0.0, -2.0 * y}, Sd[2] = {2.0 * x, -2.0 * y};
    const double mud[2] = {4.0 * p * p * X2 * x, -4.0 * q * q * Y2 * y};
    const double sgd[2] = {4.0 * p * q * x, -4.0 * p * q * y};
    const double nud[2] = {12.0 * p * x * x + 16.0 * x + 4.0 * p, 0.0};
    const double taud[2] = {-4.0 * q * Y2, 8.0 * q * y * (p * x + 1.0) / p};
    double Ad[2], Bd[2], Cd[2];
    for (int i = 0; i < 2; ++i) {
      Ad[i] = 2.0 * mu * mud[i] - (X2d[i] * Y2 + X2 * Y2d[i]) * sg * sg - 2.0 * X2 * Y2 * sg * sgd[i];
      Bd[i] = 2.0 * mu * mud[i] + mud[i] * nu + mu * nud[i] - Y2d[i] * (X2 * sg * sg - sg * tau) -
              Y2 * (X2d[i] * sg * sg + 2.0 * X2 * sg * sgd[i] - sgd[i] * tau - sg * taud[i]);
      Cd[i] = X2d[i] * sg * nu + X2 * sgd[i] * nu + X2 * sg * nud[i] + mud[i] * tau + mu * taud[i];
    }
    const double iB = 1.0 / B, iA = 1.0 / A, S3 = S * S * S;
    // Ratios first: A, B ~ x⁸ and C ~ x⁷ far out, so products like C²AB overflow beyond x ~ 1e10.
    const double H1 = X2 * B * iA, H2 = Y2 * (C * iA) * (C * iB), H = H1 - H2;
    d.g[0][0] = -A * iB;
    d.g[0][3] = d.g[3][0] = -k_ * Y2 * C * iB;
    d.g[1][1] = k2_ * B / (p4_ * S3 * X2);
    d.g[2][2] = k2_ * B / (p4_ * S3 * Y2);
    d.g[3][3] = k2_ * Y2 * H;
    for (int i = 0; i < 2; ++i) {
      const int c = i + 1;  // coordinate index of x, y
      d.dg[c][0][0] = -(Ad[i] - A * iB * Bd[i]) * iB;
      d.dg[c][0][3] = d.dg[c][3][0] = -k_ * (Y2d[i] * C + Y2 * Cd[i] - Y2 * C * Bd[i] * iB) * iB;
      d.dg[c][1][1] = k2_ / p4_ * (Bd[i] / (S3 * X2) - 3.0 * B * Sd[i] / (S3 * S * X2) - B * X2d[i] / (S3 * X2 * X2));
      d.dg[c][2][2] = k2_ / p4_ * (Bd[i] / (S3 * Y2) - 3.0 * B * Sd[i] / (S3 * S * Y2) - B * Y2d[i] / (S3 * Y2 * Y2));
      const double Hd = (X2d[i] * B + X2 * Bd[i]) * iA - H1 * Ad[i] * iA -
                        (Y2d[i] * C + 2.0 * Y2 * Cd[i]) * (C * iA) * iB + H2 * (Ad[i] * iA + Bd[i] * iB);
      d.dg[c][3][3] = k2_ * (Y2d[i] * H + Y2 * Hd);
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    derivs(x, d);
    christoffel_from_derivs(d, G);
  }

  /// Outside x = 1 + horizon_eps (x = 1 is the horizon rod of the chart), where B > 0 (g_xx,
  /// g_yy > 0; B vanishes on the naked ring singularities of the solution), and off the axis:
  /// y = ±1 is a chart edge that a ray cannot cross in these coordinates (y ≈ 1 − ϑ²/2 in terms of
  /// the angle ϑ from the axis, g_yy ∝ 1/(1 − y²)), so the ray stops at 1 − |y| = kAxisMargin
  /// (ϑ ≈ 1.4e-4) instead of crawling into it (Motion4D has no break condition here).
  bool is_valid(const Vec4& X) const override {
    if (!(X[1] > x_break_ && std::fabs(X[2]) < 1.0 - kAxisMargin && std::isfinite(X[0]) && std::isfinite(X[1]) &&
          std::isfinite(X[3])))
      return false;
    Mat4 g;
    g_tmpl(X, g);
    return g[1][1] > 0.0 && std::isfinite(g[3][3]);
  }

  Tetrad natural_tetrad(const Vec4& X, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Mat4 g;
    if (is_valid(X)) g_tmpl(X, g);
    if (!is_valid(X) || !(g[3][3] > 0.0) || !(g[0][0] < 0.0)) {
      std::ostringstream os;
      os << "TomimatsuSato: no static observer at (x, y) = (" << X[1] << ", " << X[2]
         << ") (needs x > 1, |y| < 1, B > 0, g_phiphi > 0 and g_tt < 0, i.e. outside the ergoregion)";
      throw Error(os.str());
    }
    const double D = g[0][3] * g[0][3] - g[0][0] * g[3][3];  // > 0: −det of the (t, φ) block
    const double w = std::sqrt(-g[0][0]);
    Tetrad e{};
    e[0][0] = 1.0 / w;
    e[1][1] = 1.0 / std::sqrt(g[1][1]);
    e[2][2] = 1.0 / std::sqrt(g[2][2]);
    e[3][0] = g[0][3] / (w * std::sqrt(D));
    e[3][3] = -g[0][0] / (w * std::sqrt(D));
    return e;
  }

  int to_pseudo_cartesian(const Vec4& X, Vec3& p) const override {
    const double rho = k_ * std::sqrt(std::max(0.0, (X[1] * X[1] - 1.0) * (1.0 - X[2] * X[2])));
    p = {rho * std::cos(X[3]), rho * std::sin(X[3]), k_ * X[1] * X[2]};
    return 0;
  }
  /// Inverse: x = (r₁ + r₂)/(2k), y = (r₁ − r₂)/(2k) with r₁,₂ the distances from the foci z = ∓k.
  Vec4 from_pseudo_cartesian(double t, const Vec3& p, int /*chart*/) const override {
    const double rho = std::hypot(p.x, p.y);
    const double r1 = std::hypot(rho, p.z + k_), r2 = std::hypot(rho, p.z - k_);
    return {{t, (r1 + r2) / (2.0 * k_), (r1 - r2) / (2.0 * k_), std::atan2(p.y, p.x)}};
  }

 protected:
  void on_params_changed() override {
    k_ = p(0);
    p_ = p(1);
    q_ = p(2);
    if (std::fabs(p_ * p_ + q_ * q_ - 1.0) > 1e-8) {
      std::ostringstream os;
      os << "TomimatsuSato: p^2 + q^2 must be 1, found p = " << p_ << ", q = " << q_;
      throw Error(os.str());
    }
    k2_ = k_ * k_;
    p4_ = p_ * p_ * p_ * p_;
    x_break_ = 1.0 + horizon_eps_;
  }

 private:
  static constexpr double kAxisMargin = 1e-8;
  double k_ = 0.4330127019, p_ = 0.5, q_ = 0.8660254038, k2_ = 0.1875, p4_ = 0.0625, x_break_ = 1.0001;
};

std::unique_ptr<Metric> make_metric_TomimatsuSato() { return std::make_unique<TomimatsuSato>(); }

}  // namespace geovis

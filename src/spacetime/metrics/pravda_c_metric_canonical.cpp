// C-metric in the canonical coordinates of boost-rotation symmetric spacetimes (Motion4D
// "Pravda_C-Metric_Canonical_Coords"; Bičák & Schmidt, Phys. Rev. D 40 (1989) 1827; Pravda &
// Pravdová, Czech. J. Phys. 50 (2000) 333), coordinates (t, r, φ, z) = (τ, η, φ, ζ):
//   ds² = e^λ dη² + η² e^(−ρ) dφ² + [e^λ (τ dτ − ζ dζ)² − (e^ρ/q²) (ζ dτ − τ dζ)²]/(ζ² − τ²),
// i.e. with ζ = R cosh ψ, τ = R sinh ψ the Weyl form e^λ (dR² + dη²) + η² e^(−ρ) dφ² − (e^ρ/q²) R² dψ²,
// the boost ψ being the Killing time of the uniformly accelerated black holes. Motion4D writes the
// same metric with signature (+,−,−,−). All functions depend on u = ζ² − τ², w = η² through the
// Weyl coordinates ρ_W = η √u, z_W = (u − w)/2 (Bičák & Schmidt) and the distances 2R_i = S_i to
// the rod ends z_W = −Z_i:
//   S_i = √((u − w + 2Z_i)² + 4uw),  P_i = S_i/2 + (u − w)/2 + Z_i,  Q_i = S_i/2 + (u + w)/2 + Z_i,
//   e^ρ = P_3/(4α² P_1),
//   e^λ = 8α² N_1 N_2/(S_1 S_3 D_3),  N_1 = (u + w) Q_1/2 − Z_1 w,  D_3 = (u + w) Q_3/2 − Z_3 w,
//   N_2 = S_1 S_3/4 + ((u + w)/2 + Z_1)((u + w)/2 + Z_3) − (Z_1 + Z_3) w;
// z_1 < z_2 < z_3 are the roots of z³ − z²/(2A²) + m²/(2A⁴) (three real roots need 27 m² A² < 1),
// Z_1 = z_2 − z_3, Z_3 = z_1 − z_3, α² = m²/(4A⁶ (z_3 − z_2)² (z_1 − z_2)²), q = 1/(4α²)
// (Motion4D MetricPravda_C_Can::setParam, rho, lambda). Motion4D's code has
// S_i = √(2u + 2w + 4Z_i − 8Z_i w), which is not even homogeneous in the dimension (u, w, Z_i are
// lengths²) and gives R_ab != 0; the distance above makes P_i = R_i + z_W − z_i the rod
// combination of Weyl potentials, and the metric is then Ricci-flat (test_metrics_registry.cpp).
// For small A the rod ends |Z_i| ~ 1/(2A²) are far away and P_i = S_i/2 + (u − w)/2 + Z_i cancels
// to a few digits; rod() and rod_rates() evaluate it as uw/(S_i/2 − (u − w)/2 − Z_i) there.
// Christoffel symbols: metric_derivs.h from g and ∂g written out, ∂_τ = −2τ ∂_u, ∂_ζ = 2ζ ∂_u,
// ∂_η = 2η ∂_w, with the logarithmic derivatives
//   ∂ ln e^ρ = ∂P_3/P_3 − ∂P_1/P_1,  ∂ ln e^λ = ∂N_1/N_1 + ∂N_2/N_2 − ∂S_1/S_1 − ∂S_3/S_3 − ∂D_3/D_3,
//   ∂_u S_i = (u + w + 2Z_i)/S_i, ∂_w S_i = (u + w − 2Z_i)/S_i, ∂_u P_i = (1 + ∂_u S_i)/2,
//   ∂_w P_i = (∂_w S_i − 1)/2, ∂Q_i = (1 + ∂S_i)/2, ∂_u N_1 = Q_1/2 + (u + w) ∂_u Q_1/2,
//   ∂_w N_1 = Q_1/2 + (u + w) ∂_w Q_1/2 − Z_1 (D_3 alike), ∂N_2 = (∂S_1 S_3 + S_1 ∂S_3)/4 + (u + w)/2
//   + (Z_1 + Z_3)/2, minus (Z_1 + Z_3) for ∂_w.
// Natural tetrad (Motion4D localToCoord), k = 1/√|ζ² − τ²|: where ζ² > τ² e_(0) = k q (ζ ∂_τ +
// τ ∂_ζ)/√(e^ρ), e_(3) = k (τ ∂_τ + ζ ∂_ζ)/√(e^λ); where τ² > ζ² the two are exchanged;
// e_(1) = ∂_η/√(e^λ), e_(2) = √(e^ρ) ∂_φ/η. The ray stops on the roof ζ² = τ², on the axis η = 0
// and where e^ρ or e^λ is not positive (Motion4D has no break condition).
#include <algorithm>
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class PravdaCMetricCanonical final : public MetricCRTP<PravdaCMetricCanonical> {
 public:
  PravdaCMetricCanonical()
      : MetricCRTP({"Pravda_C-Metric_Canonical_Coords",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"a", 0.01, 0.0, 1e300, true, false, "acceleration A > 0 of the black holes (27 m^2 A^2 < 1)"},
                     {"m", 1.0, 0.0, 1e300, true, false, "mass m > 0 of the black holes (27 m^2 A^2 < 1)"}},
                    {TetradKind::Default},
                    "C-metric in boost-rotation symmetric coordinates (Bicak & Schmidt, PRD 40 (1989) 1827; Pravda "
                    "& Pravdova, Czech. J. Phys. 50 (2000) 333)",
                    Vec4{{1, 1, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  /// S_i and P_i (file comment). With c = (u − w)/2 + Z_i < 0 (|Z_i| ~ 1/(2A²) is large for small
  /// accelerations) P_i = S_i/2 + c cancels to a few digits; then P_i = uw/(S_i/2 − c), exactly.
  template <class T>
  static void rod(const T& u, const T& w, double Z, T& S, T& P) {
    using std::sqrt;
    const T c = 0.5 * (u - w) + Z;
    S = 2.0 * sqrt(c * c + u * w);
    P = value_of(c) < 0.0 ? u * w / (0.5 * S - c) : 0.5 * S + c;
  }

  /// e^ρ and e^λ of (u, w) (file comment); templated for automatic differentiation.
  template <class T>
  void potentials(const T& u, const T& w, T& erho, T& elam) const {
    T S1, S3, P1, P3;
    rod(u, w, z1_, S1, P1);
    rod(u, w, z3_, S3, P3);
    const T Q1 = P1 + w, Q3 = P3 + w;
    const T N1 = 0.5 * (u + w) * Q1 - z1_ * w, D3 = 0.5 * (u + w) * Q3 - z3_ * w;
    const T N2 = 0.25 * S1 * S3 + (0.5 * (u + w) + z1_) * (0.5 * (u + w) + z3_) - (z1_ + z3_) * w;
    erho = P3 / (4.0 * alpha2_ * P1);
    elam = 8.0 * alpha2_ * N1 * N2 / (S1 * S3 * D3);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& tau = x[0];
    const T& eta = x[1];
    const T& zeta = x[3];
    const T u = zeta * zeta - tau * tau, w = eta * eta;
    T erho, elam;
    potentials(u, w, erho, elam);
    const T e = erho / qq_;
    g[0][0] = (elam * tau * tau - e * zeta * zeta) / u;
    g[0][3] = g[3][0] = (e - elam) * zeta * tau / u;
    g[3][3] = (elam * zeta * zeta - e * tau * tau) / u;
    g[1][1] = elam;
    g[2][2] = w / erho;
  }

  /// ∂_u P_i, ∂_w P_i without the cancellation of (1 ± ∂S_i)/2 (see rod): for c < 0, P = uw/M,
  /// M = S/2 − c, ∂_u M = (u + w + 2Z − S)/(2S), ∂_w M = (u + w − 2Z + S)/(2S).
  static void rod_rates(double u, double w, double Z, double S, double P, double& Pu, double& Pw) {
    const double c = 0.5 * (u - w) + Z, s = u + w;
    if (c < 0.0) {
      const double M = 0.5 * S - c;
      Pu = (w - P * (s + 2.0 * Z - S) / (2.0 * S)) / M;
      Pw = (u - P * (s - 2.0 * Z + S) / (2.0 * S)) / M;
    } else {
      Pu = 0.5 * (1.0 + (s + 2.0 * Z) / S);
      Pw = 0.5 * ((s - 2.0 * Z) / S - 1.0);
    }
  }

  /// g and ∂g (file comment).
  void derivs(const Vec4& x, MetricDerivs& d) const {
    d = MetricDerivs{};
    const double tau = x[0], eta = x[1], zeta = x[3];
    const double u = zeta * zeta - tau * tau, w = eta * eta, s = u + w;
    double S1, S3, P1, P3;
    rod(u, w, z1_, S1, P1);
    rod(u, w, z3_, S3, P3);
    const double S1u = (s + 2.0 * z1_) / S1, S1w = (s - 2.0 * z1_) / S1;
    const double S3u = (s + 2.0 * z3_) / S3, S3w = (s - 2.0 * z3_) / S3;
    double P1u, P1w, P3u, P3w;
    rod_rates(u, w, z1_, S1, P1, P1u, P1w);
    rod_rates(u, w, z3_, S3, P3, P3u, P3w);
    const double Q1 = P1 + w, Q3 = P3 + w;
    const double Q1u = P1u, Q1w = P1w + 1.0, Q3u = P3u, Q3w = P3w + 1.0;
    const double N1 = 0.5 * s * Q1 - z1_ * w, D3 = 0.5 * s * Q3 - z3_ * w;
    const double N1u = 0.5 * Q1 + 0.5 * s * Q1u, N1w = 0.5 * Q1 + 0.5 * s * Q1w - z1_;
    const double D3u = 0.5 * Q3 + 0.5 * s * Q3u, D3w = 0.5 * Q3 + 0.5 * s * Q3w - z3_;
    const double N2 = 0.25 * S1 * S3 + (0.5 * s + z1_) * (0.5 * s + z3_) - (z1_ + z3_) * w;
    const double N2u = 0.25 * (S1u * S3 + S1 * S3u) + 0.5 * s + 0.5 * (z1_ + z3_);
    const double N2w = N2u - 0.25 * (S1u * S3 + S1 * S3u) + 0.25 * (S1w * S3 + S1 * S3w) - (z1_ + z3_);
    const double erho = P3 / (4.0 * alpha2_ * P1);
    const double elam = 8.0 * alpha2_ * N1 * N2 / (S1 * S3 * D3);
    const double rho_u = erho * (P3u / P3 - P1u / P1), rho_w = erho * (P3w / P3 - P1w / P1);
    const double lam_u = elam * (N1u / N1 + N2u / N2 - S1u / S1 - S3u / S3 - D3u / D3);
    const double lam_w = elam * (N1w / N1 + N2w / N2 - S1w / S1 - S3w / S3 - D3w / D3);
    // ∂_c of functions of (u, w), c = (τ, η, φ, ζ).
    const double du[4] = {-2.0 * tau, 0.0, 0.0, 2.0 * zeta};
    const double dw[4] = {0.0, 2.0 * eta, 0.0, 0.0};
    const double e = erho / qq_;
    const double gtt = (elam * tau * tau - e * zeta * zeta) / u;
    const double gtz = (e - elam) * zeta * tau / u;
    const double gzz = (elam * zeta * zeta - e * tau * tau) / u;
    d.g[0][0] = gtt;
    d.g[0][3] = d.g[3][0] = gtz;
    d.g[3][3] = gzz;
    d.g[1][1] = elam;
    d.g[2][2] = w / erho;
    const double dtt[4] = {2.0 * tau, 0.0, 0.0, 0.0}, dzz[4] = {0.0, 0.0, 0.0, 2.0 * zeta};
    const double dzt[4] = {zeta, 0.0, 0.0, tau};
    for (int c = 0; c < 4; ++c) {
      const double dl = lam_u * du[c] + lam_w * dw[c];
      const double dr = rho_u * du[c] + rho_w * dw[c];
      const double de = dr / qq_;
      d.dg[c][0][0] = (dl * tau * tau + elam * dtt[c] - de * zeta * zeta - e * dzz[c] - gtt * du[c]) / u;
      d.dg[c][0][3] = d.dg[c][3][0] = ((de - dl) * zeta * tau + (e - elam) * dzt[c] - gtz * du[c]) / u;
      d.dg[c][3][3] = (dl * zeta * zeta + elam * dzz[c] - de * tau * tau - e * dtt[c] - gzz * du[c]) / u;
      d.dg[c][1][1] = dl;
      d.dg[c][2][2] = (dw[c] - w * dr / erho) / erho;
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    derivs(x, d);
    christoffel_from_derivs(d, G);
  }

  /// Off the roof ζ² = τ² and the axis η = 0, where e^ρ, e^λ are positive (file comment).
  bool is_valid(const Vec4& x) const override {
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]))) return false;
    const double u = x[3] * x[3] - x[0] * x[0], w = x[1] * x[1];
    if (u == 0.0 || x[1] == 0.0) return false;
    double erho, elam;
    potentials(u, w, erho, elam);
    return erho > 0.0 && elam > 0.0 && std::isfinite(erho) && std::isfinite(elam);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x))
      throw Error("Pravda_C-Metric_Canonical_Coords: no observer at (t, r, z) = (" + std::to_string(x[0]) + ", " +
                  std::to_string(x[1]) + ", " + std::to_string(x[3]) +
                  ") (on the roof z^2 = t^2, on the axis r = 0 or outside the chart)");
    const double tau = x[0], eta = x[1], zeta = x[3];
    const double u = zeta * zeta - tau * tau;
    double erho, elam;
    potentials(u, eta * eta, erho, elam);
    const double l1 = std::sqrt(elam), r1 = std::sqrt(erho), k = 1.0 / std::sqrt(std::fabs(u));
    const double q = std::sqrt(qq_);
    // The boost direction ζ ∂_τ + τ ∂_ζ and the "radial" one τ ∂_τ + ζ ∂_ζ, normalized.
    const double b0 = k * q * zeta / r1, b3 = k * q * tau / r1;
    const double c0 = k * tau / l1, c3 = k * zeta / l1;
    const bool outside = u > 0.0;
    Tetrad e{};
    e[0][0] = outside ? b0 : c0;
    e[0][3] = outside ? b3 : c3;
    e[3][0] = outside ? c0 : b0;
    e[3][3] = outside ? c3 : b3;
    e[1][1] = 1.0 / l1;
    e[2][2] = r1 / std::fabs(eta);
    return e;
  }

 protected:
  void on_params_changed() override {
    const double A = p(0), m = p(1);
    if (!(27.0 * m * m * A * A < 1.0))
      throw Error("Pravda_C-Metric_Canonical_Coords: needs 27 m^2 a^2 < 1 (three real roots)");
    // Roots of z³ + a z² + c, a = −1/(2A²), c = m²/(2A⁴), by the trigonometric method for the
    // depressed cubic t³ + P t + Q (z = t − a/3).
    const double a = -0.5 / (A * A), c = 0.5 * m * m / (A * A * A * A);
    const double P = -a * a / 3.0, Q = 2.0 * a * a * a / 27.0 + c;
    const double rr = 2.0 * std::sqrt(-P / 3.0);
    const double phi = std::acos(std::clamp(3.0 * Q / (P * rr), -1.0, 1.0)) / 3.0;
    double z[3];
    for (int k = 0; k < 3; ++k) z[k] = rr * std::cos(phi - 2.0 * M_PI * k / 3.0) - a / 3.0;
    std::sort(z, z + 3);
    z1_ = z[1] - z[2];
    z3_ = z[0] - z[2];
    alpha2_ = 0.25 * m * m / std::pow(A, 6) / ((z[2] - z[1]) * (z[2] - z[1]) * (z[0] - z[1]) * (z[0] - z[1]));
    qq_ = 1.0 / (16.0 * alpha2_ * alpha2_);  // q², q = 1/(4α²)
  }

 private:
  double z1_ = 0.0, z3_ = 0.0, alpha2_ = 1.0, qq_ = 1.0;
};

std::unique_ptr<Metric> make_metric_PravdaCMetricCanonical() { return std::make_unique<PravdaCMetricCanonical>(); }

}  // namespace geovis

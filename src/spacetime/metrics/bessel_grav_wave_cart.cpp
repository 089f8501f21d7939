// Gravitational Bessel wave (a standing Einstein–Rosen cylindrical wave) in Cartesian coordinates
// (t, x, y, z) (Motion4D "BesselGravWaveCart"; D. Kramer, Ann. Phys. (Leipzig) 9 (2000) 331, with
// ωt − kz -> t, kt − ωz -> z; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184):
//   ds² = −e^(2(K−U)) dt² + e^(−2U)/ρ² [(e^(2K) x² + y²) dx² + 2xy (e^(2K) − 1) dx dy
//         + (x² + e^(2K) y²) dy²] + e^(2U) dz²,
//   U = C J0(ρ) cos t,  K = ½ C² ρ [ρ (J0² + J1²) − 2 J0 J1 cos²t],  ρ² = x² + y²,
// i.e. the Einstein–Rosen form e^(2(K−U)) (−dt² + dρ²) + ρ² e^(−2U) dφ² + e^(2U) dz² in Cartesian
// x = ρ cos φ, y = ρ sin φ. It is vacuum: U solves the cylindrical wave equation and
// K_ρ = ρ (U_ρ² + U_t²), K_t = 2ρ U_ρ U_t (Einstein & Rosen, J. Franklin Inst. 223 (1937) 43;
// with J0′ = −J1, J1′ = J0 − J1/ρ, Abramowitz & Stegun 9.1.27).
//
// The chart is regular on the axis ρ = 0 (Motion4D's sample position), so everything is written in
// s = ρ² with entire functions of s:
//   A(s) = J0(ρ) = Σ (−s/4)^k/(k!)²,  B(s) = J1(ρ)/ρ = ½ Σ (−s/4)^k/(k!(k+1)!)  (A&S 9.1.10),
//   A′ = dA/ds = −B/2,  B′ = (A − 2B)/(2s)  (series near the axis),
//   K = s κ,  κ = ½C² [A² + s B² − 2AB cos²t],
//   g_ij = e^(−2U) (δ_ij + E x_i x_j)  (i, j ∈ {x, y}),  E = (e^(2K) − 1)/s = 2κ φ(2K),
//   φ(w) = (e^w − 1)/w.
// Derivatives for the Christoffel symbols (metric_derivs.h), with c = cos t, S = sin t and
// ∂_x = 2x ∂_s, ∂_y = 2y ∂_s:
//   U_t = −C A S,  U_s = C A′ c,
//   κ_t = 2C² A B c S,  κ_s = ½C² [2AA′ + B² + 2sBB′ − 2(A′B + AB′) c²],
//   K_t = s κ_t,  K_s = κ + s κ_s,  E_μ = 2κ_μ φ(2K) + 4κ φ′(2K) K_μ,
//   ∂g_tt = 2 g_tt (∂K − ∂U),  ∂g_zz = 2 g_zz ∂U,
//   ∂g_ij = −2 ∂U g_ij + e^(−2U) (∂E x_i x_j + E ∂(x_i x_j)).
// Natural tetrad (Motion4D's): e_(0) = e^(U−K) ∂_t, e_(2) = ∂_y/√g_yy, e_(1) the unit vector
// orthogonal to ∂_y in the (x, y) plane, e_(3) = e^(−U) ∂_z.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/bessel.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

namespace bessel_wave {

/// Below s = ρ² = kSeries the power series (16 terms, error < 1e-20), above it the library's J0, J1.
constexpr double kSeries = 4.0;

/// Ratios of successive series terms, tabulated (the hot path multiplies instead of dividing):
/// kRatio[0][k] = 1/k² (A), kRatio[1][k] = 1/(k(k+1)) (B), kRatio[2][k] = 1/((k−1)(k+1)) (B′),
/// kRatio[3][k] = 1/(k+1) (φ), kRatio[4][k] = k/((k−1)(k+1)) (φ′), for k = 0..20.
struct SeriesRatios {
  double r[5][21];
};
constexpr SeriesRatios make_series_ratios() {
  SeriesRatios t{};
  for (int k = 2; k <= 20; ++k) {
    t.r[0][k] = 1.0 / (k * k);
    t.r[1][k] = 1.0 / (k * (k + 1));
    t.r[2][k] = 1.0 / ((k - 1) * (k + 1));
    t.r[3][k] = 1.0 / (k + 1);
    t.r[4][k] = double(k) / ((k - 1) * (k + 1));
  }
  t.r[0][1] = 1.0;
  t.r[1][1] = 0.5;
  t.r[3][1] = 0.5;
  return t;
}
constexpr SeriesRatios kRatio = make_series_ratios();

/// A(s) = J0(√s), B(s) = J1(√s)/√s for any scalar type.
template <class T>
void ab(const T& s, T& A, T& B) {
  using std::sqrt;
  if (s < kSeries) {
    // Horner form of the series in w = −s/4: A = Σ w^k/(k!)², B = ½ Σ w^k/(k!(k+1)!).
    const T w = -0.25 * s;
    A = T(1.0);
    B = T(1.0);
    for (int k = 16; k >= 1; --k) {
      A = 1.0 + A * w * kRatio.r[0][k];
      B = 1.0 + B * w * kRatio.r[1][k];
    }
    B = 0.5 * B;
    return;
  }
  const T r = sqrt(s);
  A = bessel::j0(r);
  B = bessel::j1(r) / r;
}

/// φ(w) = (e^w − 1)/w (series near w = 0) for any scalar type.
template <class T>
T phi(const T& w) {
  using std::exp;
  if (w < 0.5 && w > -0.5) {
    T p = T(1.0);
    for (int n = 20; n >= 1; --n) p = 1.0 + p * w * kRatio.r[3][n];
    return p;
  }
  return (exp(w) - 1.0) / w;
}

}  // namespace bessel_wave

class BesselGravWaveCart final : public MetricCRTP<BesselGravWaveCart> {
 public:
  BesselGravWaveCart()
      : MetricCRTP({"BesselGravWaveCart",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"c", 1.0, -1e300, 1e300, false, false, "amplitude C of the Bessel wave (C = 0: flat)"}},
                    {TetradKind::Default},
                    "Gravitational Bessel wave, a standing Einstein-Rosen wave (Kramer, Ann. Phys. 9 (2000) 331; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 0, 0, 0}},
                    {{"c", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cos;
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T s = x[1] * x[1] + x[2] * x[2];
    T A, B;
    bessel_wave::ab(s, A, B);
    const T c = cos(x[0]);
    const T U = C_ * A * c;
    const T kappa = 0.5 * C_ * C_ * (A * A + s * B * B - 2.0 * A * B * c * c);
    const T K = s * kappa;
    const T E = 2.0 * kappa * bessel_wave::phi(2.0 * K);
    const T em2U = exp(-2.0 * U);
    g[0][0] = -exp(2.0 * (K - U));
    g[1][1] = em2U * (1.0 + E * x[1] * x[1]);
    g[2][2] = em2U * (1.0 + E * x[2] * x[2]);
    g[1][2] = g[2][1] = em2U * E * x[1] * x[2];
    g[3][3] = 1.0 / em2U;
  }

  void derivs(const Vec4& x, MetricDerivs& d) const {
    d = MetricDerivs{};
    const double X = x[1], Y = x[2], s = X * X + Y * Y;
    double A, B, dB;
    bessel_wave::ab(s, A, B);
    if (s < bessel_wave::kSeries) {
      // B′ = ½ Σ_(k>=1) k (−1/4)^k s^(k−1)/(k!(k+1)!), Horner form.
      const double w = -0.25 * s;
      double p = 1.0;
      for (int k = 16; k >= 2; --k) p = 1.0 + p * w * bessel_wave::kRatio.r[2][k];
      dB = 0.5 * (-0.25) * p / 2.0;
    } else {
      dB = (A - 2.0 * B) / (2.0 * s);
    }
    const double dA = -0.5 * B;
    double S, c;
    fast_sincos(x[0], S, c);
    const double C2 = C_ * C_;
    const double U = C_ * A * c, U_t = -C_ * A * S, U_s = C_ * dA * c;
    const double kappa = 0.5 * C2 * (A * A + s * B * B - 2.0 * A * B * c * c);
    const double kappa_t = 2.0 * C2 * A * B * c * S;
    const double kappa_s = 0.5 * C2 * (2.0 * A * dA + B * B + 2.0 * s * B * dB - 2.0 * (dA * B + A * dB) * c * c);
    const double K = s * kappa, K_t = s * kappa_t, K_s = kappa + s * kappa_s;
    const double w = 2.0 * K;
    const double ph = bessel_wave::phi(w);
    double dph;  // φ′(w) = Σ n w^(n−1)/(n+1)! near 0, (e^w − φ)/w elsewhere
    if (w < 0.5 && w > -0.5) {
      double p = 1.0;
      for (int n = 20; n >= 2; --n) p = 1.0 + p * w * bessel_wave::kRatio.r[4][n];
      dph = 0.5 * p;
    } else {
      dph = (std::exp(w) - ph) / w;
    }
    const double E = 2.0 * kappa * ph;
    const double E_t = 2.0 * kappa_t * ph + 4.0 * kappa * dph * K_t;
    const double E_s = 2.0 * kappa_s * ph + 4.0 * kappa * dph * K_s;
    const double em2U = std::exp(-2.0 * U);
    // ∂_μ of U, K, E for μ = t, x, y (z: none).
    const double dU[3] = {U_t, 2.0 * X * U_s, 2.0 * Y * U_s};
    const double dK[3] = {K_t, 2.0 * X * K_s, 2.0 * Y * K_s};
    const double dE[3] = {E_t, 2.0 * X * E_s, 2.0 * Y * E_s};
    d.g[0][0] = -std::exp(2.0 * (K - U));
    d.g[1][1] = em2U * (1.0 + E * X * X);
    d.g[2][2] = em2U * (1.0 + E * Y * Y);
    d.g[1][2] = d.g[2][1] = em2U * E * X * Y;
    d.g[3][3] = 1.0 / em2U;
    // ∂_μ (x_i x_j) for (xx, yy, xy).
    const double dxx[3] = {0.0, 2.0 * X, 0.0}, dyy[3] = {0.0, 0.0, 2.0 * Y}, dxy[3] = {0.0, Y, X};
    for (int m = 0; m < 3; ++m) {
      d.dg[m][0][0] = 2.0 * d.g[0][0] * (dK[m] - dU[m]);
      d.dg[m][3][3] = 2.0 * d.g[3][3] * dU[m];
      d.dg[m][1][1] = -2.0 * dU[m] * d.g[1][1] + em2U * (dE[m] * X * X + E * dxx[m]);
      d.dg[m][2][2] = -2.0 * dU[m] * d.g[2][2] + em2U * (dE[m] * Y * Y + E * dyy[m]);
      d.dg[m][1][2] = d.dg[m][2][1] = -2.0 * dU[m] * d.g[1][2] + em2U * (dE[m] * X * Y + E * dxy[m]);
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    derivs(x, d);
    christoffel_from_derivs(d, G);
  }

  /// Regular everywhere (Motion4D has no break condition).
  bool is_valid(const Vec4& x) const override {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "BesselGravWaveCart: no tetrad at a non-finite position";
      throw Error(os.str());
    }
    Mat4 g;
    g_tmpl(x, g);
    Tetrad e{};
    e[0][0] = 1.0 / std::sqrt(-g[0][0]);
    const double gyy = g[2][2], gxy = g[1][2];
    const double n1 = 1.0 / std::sqrt(g[1][1] - gxy * gxy / gyy);
    e[1][1] = n1;
    e[1][2] = -n1 * gxy / gyy;
    e[2][2] = 1.0 / std::sqrt(gyy);
    e[3][3] = 1.0 / std::sqrt(g[3][3]);
    return e;
  }

 protected:
  void on_params_changed() override { C_ = p(0); }

 private:
  double C_ = 1.0;
};

std::unique_ptr<Metric> make_metric_BesselGravWaveCart() { return std::make_unique<BesselGravWaveCart>(); }

}  // namespace geovis

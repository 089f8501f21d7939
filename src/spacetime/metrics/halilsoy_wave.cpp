// Halilsoy's cross-polarised standing cylindrical gravitational wave, coordinates (t, ρ, φ, z)
// (Motion4D "HalilsoyWave"; M. Halilsoy, Nuovo Cimento B 102 (1988) 563; Stephani et al., Exact
// Solutions of Einstein's Field Equations (2003), p. 353, as Motion4D cites; Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184):
//   ds² = V [e^(2k) (dρ² − dt²) + ρ² dφ²] + (dz + A dφ)²/V,
//   V = cosh²α e^(−2ψ) + sinh²α e^(2ψ),  ψ = C J0(ρ) cos t,  A = −2C sinh(2α) ρ J1(ρ) sin t,
//   k = ½C² [ρ² (J0² + J1²) − 2ρ J0 J1 cos²t],
// the Ehlers-type rotation (angle α) of the Einstein–Rosen Bessel wave ψ (α = 0: the
// BesselGravWaveCart line element in cylindrical coordinates, V = e^(−2ψ)); vacuum for every α.
// Derivatives (J0′ = −J1, ρJ1′ = ρJ0 − J1; c = cos t, S = sin t):
//   ψ_t = −C J0 S,  ψ_ρ = −C J1 c,  V_μ = −2ψ_μ (cosh²α e^(−2ψ) − sinh²α e^(2ψ)),
//   A_t = −2C sinh2α ρ J1 c,  A_ρ = −2C sinh2α ρ J0 S,
//   k_t = 2C² ρ J0 J1 c S,  k_ρ = C² ρ (J0² S² + J1² c²),
//   ∂g_tt = −(V_μ + 2V k_μ) e^(2k) = −∂g_ρρ,  ∂g_φφ = V_μ ρ² + 2Vρ δ_μρ + 2A A_μ/V − A² V_μ/V²,
//   ∂g_φz = A_μ/V − A V_μ/V²,  ∂g_zz = −V_μ/V²;
// the Christoffel symbols follow from metric_derivs.h.
// Natural tetrad (Motion4D's): e_(0) = e^(−k) ∂_t/√V, e_(1) = e^(−k) ∂_ρ/√V,
// e_(2) = (∂_φ − A ∂_z)/(ρ√V), e_(3) = √V ∂_z.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/bessel.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class HalilsoyWave final : public MetricCRTP<HalilsoyWave> {
 public:
  HalilsoyWave()
      : MetricCRTP(
            {"HalilsoyWave",
             {"t", "rho", "phi", "z"},
             CoordType::Cylindrical,
             {{"alpha", 0.0, -1e300, 1e300, false, false, "polarisation angle alpha (0: Einstein-Rosen Bessel wave)"},
              {"c", 1.0, -1e300, 1e300, false, false, "amplitude C of the wave (C = 0: flat)"}},
             {TetradKind::Default},
             "Halilsoy cross-polarised standing cylindrical wave (Halilsoy, Nuovo Cimento B 102 (1988) 563; "
             "Mueller & Grave, arXiv:0904.4184)",
             Vec4{{0, 5, 0, 0}},
             {{"c", 0.0}}}) {
    on_params_changed();
  }

  /// V, A, k for any scalar type.
  template <class T>
  void functions(const T& t, const T& rho, T& V, T& A, T& k) const {
    using std::cos;
    using std::exp;
    using std::sin;
    const T J0 = bessel::j0(rho), J1 = bessel::j1(rho);
    const T c = cos(t);
    const T psi = C_ * J0 * c;
    V = ch2_ * exp(-2.0 * psi) + sh2_ * exp(2.0 * psi);
    A = -2.0 * C_ * sh2a_ * rho * J1 * sin(t);
    k = 0.5 * C_ * C_ * (rho * rho * (J0 * J0 + J1 * J1) - 2.0 * rho * J0 * J1 * c * c);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    T V, A, k;
    functions(x[0], x[1], V, A, k);
    const T Ve2k = V * exp(2.0 * k);
    g[0][0] = -Ve2k;
    g[1][1] = Ve2k;
    g[2][2] = V * x[1] * x[1] + A * A / V;
    g[2][3] = g[3][2] = A / V;
    g[3][3] = 1.0 / V;
  }

  void derivs(const Vec4& x, MetricDerivs& d) const {
    d = MetricDerivs{};
    const double rho = x[1];
    const double J0 = bessel::j0(rho), J1 = bessel::j1(rho);
    double S, c;
    fast_sincos(x[0], S, c);
    const double psi = C_ * J0 * c;
    const double em = ch2_ * std::exp(-2.0 * psi), ep = sh2_ * std::exp(2.0 * psi);
    const double V = em + ep;
    const double A = -2.0 * C_ * sh2a_ * rho * J1 * S;
    const double C2 = C_ * C_;
    const double k = 0.5 * C2 * (rho * rho * (J0 * J0 + J1 * J1) - 2.0 * rho * J0 * J1 * c * c);
    // index 0: ∂_t, 1: ∂_ρ
    const double psi_d[2] = {-C_ * J0 * S, -C_ * J1 * c};
    const double V_d[2] = {-2.0 * psi_d[0] * (em - ep), -2.0 * psi_d[1] * (em - ep)};
    const double A_d[2] = {-2.0 * C_ * sh2a_ * rho * J1 * c, -2.0 * C_ * sh2a_ * rho * J0 * S};
    const double k_d[2] = {2.0 * C2 * rho * J0 * J1 * c * S, C2 * rho * (J0 * J0 * S * S + J1 * J1 * c * c)};
    const double e2k = std::exp(2.0 * k), iV = 1.0 / V, iV2 = iV * iV;
    d.g[0][0] = -V * e2k;
    d.g[1][1] = V * e2k;
    d.g[2][2] = V * rho * rho + A * A * iV;
    d.g[2][3] = d.g[3][2] = A * iV;
    d.g[3][3] = iV;
    for (int m = 0; m < 2; ++m) {
      d.dg[m][0][0] = -(V_d[m] + 2.0 * V * k_d[m]) * e2k;
      d.dg[m][1][1] = -d.dg[m][0][0];
      d.dg[m][2][2] =
          V_d[m] * rho * rho + (m == 1 ? 2.0 * V * rho : 0.0) + 2.0 * A * A_d[m] * iV - A * A * V_d[m] * iV2;
      d.dg[m][2][3] = d.dg[m][3][2] = A_d[m] * iV - A * V_d[m] * iV2;
      d.dg[m][3][3] = -V_d[m] * iV2;
    }
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    derivs(x, d);
    christoffel_from_derivs(d, G);
  }

  /// Off the axis ρ = 0, a coordinate singularity of the cylindrical chart (Motion4D has no
  /// break condition).
  bool is_valid(const Vec4& x) const override {
    return x[1] > 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "HalilsoyWave: the natural tetrad needs rho > 0, found rho = " << x[1];
      throw Error(os.str());
    }
    double V, A, k;
    functions(x[0], x[1], V, A, k);
    const double sV = std::sqrt(V), ek = std::exp(-k) / sV;
    Tetrad e{};
    e[0][0] = ek;
    e[1][1] = ek;
    e[2][2] = 1.0 / (x[1] * sV);
    e[2][3] = -A / (x[1] * sV);
    e[3][3] = sV;
    return e;
  }

 protected:
  void on_params_changed() override {
    const double a = p(0);
    C_ = p(1);
    ch2_ = std::cosh(a) * std::cosh(a);
    sh2_ = std::sinh(a) * std::sinh(a);
    sh2a_ = std::sinh(2.0 * a);
  }

 private:
  double C_ = 1.0, ch2_ = 1.0, sh2_ = 0.0, sh2a_ = 0.0;
};

std::unique_ptr<Metric> make_metric_HalilsoyWave() { return std::make_unique<HalilsoyWave>(); }

}  // namespace geovis

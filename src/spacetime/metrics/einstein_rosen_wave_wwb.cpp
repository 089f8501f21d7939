// Einstein-Rosen cylindrical gravitational wave, Weber-Wheeler-Bonnor pulse, coordinates
// (t, ρ, φ, z):
//   ds² = e^{2(γ−ψ)} (−dt² + dρ²) + ρ² e^{−2ψ} dφ² + e^{2ψ} dz²
// (Einstein & Rosen, J. Franklin Inst. 223 (1937) 43; Weber & Wheeler, Rev. Mod. Phys. 29 (1957)
// 509; Bonnor, J. Math. Mech. 6 (1957) 203; Müller & Grave, Catalogue of Spacetimes, section
// "Einstein-Rosen wave"; Motion4D m4dMetricEinsteinRosenWaveWWB). With A = a² + ρ² − t²,
// D = A² + 4a²t² and S = √D:
//   ψ = √2 c √(S + A) / S,
//   γ = c²/(2a²) · [1 − 2a²ρ² (A² − 4a²t²)/D² + (ρ² − a² − t²)/S].
// ψ solves the cylindrical wave equation and γ follows from the vacuum field equations, so the
// Ricci tensor vanishes (checked in the tests).
//
// Christoffel symbols (derived from the line element, G = γ − ψ, E = e^{2G}):
//   Γ^t_tt = Γ^t_ρρ = Γ^ρ_tρ = G_t,  Γ^t_tρ = Γ^ρ_tt = Γ^ρ_ρρ = G_ρ,
//   Γ^t_φφ = −ψ_t ρ² e^{−2ψ}/E,  Γ^t_zz = ψ_t e^{2ψ}/E,
//   Γ^ρ_φφ = −ρ (1 − ρψ_ρ) e^{−2ψ}/E,  Γ^ρ_zz = −ψ_ρ e^{2ψ}/E,
//   Γ^φ_tφ = −ψ_t,  Γ^φ_ρφ = 1/ρ − ψ_ρ,  Γ^z_tz = ψ_t,  Γ^z_ρz = ψ_ρ.
// Natural tetrad (default only): e_(0) = e^{ψ−γ} ∂_t, e_(1) = e^{ψ−γ} ∂_ρ, e_(2) = e^{ψ}/ρ ∂_φ,
// e_(3) = e^{−ψ} ∂_z.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"

namespace geovis {

class EinsteinRosenWaveWWB final : public MetricCRTP<EinsteinRosenWaveWWB> {
 public:
  EinsteinRosenWaveWWB()
      : MetricCRTP({"EinsteinRosenWaveWWB",
                    {"t", "rho", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"a", 1.0, 0.0, 1e300, true, false, "width a > 0 of the Weber-Wheeler-Bonnor pulse"},
                     {"c", 1.0, -1e300, 1e300, false, false, "amplitude c of the pulse (c = 0: flat)"}},
                    {TetradKind::Default},
                    "Einstein-Rosen wave, Weber-Wheeler-Bonnor pulse (Weber & Wheeler, RMP 29 (1957) 509; Mueller & "
                    "Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 5, 0, 0}},
                    {{"c", 0.0}}}) {
    on_params_changed();
  }

  /// γ and ψ of the line element, generic in the scalar.
  template <class T>
  void potentials(const T& t, const T& rho, T& gam, T& psi) const {
    using std::sqrt;
    const T A = a2_ + rho * rho - t * t;
    const T a2t2 = a2_ * t * t;
    const T D = A * A + 4.0 * a2t2;
    const T S = sqrt(D);
    psi = std::sqrt(2.0) * c_ * sqrt(S + A) / S;
    gam = (0.5 * c_ * c_ / a2_) *
          (1.0 - 2.0 * a2_ * rho * rho * (A * A - 4.0 * a2t2) / (D * D) + (rho * rho - a2_ - t * t) / S);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    T gam, psi;
    potentials(x[0], x[1], gam, psi);
    const T E = exp(2.0 * (gam - psi));
    const T e2psi = exp(2.0 * psi);
    g[0][0] = -E;
    g[1][1] = E;
    g[2][2] = x[1] * x[1] / e2psi;
    g[3][3] = e2psi;
  }

  /// γ, ψ and their t- and ρ-derivatives in closed form (chain rule through A, D, S above):
  ///   ∂A = (−2t, 2ρ), ∂D = 2A∂A + 8a²t ∂t, ∂S = ∂D/(2S), u = S + A,
  ///   ∂ψ = ψ (∂u/(2u) − ∂S/S),
  ///   ∂γ = c²/(2a²) [−2a² ∂Q + ∂P/S − P ∂S/S²],  P = ρ² − a² − t², Q = ρ²B/D², B = A² − 4a²t²,
  ///   ∂Q = (∂(ρ²) B + ρ² ∂B)/D² − 2ρ²B ∂D/D³,  ∂B = 2A∂A − 8a²t ∂t.
  void potential_derivs(double t, double rho, double& gam, double& psi, double& gam_t, double& gam_r, double& psi_t,
                        double& psi_r) const {
    const double t2 = t * t, r2 = rho * rho;
    const double A = a2_ + r2 - t2;
    const double B = A * A - 4.0 * a2_ * t2;
    const double D = A * A + 4.0 * a2_ * t2;
    const double S = std::sqrt(D);
    const double u = S + A;
    const double P = r2 - a2_ - t2;
    const double Q = r2 * B / (D * D);
    psi = std::sqrt(2.0) * c_ * std::sqrt(u) / S;
    const double pref = 0.5 * c_ * c_ / a2_;
    gam = pref * (1.0 - 2.0 * a2_ * Q + P / S);
    // t-derivatives
    const double A_t = -2.0 * t, A_r = 2.0 * rho;
    const double D_t = 2.0 * A * A_t + 8.0 * a2_ * t, D_r = 2.0 * A * A_r;
    const double S_t = D_t / (2.0 * S), S_r = D_r / (2.0 * S);
    psi_t = psi * ((S_t + A_t) / (2.0 * u) - S_t / S);
    psi_r = psi * ((S_r + A_r) / (2.0 * u) - S_r / S);
    const double B_t = 2.0 * A * A_t - 8.0 * a2_ * t, B_r = 2.0 * A * A_r;
    const double D2 = D * D, D3 = D2 * D;
    const double Q_t = r2 * B_t / D2 - 2.0 * r2 * B * D_t / D3;
    const double Q_r = (2.0 * rho * B + r2 * B_r) / D2 - 2.0 * r2 * B * D_r / D3;
    const double P_t = -2.0 * t, P_r = 2.0 * rho;
    gam_t = pref * (-2.0 * a2_ * Q_t + P_t / S - P * S_t / D);
    gam_r = pref * (-2.0 * a2_ * Q_r + P_r / S - P * S_r / D);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double rho = x[1];
    double gam, psi, gam_t, gam_r, psi_t, psi_r;
    potential_derivs(x[0], rho, gam, psi, gam_t, gam_r, psi_t, psi_r);
    const double G_t = gam_t - psi_t, G_r = gam_r - psi_r;
    const double iE = std::exp(-2.0 * (gam - psi));
    const double e2psi = std::exp(2.0 * psi), em2psi = 1.0 / e2psi;
    auto set = [&G](int mu, int a, int b, double v) { G.G[mu][a][b] = G.G[mu][b][a] = v; };
    set(0, 0, 0, G_t);
    set(0, 0, 1, G_r);
    set(0, 1, 1, G_t);
    set(0, 2, 2, -psi_t * rho * rho * em2psi * iE);
    set(0, 3, 3, psi_t * e2psi * iE);
    set(1, 0, 0, G_r);
    set(1, 0, 1, G_t);
    set(1, 1, 1, G_r);
    set(1, 2, 2, -rho * (1.0 - rho * psi_r) * em2psi * iE);
    set(1, 3, 3, -psi_r * e2psi * iE);
    set(2, 0, 2, -psi_t);
    set(2, 1, 2, 1.0 / rho - psi_r);
    set(3, 0, 3, psi_t);
    set(3, 1, 3, psi_r);
  }

  /// The axis ρ = 0 is a coordinate singularity of the cylindrical chart.
  bool is_valid(const Vec4& x) const override {
    return x[1] > 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!(x[1] > 0.0)) {
      std::ostringstream os;
      os << "EinsteinRosenWaveWWB: the natural tetrad needs rho > 0, found rho = " << x[1];
      throw Error(os.str());
    }
    double gam, psi;
    potentials(x[0], x[1], gam, psi);
    const double epg = std::exp(psi - gam);
    Tetrad e{};
    e[0][0] = epg;
    e[1][1] = epg;
    e[2][2] = std::exp(psi) / x[1];
    e[3][3] = std::exp(-psi);
    return e;
  }

 protected:
  void on_params_changed() override {
    a2_ = p(0) * p(0);
    c_ = p(1);
  }

 private:
  double a2_ = 1.0, c_ = 1.0;
};

std::unique_ptr<Metric> make_metric_EinsteinRosenWaveWWB() { return std::make_unique<EinsteinRosenWaveWWB>(); }

}  // namespace geovis

// Taub-NUT spacetime in (t, r, θ, φ), G = c = 1:
//   ds² = −(Δ/Σ) (dt + 2l cosθ dφ)² + (Σ/Δ) dr² + Σ (dθ² + sin²θ dφ²),
//   Δ = r² − 2Mr − l²,  Σ = r² + l²
// Müller & Grave, Catalogue of Spacetimes (arXiv:0904.4184), section "Taub-NUT"; the sign
// convention of the dt + 2l cosθ dφ term and the static tetrad follow Motion4D's m4dMetricTaubNUT.
// The Misner strings sit on both halves of the axis (θ = 0, π). Static region: r > r+ = M + sqrt(M² + l²).
#include <cmath>
#include <string>

#include "spacetime/metric_crtp.h"

namespace geovis {

class TaubNUT final : public MetricCRTP<TaubNUT> {
 public:
  TaubNUT()
      : MetricCRTP({"TaubNUT",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"l", 0.5, -1e300, 1e300, false, false,
                      "NUT parameter l (gravitomagnetic monopole; any real, l = 0 is Schwarzschild)"},
                     {"mass", 1.0, 0.0, 1e300, false, false, "mass M >= 0 (horizon r+ = M + sqrt(M^2 + l^2))"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Taub-NUT spacetime (Mueller & Grave, Catalogue of Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {{"l", 0.0}, {"mass", 0.0}}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::cos;
    using std::sin;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T& r = x[1];
    T st, ct;
    sincos_t(x[2], st, ct);
    const T D = r * r - 2.0 * M_ * r - l_ * l_;
    const T S = r * r + l_ * l_;
    const T DS = D / S;
    g[0][0] = -DS;
    g[0][3] = g[3][0] = -2.0 * l_ * ct * DS;
    g[1][1] = S / D;
    g[2][2] = S;
    g[3][3] = S * st * st - 4.0 * l_ * l_ * ct * ct * DS;
  }

  /// Non-zero symbols (from the line element above; they agree with Motion4D's m4dMetricTaubNUT),
  /// with ρ = 2rl² + M(r² − l²) and P = r³ − 3Mr² − 3rl² + Ml² (P = 0 is the photon sphere):
  ///   Γ^t_tr = ρ/(ΣΔ), Γ^t_tθ = −2l²Δ cotθ/Σ², Γ^t_rφ = −2lP cosθ/(ΣΔ),
  ///   Γ^t_θφ = −l [cos²θ (r⁴ + 6r²l² − 8Mrl² − 3l⁴) + Σ²]/(Σ² sinθ),
  ///   Γ^r_tt = Δρ/Σ³, Γ^r_tφ = 2lρΔ cosθ/Σ³, Γ^r_rr = −ρ/(ΣΔ), Γ^r_θθ = −rΔ/Σ,
  ///   Γ^r_φφ = Δ [cos²θ (r⁵ + 2l²r³ + 9rl⁴ + 4Ml²r² − 4Ml⁴) − rΣ²]/Σ³,
  ///   Γ^θ_tφ = −lΔ sinθ/Σ², Γ^θ_rθ = r/Σ, Γ^θ_φφ = −(r⁴ + 6r²l² − 8Mrl² − 3l⁴) sinθ cosθ/Σ²,
  ///   Γ^φ_tθ = lΔ/(Σ² sinθ), Γ^φ_rφ = r/Σ, Γ^φ_θφ = (r⁴ + 4r²l² − 4Mrl² − l⁴) cotθ/Σ².
  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    G = Christoffel{};
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double l = l_, l2 = l_ * l_, l4 = l2 * l2, M = M_;
    const double r2 = r * r, r4 = r2 * r2;
    const double D = r2 - 2.0 * M * r - l2;
    const double S = r2 + l2, S2 = S * S, S3 = S2 * S;
    const double rho = 2.0 * r * l2 + M * (r2 - l2);
    const double P = r2 * r - 3.0 * M * r2 - 3.0 * r * l2 + M * l2;
    const double Q6 = r4 + 6.0 * r2 * l2 - 8.0 * M * r * l2 - 3.0 * l4;
    const double cot = ct / st;
    G.G[0][0][1] = G.G[0][1][0] = rho / (S * D);
    G.G[0][0][2] = G.G[0][2][0] = -2.0 * l2 * D * cot / S2;
    G.G[0][1][3] = G.G[0][3][1] = -2.0 * l * P * ct / (S * D);
    G.G[0][2][3] = G.G[0][3][2] = -l * (ct * ct * Q6 + S2) / (S2 * st);
    G.G[1][0][0] = D * rho / S3;
    G.G[1][0][3] = G.G[1][3][0] = 2.0 * l * rho * D * ct / S3;
    G.G[1][1][1] = -rho / (S * D);
    G.G[1][2][2] = -r * D / S;
    G.G[1][3][3] =
        D * (ct * ct * (r4 * r + 2.0 * l2 * r2 * r + 9.0 * r * l4 + 4.0 * M * l2 * r2 - 4.0 * M * l4) - r * S2) / S3;
    G.G[2][0][3] = G.G[2][3][0] = -l * D * st / S2;
    G.G[2][1][2] = G.G[2][2][1] = r / S;
    G.G[2][3][3] = -Q6 * st * ct / S2;
    G.G[3][0][2] = G.G[3][2][0] = l * D / (S2 * st);
    G.G[3][1][3] = G.G[3][3][1] = r / S;
    G.G[3][2][3] = G.G[3][3][2] = (r4 + 4.0 * r2 * l2 - 4.0 * M * r * l2 - l4) * cot / S2;
  }

  /// Outside the horizon r+ (Δ > 0, margin 1e-8) and off the axis (Misner strings).
  bool is_valid(const Vec4& x) const override {
    return x[1] > r_min_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Static observer (Δ > 0): e_(0) = sqrt(Σ/Δ) ∂_t, e_(1) = sqrt(Δ/Σ) ∂_r, e_(2) = ∂_θ/sqrt(Σ),
  /// e_(3) = (∂_φ − 2l cosθ ∂_t)/(sqrt(Σ) sinθ) (annihilated by dt + 2l cosθ dφ, hence
  /// orthogonal to e_(0)).
  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    double st, ct;
    fast_sincos(x[2], st, ct);
    if (!(r > r_plus_) || st == 0.0)
      throw Error("TaubNUT: no static observer at r = " + std::to_string(r) +
                  " (needs r > r+ = " + std::to_string(r_plus_) + " and sin(theta) != 0)");
    const double D = r * r - 2.0 * M_ * r - l_ * l_;
    const double S = r * r + l_ * l_;
    const double sS = std::sqrt(S);
    Tetrad e{};
    e[0][0] = std::sqrt(S / D);
    e[1][1] = std::sqrt(D / S);
    e[2][2] = 1.0 / sS;
    e[3][0] = -2.0 * l_ * ct / (sS * st);
    e[3][3] = 1.0 / (sS * st);
    return e;
  }

 protected:
  void on_params_changed() override {
    l_ = p(0);
    M_ = p(1);
    r_plus_ = M_ + std::sqrt(M_ * M_ + l_ * l_);                       // root of Δ = 0
    r_min_ = r_plus_ > 0.0 ? r_plus_ * (1.0 + horizon_eps_) : 1e-300;  // Metric::horizon_eps
  }

 private:
  double l_ = 0.5, M_ = 1.0, r_plus_ = 2.118, r_min_ = 2.118;
};

std::unique_ptr<Metric> make_metric_TaubNUT() { return std::make_unique<TaubNUT>(); }

}  // namespace geovis

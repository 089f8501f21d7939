// Schwarzschild spacetime in Kruskal–Szekeres coordinates (T, X, θ, φ) (Motion4D "Kruskal";
// Misner, Thorne & Wheeler (1973) eq. (31.14); Müller & Grave, Catalogue of Spacetimes,
// arXiv:0904.4184, "Schwarzschild: Kruskal–Szekeres coordinates"):
//   ds² = (4 r_s³/r) e^(−r/r_s) (−dT² + dX²) + r² (dθ² + sin²θ dφ²),  r_s = 2M,
// with the areal radius r(T, X) given implicitly by (r/r_s − 1) e^(r/r_s) = X² − T² (MTW 31.13),
// i.e. r = r_s (1 + W(u/e)), u = X² − T² (Lambert W, principal branch). The chart covers the
// maximally extended spacetime up to the singularity r = 0 at u = −1 and is regular at the horizon
// u = 0; radial light rays are T ± X = const.
//
// r(u) is found by Halley's method on ρ(u) = r/r_s, (ρ − 1) e^ρ = u; differentiating that relation,
// dρ/du = e^(−ρ)/ρ and d²ρ/du² = −e^(−2ρ) (ρ + 1)/ρ³, which carry r through automatic
// differentiation (second-order Taylor step from the double value, exact for Dual and Dual²).
// Christoffel symbols: diagonal metric (diagonal_metric.h) with F = (4 r_s³/r) e^(−r/r_s),
// h = (−F, F, r², r² sin²θ), ∂_r F = −F (r + r_s)/(r r_s), ∂_T r = −2T q, ∂_X r = 2X q,
// q = ∂r/∂u = r_s² e^(−r/r_s)/r.
// Natural tetrads: default (Motion4D localToCoord) e_(0) = ∂_T/√F, e_(1) = ∂_X/√F, e_(2) = ∂_θ/r,
// e_(3) = ∂_φ/(r sin θ) — the observer at constant X. static: Motion4D lists it but returns the
// default frame; here it is the observer along the Killing vector ∂_t = (X ∂_T + T ∂_X)/(2 r_s)
// (MTW 31.14 with t = 2 r_s artanh(T/X)), e_(0) = ±(X ∂_T + T ∂_X)/√(F u),
// e_(1) = ±(T ∂_T + X ∂_X)/√(F u) (sign of X, future pointing), only outside the horizon |X| > |T|.
// The ray stops before the singularity u = −1 where u + 1 < horizon_eps (the break margin taken on
// the function that vanishes there, as 1 − r_s/r at a Schwarzschild horizon; metric.h), i.e. at
// r ≈ r_s √(2 horizon_eps) (u + 1 = ρ²/2 + O(ρ³) for ρ = r/r_s → 0), and on the polar axis.
// Motion4D breaks at u < −1, which a ray never reaches. A margin in r itself (r < r_s·horizon_eps,
// u + 1 ≈ horizon_eps²/2, used before) is not reachable either: r comes from u = (X + T)(X − T),
// whose rounding error is ~DBL_EPSILON (X² + T²) (X² + T² ≈ 280 for a shadow ray of the gallery's
// observer at X = 20), so r carries a relative error ~DBL_EPSILON (X² + T²)/ρ², the Christoffel
// symbols (∝ T/ρ², X/ρ²) carry it into k, and the step control shrinks the steps geometrically:
// a non-radial ray from X = 20 crept from r = 2.3e-3 M to 5.4e-4 M in 66000 steps before the
// step size underflowed, and inside the gallery's shadow every ray used up its 3000 points
// (max-steps) instead of stopping at the singularity (with this margin: ~100-200 steps).
// Pseudo-Cartesian coordinates: the areal radius r with θ, φ (Motion4D transToPseudoCart); chart
// 0 for X >= 0, chart 1 for the other exterior X < 0.
#include <algorithm>
#include <cmath>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class Kruskal final : public MetricCRTP<Kruskal> {
 public:
  Kruskal()
      : MetricCRTP({"Kruskal",
                    {"T", "X", "theta", "phi"},
                    CoordType::Spherical,
                    {{"mass", 1.0, 0.0, 1e300, true, false, "mass M > 0 of the black hole (r_s = 2M)"}},
                    {TetradKind::Default, TetradKind::Static},
                    "Schwarzschild black hole in Kruskal-Szekeres coordinates (Misner, Thorne & Wheeler (1973) "
                    "31.14; Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 6, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  /// ρ = r/r_s from (ρ − 1) e^ρ = u, u >= −1: ρ = 1 + W(u/e) by Halley's iteration on
  /// w e^w = a (Corless et al., Adv. Comput. Math. 5 (1996) 329, eq. 5.9), started from the branch
  /// point series near a = −1/e, the Taylor series near 0 and the asymptotic form for large a.
  static double rho_of_u(double u) {
    if (!(u > -1.0)) return 0.0;
    const double a = u / M_E;
    double w;
    if (a < -0.25) {
      const double p = std::sqrt(2.0 * (M_E * a + 1.0));
      w = -1.0 + p - p * p / 3.0;
    } else if (a < 2.0) {
      w = a * (1.0 - a + 1.5 * a * a) / (1.0 + 2.5 * a * a);
    } else {
      const double la = std::log(a), lla = std::log(la);
      w = la - lla + lla / la;
    }
    // Halley converges cubically: after a step of size δ the error is O(δ³), so a step below
    // 1e-9 (1 + |w|) leaves an error far below the double rounding (and a test on δ ~ 1e-16 would
    // never be met reliably: δ itself is then rounding noise).
    for (int i = 0; i < 20; ++i) {
      const double ew = std::exp(w), f = w * ew - a, wp1 = w + 1.0;
      if (wp1 <= 0.0) break;
      const double dw = f / (ew * wp1 - (w + 2.0) * f / (2.0 * wp1));
      w -= dw;
      if (std::fabs(dw) <= 1e-9 * (1.0 + std::fabs(w))) break;
    }
    return 1.0 + w;
  }

  /// Areal radius r(T, X) (file comment).
  double areal_radius(double T, double X) const { return rs_ * rho_of_u((X + T) * (X - T)); }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::exp;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T u = (x[1] + x[0]) * (x[1] - x[0]);
    const double u0 = value_of(u);
    const double rho0 = rho_of_u(u0);
    const double e0 = std::exp(-rho0);
    const double d1 = e0 / rho0, d2 = -e0 * e0 * (rho0 + 1.0) / (rho0 * rho0 * rho0);
    const T du = u - u0;
    const T r = rs_ * (rho0 + d1 * du + 0.5 * d2 * du * du);
    const T F = 4.0 * rs_ * rs_ * rs_ / r * exp(-r / rs_);
    const T st = sin_t(x[2]);
    g[0][0] = -F;
    g[1][1] = F;
    g[2][2] = r * r;
    g[3][3] = r * r * st * st;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    const double T = x[0], X = x[1];
    const double r = areal_radius(T, X);
    const double ex = std::exp(-r / rs_);
    const double F = 4.0 * rs_ * rs_ * rs_ / r * ex;
    const double q = rs_ * rs_ * ex / r;
    const double drT = -2.0 * T * q, drX = 2.0 * X * q;
    const double dFdr = -F * (r + rs_) / (r * rs_);
    double st, ct;
    fast_sincos(x[2], st, ct);
    const double s2 = st * st;
    d.h[0] = -F;
    d.h[1] = F;
    d.h[2] = r * r;
    d.h[3] = r * r * s2;
    d.dh[0][0] = -dFdr * drT;
    d.dh[1][0] = -dFdr * drX;
    d.dh[0][1] = dFdr * drT;
    d.dh[1][1] = dFdr * drX;
    d.dh[0][2] = 2.0 * r * drT;
    d.dh[1][2] = 2.0 * r * drX;
    d.dh[0][3] = 2.0 * r * drT * s2;
    d.dh[1][3] = 2.0 * r * drX * s2;
    d.dh[2][3] = 2.0 * r * r * st * ct;
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_christoffel(d, G);
  }
  GEOVIS_HOT_INLINE void accel_closed(const Vec4& x, const Vec4& k, Vec4& a) const {
    DiagonalMetric d;
    diagonal(x, d);
    diagonal_accel(d, k, a);
  }

  /// Before the singularity, u + 1 > horizon_eps (file comment), and off the polar axis.
  bool is_valid(const Vec4& x) const override {
    return (x[1] + x[0]) * (x[1] - x[0]) > u_break_ && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]) && x[2] != 0.0;
  }

  /// Escape (escape.h): the spacetime is Schwarzschild, h² = r²/(1 − r_s/r) grows beyond the
  /// photon sphere r = 1.5 r_s (schwarzschild.cpp); dr/dλ = 2q (X k^X − T k^T); |p| = r.
  bool escapes(const Vec4& x, const Vec4& k, double r_min, double& radius) const {
    const double r = areal_radius(x[0], x[1]);
    const double q = rs_ * rs_ * std::exp(-r / rs_) / r;
    return escapes_spherical(r, 2.0 * q * (x[1] * k[1] - x[0] * k[0]), 1.5 * rs_, r_min, r, radius);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double T = x[0], X = x[1], u = (X + T) * (X - T);
    const double st = std::sin(x[2]);
    if (!(u > -1.0) || st == 0.0)
      throw Error("Kruskal: no observer at T = " + std::to_string(T) + ", X = " + std::to_string(X) +
                  ", theta = " + std::to_string(x[2]) + " (needs X^2 - T^2 > -1, sin(theta) != 0)");
    const double r = areal_radius(T, X);
    const double F = 4.0 * rs_ * rs_ * rs_ / r * std::exp(-r / rs_);
    Tetrad e{};
    e[2][2] = 1.0 / r;
    e[3][3] = 1.0 / (r * st);
    if (kind == TetradKind::Static) {
      if (!(u > 0.0))
        throw Error("Kruskal: no static observer at T = " + std::to_string(T) + ", X = " + std::to_string(X) +
                    " (inside the horizon, |X| <= |T|)");
      const double n = (X > 0.0 ? 1.0 : -1.0) / std::sqrt(F * u);
      e[0][0] = X * n;
      e[0][1] = T * n;
      e[1][0] = T * n;
      e[1][1] = X * n;
      return e;
    }
    const double sF = std::sqrt(F);
    e[0][0] = 1.0 / sF;
    e[1][1] = 1.0 / sF;
    return e;
  }

  int to_pseudo_cartesian(const Vec4& x, Vec3& p) const override {
    const double r = areal_radius(x[0], x[1]);
    double st, ct, sp, cp;
    fast_sincos(x[2], st, ct);
    fast_sincos(x[3], sp, cp);
    p = {r * st * cp, r * st * sp, r * ct};
    return x[1] >= 0.0 ? 0 : 1;
  }

  /// ∂p/∂(X, θ, φ) at fixed T: p = r(T, X) (sinθ cosφ, sinθ sinφ, cosθ) with the areal radius, so
  /// the X column is ∂_X r = 2X q, q = r_s² e^(−r/r_s)/r (file comment), times the radial unit
  /// vector (the default spherical Jacobian would take X for r).
  bool pseudo_cartesian_jacobian(const Vec4& x, double J[3][3]) const override {
    const double r = areal_radius(x[0], x[1]);
    const double drdX = 2.0 * x[1] * rs_ * rs_ * std::exp(-r / rs_) / r;
    const double st = std::sin(x[2]), ct = std::cos(x[2]), sp = std::sin(x[3]), cp = std::cos(x[3]);
    const double j[3][3] = {{drdX * st * cp, r * ct * cp, -r * st * sp},
                            {drdX * st * sp, r * ct * sp, r * st * cp},
                            {drdX * ct, -r * st, 0.0}};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) J[i][k] = j[i][k];
    return true;
  }

  /// T is kept; X = ±√(T² + u(r)), u = (r/r_s − 1) e^(r/r_s), on the side of the chart.
  Vec4 from_pseudo_cartesian(double T, const Vec3& p, int chart) const override {
    const double r = norm(p);
    const double th = r > 0 ? std::acos(std::clamp(p.z / r, -1.0, 1.0)) : 0.0;
    const double rho = r / rs_;
    const double X2 = T * T + (rho - 1.0) * std::exp(rho);
    const double X = (chart == 0 ? 1.0 : -1.0) * std::sqrt(std::max(X2, 0.0));
    return {{T, X, th, std::atan2(p.y, p.x)}};
  }

 protected:
  void on_params_changed() override {
    rs_ = 2.0 * p(0);
    u_break_ = horizon_eps_ - 1.0;
  }

 private:
  double rs_ = 2.0, u_break_ = -1.0;
};

std::unique_ptr<Metric> make_metric_Kruskal() { return std::make_unique<Kruskal>(); }

}  // namespace geovis

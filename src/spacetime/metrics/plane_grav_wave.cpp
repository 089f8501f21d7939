// Plane gravitational sandwich wave of finite longitudinal extension a (Motion4D "PlaneGravWave";
// Rindler, Relativity: Special, General, and Cosmological (2006), as Motion4D cites; Müller & Grave, Catalogue
// of Spacetimes, arXiv:0904.4184, "Plane gravitational wave"), coordinates (t, x, y, z), u = t − x:
//   ds² = −dt² + dx² + p(u)² dy² + q(u)² dz²,
//   p = p0, q = q0 for u < −a;  p = L e^m, q = L e^(−m) for −a <= u <= 0;  p = q = 1 − u for u > 0,
//   L = 1 − u + u³/a² + u⁴/(2a³).
// Vacuum needs p″/p + q″/q = 0 (R_uu = −(p″/p + q″/q), the only Ricci component), i.e.
// m′² = −L″/L = −6u(u + a)/(a³ L), which Motion4D solves by expanding the odd 2a-periodic
// continuation of m′ = −√(−L″/L) in a sine series with N = 2n equidistant samples on [−a, a]
// (n = `degree`):  b_k = (2/N) Σ_{i=1..N} m′(u_i) sin(kπu_i/a),  and then
//   m′ = Σ_{k=1..n−1} b_k sin(kπu/a),  m = Σ_{k=1..n−1} b_k a/(kπ) (1 − cos(kπu/a))  (m(0) = 0),
//   p0 = (1 + a/2) e^(m(−a)),  q0 = (1 + a/2) e^(−m(−a)).
// The line element is that of the truncated series (as Motion4D's), so it is vacuum only up to the
// truncation error, which shrinks with the degree (checked in the tests); p and q are C¹ at u = −a
// and u = 0 (L(−a) = 1 + a/2, L′(−a) = 0, L(0) = 1, L′(0) = −1, m(0) = m′(0) = m′(−a) = 0). After
// the wave the rays focus at u = 1 (p = q = 0), where the chart ends.
// Christoffel symbols (diagonal_metric.h) from ∂_t p² = −∂_x p² = 2pp′, p′ = (L′ + L m′) e^m,
// q′ = (L′ − L m′) e^(−m), L′ = −1 + 3u²/a² + 2u³/a³; Killing vectors ∂_y, ∂_z and ∂_t + ∂_x.
// Natural tetrad (Motion4D's): e_(0) = ∂_t, e_(1) = ∂_x, e_(2) = ∂_y/p, e_(3) = ∂_z/q.
#include <cmath>
#include <sstream>
#include <vector>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/diagonal_metric.h"

namespace geovis {

class PlaneGravWave final : public MetricCRTP<PlaneGravWave> {
 public:
  PlaneGravWave()
      : MetricCRTP({"PlaneGravWave",
                    {"t", "x", "y", "z"},
                    CoordType::Cartesian,
                    {{"degree", 30.0, 1.0, 1e6, false, false,
                      "degree n of the sine polynomial for m'(u) (truncated to an integer)"},
                     {"long_ext", 1.0, 1e-6, 1e300, false, false, "longitudinal extension a of the wave"}},
                    {TetradKind::Default},
                    "Plane gravitational sandwich wave (Rindler, Relativity (2006); Mueller & Grave, Catalogue of "
                    "Spacetimes, arXiv:0904.4184)",
                    Vec4{{0, 2, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  /// p(u), q(u) for any scalar type (piecewise; the branches compare values only).
  template <class T>
  void pq(const T& u, T& p, T& q) const {
    using std::cos;
    using std::exp;
    if (u < -a_) {
      p = T(p0_);
      q = T(q0_);
      return;
    }
    if (u > 0.0) {
      p = 1.0 - u;
      q = p;
      return;
    }
    const T L = 1.0 - u + u * u * u / (a_ * a_) + u * u * u * u / (2.0 * a_ * a_ * a_);
    T m = T(0.0);
    for (size_t k = 1; k < b_.size(); ++k) m = m + c_[k] * (1.0 - cos(w_[k] * u));
    const T em = exp(m);
    p = L * em;
    q = L / em;
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    T p, q;
    pq<T>(x[0] - x[1], p, q);
    g[0][0] = T(-1.0);
    g[1][1] = T(1.0);
    g[2][2] = p * p;
    g[3][3] = q * q;
  }

  /// p, q and their u-derivatives (file comment).
  void pq_derivs(double u, double& p, double& q, double& dp, double& dq) const {
    if (u < -a_) {
      p = p0_, q = q0_, dp = dq = 0.0;
      return;
    }
    if (u > 0.0) {
      p = q = 1.0 - u;
      dp = dq = -1.0;
      return;
    }
    const double a2 = a_ * a_, a3 = a2 * a_;
    const double L = 1.0 - u + u * u * u / a2 + u * u * u * u / (2.0 * a3);
    const double dL = -1.0 + 3.0 * u * u / a2 + 2.0 * u * u * u / a3;
    double m = 0.0, dm = 0.0;
    for (size_t k = 1; k < b_.size(); ++k) {
      double s, c;
      fast_sincos(w_[k] * u, s, c);
      m += c_[k] * (1.0 - c);
      dm += b_[k] * s;
    }
    const double em = std::exp(m);
    p = L * em;
    q = L / em;
    dp = (dL + L * dm) * em;
    dq = (dL - L * dm) / em;
  }

  void diagonal(const Vec4& x, DiagonalMetric& d) const {
    d = DiagonalMetric{};
    double p, q, dp, dq;
    pq_derivs(x[0] - x[1], p, q, dp, dq);
    d.h[0] = -1.0;
    d.h[1] = 1.0;
    d.h[2] = p * p;
    d.h[3] = q * q;
    d.dh[0][2] = 2.0 * p * dp;
    d.dh[1][2] = -2.0 * p * dp;
    d.dh[0][3] = 2.0 * q * dq;
    d.dh[1][3] = -2.0 * q * dq;
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

  /// Before the focal plane u = 1 of the wave (Motion4D stops at u >= 1 − 1e-6).
  bool is_valid(const Vec4& x) const override {
    return x[0] - x[1] < 1.0 - 1e-6 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) &&
           std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "PlaneGravWave: no tetrad at u = t - x = " << x[0] - x[1] << " (the chart ends at u = 1)";
      throw Error(os.str());
    }
    double p, q, dp, dq;
    pq_derivs(x[0] - x[1], p, q, dp, dq);
    Tetrad e{};
    e[0][0] = 1.0;
    e[1][1] = 1.0;
    e[2][2] = 1.0 / p;
    e[3][3] = 1.0 / q;
    return e;
  }

 protected:
  void on_params_changed() override {
    a_ = p(1);
    const int n = static_cast<int>(p(0));
    const int N = 2 * n;
    // m′ at u_i = −a + i a/n, i = 0..N, continued oddly to u > 0 (file comment).
    std::vector<double> dm(N + 1);
    const double a3 = a_ * a_ * a_;
    for (int i = 0; i <= N; ++i) {
      const double u = -a_ + i * a_ / n, v = -std::fabs(u);
      const double L = 1.0 - v + v * v * v / (a_ * a_) + v * v * v * v / (2.0 * a3);
      const double w = -6.0 * v * (v + a_) / (a3 * L);  // −L″/L >= 0 on [−a, 0]
      dm[i] = (u <= 0.0 ? -1.0 : 1.0) * std::sqrt(std::max(w, 0.0));
    }
    b_.assign(n, 0.0);
    c_.assign(n, 0.0);
    w_.assign(n, 0.0);
    for (int k = 1; k < n; ++k) {
      w_[k] = k * M_PI / a_;
      double s = 0;
      for (int i = 1; i <= N; ++i) s += dm[i] * std::sin(w_[k] * (-a_ + i * a_ / n));
      b_[k] = 2.0 / N * s;
      c_[k] = b_[k] / w_[k];
    }
    double m0 = 0.0;
    for (int k = 1; k < n; ++k) m0 += c_[k] * (1.0 - std::cos(k * M_PI));
    p0_ = (1.0 + 0.5 * a_) * std::exp(m0);
    q0_ = (1.0 + 0.5 * a_) * std::exp(-m0);
  }

 private:
  double a_ = 1.0, p0_ = 1.5, q0_ = 1.5;
  std::vector<double> b_, c_, w_;  ///< b_k, b_k a/(kπ), kπ/a for k = 1..n−1 (index 0 unused)
};

std::unique_ptr<Metric> make_metric_PlaneGravWave() { return std::make_unique<PlaneGravWave>(); }

}  // namespace geovis

// Hartle–Thorne spacetime of a slowly rotating, slightly deformed body in the quasi-Kerr form of
// Glampedakis & Babak (Motion4D "HartleThorneGB"; J. B. Hartle & K. S. Thorne, ApJ 153 (1968) 807;
// K. Glampedakis & S. Babak, Class. Quantum Grav. 23 (2006) 4167, eq. (7) ff.), coordinates
// (t, r, θ, φ): Kerr plus the Hartle–Thorne quadrupole deviation with ε = η a², η measuring the
// quadrupole moment's deviation from Kerr's in units of a² (Motion4D's metric components are
// exactly those of quasi_kerr.h with this ε). Line element, derivatives and tetrad:
// spacetime/metrics/quasi_kerr.h.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/quasi_kerr.h"

namespace geovis {

class HartleThorneGB final : public MetricCRTP<HartleThorneGB> {
 public:
  HartleThorneGB()
      : MetricCRTP({"HartleThorneGB",
                    {"t", "r", "theta", "phi"},
                    CoordType::Spherical,
                    {{"angmom", 0.0, -1e300, 1e300, false, false, "Kerr parameter a"},
                     {"eta", 0.0, -1e300, 1e300, false, false, "quadrupole deviation eta (epsilon = eta a^2)"},
                     {"mass", 1.0, 0.0, 1e300, true, false, "mass M > 0"}},
                    {TetradKind::Default},
                    "Hartle-Thorne in quasi-Kerr form (Hartle & Thorne, ApJ 153 (1968) 807; Glampedakis & Babak, CQG "
                    "23 (2006) 4167)",
                    Vec4{{0, 10, M_PI / 2, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    quasi_kerr::metric(M_, a_, a2_, eps_, x, g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    quasi_kerr::derivs(M_, a_, a2_, eps_, x, d);
    christoffel_from_derivs(d, G);
  }

  /// Motion4D's break condition: outside r = 2M (here with the horizon_eps margin; the deviation
  /// diverges there through ln(r/(r − 2M))), off the axis, and where g_rr, g_θθ > 0 and the (t, φ)
  /// block is Lorentzian (g_tφ² − g_tt g_φφ > 0; a large deviation can spoil the signature).
  bool is_valid(const Vec4& x) const override {
    if (!(x[1] > r_break_ && std::isfinite(x[0]) && std::isfinite(x[2]) && std::isfinite(x[3]) &&
          std::sin(x[2]) != 0.0))
      return false;
    Mat4 g;
    g_tmpl(x, g);
    return g[1][1] > 0.0 && g[2][2] > 0.0 && g[0][3] * g[0][3] - g[0][0] * g[3][3] > 0.0;
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    Mat4 g;
    if (is_valid(x)) g_tmpl(x, g);
    if (!is_valid(x) || !(g[0][0] < 0.0)) {
      std::ostringstream os;
      os << "HartleThorneGB: no static observer at (r, theta) = (" << x[1] << ", " << x[2]
         << ") (needs r > 2M, a Lorentzian metric and g_tt < 0)";
      throw Error(os.str());
    }
    return quasi_kerr::static_tetrad(g);
  }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    a2_ = a_ * a_;
    eps_ = p(1) * a2_;
    M_ = p(2);
    r_break_ = 2.0 * M_ * (1.0 + horizon_eps_);
  }

 private:
  double a_ = 0.0, a2_ = 0.0, eps_ = 0.0, M_ = 1.0, r_break_ = 2.0002;
};

std::unique_ptr<Metric> make_metric_HartleThorneGB() { return std::make_unique<HartleThorneGB>(); }

}  // namespace geovis

// Alcubierre warp drive with Alcubierre's tanh shape function (Motion4D "AlcubierreWarp"),
// coordinates (t, x, y, z):
//   ds² = −dt² + (dx − v_s f(r_s) dt)² + dy² + dz²,  r_s = √((x − v_s t)² + y² + z²),
//   f(r_s) = [tanh(σ(r_s + R)) − tanh(σ(r_s − R))]/(2 tanh σR)
// (Alcubierre, Class. Quantum Grav. 11 (1994) L73, eq. (8) and its shape function; Müller & Grave, Catalogue of
// Spacetimes, arXiv:0904.4184, "Alcubierre warp drive"). With tanh a − tanh b =
// sinh(a − b)/(cosh a cosh b) and sinh 2σR/(2 tanh σR) = cosh²σR the shape function is evaluated
// without cancellation as
//   f = cosh²σR/(cosh²σr_s + sinh²σR),  f′ = df/dr_s = −σ sinh(2σr_s) f²/cosh²σR
// (the same function as Motion4D's alternative branch of calcF). The difference form of the
// definition loses all digits of f′ where both tanh are 1 to double precision (σ|r_s ± R| > 19),
// although f′/f stays −2σ there. Beyond σ(r_s − R) > 300, f < e^(−600): flat, all Γ vanish; the
// sharpness is limited to σR <= 50 (a wall 1/50 of the radius thick) so that cosh²σr_s stays
// finite up to that cut.
// Line element, Christoffel symbols and tetrads: spacetime/metrics/alcubierre.h.
// Motion4D's resize for this metric projects k back onto the null cone (it recomputes k^t from
// g(k,k) = 0 whenever the constraint drifts); geovis does not: the constraint is the measure of
// the integration error (test NullGeodesicKeepsItsConstraint), not something to be enforced.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/alcubierre.h"

namespace geovis {

class AlcubierreWarp final : public MetricCRTP<AlcubierreWarp> {
 public:
  AlcubierreWarp()
      : MetricCRTP(
            {"AlcubierreWarp",
             {"t", "x", "y", "z"},
             CoordType::Cartesian,
             {{"r", 1.0, 0.0, 1e300, true, false, "radius R > 0 of the warp bubble"},
              {"sigma", 8.0, 0.0, 1e300, true, false, "sharpness sigma > 0 of the bubble wall"},
              {"vs", 1.0, -1e300, 1e300, false, false, "velocity v_s of the warp bubble along x (may exceed 1)"}},
             {TetradKind::Default, TetradKind::Comoving, TetradKind::Static},
             "Alcubierre warp drive with tanh wall (Alcubierre, CQG 11 (1994) L73)",
             Vec4{{0, 0, -10, 0}},
             {{"vs", 0.0}}}) {
    on_params_changed();
  }

  /// f(r_s) for any scalar type (file comment).
  template <class T>
  T shape(const T& rs) const {
    using std::cosh;
    if (sigma_ * rs > kFlat + sR_) return T(0.0);
    const T c = cosh(sigma_ * rs);
    return ch2_ / (c * c + sh2_);
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    using std::sqrt;
    const T X = x[1] - vs_ * x[0];
    alcubierre::metric(vs_ * shape<T>(sqrt(X * X + x[2] * x[2] + x[3] * x[3])), g);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    const double X = x[1] - vs_ * x[0];
    const double rs = std::sqrt(X * X + x[2] * x[2] + x[3] * x[3]);
    if (sigma_ * rs > kFlat + sR_) {
      G = Christoffel{};
      return;
    }
    const double f = shape<double>(rs);
    // f′/r_s = −σ (sinh 2σr_s / r_s) f²/cosh²σR, with sinh 2σr_s/r_s -> 2σ at the centre.
    const double s = rs > 0.0 ? std::sinh(2.0 * sigma_ * rs) / rs : 2.0 * sigma_;
    const double df_rs = -sigma_ * s * f * f / ch2_;
    alcubierre::christoffel(vs_, f, df_rs * X, df_rs * x[2], df_rs * x[3], G);
  }

  /// Regular everywhere (Motion4D has no break condition).
  bool is_valid(const Vec4& x) const override {
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double X = x[1] - vs_ * x[0];
    const double vf = vs_ * shape<double>(std::sqrt(X * X + x[2] * x[2] + x[3] * x[3]));
    Tetrad e;
    if (!alcubierre::tetrad(vf, kind == TetradKind::Comoving, e)) {
      std::ostringstream os;
      os << "AlcubierreWarp: no static observer at (" << x[0] << ", " << x[1] << ", " << x[2] << ", " << x[3]
         << "): v_s f = " << vf << " (|v_s f| >= 1, d/dt is not timelike here); use the comoving frame";
      throw Error(os.str());
    }
    return e;
  }

 protected:
  void on_params_changed() override {
    const double R = p(0);
    sigma_ = p(1);
    vs_ = p(2);
    sR_ = sigma_ * R;
    if (!(sR_ <= kSharpest)) {
      std::ostringstream os;
      os << "AlcubierreWarp: sigma R = " << sR_ << " must not exceed " << kSharpest
         << " (cosh^2(sigma r_s) would overflow within the bubble's reach)";
      throw Error(os.str());
    }
    const double c = std::cosh(sR_), s = std::sinh(sR_);
    ch2_ = c * c;
    sh2_ = s * s;
  }

 private:
  /// σ(r_s − R) beyond which f < e^(−2·kFlat) is zero in double precision (and cosh would overflow).
  static constexpr double kFlat = 300.0;
  /// Largest σR: cosh²(σr_s) <= cosh²(kFlat + kSharpest) stays below the double range.
  static constexpr double kSharpest = 50.0;
  double sigma_ = 8.0, vs_ = 1.0, sR_ = 8.0, ch2_ = 1.0, sh2_ = 0.0;
};

std::unique_ptr<Metric> make_metric_AlcubierreWarp() { return std::make_unique<AlcubierreWarp>(); }

}  // namespace geovis

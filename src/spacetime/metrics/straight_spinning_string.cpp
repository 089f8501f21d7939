// Straight spinning cosmic string in cylindrical coordinates (t, ρ, φ, z) (Motion4D
// "StraightSpinningString"; Deser, Jackiw & 't Hooft, Ann. Phys. 152 (1984) 220; Mazur, PRL 57
// (1986) 929; Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Straight spinning string"):
//   ds² = −(dt − a dφ)² + dρ² + k² ρ² dφ² + dz²,
// i.e. g_tt = −1, g_tφ = a, g_φφ = k² ρ² − a²: locally flat off the string (Riemann = 0), with a
// conical deficit 2π(1 − k) and a helical time shift 2πa around it. Closed timelike curves exist
// where g_φφ < 0, ρ < |a|/k. Christoffel symbols from the hand-written ∂_ρ g_φφ = 2 k² ρ
// (metric_derivs.h). Natural tetrads (Motion4D localToCoord):
//   default/static: e_(0) = ∂_t, e_(2) = (a ∂_t + ∂_φ)/(k ρ);
//   lnrf (zero angular momentum, ρ > |a|/k): e_(0) = (w/(k ρ)) ∂_t − a/(w k ρ) ∂_φ, e_(2) = ∂_φ/w,
//   w = √(k² ρ² − a²); e_(1) = ∂_ρ, e_(3) = ∂_z.
// Motion4D has no break condition; we stop on the string ρ = 0.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class StraightSpinningString final : public MetricCRTP<StraightSpinningString> {
 public:
  StraightSpinningString()
      : MetricCRTP({"StraightSpinningString",
                    {"t", "rho", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"a", 1.0, -1e300, 1e300, false, false, "angular momentum parameter a (time shift 2 pi a)"},
                     {"k", 0.5, 0.0, 1e300, true, false, "cone factor k > 0 (deficit angle 2 pi (1 - k))"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::LNRF},
                    "straight spinning cosmic string (Deser, Jackiw & 't Hooft, Ann. Phys. 152 (1984) 220; "
                    "Mueller & Grave, arXiv:0904.4184)",
                    Vec4{{0, 5, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    g[0][0] = T(-1.0);
    g[0][2] = g[2][0] = T(a_);
    g[1][1] = T(1.0);
    g[2][2] = k_ * k_ * x[1] * x[1] - a_ * a_;
    g[3][3] = T(1.0);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    g_tmpl(x, d.g);
    d.dg[1][2][2] = 2.0 * k_ * k_ * x[1];
    christoffel_from_derivs(d, G);
  }

  /// Off the string ρ = 0.
  bool is_valid(const Vec4& x) const override {
    return x[1] != 0.0 && std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double rho = std::fabs(x[1]), kr = k_ * rho;
    Tetrad e{};
    e[1][1] = 1.0;
    e[3][3] = 1.0;
    if (kind == TetradKind::LNRF) {
      const double w2 = kr * kr - a_ * a_;
      if (!(w2 > 0.0)) {
        std::ostringstream os;
        os << "StraightSpinningString: no locally non-rotating observer at rho = " << x[1]
           << " (needs rho > |a|/k = " << std::fabs(a_) / k_ << ")";
        throw Error(os.str());
      }
      const double w = std::sqrt(w2);
      e[0][0] = w / kr;
      e[0][2] = -a_ / (w * kr);
      e[2][2] = 1.0 / w;
      return e;
    }
    if (!(kr > 0.0)) throw Error("StraightSpinningString: no static observer on the string rho = 0");
    e[0][0] = 1.0;
    e[2][0] = a_ / kr;
    e[2][2] = 1.0 / kr;
    return e;
  }

 protected:
  void on_params_changed() override {
    a_ = p(0);
    k_ = p(1);
  }

 private:
  double a_ = 1.0, k_ = 0.5;
};

std::unique_ptr<Metric> make_metric_StraightSpinningString() { return std::make_unique<StraightSpinningString>(); }

}  // namespace geovis

// Minkowski spacetime seen from a rotating lattice (Motion4D "MinkowskiRotLattice", getMetricName
// "RotLattice"), cylindrical coordinates (t, r, φ, z) co-rotating with angular velocity ω
// (φ = φ_inertial − ω t; Rindler, Relativity: Special, General, and Cosmological (2006) §9.8;
// Müller & Grave, Catalogue of Spacetimes, arXiv:0904.4184, "Minkowski: rotating coordinates"):
//   ds² = −(1 − ω² r²) dt² + 2 ω r² dt dφ + dr² + r² dφ² + dz².
// Flat for every ω; the lattice exists inside the light cylinder r < 1/|ω| (Motion4D
// breakCondition r >= 1/|ω|). Christoffel symbols from the hand-written ∂_r g (metric_derivs.h):
// ∂_r g_tt = 2ω² r, ∂_r g_tφ = 2ω r, ∂_r g_φφ = 2r.
// Natural tetrads (Motion4D localToCoord), s = √(1 − ω² r²):
//   default/static (observer at rest on the lattice): e_(0) = ∂_t/s, e_(2) = (ω r/s) ∂_t + (s/r) ∂_φ;
//   lnrf (the inertial observer, non-rotating): e_(0) = ∂_t − ω ∂_φ, e_(2) = ∂_φ/r;
//   e_(1) = ∂_r, e_(3) = ∂_z in both.
#include <cmath>
#include <sstream>

#include "spacetime/metric_crtp.h"
#include "spacetime/metrics/metric_derivs.h"

namespace geovis {

class MinkowskiRotLattice final : public MetricCRTP<MinkowskiRotLattice> {
 public:
  MinkowskiRotLattice()
      : MetricCRTP({"MinkowskiRotLattice",
                    {"t", "r", "phi", "z"},
                    CoordType::Cylindrical,
                    {{"omega", 0.0, -1e300, 1e300, false, false,
                      "angular velocity omega of the lattice (light cylinder at r = 1/|omega|)"}},
                    {TetradKind::Default, TetradKind::Static, TetradKind::LNRF},
                    "Minkowski spacetime in rotating cylindrical coordinates (Rindler (2006) 9.8; Mueller & Grave, "
                    "arXiv:0904.4184)",
                    Vec4{{0, 1, 0, 0}},
                    {}}) {
    on_params_changed();
  }

  template <class T>
  void g_tmpl(const Vec4T<T>& x, Mat4T<T>& g) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) g[i][j] = T(0.0);
    const T r2 = x[1] * x[1];
    g[0][0] = -1.0 + w_ * w_ * r2;
    g[0][2] = g[2][0] = w_ * r2;
    g[1][1] = T(1.0);
    g[2][2] = r2;
    g[3][3] = T(1.0);
  }

  void christoffel_closed(const Vec4& x, Christoffel& G) const {
    MetricDerivs d;
    g_tmpl(x, d.g);
    const double r = x[1];
    d.dg[1][0][0] = 2.0 * w_ * w_ * r;
    d.dg[1][0][2] = d.dg[1][2][0] = 2.0 * w_ * r;
    d.dg[1][2][2] = 2.0 * r;
    christoffel_from_derivs(d, G);
  }

  /// Inside the light cylinder |ω| r < 1, off the axis.
  bool is_valid(const Vec4& x) const override {
    return x[1] != 0.0 && std::fabs(w_ * x[1]) < 1.0 && std::isfinite(x[0]) && std::isfinite(x[1]) &&
           std::isfinite(x[2]) && std::isfinite(x[3]);
  }

  Tetrad natural_tetrad(const Vec4& x, TetradKind kind) const override {
    require_tetrad_kind(kind);
    const double r = x[1];
    if (!is_valid(x)) {
      std::ostringstream os;
      os << "MinkowskiRotLattice: no lattice observer at r = " << r << " (needs 0 < |r| < 1/|omega|)";
      throw Error(os.str());
    }
    Tetrad e{};
    e[1][1] = 1.0;
    e[3][3] = 1.0;
    if (kind == TetradKind::LNRF) {
      e[0][0] = 1.0;
      e[0][2] = -w_;
      e[2][2] = 1.0 / r;
      return e;
    }
    const double s = std::sqrt(1.0 - w_ * w_ * r * r);
    e[0][0] = 1.0 / s;
    e[2][0] = w_ * r / s;
    e[2][2] = s / r;
    return e;
  }

 protected:
  void on_params_changed() override { w_ = p(0); }

 private:
  double w_ = 0.0;
};

std::unique_ptr<Metric> make_metric_MinkowskiRotLattice() { return std::make_unique<MinkowskiRotLattice>(); }

}  // namespace geovis

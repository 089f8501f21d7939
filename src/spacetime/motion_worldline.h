// A user-given worldline (GeoViS `init-motion '(type "file")`, whose GvsStMotionWorldline was
// left out of the GeoViS build; Motion4D FermiWalker "along a given worldline"): a list of events
// x_i (optionally with a curve parameter p_i, e.g. the proper times of a file with `havetau`),
// interpolated by a natural cubic spline in p (p = x^0 when no parameter is given). Proper time
// is τ(p) = τ0 + ∫ √(−g(x', x')) dp (5-point Gauss-Legendre per interval), the four-velocity
// u = x'/√(−g(x',x')), the four-acceleration a = P_⊥(x'' + Γ(x', x'))/(−g(x',x')) (P_⊥ projects
// orthogonally to u), and the tetrad is Fermi-Walker transported (spacetime/transport.h) from the
// first event, where it is the given frame boosted to u.
#pragma once

#include <vector>

#include "spacetime/motion_sampled.h"
#include "spacetime/transport.h"

namespace geovis {

class WorldlineMotion final : public SampledMotion {
 public:
  /// events: at least 2; params: empty (use x^0) or one strictly increasing value per event.
  /// frame: reference tetrad at events[0] (e.g. a natural tetrad, or a user tetrad); it is boosted
  /// so that e_(0) = u there (tetrad_for_four_velocity). Throws Error for too few events, a
  /// parameter that does not increase, a spacelike or null segment, or an invalid position.
  WorldlineMotion(std::shared_ptr<const Metric> metric, std::vector<Vec4> events, std::vector<double> params,
                  const Tetrad& frame, double tau0 = 0.0, const FermiWalkerConfig& fw = {});

  const char* type_name() const override { return "Worldline"; }
  /// Position, four-velocity and four-acceleration at proper time tau (from the spline).
  WorldlineState state_at(double tau) const;

 private:
  WorldlineState state_at_param(double p) const;
  double param_at(double tau) const;  ///< inverse of τ(p)
  void spline_eval(double p, Vec4& x, Vec4& dx, Vec4& ddx) const;

  std::vector<double> p_;    ///< curve parameter at the events
  std::vector<Vec4> x_;      ///< events
  std::vector<Vec4> m2_;     ///< spline second derivatives d²x/dp² at the events
  std::vector<double> tau_;  ///< proper time at the events
};

}  // namespace geovis

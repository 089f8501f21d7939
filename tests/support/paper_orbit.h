// The circular geodesic orbit at r = 6M in Schwarzschild of paper §3 (init-motion), with more
// points and a longer forward range (one full orbit): a sampled motion with analytic properties
// (period 92.3436, geodetic precession), shared by the motion and local-object tests.
#pragma once

#include <cmath>
#include <vector>

#include "core/params.h"
#include "spacetime/geodesic.h"

namespace geovis::testing_support {

/// theta: the start's θ (sphereAroundBlackhole.scm writes 1.5707963); forward, backward: the
/// proper-time range.
inline ParamSet paper_orbit_params(double forward = 70.0, double backward = 10.0, double theta = M_PI / 2) {
  ParamSet ps("init-motion", SourceLoc{"orbit.scm", 20});
  ps.add("type", "Geodesic");
  ps.add("pos", std::vector<double>{0.0, 6.0, theta, 0.0});
  ps.add("localvel", std::vector<double>{0.0, 0.0, 0.5});
  ps.add("e0", std::vector<double>{1, 0, 0, 0});
  ps.add("e1", std::vector<double>{0, 0, -1, 0});
  ps.add("e2", std::vector<double>{0, 0, 0, -1});
  ps.add("e3", std::vector<double>{0, 1, 0, 0});
  ps.add("maxnumpoints", 1000);
  ps.add("forward", forward);
  ps.add("backward", backward);
  return ps;
}

/// A radial free fall in Schwarzschild from rest at r = 10M in the equatorial plane (init-motion,
/// fallEddFinkIn.scm's start), over the proper time `forward` with `points` points.
inline ParamSet radial_fall_params(int points, double forward, SourceLoc loc = SourceLoc{"fall.scm", 1}) {
  ParamSet ps("init-motion", loc);
  ps.add("type", "Geodesic");
  ps.add("pos", std::vector<double>{0.0, 10.0, M_PI / 2, 0.0});
  ps.add("localvel", std::vector<double>{0, 0, 0});
  ps.add("maxnumpoints", points);
  ps.add("forward", forward);
  return ps;
}

inline SolverConfig paper_solver() {
  SolverConfig cfg;  // paper §3: GSL_RK_Cash-Karp, step_ctrl #f, step_size 0.1
  cfg.kind = SolverKind::CashKarp45;
  cfg.step_ctrl = false;
  cfg.step_size = 0.1;
  cfg.eps_abs = 0.01;
  return cfg;
}

}  // namespace geovis::testing_support

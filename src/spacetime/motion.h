// Motions of local reference frames (paper §2.3, catalogue §8): a worldline with a tetrad at each
// point — a timelike geodesic with parallel-transported tetrad, uniform motion in Minkowski, or a
// user-given worldline with Fermi-Walker transport.
#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "spacetime/metric.h"

namespace geovis {

struct MotionSample {
  double tau = 0;        ///< proper time
  Vec4 x{{0, 0, 0, 0}};  ///< position (metric coordinates)
  Vec4 u{{0, 0, 0, 0}};  ///< four-velocity dx/dτ (= e(0))
  Tetrad e{};            ///< local tetrad e_(a)^μ, e_(0) = u
};

class Motion {
 public:
  virtual ~Motion() = default;
  /// State at proper time tau (interpolated between samples to integration precision).
  virtual MotionSample at_proper_time(double tau) const = 0;
  /// Event x and four-velocity u = e_(0) at proper time τ, the same values as at_proper_time
  /// without the spatial axes (what a simultaneity search needs; sampled motions skip
  /// interpolating and orthonormalizing e_(1..3)).
  virtual void event_at_proper_time(double tau, Vec4& x, Vec4& u) const {
    const MotionSample s = at_proper_time(tau);
    x = s.x;
    u = s.e[0];
  }
  /// State at the event of the worldline whose coordinate time x^0 equals t.
  virtual MotionSample at_coordinate_time(double t) const = 0;
  /// Samples (GeoViS `actualpos N` of a projector with a motion picks sample N).
  virtual const std::vector<MotionSample>& samples() const = 0;
  double tau_min() const { return samples().front().tau; }
  double tau_max() const { return samples().back().tau; }
  /// gvs-print-motion: one line per sample "tau x0 x1 x2 x3 u0 u1 u2 u3 e0^0..e3^3".
  void write(std::ostream& os) const;
  /// Scene name of the motion type ("Geodesic", "ConstVelocity", "Worldline").
  virtual const char* type_name() const { return "Motion"; }
  /// True when at_proper_time/at_coordinate_time are defined for every τ/t (analytic motions);
  /// false when only [tau_min, tau_max] was computed (they throw Error outside).
  virtual bool unbounded() const { return false; }
};

using MotionPtr = std::shared_ptr<Motion>;

}  // namespace geovis

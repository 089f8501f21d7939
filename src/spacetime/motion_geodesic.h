// GeoViS `init-motion '(type "Geodesic")` (GvsStMotionGeodesic; paper §2.3, §3, §4.1): a local
// reference frame moving freely along a timelike geodesic, its tetrad parallel-transported
// (GeodesicSystem::Transport). Integrated from proper time tau0 forward by `forward` and backward
// by `backward` (proper-time ranges), each direction with at most max_points samples (including
// the start) — one per accepted integrator step, so `step_ctrl #f` gives uniform proper-time
// sampling with `step_size`.
#pragma once

#include "spacetime/motion_sampled.h"

namespace geovis {

class GeodesicMotion final : public SampledMotion {
 public:
  /// e: initial tetrad at pos in coordinates, e_(0) = initial four-velocity (see build_tetrad for
  /// the GeoViS `localvel`/e0..e3 convention). Throws Error for an invalid position, a tetrad that
  /// is not orthonormal (to 1e-8), forward/backward < 0 or max_points < 2.
  GeodesicMotion(std::shared_ptr<const Metric> metric, const SolverConfig& solver, const Vec4& pos, const Tetrad& e,
                 double tau0, double forward, double backward, int max_points);

  const char* type_name() const override { return "Geodesic"; }
  /// Why the forward/backward integration ended (LambdaMax when the full range was covered).
  StopReason forward_stop() const { return forward_stop_; }
  StopReason backward_stop() const { return backward_stop_; }

 private:
  StopReason forward_stop_ = StopReason::None, backward_stop_ = StopReason::None;
};

}  // namespace geovis

// Builds motions from `init-motion` parameter sets (catalogue §1, §8; paper §3):
//   Geodesic      — pos, localvel | vel, e0..e3, incoords, localframe, tau0, forward, backward,
//                   maxnumpoints, stepsize; the solver (`solver` key) is resolved by the caller
//                   and passed in;
//   ConstVelocity — boost #(vx vy vz) and rotation #(ω ax ay az), repeatable, applied in order
//                   (to Minkowski coordinates; in another metric to the pseudo-Cartesian
//                   coordinates of the ray, as GeoViS);
//   Worldline (GeoViS "file") — events from `points` (list of #(x0 x1 x2 x3), or
//                   #(tau x0 x1 x2 x3) with havetau #t) or `filename` (one event per line, same
//                   columns, '#' starts a comment); frame e0..e3/incoords/localframe at the first
//                   event, Fermi-Walker transported; tau0.
// `id`, `metric` and `solver` are read by the scene builder, not here.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "core/type_registry.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"
#include "spacetime/motion.h"

namespace geovis {

class ParamReader;

/// The description of a motion type (core/type_registry.h), registered beside its class
/// (motion_geodesic.cpp, motion_const_velocity.cpp, motion_worldline.cpp).
struct MotionType : TypeDescription {
  /// The motion from its keys (absent keys read as their defaults).
  MotionPtr (*make)(const ParamReader& keys, std::shared_ptr<const Metric> metric,
                    const SolverConfig& solver) = nullptr;
  bool needs_metric = true;  ///< false: defined without a spacetime (ConstVelocity acts on Minkowski coordinates)
};
using MotionRegistry = TypeRegistry<MotionType>;

/// Keys of a motion's local frame at its start: e0..e3, incoords, localframe, tau0 (Geodesic and
/// Worldline).
std::vector<ParamSpec> motion_frame_specs();
/// The last three components of vector key p, which must have n finite numbers (all n in `out`);
/// otherwise a SceneError naming the key.
Vec3 motion_vector_key(const Param& p, const ParamSet& ps, size_t n, std::vector<double>& out);

/// Valid `type` values (sorted; the alias "file" of Worldline is accepted too).
std::vector<std::string> motion_type_names();

/// Keys accepted by init-motion of the given type (for ParamSet::validate). Unknown type ->
/// SceneError-free: returns the common keys.
std::vector<ParamSpec> motion_param_specs(const std::string& type);

/// Creates the motion; every problem is a SceneError "file:line: init-motion: key: ...", an
/// unknown type names the closest valid one.
MotionPtr make_motion(const ParamSet& ps, std::shared_ptr<const Metric> metric, const SolverConfig& solver);

}  // namespace geovis

// Geodesic integration API: solver configuration, state layouts, stop reasons and the
// per-accepted-step callback. The integrators themselves are templates in
// spacetime/integrators.h, instantiated once per metric (spacetime/metric_crtp.h) so that the
// Christoffel symbols are inlined into every Runge-Kutta stage: no virtual call and no heap
// allocation per stage; dispatch happens once per geodesic.
#pragma once

#include <cfloat>
#include <limits>
#include <string>
#include <vector>

#include "core/function_ref.h"
#include "spacetime/vec.h"

namespace geovis {

enum class GeodesicType { Lightlike, Timelike, Spacelike };
/// Value of g(k,k) the constraint keeps: 0 lightlike, -1 timelike, +1 spacelike (signature -+++).
constexpr double constraint_target(GeodesicType t) {
  return t == GeodesicType::Lightlike ? 0.0 : (t == GeodesicType::Timelike ? -1.0 : 1.0);
}
const char* geodesic_type_name(GeodesicType t);
GeodesicType parse_geodesic_type(const std::string& s);  ///< throws Error listing valid names

/// Our integrators (catalogue §13 maps GeoViS/Motion4D names onto these).
enum class SolverKind {
  RK2,                  ///< Heun-Euler embedded 2(1)
  RK4,                  ///< classical Runge-Kutta, fixed step
  CashKarp45,           ///< Cash & Karp (1990) embedded 4(5)
  Fehlberg45,           ///< Runge-Kutta-Fehlberg 4(5)
  DormandPrince54,      ///< Dormand & Prince (1980) 5(4), FSAL
  DormandPrince853,     ///< Hairer's DOP853: 8th order, 5th and 3rd order error estimate
  BulirschStoer,        ///< Gragg-Bulirsch-Stoer extrapolation with modified midpoint
  RungeKuttaNystrom86,  ///< Dormand-El-Mikkawy-Prince RKN 8(6): y'' = f(y) only (separable Kerr equations)
};

struct SolverInfo {
  std::string name;  ///< name accepted in scenes (GeoViS nickname or ours)
  SolverKind kind;
  std::string description;
};
/// Every accepted solver name: each integrator of the registry (spacetime/solver_type.h), then its GeoViS names.
const std::vector<SolverInfo>& solver_names();
/// Looks up a solver by name (exact, then case-insensitive); unknown -> Error listing valid names
/// with the closest one.
SolverKind solver_kind_from_name(const std::string& name);
const char* solver_kind_name(SolverKind k);
int solver_order(SolverKind k);  ///< order of the propagated solution

/// Which ODE system is integrated along the geodesic.
enum class GeodesicSystem {
  Geodesic,   ///< y = (x^μ, k^μ): 8 components
  Transport,  ///< + 4 parallel-transported vectors e_(a)^μ: 24 components
  Jacobi,     ///< + Sachs basis s1, s2 (8) + two Jacobi fields Y and dY/dλ (16): 32 components (jacobi.h)
};
constexpr int system_dim(GeodesicSystem s) {
  return s == GeodesicSystem::Geodesic ? 8 : (s == GeodesicSystem::Transport ? 24 : 32);
}
constexpr int kMaxSystemDim = 32;

struct SolverConfig {
  SolverKind kind = SolverKind::CashKarp45;
  GeodesicType type = GeodesicType::Lightlike;
  double eps_abs = 1e-4;    ///< GeoViS default
  double eps_rel = 0.0;     ///< GeoViS default
  bool step_ctrl = true;    ///< false: fixed step `step_size`
  double step_size = 0.01;  ///< initial (or fixed) step |h|
  double step_max = 1e10;   ///< maximal |h| in the affine parameter (scenes: GeoViS's max_step, default 1)
  /// step_max also limits Carter's separated equations (`separable`). The scene builder clears it
  /// when the scene gives no max_step: GeoViS's default of 1 belongs to its coordinate form, whose
  /// error control can step over a thin feature of the metric (a warp bubble) that it never
  /// samples, while the separated equations' right-hand side is one polynomial in 1/r and cos θ.
  bool step_max_separable = true;
  double step_min = 1e-14;  ///< below this the integration stops with StepUnderflow
  int max_steps = 3000;     ///< maximal number of accepted steps (GeoViS maxNumPoints)
  double lambda_max = std::numeric_limits<double>::infinity();  ///< maximal |affine parameter|
  /// Direction of integration in the affine parameter: +1 forward, -1 backward.
  double direction = 1.0;
  /// Scene bounding box in the metric's coordinates (GeoViS boundBoxLL/UR); the ray stops when
  /// it leaves it.
  Vec4 box_ll{{-DBL_MAX, -DBL_MAX, -DBL_MAX, -DBL_MAX}};
  Vec4 box_ur{{DBL_MAX, DBL_MAX, DBL_MAX, DBL_MAX}};
  /// Stop when |g(k,k) - target| exceeds this times max(Σ_{μν} |g_μν k^μ k^ν|, |target|), i.e.
  /// relative to the size of the terms that cancel in g(k,k) (integrators.h, MetricSystem).
  double constraint_tol = 1e-2;
  /// Re-project k onto the constraint surface after every accepted step.
  bool reproject = false;
  /// Geodesics of KerrBL and Schwarzschild (system Geodesic) are integrated through Carter's
  /// separated equations in Mino time (spacetime/kerr_mino.h): exact E, L, Q and a cheaper
  /// right-hand side; the tolerances are scaled to keep their meaning in Boyer–Lindquist
  /// coordinates. false: the second-order geodesic equation in coordinates (GeoViS's form).
  bool separable = true;
  /// Escape (StopReason::Escaped): no object lies farther than this from the origin (distance |p|
  /// in the metric's pseudo-Cartesian coordinates, metric.h). A ray beyond it that provably can no
  /// longer turn back (it moves outward outside the photon region of an asymptotically flat
  /// metric, spacetime/escape.h) stops there. The renderer sets the scene's bounding sphere;
  /// +∞ (default): never; 0: as soon as the ray cannot turn back.
  double escape_radius = std::numeric_limits<double>::infinity();
  /// Capture (spacetime/capture.h): no object lies closer than this to the origin (distance |p| in
  /// the metric's pseudo-Cartesian coordinates). A light ray below it that provably falls into the
  /// horizon without turning back stops there with StopReason::Invalid, the reason it gets at the
  /// break radius. The renderer sets the scene's innermost radius, or the radius of the ball that
  /// holds none of the scene's surface where that is larger; 0 (default): never.
  double capture_radius = 0.0;
};

enum class StopReason {
  None,           ///< still running (internal)
  Callback,       ///< the step callback stopped it (e.g. the ray hit an object)
  Invalid,        ///< left the coordinate validity domain (horizon, singularity, throat chart ...),
                  ///< or is certain to reach the horizon without turning back (capture.h)
  BoundingBox,    ///< left the scene's bounding box
  LambdaMax,      ///< reached the maximal affine parameter
  MaxSteps,       ///< reached the maximal number of accepted steps
  Constraint,     ///< normalization constraint drifted beyond tolerance
  StepUnderflow,  ///< the step size control asked for a step below step_min
  NotFinite,      ///< NaN/Inf appeared in the state
  Escaped,        ///< beyond SolverConfig::escape_radius, moving outward, can no longer turn back
};
const char* stop_reason_name(StopReason r);

/// One accepted step handed to the callback. y0/y1 are the states at lambda0/lambda1, dy0/dy1
/// their derivatives (so the caller can Hermite-interpolate inside the step to integration
/// precision).
struct StepView {
  double lambda0, lambda1;
  const double* y0;
  const double* y1;
  const double* dy0;
  const double* dy1;
  int dim;
  int step_index;  ///< 1 for the first accepted step
  /// Pseudo-Cartesian positions (Metric::to_pseudo_cartesian, 3 components) of the two ends when
  /// the integrator has them at hand without trigonometry (Carter's equations in Mino time hold
  /// cos θ and sin²θ: kerr_mino.h), else null.
  const double* p0 = nullptr;
  const double* p1 = nullptr;
  /// Set where the integrator gives y0, y1, dy0 and dy1 only on request (PacketRays::
  /// states_on_request): they are valid after fill_states(fill_context); p0 and p1 are then always
  /// given. Null where the states are valid as handed over.
  void (*fill_states)(const void*) = nullptr;
  const void* fill_context = nullptr;
  /// Makes y0, y1, dy0 and dy1 valid (fill_states, where set).
  void ensure_states() const {
    if (fill_states) fill_states(fill_context);
  }
};
enum class StepAction { Continue, Stop };
using StepCallback = FunctionRef<StepAction(const StepView&)>;

struct GeodesicResult {
  StopReason reason = StopReason::None;
  int steps = 0;                ///< accepted steps
  int rejected = 0;             ///< rejected steps
  long rhs_evals = 0;           ///< right-hand-side evaluations
  double lambda = 0;            ///< final affine parameter
  double constraint_drift = 0;  ///< final g(k,k) - target
  double escape_radius = 0;     ///< Escaped: the radius (as SolverConfig::escape_radius) at the stop
};

/// Hermite-cubic position/direction at fraction s in [0,1] of an accepted step (exact to
/// O(h^4), the order of the step's dense output for the position).
void hermite_interpolate(const StepView& st, double s, Vec4& x, Vec4& k);

}  // namespace geovis

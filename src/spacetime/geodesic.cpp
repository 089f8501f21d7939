#include "spacetime/geodesic.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "spacetime/integrators.h"
#include "spacetime/metric_kernel.h"

namespace geovis {

const char* geodesic_type_name(GeodesicType t) {
  switch (t) {
    case GeodesicType::Lightlike: return "lightlike";
    case GeodesicType::Timelike: return "timelike";
    case GeodesicType::Spacelike: return "spacelike";
  }
  return "lightlike";
}

GeodesicType parse_geodesic_type(const std::string& s) {
  const std::string l = to_lower(s);
  if (l == "lightlike") return GeodesicType::Lightlike;
  if (l == "timelike") return GeodesicType::Timelike;
  if (l == "spacelike") return GeodesicType::Spacelike;
  const std::vector<std::string> valid = {"lightlike", "timelike", "spacelike"};
  throw Error("unknown geodesic type \"" + s + "\"" + did_you_mean(s, valid) + " (valid: " + join(valid) + ")");
}

const std::vector<SolverInfo>& solver_names() {
  // Catalogue §13: GeoViS/Motion4D names and what they map onto here. GSL's implicit methods
  // (Gaussian points, Gear) target stiff problems; geodesics are not stiff, so they map onto the
  // explicit method of the same order with step control. GSL's rk8pd (Prince-Dormand 8(7)) and
  // Motion4D's DP65 map onto the closest high-order method we have, DOP853.
  static const std::vector<SolverInfo> names = {
      {"RK4", SolverKind::RK4, "classical 4th-order Runge-Kutta, fixed step (Motion4D GeodesicRK4)"},
      {"BS", SolverKind::BulirschStoer, "Bulirsch-Stoer extrapolation (Motion4D GeodesicBS)"},
      {"GSL_RK2", SolverKind::RK2, "embedded 2nd-order Runge-Kutta (Heun-Euler 2(1))"},
      {"GSL_RK4", SolverKind::RK4, "classical 4th-order Runge-Kutta, fixed step"},
      {"GSL_RK_Fehlberg", SolverKind::Fehlberg45, "Runge-Kutta-Fehlberg 4(5)"},
      {"GSL_RK_Cash-Karp", SolverKind::CashKarp45, "Runge-Kutta Cash-Karp 4(5)"},
      {"GSL_RK_Prince-Dormand", SolverKind::DormandPrince853, "8th-order Dormand-Prince (DOP853)"},
      {"GSL_RK_Gaussian-points", SolverKind::RK2, "mapped onto the embedded 2nd-order Runge-Kutta"},
      {"GSL_M1_IG", SolverKind::RK2, "mapped onto the embedded 2nd-order Runge-Kutta"},
      {"GSL_M2_IG", SolverKind::RK2, "mapped onto the embedded 2nd-order Runge-Kutta"},
      {"DP54", SolverKind::DormandPrince54, "Dormand-Prince 5(4)"},
      {"DP65", SolverKind::DormandPrince853, "mapped onto Dormand-Prince 8(5,3)"},
      // Our names (solver_kind_name) and short aliases.
      {"RK2", SolverKind::RK2, "Heun-Euler embedded 2(1)"},
      {"CashKarp45", SolverKind::CashKarp45, "Runge-Kutta Cash-Karp 4(5)"},
      {"CashKarp", SolverKind::CashKarp45, "Runge-Kutta Cash-Karp 4(5)"},
      {"Fehlberg45", SolverKind::Fehlberg45, "Runge-Kutta-Fehlberg 4(5)"},
      {"Fehlberg", SolverKind::Fehlberg45, "Runge-Kutta-Fehlberg 4(5)"},
      {"DormandPrince54", SolverKind::DormandPrince54, "Dormand-Prince 5(4), FSAL"},
      {"DOP853", SolverKind::DormandPrince853, "Dormand-Prince 8(5,3) (Hairer's DOP853)"},
      {"DP853", SolverKind::DormandPrince853, "Dormand-Prince 8(5,3) (Hairer's DOP853)"},
      {"BulirschStoer", SolverKind::BulirschStoer, "Gragg-Bulirsch-Stoer extrapolation"},
      {"RKN86", SolverKind::RungeKuttaNystrom86,
       "Runge-Kutta-Nystrom 8(6) (Dormand, El-Mikkawy & Prince); KerrBL and Schwarzschild geodesics only"},
      // Motion4D full names (catalogue §13).
      {"Runge-Kutta (fourth order)", SolverKind::RK4, "classical 4th-order Runge-Kutta"},
      {"Bulirsch-Stoer", SolverKind::BulirschStoer, "Bulirsch-Stoer extrapolation"},
      {"GSL: Embedded 2nd order Runge-Kutta", SolverKind::RK2, "embedded 2nd-order Runge-Kutta"},
      {"GSL: 4th order (classical) Runge-Kutta", SolverKind::RK4, "classical 4th-order Runge-Kutta"},
      {"GSL: Embedded 4th order Runge-Kutta-Fehlberg", SolverKind::Fehlberg45, "Runge-Kutta-Fehlberg 4(5)"},
      {"GSL: Embedded 4th order Runge-Kutta Cash-Karp", SolverKind::CashKarp45, "Runge-Kutta Cash-Karp 4(5)"},
      {"GSL: Embedded 8th order Runge-Kutta Prince-Dormand", SolverKind::DormandPrince853, "DOP853"},
      {"GSL: Implicit 2nd order Runge-Kutta at Gaussian points", SolverKind::RK2, "mapped onto RK2"},
      {"GSL: M=1 implicit Gear", SolverKind::RK2, "mapped onto RK2"},
      {"GSL: M=2 implicit Gear", SolverKind::RK2, "mapped onto RK2"},
      {"Dormand-Prince: RK5(4)", SolverKind::DormandPrince54, "Dormand-Prince 5(4)"},
      {"Dormand-Prince: RK6(5)", SolverKind::DormandPrince853, "mapped onto DOP853"},
  };
  return names;
}

SolverKind solver_kind_from_name(const std::string& name) {
  for (const auto& s : solver_names())
    if (s.name == name) return s.kind;
  for (const auto& s : solver_names())
    if (to_lower(s.name) == to_lower(name)) return s.kind;
  std::vector<std::string> valid;
  for (const auto& s : solver_names())
    if (s.name.find(' ') == std::string::npos) valid.push_back(s.name);
  throw Error("unknown solver \"" + name + "\"" + did_you_mean(name, valid) + " (valid solvers: " + join(valid) + ")");
}

const char* solver_kind_name(SolverKind k) {
  switch (k) {
    case SolverKind::RK2: return "RK2";
    case SolverKind::RK4: return "RK4";
    case SolverKind::CashKarp45: return "CashKarp45";
    case SolverKind::Fehlberg45: return "Fehlberg45";
    case SolverKind::DormandPrince54: return "DormandPrince54";
    case SolverKind::DormandPrince853: return "DOP853";
    case SolverKind::BulirschStoer: return "BulirschStoer";
    case SolverKind::RungeKuttaNystrom86: return "RKN86";
  }
  return "?";
}

int solver_order(SolverKind k) {
  switch (k) {
    case SolverKind::RK2: return 2;
    case SolverKind::RK4: return 4;
    case SolverKind::CashKarp45: return 5;
    case SolverKind::Fehlberg45: return 4;
    case SolverKind::DormandPrince54: return 5;
    case SolverKind::DormandPrince853: return 8;
    case SolverKind::BulirschStoer: return 8;
    case SolverKind::RungeKuttaNystrom86: return 8;
  }
  return 0;
}

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::None: return "none";
    case StopReason::Callback: return "callback";
    case StopReason::Invalid: return "horizon";
    case StopReason::BoundingBox: return "bounding-box";
    case StopReason::LambdaMax: return "lambda-max";
    case StopReason::MaxSteps: return "max-steps";
    case StopReason::Constraint: return "constraint";
    case StopReason::StepUnderflow: return "step-underflow";
    case StopReason::NotFinite: return "not-finite";
    case StopReason::Escaped: return "escaped";
  }
  return "?";
}

void validate_solver_config(const SolverConfig& cfg) {
  auto fail = [](const char* key, const std::string& expected, double found) {
    std::ostringstream os;
    os << "solver: " << key << ": expected " << expected << ", found " << found;
    throw Error(os.str());
  };
  if (!(cfg.eps_abs >= 0) || !std::isfinite(cfg.eps_abs)) fail("eps_abs", "a finite number >= 0", cfg.eps_abs);
  if (!(cfg.eps_rel >= 0) || !std::isfinite(cfg.eps_rel)) fail("eps_rel", "a finite number >= 0", cfg.eps_rel);
  if (cfg.step_ctrl && cfg.eps_abs == 0 && cfg.eps_rel == 0)
    fail("eps_abs", "a positive tolerance (eps_abs and eps_rel are both 0)", cfg.eps_abs);
  if (!(cfg.step_size > 0) || !std::isfinite(cfg.step_size)) fail("step_size", "a finite number > 0", cfg.step_size);
  if (!(cfg.step_max > 0)) fail("max_step", "a number > 0", cfg.step_max);
  if (!(cfg.step_min >= 0)) fail("step_min", "a number >= 0", cfg.step_min);
  if (cfg.max_steps < 0) fail("max_steps", "an integer >= 0", cfg.max_steps);
  if (!(cfg.lambda_max > 0)) fail("lambda_max", "a number > 0", cfg.lambda_max);
  if (!(cfg.constraint_tol > 0)) fail("constraint_tol", "a number > 0", cfg.constraint_tol);
}

void hermite_interpolate(const StepView& st, double s, Vec4& x, Vec4& k) {
  // Cubic Hermite on [λ0, λ1] for x with x' = k at both ends, and for k with k' = dy[4..7].
  const double h = st.lambda1 - st.lambda0;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  for (int i = 0; i < 4; ++i) {
    x[i] = h00 * st.y0[i] + h10 * h * st.dy0[i] + h01 * st.y1[i] + h11 * h * st.dy1[i];
    // k = dx/dλ from the same cubic; accurate to O(h^3).
    k[i] = (d00 * st.y0[i] + d01 * st.y1[i]) / h + d10 * st.dy0[i] + d11 * st.dy1[i];
  }
}

// The integrators instantiated once for all metrics (metric_kernel.h): the geodesic system with the
// steppers MetricCRTP does not compile per metric; the other systems in transport.cpp and jacobi.cpp.
GeodesicResult integrate_geodesic_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y,
                                            double lambda0, StepCallback cb) {
  GeodesicRHS<MetricKernel> f{k};
  return integrate_system(k, f, cfg, y, lambda0, cb);
}

GeodesicResult integrate_on_kernel(const MetricKernel& k, const SolverConfig& cfg, GeodesicSystem sys, double* y,
                                   double lambda0, StepCallback cb) {
  switch (sys) {
    case GeodesicSystem::Transport: return integrate_transport_on_kernel(k, cfg, y, lambda0, cb);
    case GeodesicSystem::Jacobi: return integrate_jacobi_on_kernel(k, cfg, y, lambda0, cb);
    case GeodesicSystem::Geodesic: break;
  }
  return integrate_geodesic_on_kernel(k, cfg, y, lambda0, cb);
}

}  // namespace geovis

#include "spacetime/geodesic.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "spacetime/integrators.h"
#include "spacetime/metric_kernel.h"
#include "spacetime/solver_type.h"

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

// The integrators are registered in solver_type.cpp (one entry each, with the GeoViS names that
// map onto it); these read that registry.
const std::vector<SolverInfo>& solver_names() {
  static const std::vector<SolverInfo> names = [] {
    std::vector<SolverInfo> out;
    for (const SolverType* t : SolverRegistry::instance().entries()) {
      out.push_back({t->name, t->kind, t->doc});
      for (const std::string& alias : t->aliases) out.push_back({alias, t->kind, t->doc});
    }
    return out;
  }();
  return names;
}

SolverKind solver_kind_from_name(const std::string& name) {
  const auto& registry = SolverRegistry::instance();
  if (const SolverType* t = registry.find(name)) return t->kind;
  // GeoViS scenes name integrators by their nicknames, so those are listed too (the full Motion4D
  // names, with spaces, are in the scene reference).
  std::vector<std::string> valid;
  for (const std::string& n : registry.names_and_aliases())
    if (n.find(' ') == std::string::npos) valid.push_back(n);
  throw Error("unknown solver \"" + name + "\"" + did_you_mean(name, registry.names_and_aliases()) +
              " (valid solvers: " + join(valid) + ")");
}

namespace {
const SolverType& solver_type_of(SolverKind k) {
  for (const SolverType* t : SolverRegistry::instance().entries())
    if (t->kind == k) return *t;
  throw std::logic_error("integrator kind without a registered SolverType");
}
}  // namespace

const char* solver_kind_name(SolverKind k) { return solver_type_of(k).name.c_str(); }

int solver_order(SolverKind k) { return solver_type_of(k).order; }

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
GeodesicResult integrate_geodesic_on_kernel(const MetricKernel& k, const SolverConfig& cfg, double* y, double lambda0,
                                            StepCallback cb) {
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

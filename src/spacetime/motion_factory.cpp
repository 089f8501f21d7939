#include "spacetime/motion_factory.h"

#include <cmath>

#include "core/error.h"
#include "core/param_reader.h"
#include "spacetime/tetrad.h"

namespace geovis {

namespace {

std::vector<ParamSpec> common_specs() {
  return {
      {"type", ParamType::String, "motion type: " + join(MotionRegistry::instance().names()), true},
      {"id", ParamType::String, "name of the motion"},
      {"metric", ParamType::String, "metric id (when several are defined)"},
  };
}

}  // namespace

std::vector<ParamSpec> motion_frame_specs() {
  std::vector<ParamSpec> specs = tetrad_param_specs({"e0", "e1", "e2", "e3", "incoords", "localframe"});
  specs.push_back({"tau0", ParamType::Number, "proper time at the start event", false, false, 0.0});
  return specs;
}

Vec3 motion_vector_key(const Param& p, const ParamSet& ps, size_t n, std::vector<double>& out) {
  if (!p.value.is_vector() || std::get<std::vector<double>>(p.value.v).size() != n)
    ps.fail(p.key, "expected a " + std::to_string(n) + "-vector, found " + p.value.describe());
  out = std::get<std::vector<double>>(p.value.v);
  for (double d : out)
    if (!std::isfinite(d)) ps.fail(p.key, "expected finite numbers, found " + p.value.describe());
  return n >= 3 ? Vec3{out[n - 3], out[n - 2], out[n - 1]} : Vec3{};
}

std::vector<std::string> motion_type_names() { return MotionRegistry::instance().names(); }

std::vector<ParamSpec> motion_param_specs(const std::string& type) {
  std::vector<ParamSpec> s = common_specs();
  if (const MotionType* t = MotionRegistry::instance().find(type)) s.insert(s.end(), t->keys.begin(), t->keys.end());
  return s;
}

MotionPtr make_motion(const ParamSet& ps, std::shared_ptr<const Metric> metric, const SolverConfig& solver) {
  const MotionType& type = MotionRegistry::instance().get(ps, "type", ps.get_string("type"), "motion type");
  if (!metric && type.needs_metric) ps.fail("metric", "no metric is defined for this motion");
  const std::vector<ParamSpec> specs = motion_param_specs(type.name);
  return type.make(ParamReader(ps, specs), std::move(metric), solver);
}

}  // namespace geovis

#include "spacetime/motion_factory.h"

#include <cmath>
#include <limits>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/param_reader.h"
#include "spacetime/motion_const_velocity.h"
#include "spacetime/motion_geodesic.h"
#include "spacetime/motion_worldline.h"
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

std::vector<ParamSpec> frame_specs() {
  return {
      {"e0", ParamType::Vec4, "base vector e0 (relative to the natural tetrad unless incoords)"},
      {"e1", ParamType::Vec4, "base vector e1"},
      {"e2", ParamType::Vec4, "base vector e2"},
      {"e3", ParamType::Vec4, "base vector e3"},
      {"incoords", ParamType::Bool, "#t: e0..e3 are coordinate components"},
      {"localframe", ParamType::Any, "natural tetrad kind (name or 0..6)"},
      {"tau0", ParamType::Number, "proper time at the start event", false, false, 0.0},
  };
}

Vec3 vec3_of(const Param& p, const ParamSet& ps, size_t n, std::vector<double>& out) {
  if (!p.value.is_vector() || std::get<std::vector<double>>(p.value.v).size() != n)
    ps.fail(p.key, "expected a " + std::to_string(n) + "-vector, found " + p.value.describe());
  out = std::get<std::vector<double>>(p.value.v);
  for (double d : out)
    if (!std::isfinite(d)) ps.fail(p.key, "expected finite numbers, found " + p.value.describe());
  return n >= 3 ? Vec3{out[n - 3], out[n - 2], out[n - 1]} : Vec3{};
}

MotionPtr make_geodesic(const ParamReader& keys, std::shared_ptr<const Metric> metric, const SolverConfig& solver) {
  const ParamSet& ps = keys.params();
  Vec4 pos;
  const Tetrad e = tetrad_from_params(ps, *metric, &pos);
  const double forward = keys.number("forward"), backward = keys.number("backward");
  if (forward == 0 && backward == 0)
    ps.fail("forward", "a Geodesic motion needs `forward` and/or `backward` (proper-time ranges > 0)");
  SolverConfig cfg = solver;
  if (ps.has("stepsize")) cfg.step_size = keys.number("stepsize");
  try {
    return std::make_shared<GeodesicMotion>(metric, cfg, pos, e, keys.number("tau0"), forward, backward,
                                            keys.integer("maxnumpoints"));
  } catch (const SceneError&) {
    throw;
  } catch (const Error& err) {
    ps.fail("pos", err.what());
  }
}

MotionPtr make_const_velocity(const ParamReader& keys, std::shared_ptr<const Metric>, const SolverConfig&) {
  const ParamSet& ps = keys.params();
  // In a metric other than Minkowski the object applies the motion to pseudo-Cartesian
  // coordinates, as GeoViS does (render/local_object.h, PseudoCartesianMotionObject).
  auto motion = std::make_shared<ConstVelocityMotion>();
  for (const Param& p : ps.entries()) {
    std::vector<double> v;
    if (p.key == "boost") {
      const Vec3 b = vec3_of(p, ps, 3, v);
      if (!(dot(b, b) < 1.0)) ps.fail("boost", "expected a 3-velocity with |v| < 1, found " + p.value.describe());
      motion->add_boost(b);
    } else if (p.key == "rotation") {
      const Vec3 axis = vec3_of(p, ps, 4, v);
      if (norm(axis) == 0.0)
        ps.fail("rotation", "rotation axis is missing: expected #(omega ax ay az) with a non-zero axis, found " +
                                p.value.describe());
      motion->add_rotation(v[0], axis);
    }
  }
  return motion;
}

std::vector<std::vector<double>> read_event_file(const ParamSet& ps, const std::string& file) {
  std::ifstream in(file);
  if (!in) ps.fail("filename", "cannot open worldline file \"" + file + "\"");
  std::vector<std::vector<double>> rows;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream ls(line);
    std::vector<double> row;
    std::string tok;
    while (ls >> tok) {
      char* end = nullptr;
      const double d = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0' || !std::isfinite(d))
        ps.fail("filename", file + ":" + std::to_string(lineno) + ": expected a number, found \"" + tok + "\"");
      row.push_back(d);
    }
    if (!row.empty()) rows.push_back(std::move(row));
  }
  return rows;
}

MotionPtr make_worldline(const ParamReader& keys, std::shared_ptr<const Metric> metric, const SolverConfig&) {
  const ParamSet& ps = keys.params();
  const bool have_tau = keys.boolean("havetau");
  const size_t cols = have_tau ? 5 : 4;
  std::vector<std::vector<double>> rows;
  std::string key;
  if (ps.has("points") && ps.has("filename")) ps.fail("points", "give either `points` or `filename`, not both");
  if (ps.has("points")) {
    key = "points";
    const Param* p = ps.find("points");
    if (!p->value.is_list()) ps.fail("points", "expected a list of event vectors, found " + p->value.describe());
    for (const Value& v : std::get<ValueList>(p->value.v)) {
      if (!v.is_vector())
        ps.fail("points", "expected a list of event vectors #(x0 x1 x2 x3), found an entry " + v.describe());
      rows.push_back(std::get<std::vector<double>>(v.v));
    }
  } else if (ps.has("filename")) {
    key = "filename";
    rows = read_event_file(ps, ps.get_string("filename"));
  } else {
    ps.fail("points", "a Worldline motion needs its events: `points` (list of #(x0 x1 x2 x3)) or `filename`");
  }
  std::vector<Vec4> events;
  std::vector<double> taus;
  for (size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].size() != cols)
      ps.fail(key, "event " + std::to_string(i) + ": expected " + std::to_string(cols) + " numbers (" +
                       (have_tau ? "tau x0 x1 x2 x3" : "x0 x1 x2 x3") + "), found " + std::to_string(rows[i].size()));
    const double* r = rows[i].data() + (have_tau ? 1 : 0);
    events.push_back(Vec4{{r[0], r[1], r[2], r[3]}});
    if (have_tau) taus.push_back(rows[i][0]);
  }
  if (events.size() < 2) ps.fail(key, "a Worldline motion needs at least 2 events, found " + std::to_string(events.size()));
  if (ps.has("localvel") || ps.has("vel"))
    ps.fail(ps.has("vel") ? "vel" : "localvel", "the velocity of a Worldline motion follows from its events; remove this key");
  TetradSpec spec = tetrad_spec_from_params(ps, false, events[0]);
  if (ps.has("pos")) ps.fail("pos", "the start of a Worldline motion is its first event; remove this key");
  Tetrad frame{};
  try {
    frame = build_tetrad(*metric, spec);
  } catch (const Error& err) {
    ps.fail("e0..e3", err.what());
  }
  const double tau0 = have_tau ? taus.front() : keys.number("tau0");
  try {
    return std::make_shared<WorldlineMotion>(metric, std::move(events), std::move(taus), frame, tau0);
  } catch (const SceneError&) {
    throw;
  } catch (const Error& err) {
    ps.fail(key, err.what());
  }
}

// GeoViS's motions (docs/geovis-catalogue.md §8); their classes are spacetime/motion_*.h.
const TypeRegistrar<MotionType> geodesic{
    {{"Geodesic", {}, "free fall: a timelike geodesic from an event and a velocity, sampled in proper time", [] {
        auto keys = frame_specs();
        const std::vector<ParamSpec> own = {
            {"solver", ParamType::String, "id of the (timelike) solver"},
            {"pos", ParamType::Any, "start event (metric coordinates)", true},
            {"vel", ParamType::Vec4, "initial coordinate four-velocity"},
            {"localvel", ParamType::Vec3, "initial 3-velocity relative to the natural tetrad"},
            {"forward", ParamType::Number, "proper-time range integrated forward", false, false, 0.0,
             ParamRange::non_negative()},
            {"backward", ParamType::Number, "proper-time range integrated backward", false, false, 0.0,
             ParamRange::non_negative()},
            {"maxnumpoints", ParamType::Int, "maximal number of samples per direction", false, false, 1000.0,
             ParamRange{2, std::numeric_limits<double>::infinity(), false, true}},
            {"stepsize", ParamType::Number, "step size (overrides the solver's step_size)", false, false, {},
             ParamRange::positive()}};
        keys.insert(keys.end(), own.begin(), own.end());
        return keys;
      }()},
     make_geodesic, true}};

const TypeRegistrar<MotionType> const_velocity{
    {{"ConstVelocity", {}, "boosts and rotations with constant velocity (special relativity)",
      {{"boost", ParamType::Vec3, "boost velocity #(vx vy vz)", false, true},
       {"rotation", ParamType::Vec4, "rotation #(omega ax ay az)", false, true}}},
     make_const_velocity, false}};

const TypeRegistrar<MotionType> worldline{
    {{"Worldline", {"file"}, "a world line through given events, its frame Fermi-Walker transported", [] {
        auto keys = frame_specs();
        const std::vector<ParamSpec> own = {
            {"points", ParamType::List, "events #(x0 x1 x2 x3) (or #(tau x0 x1 x2 x3) with havetau)"},
            {"filename", ParamType::String, "text file with one event per line"},
            {"havetau", ParamType::Bool, "events start with their proper time", false, false, false}};
        keys.insert(keys.end(), own.begin(), own.end());
        return keys;
      }()},
     make_worldline, true}};

}  // namespace

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

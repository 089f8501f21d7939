// `geovis geodesic --metric NAME [--param key=value]... [--pos t,x1,x2,x3] [--dir d1,d2,d3]
//   [--type lightlike|timelike] [--solver NAME] [--eps-abs X] [--eps-rel X] [--max-steps N]
//   [--lambda-max X] [--forward] [--format csv|json]`
// integrates one geodesic started in the metric's natural (default) tetrad at `pos` and prints
// every accepted step. Without --pos the geodesic starts at the metric's sample position; without
// --dir a light ray starts along e(1), a particle at rest.
//   lightlike: --dir is a local spatial direction along e(1), e(2), e(3) (normalized here); the ray
//              is k = −e(0) + d̂ and traced backwards in time as the renderer does (paper eq. 7),
//              or k = e(0) + d̂ towards the future with --forward.
//   timelike:  --dir is the local 3-velocity β (|β| < 1); u = γ(e(0) + β^i e(i)), integrated
//              towards the future in proper time.
// CSV: header `lambda,x0,x1,x2,x3,k0,k1,k2,k3,constraint`, one line per accepted step starting with
// the initial point (constraint = g(k,k) − target), then `# stop: REASON` (an escaped ray:
// `# stop: escaped at radius R, lambda L`). JSON carries the same.
// The start vector is checked: finite and null (timelike) to 1e-8 of its size.
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/error.h"
#include "core/number_text.h"
#include "spacetime/integrators.h"
#include "spacetime/metric_registry.h"

namespace geovis::cli {

namespace {

struct GeodesicArgs {
  std::string metric;
  std::vector<std::string> params;
  std::string pos;
  std::string dir;  ///< empty: lightlike along e(1), timelike at rest
  std::string type = "lightlike";
  std::string solver = "GSL_RK_Cash-Karp";
  double eps_abs = 1e-8;  // the paper's setting for all its images (§3)
  double eps_rel = 0.0;
  std::string equations = "separable";
  int max_steps = 100000;
  double escape_radius = 0.0;
  bool no_escape = false;
  double lambda_max = std::numeric_limits<double>::infinity();
  bool forward = false;
  std::string format = "csv";
};

/// Strict number parsing: the whole text must be one finite number.
bool parse_number(const std::string& text, double& out) {
  const char* s = text.c_str();
  char* end = nullptr;
  out = std::strtod(s, &end);
  if (end == s) return false;
  while (*end == ' ') ++end;
  return *end == '\0' && std::isfinite(out);
}

std::vector<double> parse_vector(const std::string& option, const std::string& text, size_t n, const char* layout) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  bool ok = !text.empty();
  while (ok && std::getline(ss, item, ',')) {
    double x;
    ok = parse_number(item, x);
    v.push_back(x);
  }
  if (!text.empty() && text.back() == ',') ok = false;
  if (!ok || v.size() != n)
    throw Error(option + ": expected " + std::to_string(n) + " comma-separated numbers " + layout + ", found \"" +
                text + "\"");
  return v;
}

int run_geodesic(const GeodesicArgs& a) {
  // ---- metric and parameters ----
  std::vector<std::pair<std::string, double>> params;
  for (const auto& p : a.params) {
    const size_t eq = p.find('=');
    double v = 0;
    if (eq == std::string::npos || eq == 0 || !parse_number(p.substr(eq + 1), v))
      throw Error("--param: expected KEY=VALUE with a number VALUE, found \"" + p + "\"");
    params.emplace_back(p.substr(0, eq), v);
  }
  const std::unique_ptr<Metric> m = make_metric(a.metric, params);

  // ---- options ----
  const GeodesicType type = parse_geodesic_type(a.type);
  if (type == GeodesicType::Spacelike) throw Error("--type: expected lightlike or timelike, found \"" + a.type + "\"");
  SolverConfig cfg;
  cfg.kind = solver_kind_from_name(a.solver);
  cfg.type = type;
  cfg.eps_abs = a.eps_abs;
  cfg.eps_rel = a.eps_rel;
  cfg.separable = a.equations == "separable";
  cfg.max_steps = a.max_steps;
  cfg.lambda_max = a.lambda_max;
  if (!(a.escape_radius >= 0.0) || !std::isfinite(a.escape_radius))
    throw Error("--escape-radius: expected a finite number >= 0, found " + exact_number_text(a.escape_radius));
  cfg.escape_radius = a.no_escape ? std::numeric_limits<double>::infinity() : a.escape_radius;
  if (!(a.lambda_max > 0)) throw Error("--lambda-max: expected a number > 0, found " + exact_number_text(a.lambda_max));
  if (a.max_steps < 1) throw Error("--max-steps: expected an integer >= 1, found " + std::to_string(a.max_steps));
  if (a.format != "csv" && a.format != "json") {
    const std::vector<std::string> valid = {"csv", "json"};
    throw Error("--format: expected csv or json, found \"" + a.format + "\"" + did_you_mean(a.format, valid));
  }
  validate_solver_config(cfg);

  // ---- initial state from the natural tetrad ----
  // Without --pos: the metric's sample observer position (MetricInfo::sample_pos).
  const Vec4 sample = m->info().sample_pos;
  const std::vector<double> pv = a.pos.empty() ? std::vector<double>{sample[0], sample[1], sample[2], sample[3]}
                                               : parse_vector("--pos", a.pos, 4, "t,x1,x2,x3");
  const std::string dir = !a.dir.empty() ? a.dir : (type == GeodesicType::Lightlike ? "1,0,0" : "0,0,0");
  const std::vector<double> dv = parse_vector("--dir", dir, 3, "d1,d2,d3");
  const Vec4 x{{pv[0], pv[1], pv[2], pv[3]}};
  const auto& c = m->info().coords;
  if (!m->is_valid(x))
    throw Error("--pos: (" +
                (a.pos.empty() ? exact_number_text(x[0]) + "," + exact_number_text(x[1]) + "," +
                                     exact_number_text(x[2]) + "," + exact_number_text(x[3])
                               : a.pos) +
                ") is outside the validity domain of the " + m->name() + " coordinates (" + c[0] + ", " + c[1] + ", " +
                c[2] + ", " + c[3] + ")");
  const Tetrad e = m->natural_tetrad(x, TetradKind::Default);
  const Vec3 d{dv[0], dv[1], dv[2]};
  Vec4 k;
  if (type == GeodesicType::Lightlike) {
    if (!(norm(d) > 0)) throw Error("--dir: expected a non-zero direction, found \"" + dir + "\"");
    if (!std::isfinite(norm(d)))
      throw Error("--dir: the length of the direction (" + dir +
                  ") overflows in double precision; give components of moderate size (only the direction counts)");
    k = local_null_direction(e, d, /*past_directed=*/!a.forward);
  } else {
    if (!(norm(d) < 1.0))
      throw Error("--dir: expected a local 3-velocity with |v| < 1, found |v| = " + exact_number_text(norm(d)));
    k = local_four_velocity(e, d);
  }

  // The start vector must be what --type says: finite, g(k,k) = target to 1e-8 of the size of
  // its terms (a direction whose components under- or overflow the normalisation is not).
  {
    Mat4 g;
    m->metric_tensor(x, g);
    double gkk = 0, size = 0;
    bool finite = true;
    for (int i = 0; i < 4; ++i) {
      finite = finite && std::isfinite(k[i]);
      for (int j = 0; j < 4; ++j) {
        gkk += g[i][j] * k[i] * k[j];
        size += std::fabs(g[i][j] * k[i] * k[j]);
      }
    }
    const double target = constraint_target(type);
    if (!finite || !(std::fabs(gkk - target) <= 1e-8 * std::max(size, 1.0)))
      throw Error(std::string("--dir: the start vector k = (") + exact_number_text(k[0]) + ", " +
                  exact_number_text(k[1]) + ", " + exact_number_text(k[2]) + ", " + exact_number_text(k[3]) +
                  ") is not " + (type == GeodesicType::Lightlike ? "null" : "a unit timelike vector") + ": g(k,k) = " +
                  exact_number_text(gkk) + " instead of " + exact_number_text(target) + " (direction \"" + dir + "\")");
  }

  // ---- integrate, collecting points ----
  struct Point {
    double lambda;
    double y[8];
    double constraint;
  };
  std::vector<Point> points;
  const double target = constraint_target(type);
  auto add_point = [&](double lambda, const double* y) {
    Point p{lambda, {}, 0};
    for (int i = 0; i < 8; ++i) p.y[i] = y[i];
    Mat4 g;
    m->metric_tensor(Vec4{{y[0], y[1], y[2], y[3]}}, g);
    p.constraint = dot(g, Vec4{{y[4], y[5], y[6], y[7]}}, Vec4{{y[4], y[5], y[6], y[7]}}) - target;
    points.push_back(p);
  };
  double y[8] = {x[0], x[1], x[2], x[3], k[0], k[1], k[2], k[3]};
  add_point(0.0, y);
  auto cb = [&](const StepView& s) {
    add_point(s.lambda1, s.y1);
    return StepAction::Continue;
  };
  const GeodesicResult res = m->integrate(cfg, GeodesicSystem::Geodesic, y, 0.0, cb);

  // ---- output ----
  if (a.format == "json") {
    nlohmann::json j;
    j["metric"] = m->name();
    nlohmann::json pj = nlohmann::json::object();
    for (size_t i = 0; i < m->info().params.size(); ++i) pj[m->info().params[i].name] = m->param_values()[i];
    j["params"] = pj;
    j["coordinates"] = c;
    j["type"] = geodesic_type_name(type);
    j["solver"] = solver_kind_name(cfg.kind);
    j["eps_abs"] = cfg.eps_abs;
    j["eps_rel"] = cfg.eps_rel;
    j["separable"] = cfg.separable;
    nlohmann::json pts = nlohmann::json::array();
    for (const auto& p : points)
      pts.push_back({{"lambda", p.lambda},
                     {"x", {p.y[0], p.y[1], p.y[2], p.y[3]}},
                     {"k", {p.y[4], p.y[5], p.y[6], p.y[7]}},
                     {"constraint", p.constraint}});
    j["points"] = pts;
    j["stop"] = stop_reason_name(res.reason);
    if (res.reason == StopReason::Escaped) j["escape"] = {{"radius", res.escape_radius}, {"lambda", res.lambda}};
    j["steps"] = res.steps;
    j["rejected"] = res.rejected;
    j["rhs_evals"] = res.rhs_evals;
    std::cout << j.dump(1) << "\n";
    return 0;
  }
  std::ostringstream os;
  os << "lambda,x0,x1,x2,x3,k0,k1,k2,k3,constraint\n";
  for (const auto& p : points) {
    os << exact_number_text(p.lambda);
    for (double v : p.y) os << ',' << exact_number_text(v);
    os << ',' << exact_number_text(p.constraint) << '\n';
  }
  os << "# stop: " << stop_reason_name(res.reason);
  if (res.reason == StopReason::Escaped)
    os << " at radius " << exact_number_text(res.escape_radius) << ", lambda " << exact_number_text(res.lambda);
  os << '\n';
  std::cout << os.str();
  return 0;
}

void setup_geodesic(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<GeodesicArgs>();
  CLI::App* sub = app.add_subcommand("geodesic", "integrate one geodesic and print every step (CSV or JSON)");
  sub->footer(
      "The last line says why the integration stopped:\n"
      "  escaped         a light ray beyond --escape-radius, moving outward, that provably can no longer\n"
      "                  turn back (outside the photon region of an asymptotically flat metric: Minkowski,\n"
      "                  Schwarzschild and its other charts, KerrBL, ReissnerNordstrom, JanisNewmanWinicour,\n"
      "                  MorrisThorne, Kottler with lambda = 0; the line gives its radius and lambda)\n"
      "  horizon         left the validity domain of the coordinates (horizon, singularity, chart edge)\n"
      "  bounding-box    left the bounding box\n"
      "  lambda-max      reached --lambda-max\n"
      "  max-steps       reached --max-steps accepted steps\n"
      "  constraint      g(k,k) drifted beyond the constraint tolerance\n"
      "  step-underflow  the step size control asked for a step below the minimal step\n"
      "  not-finite      NaN or infinity appeared in the state");
  sub->add_option("--metric", a->metric, "metric name (see `geovis metrics`)")->required();
  sub->add_option("--param", a->params, "metric parameter KEY=VALUE (repeatable)")->allow_extra_args(false);
  sub->add_option("--pos", a->pos,
                  "start position t,x1,x2,x3 in the metric's coordinates (default: the metric's sample position, "
                  "see `geovis metrics`)");
  sub->add_option("--dir", a->dir,
                  "lightlike: local direction d1,d2,d3 along e(1),e(2),e(3) (default 1,0,0); timelike: local "
                  "3-velocity (default 0,0,0)");
  sub->add_option("--type", a->type, "lightlike or timelike")->capture_default_str();
  sub->add_option("--solver", a->solver, "integrator (GeoViS name or ours)")->capture_default_str();
  sub->add_option("--eps-abs", a->eps_abs, "absolute tolerance")->capture_default_str();
  sub->add_option("--eps-rel", a->eps_rel, "relative tolerance")->capture_default_str();
  sub->add_option("--equations", a->equations,
                  "separable: KerrBL/Schwarzschild through Carter's equations in Mino time; coordinate: the "
                  "second-order geodesic equation (every other metric uses it anyway)")
      ->check(CLI::IsMember({"separable", "coordinate"}))
      ->capture_default_str();
  sub->add_option("--max-steps", a->max_steps, "maximal number of accepted steps")->capture_default_str();
  sub->add_option("--lambda-max", a->lambda_max, "maximal affine parameter (proper time for timelike)");
  sub->add_option("--escape-radius", a->escape_radius,
                  "radius of the objects' bounding sphere: a light ray stops as escaped only beyond it")
      ->capture_default_str();
  sub->add_flag("--no-escape", a->no_escape, "never stop a ray as escaped (follow it to the other limits)");
  sub->add_flag("--forward", a->forward, "lightlike: trace towards the future instead of backwards in time");
  sub->add_option("--format", a->format, "csv or json")->capture_default_str();
  sub->callback([a, &g]() {
    g.exit_code = run_geodesic(*a);  // errors are reported by run() (app.cpp)
  });
}

const bool geodesic_registered = register_command("geodesic", &setup_geodesic);

}  // namespace

}  // namespace geovis::cli

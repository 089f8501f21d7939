#include "spacetime/motion_worldline.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/number_text.h"
#include "core/param_reader.h"
#include "spacetime/motion_factory.h"
#include "spacetime/tetrad.h"

namespace geovis {

namespace {

/// −g(v, v) at x: positive for timelike v.
double minus_norm2(const Metric& m, const Vec4& x, const Vec4& v) {
  Mat4 g;
  m.metric_tensor(x, g);
  return -dot(g, v, v);
}

}  // namespace

WorldlineMotion::WorldlineMotion(std::shared_ptr<const Metric> metric, std::vector<Vec4> events,
                                 std::vector<double> params, const Tetrad& frame, double tau0,
                                 const FermiWalkerConfig& fw)
    : SampledMotion(metric), x_(std::move(events)) {
  const Metric& m = *metric;
  const size_t n = x_.size();
  if (n < 2) throw Error("Worldline motion: needs at least 2 events, found " + std::to_string(n));
  for (size_t i = 0; i < n; ++i) require_valid_position(m, x_[i], "Worldline motion: event " + std::to_string(i));
  const bool given_params = !params.empty();
  if (!given_params) {
    for (const Vec4& x : x_) p_.push_back(x[0]);
  } else {
    if (params.size() != n)
      throw Error("Worldline motion: " + std::to_string(params.size()) + " curve parameters for " + std::to_string(n) +
                  " events");
    p_ = std::move(params);
  }
  for (size_t i = 1; i < n; ++i)
    if (!(p_[i] > p_[i - 1]))
      throw Error("Worldline motion: the curve parameter (" +
                  std::string(given_params ? "tau" : "coordinate time x^0") +
                  ") must increase strictly from event to event, but event " + std::to_string(i) + " has " +
                  number_text(p_[i]) + " after " + number_text(p_[i - 1]));

  // Natural cubic spline per coordinate (second derivatives zero at both ends): solve the
  // tridiagonal system h_{i-1} M_{i-1} + 2(h_{i-1}+h_i) M_i + h_i M_{i+1} = 6(Δ_i − Δ_{i-1})
  // (Press et al., Numerical Recipes, §3.3) with the Thomas algorithm.
  m2_.assign(n, Vec4{{0, 0, 0, 0}});
  if (n > 2) {
    std::vector<double> c(n, 0.0);
    std::vector<Vec4> d(n, Vec4{{0, 0, 0, 0}});
    for (size_t i = 1; i + 1 < n; ++i) {
      const double h0 = p_[i] - p_[i - 1], h1 = p_[i + 1] - p_[i];
      const double a = h0, b = 2 * (h0 + h1), cc = h1;
      Vec4 r;
      for (int mu = 0; mu < 4; ++mu)
        r[mu] = 6.0 * ((x_[i + 1][mu] - x_[i][mu]) / h1 - (x_[i][mu] - x_[i - 1][mu]) / h0);
      const double denom = b - a * c[i - 1];
      c[i] = cc / denom;
      d[i] = (1.0 / denom) * (r - a * d[i - 1]);
    }
    for (size_t i = n - 2; i >= 1; --i) {
      m2_[i] = d[i] - c[i] * m2_[i + 1];
      if (i == 1) break;
    }
  }

  // Proper time per interval with 5-point Gauss-Legendre quadrature (exact for polynomials of
  // degree 9; the integrand √(−g(x',x')) is smooth inside an interval).
  static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
  tau_.assign(n, tau0);
  for (size_t i = 0; i + 1 < n; ++i) {
    const double a = p_[i], b = p_[i + 1];
    double s = 0;
    for (int q = 0; q < 5; ++q) {
      const double p = 0.5 * (a + b) + 0.5 * (b - a) * gx[q];
      Vec4 x, dx, ddx;
      spline_eval(p, x, dx, ddx);
      const double nn = minus_norm2(m, x, dx);
      if (!(nn > 0))
        throw Error("Worldline motion: the worldline is not timelike between events " + std::to_string(i) + " and " +
                    std::to_string(i + 1) + " (g(dx/dp, dx/dp) = " + number_text(-nn) + " >= 0)");
      s += gw[q] * std::sqrt(nn);
    }
    tau_[i + 1] = tau_[i] + 0.5 * (b - a) * s;
  }

  // Initial tetrad: the given frame boosted to the four-velocity at the first event; then
  // Fermi-Walker transport event to event.
  const WorldlineState w0 = state_at_param(p_[0]);
  Tetrad e = tetrad_for_four_velocity(m, w0.x, frame, w0.u);
  auto make_node = [&](double tau, const WorldlineState& w, const Tetrad& et) {
    MotionNode nd;
    nd.tau = tau;
    nd.x = w.x;
    nd.u = w.u;
    Christoffel G;
    m.christoffel(w.x, G);
    for (int mu = 0; mu < 4; ++mu) {  // du/dτ = a − Γ(u,u)
      double s = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * w.u[a] * w.u[b];
      nd.du[mu] = w.a[mu] - s;
    }
    nd.e = et;
    fermi_walker_rhs(m, w, et, nd.de);
    return nd;
  };
  std::vector<MotionNode> nodes;
  nodes.reserve(n);
  nodes.push_back(make_node(tau_[0], w0, e));
  auto wl = [this](double tau) { return state_at(tau); };
  for (size_t i = 0; i + 1 < n; ++i) {
    e = fermi_walker_transport(m, wl, tau_[i], tau_[i + 1], e, fw);
    nodes.push_back(make_node(tau_[i + 1], state_at_param(p_[i + 1]), e));
  }
  set_nodes(std::move(nodes));
}

void WorldlineMotion::spline_eval(double p, Vec4& x, Vec4& dx, Vec4& ddx) const {
  size_t i = static_cast<size_t>(std::upper_bound(p_.begin(), p_.end(), p) - p_.begin());
  i = std::min(i == 0 ? 0 : i - 1, p_.size() - 2);
  const double h = p_[i + 1] - p_[i];
  const double A = (p_[i + 1] - p) / h, B = (p - p_[i]) / h;
  for (int mu = 0; mu < 4; ++mu) {
    const double y0 = x_[i][mu], y1 = x_[i + 1][mu], M0 = m2_[i][mu], M1 = m2_[i + 1][mu];
    x[mu] = A * y0 + B * y1 + ((A * A * A - A) * M0 + (B * B * B - B) * M1) * h * h / 6.0;
    dx[mu] = (y1 - y0) / h - (3 * A * A - 1) / 6.0 * h * M0 + (3 * B * B - 1) / 6.0 * h * M1;
    ddx[mu] = A * M0 + B * M1;
  }
}

WorldlineState WorldlineMotion::state_at_param(double p) const {
  const Metric& m = metric();
  Vec4 x, dx, ddx;
  spline_eval(p, x, dx, ddx);
  Mat4 g;
  m.metric_tensor(x, g);
  const double nn = -dot(g, dx, dx);
  if (!(nn > 0))
    throw Error("Worldline motion: the interpolated worldline is not timelike at parameter " + number_text(p));
  WorldlineState w;
  w.x = x;
  w.u = (1.0 / std::sqrt(nn)) * dx;
  // a = P_⊥(Dx'/dp)/N², Dx'/dp = x'' + Γ(x', x'), N² = −g(x', x').
  Christoffel G;
  m.christoffel(x, G);
  Vec4 D;
  for (int mu = 0; mu < 4; ++mu) {
    double s = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) s += G.G[mu][a][b] * dx[a] * dx[b];
    D[mu] = ddx[mu] + s;
  }
  const double du = dot(g, D, w.u);
  w.a = (1.0 / nn) * (D + du * w.u);
  return w;
}

double WorldlineMotion::param_at(double tau) const {
  // Invert τ(p) inside the interval holding tau: Newton with dτ/dp = √(−g(x',x')), bracketed.
  size_t i = static_cast<size_t>(std::upper_bound(tau_.begin(), tau_.end(), tau) - tau_.begin());
  i = std::min(i == 0 ? 0 : i - 1, tau_.size() - 2);
  double lo = p_[i], hi = p_[i + 1];
  if (tau <= tau_[i]) return lo;
  if (tau >= tau_[i + 1]) return hi;
  double p = lo + (hi - lo) * (tau - tau_[i]) / (tau_[i + 1] - tau_[i]);
  static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                               0.2369268850561891};
  const Metric& m = metric();
  auto speed = [&](double q) {
    Vec4 x, dx, ddx;
    spline_eval(q, x, dx, ddx);
    return std::sqrt(std::max(0.0, minus_norm2(m, x, dx)));
  };
  for (int iter = 0; iter < 60; ++iter) {
    double s = 0;  // τ(p) − τ_i by Gauss-Legendre on [p_i, p]
    for (int q = 0; q < 5; ++q) s += gw[q] * speed(0.5 * (p_[i] + p) + 0.5 * (p - p_[i]) * gx[q]);
    const double f = tau_[i] + 0.5 * (p - p_[i]) * s - tau;
    if (f > 0)
      hi = p;
    else
      lo = p;
    const double v = speed(p);
    double next = v > 0 ? p - f / v : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - p) <= 1e-15 * std::max(1.0, std::fabs(p))) return next;
    p = next;
  }
  return p;
}

WorldlineState WorldlineMotion::state_at(double tau) const { return state_at_param(param_at(tau)); }

// ---- init-motion type "Worldline" (GeoViS "file"; docs/geovis-catalogue.md §8) -------------------

namespace {

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
  if (events.size() < 2)
    ps.fail(key, "a Worldline motion needs at least 2 events, found " + std::to_string(events.size()));
  if (ps.has("localvel") || ps.has("vel"))
    ps.fail(ps.has("vel") ? "vel" : "localvel",
            "the velocity of a Worldline motion follows from its events; remove this key");
  TetradSpec spec = tetrad_spec_from_params(ps, false, events[0]);
  if (ps.has("pos")) ps.fail("pos", "the start of a Worldline motion is its first event; remove this key");
  Tetrad frame{};
  try {
    frame = build_tetrad(*metric, spec);
  } catch (const Error& err) {
    ps.fail("e0..e3", err.what());
  }
  const double tau0 = have_tau ? taus.front() : keys.number("tau0");
  return ps.blame(key, [&]() -> MotionPtr {
    return std::make_shared<WorldlineMotion>(metric, std::move(events), std::move(taus), frame, tau0);
  });
}

const TypeRegistrar<MotionType> worldline{
    {{"Worldline",
      {"file"},
      "a world line through given events, its frame Fermi-Walker transported",
      [] {
        auto keys = motion_frame_specs();
        const std::vector<ParamSpec> own = {
            {"points", ParamType::List, "events #(x0 x1 x2 x3) (or #(tau x0 x1 x2 x3) with havetau)"},
            {"filename", ParamType::String, "text file with one event per line"},
            {"havetau", ParamType::Bool, "events start with their proper time", false, false, false}};
        keys.insert(keys.end(), own.begin(), own.end());
        return keys;
      }()},
     make_worldline,
     true}};

}  // namespace

}  // namespace geovis

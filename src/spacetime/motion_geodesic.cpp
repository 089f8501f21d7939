#include "spacetime/motion_geodesic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/param_reader.h"
#include "spacetime/motion_factory.h"
#include "spacetime/tetrad.h"
#include "spacetime/transport.h"

namespace geovis {

namespace {

MotionNode node_from_state(double tau, const double* y, const double* dy) {
  MotionNode n;
  n.tau = tau;
  unpack_transport_state(y, n.x, n.u, n.e);
  for (int i = 0; i < 4; ++i) {
    n.du[i] = dy[4 + i];
    for (int a = 0; a < 4; ++a) n.de[a][i] = dy[8 + 4 * a + i];
  }
  return n;
}

}  // namespace

GeodesicMotion::GeodesicMotion(std::shared_ptr<const Metric> metric, const SolverConfig& solver, const Vec4& pos,
                               const Tetrad& e, double tau0, double forward, double backward, int max_points)
    : SampledMotion(metric) {
  const Metric& m = *metric;
  require_valid_position(m, pos, "Geodesic motion: start position");
  check_orthonormal(m, pos, e, 1e-8, "Geodesic motion: initial tetrad");
  if (!(forward >= 0) || !(backward >= 0))
    throw Error("Geodesic motion: forward and backward are proper-time ranges and must be >= 0 (found forward = " +
                std::to_string(forward) + ", backward = " + std::to_string(backward) + ")");
  if (max_points < 2)
    throw Error("Geodesic motion: maxnumpoints must be at least 2, found " + std::to_string(max_points));

  double y0[kTransportDim], dy0[kTransportDim];
  pack_transport_state(pos, e[0], e, y0);
  transport_rhs(m, y0, dy0);
  std::vector<MotionNode> fwd, bwd;
  const MotionNode start = node_from_state(tau0, y0, dy0);

  auto run = [&](double dir, double range, std::vector<MotionNode>& out) -> StopReason {
    if (range <= 0) return StopReason::LambdaMax;
    SolverConfig cfg = solver;
    cfg.type = GeodesicType::Timelike;
    cfg.direction = dir;
    cfg.lambda_max = range;
    cfg.max_steps = max_points - 1;
    double y[kTransportDim];
    std::copy(y0, y0 + kTransportDim, y);
    auto cb = [&](const StepView& st) {
      // The driver clips the last step to reach lambda_max exactly; after n fixed steps the
      // remainder can be a rounding-level step (e.g. 10 − 100·0.1 ≈ 2e-14). Such a sample would
      // duplicate the previous one, so it replaces it instead.
      const double prev = out.empty() ? tau0 : out.back().tau;
      const bool negligible = std::fabs(st.lambda1 - prev) <= 1e-9 * std::fabs(st.lambda1 - tau0);
      if (negligible && !out.empty())
        out.back() = node_from_state(st.lambda1, st.y1, st.dy1);
      else
        out.push_back(node_from_state(st.lambda1, st.y1, st.dy1));
      return StepAction::Continue;
    };
    return m.integrate(cfg, GeodesicSystem::Transport, y, tau0, cb).reason;
  };
  forward_stop_ = run(+1.0, forward, fwd);
  backward_stop_ = run(-1.0, backward, bwd);

  std::vector<MotionNode> nodes;
  nodes.reserve(fwd.size() + bwd.size() + 1);
  for (auto it = bwd.rbegin(); it != bwd.rend(); ++it) nodes.push_back(*it);
  nodes.push_back(start);
  for (const MotionNode& n : fwd) nodes.push_back(n);
  set_nodes(std::move(nodes));
}

// ---- init-motion type "Geodesic" (docs/geovis-catalogue.md §8) -----------------------------------

namespace {

MotionPtr make_geodesic(const ParamReader& keys, std::shared_ptr<const Metric> metric, const SolverConfig& solver) {
  const ParamSet& ps = keys.params();
  Vec4 pos;
  const Tetrad e = tetrad_from_params(ps, *metric, &pos);
  const double forward = keys.number("forward"), backward = keys.number("backward");
  if (forward == 0 && backward == 0)
    ps.fail("forward", "a Geodesic motion needs `forward` and/or `backward` (proper-time ranges > 0)");
  SolverConfig cfg = solver;
  if (ps.has("stepsize")) cfg.step_size = keys.number("stepsize");
  return keys.blame("pos", [&]() -> MotionPtr {
    return std::make_shared<GeodesicMotion>(metric, cfg, pos, e, keys.number("tau0"), forward, backward,
                                            keys.integer("maxnumpoints"));
  });
}

const TypeRegistrar<MotionType> geodesic{
    {{"Geodesic",
      {},
      "free fall: a timelike geodesic from an event and a velocity, sampled in proper time",
      [] {
        auto keys = motion_frame_specs();
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
            {"stepsize",
             ParamType::Number,
             "step size (overrides the solver's step_size)",
             false,
             false,
             {},
             ParamRange::positive()}};
        keys.insert(keys.end(), own.begin(), own.end());
        return keys;
      }()},
     make_geodesic,
     true}};

}  // namespace

}  // namespace geovis

#include "render/tracer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.h"
#include "spacetime/circular_orbit.h"
#include "spacetime/geodesic_packet.h"
#include "spacetime/jacobi.h"
#include "spacetime/metric.h"
#include "spacetime/straight_ray.h"

namespace geovis {

/// State of the hit search of one ray (tracer.h).
struct RayState {
  /// One end of a step's chord: its chart and squared distance |p|² from the origin, and the
  /// pseudo-Cartesian point p itself where it is known (have_p).
  struct ChordEnd {
    Vec3 p;
    double radius2 = 0;
    int chart = 0;
    bool have_p = false;
  };
  const Metric* metric;
  const SceneObject* scene;
  const SegmentCull* cull = nullptr;
  bool hit = false;
  Hit best;         ///< the refined hit; until a chord hits, the fresh Hit its tests fill (test_chord)
  double frac = 0;  ///< refined hit position as fraction of the step
  double lambda0 = 0, lambda1 = 0;
  double y0[kMaxSystemDim], y1[kMaxSystemDim], dy0[kMaxSystemDim], dy1[kMaxSystemDim];
  int dim = 8;
  // The end of the previous step = the start of the next one (saves one transformation).
  bool have_prev = false;
  ChordEnd prev;
};

namespace {

inline Vec4 vec4_at(const double* y) { return Vec4{{y[0], y[1], y[2], y[3]}}; }

bool is_zero(const Vec4& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0; }

/// Refines a hit found on the chord of step `st` (fraction `s0` of the chord, hit `h`): the curved
/// step (cubic Hermite dense output of the integrator, geodesic.h) is split into 4 sub-chords, the
/// first one that hits becomes the new interval, until the curve deviates from the chord by less
/// than the tolerance. Returns false when the chord hit but none of its sub-chords does: the
/// curve passes the object (a grazing ray whose chord cuts a corner of it); else the hit and its
/// fraction of the step. Each sub-chord is tested with the hit it refines (Segment::refines): a
/// local object starts its search in the frame it found that hit in.
bool refine_hit(const StepView& st, const Segment& chord, const SceneObject& scene, const Metric& m, Hit& best,
                double& frac) {
  double a = 0, b = 1;
  Vec4 xa = chord.x0, xb = chord.x1;
  Vec3 pa = chord.p0, pb = chord.p1;
  int ca = chord.chart0, cb = chord.chart1;
  frac = best.s;
  for (int level = 0; level < Tracer::kMaxRefineLevels; ++level) {
    // Deviation of the curve from the chord at the middle of the interval (sagitta).
    Vec4 xm, km;
    hermite_interpolate(st, 0.5 * (a + b), xm, km);
    Vec3 pm;
    m.to_pseudo_cartesian(xm, pm);
    const double sag = norm(pm - 0.5 * (pa + pb));
    const double tol = Tracer::kRefineTolerance * (1.0 + norm(pm));
    if (!(sag > tol)) break;
    bool found = false;
    Vec4 xp = xa;
    Vec3 pp = pa;
    int cp = ca;
    for (int i = 1; i <= 4; ++i) {
      const double f0 = a + (b - a) * (i - 1) / 4.0, f1 = i == 4 ? b : a + (b - a) * i / 4.0;
      Vec4 xi, ki;
      Vec3 pi;
      int ci;
      if (i == 4) {
        xi = xb;
        pi = pb;
        ci = cb;
      } else if (i == 2) {
        xi = xm;
        pi = pm;
        ci = m.to_pseudo_cartesian(xi, pi);
      } else {
        hermite_interpolate(st, f1, xi, ki);
        ci = m.to_pseudo_cartesian(xi, pi);
      }
      Segment sub{xp, xi, pp, pi, cp, ci, &st, &m, &best};
      Hit h;
      if (scene.intersect(sub, h)) {
        best = h;
        frac = f0 + h.s * (f1 - f0);
        a = f0;
        b = f1;
        xa = xp;
        pa = pp;
        ca = cp;
        xb = xi;
        pb = pi;
        cb = ci;
        found = true;
        break;
      }
      xp = xi;
      pp = pi;
      cp = ci;
    }
    // The chord hit but the closer approximation of the curve does not (grazing ray).
    if (!found) return false;
  }
  return true;
}

// ---- the steps of one ray (Tracer::trace_direction) ---------------------------------------------

/// Start state: the observer's event and the past-directed null tangent k = −e_(0) + n^i e_(i)
/// (paper eq. 7); for the Jacobi filter also the Sachs basis s_a ⟂ k, u_obs and the Jacobi fields
/// Y_a(0) = 0, Y_a'(0) = s_a (a bundle with its vertex at the observer, jacobi.h). Returns k.
Vec4 start_state(const Observer& obs, const Vec3& n, GeodesicSystem system, double* y) {
  const Vec4 k0 = local_null_direction(obs.e, n, true);
  for (int i = 0; i < 4; ++i) {
    y[i] = obs.pos[i];
    y[4 + i] = k0[i];
  }
  if (system == GeodesicSystem::Jacobi) {
    Vec3 s1, s2;
    screen_basis(n, s1, s2);  // a Sachs basis at the observer (Perlick 2004, §4)
    const Vec4 c1 = local_to_coord(obs.e, Vec4{{0, s1.x, s1.y, s1.z}});
    const Vec4 c2 = local_to_coord(obs.e, Vec4{{0, s2.x, s2.y, s2.z}});
    for (int i = 0; i < 4; ++i) {
      y[kJacobiS1 + i] = c1[i];
      y[kJacobiS2 + i] = c2[i];
      y[kJacobiDY1 + i] = c1[i];
      y[kJacobiDY2 + i] = c2[i];
    }
  }
  return k0;
}

/// The ray's geodesic: integrated, or in a flat metric in inertial Cartesian coordinates the exact
/// straight line as one step (spacetime/straight_ray.h; `straight`).
GeodesicResult integrate_ray(const Metric& m, bool straight, const SolverConfig& cfg, GeodesicSystem system, double* y,
                             StepCallback cb) {
  if (straight) return integrate_straight(cfg, system, y, 0.0, m.asymptotically_flat(), cb);
  return m.integrate(cfg, system, y, 0.0, cb);
}

/// The end at metric coordinates x, transformed to its pseudo-Cartesian point. Built from locals:
/// p written through a reference into the end kept the end in memory, and its copy to
/// RayState::prev then loaded wide words over the narrow stores just made (a store-forwarding
/// stall, a third of test_step's time in perf annotate).
GEOVIS_HOT_INLINE RayState::ChordEnd transformed_end(const Metric& m, const Vec4& x) {
  Vec3 p;
  const int chart = m.to_pseudo_cartesian(x, p);
  return {p, dot(p, p), chart, true};
}

/// The end at metric coordinates x = y[0..4) (the integrator's pseudo-Cartesian point `given`,
/// chart 0, where it has one): only its chart and radius where the metric gives them without
/// transforming x (Metric::pseudo_cartesian_radius), else the transformed point. x is read only
/// without `given` (as a Vec4 argument it was copied to the stack on every step, used or not).
GEOVIS_HOT_INLINE RayState::ChordEnd chord_end(const Metric& m, const double* y, const double* given) {
  if (given) {
    const Vec3 p{given[0], given[1], given[2]};
    return {p, dot(p, p), 0, true};
  }
  const Vec4 x = vec4_at(y);
  double radius;
  int chart;
  if (m.pseudo_cartesian_radius(x, radius, chart)) return {Vec3{}, radius * radius, chart, false};
  return transformed_end(m, x);
}

/// The scene's test of the chord of step `st` from p0 in chart0 to p1 in chart1 (test_step); a
/// chord hit is refined on the curved step (refine_hit) and stops the ray. Not inlined, and the
/// ends by value: test_step skips most steps, and without this function's frame (the segment, the
/// hit) and with its chord ends in registers it does so in a few instructions.
[[gnu::noinline]] StepAction test_chord(RayState& rs, const StepView& st, Vec3 p0, Vec3 p1, int chart0, int chart1) {
  st.ensure_states();  // the packet integrator's states on request (PacketRays::states_on_request)
  const Metric& mm = *rs.metric;
  const Segment seg{vec4_at(st.y0), vec4_at(st.y1), p0, p1, chart0, chart1, &st, &mm};
  // rs.best is a fresh Hit until a chord hits, and an object that finds no hit leaves it as it is
  // (SceneObject::intersect): no 200-byte Hit to clear per tested chord (rep stos, half of this
  // function's time on sphereAroundBlackhole in perf annotate).
  if (!rs.scene->intersect(seg, rs.best)) return StepAction::Continue;
  if (!refine_hit(st, seg, *rs.scene, mm, rs.best, rs.frac)) {
    rs.best = Hit{};  // a grazing ray: no hit, the next chords are tested afresh
    return StepAction::Continue;
  }
  rs.hit = true;
  rs.lambda0 = st.lambda0;
  rs.lambda1 = st.lambda1;
  rs.dim = st.dim;
  for (int i = 0; i < st.dim; ++i) {
    rs.y0[i] = st.y0[i];
    rs.y1[i] = st.y1[i];
    rs.dy0[i] = st.dy0[i];
    rs.dy1[i] = st.dy1[i];
  }
  return StepAction::Stop;
}

/// test_step in general: either end may still have to be transformed (Metric calls), or be the
/// ray's first. Not inlined: its frame and saved registers stay off test_step's common path.
[[gnu::noinline]] StepAction test_step_general(RayState& rs, const StepView& st) {
  const Metric& mm = *rs.metric;
  RayState::ChordEnd e0 = rs.have_prev ? rs.prev : chord_end(mm, st.y0, st.p0);
  RayState::ChordEnd e1 = chord_end(mm, st.y1, st.p1);
  rs.have_prev = true;
  rs.prev = e1;
  const SegmentCull& cull = *rs.cull;
  if (cull.inside_empty_ball(e0.chart, e0.radius2, e1.chart, e1.radius2)) return StepAction::Continue;
  // Both pseudo-Cartesian ends (the charts from the radius agree with to_pseudo_cartesian's,
  // Metric::pseudo_cartesian_radius).
  if (!e0.have_p) e0 = transformed_end(mm, vec4_at(st.y0));
  if (!e1.have_p) {
    e1 = transformed_end(mm, vec4_at(st.y1));
    rs.prev = e1;
  }
  if (cull.outside_bounds(e0.p, e1.p)) return StepAction::Continue;
  return test_chord(rs, st, e0.p, e1.p, e0.chart, e1.chart);
}

/// test_step's common case (below) for a step whose view `view()` gives (a StepView, or a
/// reference to one) and whose end's pseudo-Cartesian position p1 (chart 0) is known without it:
/// the view is made only for a chord that is tested, or for the ray's first step (the packet's
/// batched steps in Mino time, PacketSteps::p1).
template <class View>
GEOVIS_HOT_INLINE StepAction test_step_at(RayState& rs, const Vec3& p1, View&& view) {
  if (!rs.scene) return StepAction::Continue;
  if (!(rs.have_prev && rs.prev.have_p)) return test_step_general(rs, view());
  const RayState::ChordEnd e0 = rs.prev;
  rs.prev = RayState::ChordEnd{p1, dot(p1, p1), 0, true};
  const SegmentCull& cull = *rs.cull;
  if (cull.inside_empty_ball(e0.chart, e0.radius2, 0, rs.prev.radius2)) return StepAction::Continue;
  if (cull.outside_bounds(e0.p, p1)) return StepAction::Continue;
  decltype(auto) st = view();
  return test_chord(rs, st, e0.p, p1, e0.chart, 0);
}

/// The hit search's test of one accepted step: its chord (pseudo-Cartesian segment, paper §2.3)
/// against the scene (test_chord), unless the chord lies in the scene's empty ball of its chart
/// or beyond its bounding box (SegmentCull: a few compares, before the ends are transformed where
/// the ball already excludes the chord). The common case of an integrator that gives each step's
/// pseudo-Cartesian end (StepView::p1: the Mino-time paths), after a first step whose end was
/// such a point too, here: test_step_general's steps with both ends known (chart 0), no Metric
/// call.
StepAction test_step(RayState& rs, const StepView& st) {
  if (!rs.scene) return StepAction::Continue;
  if (!st.p1) return test_step_general(rs, st);
  return test_step_at(rs, Vec3{st.p1[0], st.p1[1], st.p1[2]}, [&st]() -> const StepView& { return st; });
}

/// Hit search: integrates the ray (integrate_ray) and tests every accepted step (test_step).
/// `observe_step` (may be empty) sees every step first.
GeodesicResult search_hit(const Metric& m, bool straight, const SolverConfig& cfg, GeodesicSystem system, double* y,
                          RayState& rs, FunctionRef<void(const StepView&)> observe_step) {
  auto on_step = [&rs, observe_step](const StepView& st) -> StepAction {
    if (observe_step) observe_step(st);
    return test_step(rs, st);
  };
  return integrate_ray(m, straight, cfg, system, y, on_step);
}

/// A ray without a hit ends where the integration stopped. With the Jacobi filter, the Jacobi
/// fields ride along without acting on the ray, but they diverge at a horizon and can stop the
/// step control before the ray reaches the metric's break radius; the ray's fate must not depend
/// on the filter (GeoViS gives a ray that runs into the hole its constraint colour in every
/// filter), so the geodesic alone, integrated again from `y_start`, decides how it ends.
void end_without_hit(const Metric& m, bool straight, const SolverConfig& cfg, GeodesicSystem system, const double* y,
                     const double* y_start, const GeodesicResult& gr, TraceStats& stats, TraceResult& res) {
  res.pos = vec4_at(y);
  res.k = vec4_at(y + 4);
  res.lambda = gr.lambda;
  res.reason = gr.reason;
  if (system == GeodesicSystem::Jacobi && (gr.reason == StopReason::StepUnderflow ||
                                           gr.reason == StopReason::NotFinite || gr.reason == StopReason::MaxSteps)) {
    double yg[kMaxSystemDim] = {};
    for (int i = 0; i < 8; ++i) yg[i] = y_start[i];
    const GeodesicResult g2 = integrate_ray(m, straight, cfg, GeodesicSystem::Geodesic, yg, {});
    stats.steps += g2.steps;
    stats.rhs_evals += g2.rhs_evals;
    res.reason = g2.reason;
  }
}

/// Frequency ratio ω_src/ω_obs with ω = −g(p, u) for the future-directed photon momentum p = −k
/// (e.g. Misner-Thorne-Wheeler eq. 2.34 / Catalogue of Spacetimes §1.3). The source moves with
/// the object's emitter velocity, else on a Keplerian orbit where the object asks for it, else
/// with the static observer; 0 where none exists (e.g. inside an ergoregion).
double frequency_shift(const Metric& m, const Observer& obs, const Vec4& k0, const Hit& hit, const Vec4& pos,
                       const Vec4& k) {
  Mat4 g;
  m.metric_tensor(obs.pos, g);
  const double w_obs = dot(g, k0, obs.e[0]);  // = 1 for the normalised k of eq. 7
  Vec4 u_src = hit.emitter_u;
  bool have_u = !is_zero(u_src);
  if (!have_u && hit.keplerian) {
    have_u = circular_orbit_velocity(m, pos, u_src);  // false inside the photon orbit
  } else if (!have_u) {
    try {
      u_src = m.natural_tetrad(pos, TetradKind::Default)[0];
      have_u = true;
    } catch (const Error&) {
      have_u = false;  // no static observer there: no shift known
    }
  }
  if (!have_u || w_obs == 0) return 0.0;
  m.metric_tensor(pos, g);
  return dot(g, k, u_src) / w_obs;
}

/// The Jacobi matrix J_ab = g(s_a, Y_b) at the hit (res.pos, the Hermite-interpolated event), and
/// its lensing parameters (jacobi.h). Y_b is interpolated inside the step by the cubic Hermite
/// polynomial on its values and λ-derivatives at both ends (as hermite_interpolate does for x):
/// O(h⁴) instead of the O(h²) of GeoViS's linear interpolation of J, so the lensing data at the hit
/// does not depend on the length of the step. The screen s_a there is the transport of the
/// observer's (`start`: the start state, jacobi.h layout) in closed form where the metric has one
/// and the rays run through separated equations (`closed_form_screen`; Metric::transported_screen:
/// the steps of that path carry no s_a, spacetime/kerr_jacobi.h), else interpolated as Y_b.
void jacobi_at_hit(const Metric& m, const RayState& rs, const double* start, bool closed_form_screen,
                   TraceResult& res) {
  const double h = rs.lambda1 - rs.lambda0, s = rs.frac, s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  auto hermite = [&](int i) { return h00 * rs.y0[i] + h10 * h * rs.dy0[i] + h01 * rs.y1[i] + h11 * h * rs.dy1[i]; };
  double y[kJacobiDim];
  for (int i = 0; i < 4; ++i) {
    y[kJacobiX + i] = res.pos[i];
    y[kJacobiY1 + i] = hermite(kJacobiY1 + i);
    y[kJacobiY2 + i] = hermite(kJacobiY2 + i);
  }
  const Vec4 s0[2] = {vec4_at(start + kJacobiS1), vec4_at(start + kJacobiS2)};
  Vec4 screen[2];
  if (closed_form_screen &&
      m.transported_screen(vec4_at(start), vec4_at(start + kJacobiK), s0, res.pos, res.k, screen)) {
    for (int i = 0; i < 4; ++i) {
      y[kJacobiS1 + i] = screen[0][i];
      y[kJacobiS2 + i] = screen[1][i];
    }
  } else {
    for (int i = kJacobiS1; i < kJacobiY1; ++i) y[i] = hermite(i);
  }
  double J[4];
  jacobi_matrix(m, y, J);
  for (int i = 0; i < 4; ++i) res.jacobi_matrix[i] = J[i];
  const JacobiParams jp = jacobi_params(J, res.lambda);
  res.jacobi[0] = jp.d_plus;
  res.jacobi[1] = jp.d_minus;
  res.jacobi[2] = jp.mu;
  res.jacobi[3] = jp.angle;
  res.jacobi[4] = jp.ellipticity;
}

/// Shading (paper §2.4) of the hit, with shadow rays to the point lights where light travels on
/// straight lines (MetricInfo::inertial_cartesian) and the object is at rest.
Color shade_hit(const RenderJob& job, bool point_lights, const Hit& hit, const Vec4& pos) {
  if (!hit.shader) return Color{1, 1, 1};
  const Metric& m = *job.metric;
  if (point_lights && is_zero(hit.emitter_u)) {
    // Flat inertial coordinates and an object at rest: the shadow ray is the straight light ray
    // from the light to the hit point, arriving there at the hit's time t, traced backwards
    // (GeoViS GvsSurfaceShader::reflLightColor: direction (−1, l̂)): it left the light at
    // t − |l − p|, so moving objects cast their shadow from where they were when the light
    // passed them.
    const SceneObject* scene = job.scene.get();
    const double t = pos[0];
    auto visible = [scene, &m, t](const Vec3& p, const PointLight& light) -> bool {
      const Vec3 lp{light.pos[1], light.pos[2], light.pos[3]};
      const Vec3 dl = lp - p;
      const double len = norm(dl);
      if (!(len > 0)) return true;
      // Start just off the surface so that the surface itself does not shadow the point.
      const double eps = 1e-9 * (1.0 + norm(p)) + 1e-9 * len;
      const Vec3 p0 = p + (eps / len) * dl;
      Segment seg{Vec4{{t - eps, p0.x, p0.y, p0.z}}, Vec4{{t - len, lp.x, lp.y, lp.z}}, p0, lp, 0, 0, nullptr, &m};
      Hit h;
      return !(scene->intersect(seg, h) && h.s <= 1.0);
    };
    ShadeContext ctx{&job.lights, visible};
    return hit.shader->shade(hit, ctx);
  }
  ShadeContext ctx{&job.lights, {}};
  return hit.shader->shade(hit, ctx);
}

}  // namespace

Tracer::Tracer(const RenderJob& job) : job_(job), cfg_(job.solver) {
  if (!job.metric) throw Error("render: the job has no metric");
  if (!job.camera) throw Error("render: the job has no camera");
  if (job.supersample < 1)
    throw Error("render: supersample: expected a positive integer, found " + std::to_string(job.supersample));
  if (cfg_.max_steps < 1) throw Error("render: maxNumPoints: expected a positive number of steps");
  // Light rays start with the past-directed tangent k = −e_(0) + d^i e_(i) (eq. 7) and are
  // integrated forward in the affine parameter: GeoViS forces a raygen's solver to
  // lightlike/backward, which is this.
  cfg_.type = GeodesicType::Lightlike;
  cfg_.direction = 1.0;
  system_ = job.filter == Filter::RGBjac ? GeodesicSystem::Jacobi : GeodesicSystem::Geodesic;
  // Escape (geodesic.h): nothing to hit beyond the scene's bounding sphere; an empty scene has
  // none, an unbounded object (or unknown bounds) keeps every ray going.
  cfg_.escape_radius = 0.0;
  if (job.scene) {
    const Bounds3 b = job.scene->bounds();
    if (!b.empty()) {
      double r2 = 0;
      for (double x : {b.lo.x, b.hi.x})
        for (double y : {b.lo.y, b.hi.y})
          for (double z : {b.lo.z, b.hi.z}) r2 = std::max(r2, x * x + y * y + z * z);
      cfg_.escape_radius = std::sqrt(r2);  // +inf for unbounded objects
    }
  }
  // Capture (geodesic.h): nothing to hit below the scene's innermost radius (0 when an object may
  // reach the origin or its bounds are unknown: never); nothing at all without a scene. Nor inside
  // the ball that holds no surface in any chart (SegmentCull's, shrunk by its margin): a solid
  // around the hole (GeoViS's background spheres) is hit only where a chord crosses its surface,
  // and every chord of a captured ray lies below the radius of its start (capture.h).
  cfg_.capture_radius = job.scene ? job.scene->inner_radius() : std::numeric_limits<double>::infinity();
  if (job.scene) {
    cull_ = SegmentCull(*job.scene);
    double empty_ball = std::numeric_limits<double>::infinity();
    for (int c = 0; c < SegmentCull::kCharts; ++c) empty_ball = std::min(empty_ball, cull_.radius(c));
    cfg_.capture_radius = std::max(cfg_.capture_radius, empty_ball);
  }
  point_lights_ = job.metric->info().inertial_cartesian && job.lights.shadows && !job.lights.lights.empty();
  // Flat inertial coordinates: the rays are straight lines, no integrator (spacetime/straight_ray.h).
  // Here and not in the metric's integrate(): only the renderer's light rays are one step each —
  // motions along geodesics need their worldline sampled, `geovis geodesic` prints the steps — and
  // the objects test such a step whole however long it is (render/local_object.h).
  straight_ = job.metric->info().inertial_cartesian;
  // Packets (spacetime/geodesic_packet.h): the geodesic system with an embedded Runge–Kutta pair
  // (packet_solver: Cash–Karp, Fehlberg, Dormand–Prince 5(4), DOP853), in the metric's
  // coordinates or through Carter's separated equations (Metric::integrate_packet chooses as
  // integrate does), also RGBjac's geodesic pass (jacobi_hits_only_) and its Jacobi pass
  // (Metric::integrate_jacobi_packet); other solvers stay scalar, and straight rays need no
  // integrator at all.
  jacobi_hits_only_ = system_ == GeodesicSystem::Jacobi;
  packets_ = packet_solver(cfg_.kind) && !straight_;
  if (job.reference_tracing) {
    straight_ = packets_ = jacobi_hits_only_ = false;
    cfg_.escape_radius = std::numeric_limits<double>::infinity();  // SolverConfig: no escape test
    cfg_.capture_radius = 0.0;                                     // no capture test
    cull_ = SegmentCull{};                                         // every step tested
  }
}

TraceResult Tracer::trace_direction(const Vec3& d, TraceStats& stats) const { return trace_direction(d, stats, {}); }

TraceResult Tracer::trace_direction(const Vec3& d, TraceStats& stats,
                                    FunctionRef<void(const StepView&)> observe_step) const {
  ++stats.rays;
  // RGBjac: the Jacobi fields only for a ray that hits (jacobi_hits_only_). A ray the geodesic pass
  // sees miss keeps that result, which has no lensing data (fill_data); one that hits is traced
  // again with its fields and keeps that second result whole (its hit and its data), so every
  // pixel's colour and data come from one traced ray. The steps of both passes are counted. A
  // caller watching the steps (the viewer) sees one pass.
  if (jacobi_hits_only_ && !observe_step) {
    TraceResult g = trace_system(GeodesicSystem::Geodesic, d, stats, {});
    if (!g.hit) return g;
  }
  return trace_system(system_, d, stats, observe_step);
}

TraceResult Tracer::trace_system(GeodesicSystem system, const Vec3& d_in, TraceStats& stats,
                                 FunctionRef<void(const StepView&)> observe_step) const {
  const Metric& m = *job_.metric;
  double y[kMaxSystemDim] = {};
  const Vec4 k0 = start_state(job_.observer, normalize(d_in), system, y);
  double y_start[kJacobiY1];  // x, k and, for the Jacobi system, the observer's screen s_a
  for (int i = 0; i < kJacobiY1; ++i) y_start[i] = y[i];

  RayState rs;
  rs.metric = &m;
  rs.scene = job_.scene.get();
  rs.cull = &cull_;
  const GeodesicResult gr = search_hit(m, straight_, cfg_, system, y, rs, observe_step);
  return end_ray(system, rs, k0, y, y_start, gr, stats);
}

TraceResult Tracer::end_ray(GeodesicSystem system, const RayState& rs, const Vec4& k0, const double* y,
                            const double* y_start, const GeodesicResult& gr, TraceStats& stats) const {
  TraceResult res;
  res.traced = true;
  const Metric& m = *job_.metric;
  stats.steps += gr.steps;
  stats.rhs_evals += gr.rhs_evals;
  res.reason = gr.reason;
  if (!rs.hit) {
    end_without_hit(m, straight_, cfg_, system, y, y_start, gr, stats, res);
    res.color = stop_color(res.reason);
    return res;
  }

  // The refined hit event and tangent on the curved step.
  res.hit = true;
  res.hit_info = rs.best;
  const StepView st{rs.lambda0, rs.lambda1, rs.y0, rs.y1, rs.dy0, rs.dy1, rs.dim, 0};
  hermite_interpolate(st, rs.frac, res.pos, res.k);
  res.lambda = rs.lambda0 + rs.frac * (rs.lambda1 - rs.lambda0);
  res.freqshift = frequency_shift(m, job_.observer, k0, rs.best, res.pos, res.k);
  if (system == GeodesicSystem::Jacobi) jacobi_at_hit(m, rs, y_start, cfg_.separable, res);
  res.color = shade_hit(job_, point_lights_, rs.best, res.pos);
  return res;
}

void Tracer::trace_pixels(std::span<const PixelSample> samples, Color* colors, TraceStats& stats) const {
  if (!packets_) {
    for (size_t i = 0; i < samples.size(); ++i)
      trace_pixel(samples[i].px, samples[i].py, colors[i], samples[i].data, stats);
    return;
  }
  // Each lane's ray: its sample, start and hit search, as trace_direction keeps them on its stack.
  struct LaneRay {
    size_t sample;
    Vec3 d;  // the local direction (RGBjac: a ray that hits is traced again, trace_direction)
    Vec4 k0;
    double y_start[8];  // x, k: packets trace the geodesic system only (no screen, jacobi_at_hit)
    RayState rs;
  };
  LaneRay lanes[kPacketLanes];
  // The previous chord ends of the lanes' rays where they are pseudo-Cartesian points of chart 0
  // (RayState::prev with have_p, the common case of the steps in Mino time, which give their
  // ends' positions), SoA, for the cull of a round's chords at once (on_steps_at); there they
  // replace rs.prev, which is stale. Two sets, the current one (starts[current]) and the one the
  // cull writes the next ends to.
  struct ChordStarts {
    alignas(64) double p[3][kPacketLanes];
    alignas(64) double radius2[kPacketLanes];
  } starts[2] = {};
  int current = 0;
  unsigned starts_here = 0;  // bit l: lane l's previous chord end is in starts[current]
  const Metric& m = *job_.metric;
  size_t next = 0;
  auto next_ray = [&](int lane, double* y) {
    for (; next < samples.size(); ++next) {
      const PixelSample& s = samples[next];
      Vec3 d;
      if (!job_.camera->direction(s.px, s.py, d)) {
        // No ray there (trace_pixel).
        colors[next] = job_.error_color.value_or(Color{0, 0, 0});
        if (s.data) *s.data = PixelData{};
        continue;
      }
      ++stats.rays;
      LaneRay& r = lanes[lane];
      r.sample = next++;
      r.d = d;
      double ys[kMaxSystemDim];
      r.k0 = start_state(job_.observer, normalize(d), GeodesicSystem::Geodesic, ys);
      for (int i = 0; i < 8; ++i) y[i] = r.y_start[i] = ys[i];
      r.rs = RayState{};
      starts_here &= ~(1u << lane);
      r.rs.metric = &m;
      r.rs.scene = job_.scene.get();
      r.rs.cull = &cull_;
      return true;
    }
    return false;
  };
  auto on_step = [&](int lane, const StepView& st) { return test_step(lanes[lane].rs, st); };
  // The steps of a round of the packet in Mino time, with the positions of their ends
  // (PacketSteps::p1): test_step's common case on those, a lane's view (a call into the
  // integrator) made only for a chord that is tested (test_step_at). After a ray's first step its
  // chords run from chart-0 point to chart-0 point, and those of all lanes are culled at once
  // (SegmentCull::chart0_chords_skipped, from the previous ends kept in `starts`): only the chords
  // that are not are tested (test_chord) lane by lane.
  auto on_steps_at = [&](const PacketSteps& steps) {
    constexpr int W = kPacketLanes;
    unsigned stop = 0;
    if (!job_.scene) return stop;  // test_step_at's first test, the same for every lane
    const unsigned batched = steps.lanes & starts_here;
    const ChordStarts& from = starts[current];
    ChordStarts& next = starts[current ^ 1];
    const unsigned tested =
        batched & ~cull_.chart0_chords_skipped(batched, from.p[0], from.radius2, steps.p1, next.p[0], next.radius2);
    current ^= 1;
    for (unsigned todo = tested; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      double views[4][8];
      const StepView st = steps.view(l, views);
      const Vec3 p0{from.p[0][l], from.p[1][l], from.p[2][l]}, p1{steps.p1[l], steps.p1[W + l], steps.p1[2 * W + l]};
      if (test_chord(lanes[l].rs, st, p0, p1, 0, 0) == StepAction::Stop) stop |= 1u << l;
    }
    // A ray's first step (or one whose previous end is no chart-0 point): test_step_at, after
    // which its end is kept in `starts` where it is such a point.
    for (unsigned todo = steps.lanes & ~batched; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      RayState& rs = lanes[l].rs;
      const Vec3 p1{steps.p1[l], steps.p1[W + l], steps.p1[2 * W + l]};
      double views[4][8];
      auto view = [&steps, &views, l] { return steps.view(l, views); };
      if (test_step_at(rs, p1, view) == StepAction::Stop) stop |= 1u << l;
      if (rs.have_prev && rs.prev.have_p && rs.prev.chart == 0) {
        for (int i = 0; i < 3; ++i) next.p[i][l] = rs.prev.p[i];
        next.radius2[l] = rs.prev.radius2;
        starts_here |= 1u << l;
      }
    }
    return stop;
  };
  // The steps of a round of the packet in the metric's coordinates: test_step of each lane's step,
  // its common case first without the step's view — after a first step, a chord whose new end's
  // radius (for all lanes at once: Metric::pseudo_cartesian_radii) puts it in the scene's empty
  // ball is skipped (test_step_general's result and RayState::prev for it). The per-step virtual
  // radius, the lane's gathered StepView and the call per lane and step were ~150 instructions per
  // step on fallEddFinkIn, where nearly every chord lies in the empty ball (callgrind, issue 13).
  // (ray_state(l): lane l's RayState; the geodesic pass's lanes or, for RGBjac's Jacobi pass in
  // the metric's coordinates, its own.)
  auto coordinate_steps = [&](const PacketSteps& steps, auto&& ray_state) {
    double radius[kPacketLanes];
    int chart[kPacketLanes];
    m.pseudo_cartesian_radii(steps.y1, steps.lanes, radius, chart);
    unsigned stop = 0;
    for (unsigned todo = steps.lanes; todo != 0; todo &= todo - 1) {
      const int l = std::countr_zero(todo);
      RayState& rs = ray_state(l);
      if (rs.have_prev) {
        const double radius2 = radius[l] * radius[l];
        if (cull_.inside_empty_ball(rs.prev.chart, rs.prev.radius2, chart[l], radius2)) {
          // chord_end's end without its point (which is read only where have_p); the fields one by
          // one: a whole ChordEnd built on the stack and copied cost a third of this path.
          rs.prev.radius2 = radius2;
          rs.prev.have_p = false;
          continue;  // the chart is the same
        }
      }
      double views[4][kMaxSystemDim];
      if (test_step(rs, steps.view(l, views)) == StepAction::Stop) stop |= 1u << l;
    }
    return stop;
  };
  auto on_steps = [&](const PacketSteps& steps) {
    if (steps.p1) return on_steps_at(steps);
    return coordinate_steps(steps, [&](int l) -> RayState& { return lanes[l].rs; });
  };
  // RGBjac: the rays that hit, traced again with their Jacobi fields (trace_direction) a batch at a
  // time after the geodesic pass (or when the batch is full), in packets (Metric::
  // integrate_jacobi_packet: the Kerr family in Mino time, the others in their coordinates with
  // the steps a round at a time, coordinate_steps). Each ray's result as trace_system's: the same
  // start, steps, hit search and end (end_ray).
  struct HitRay {
    size_t sample;
    Vec3 d;
  };
  constexpr size_t kHitBatch = 256;
  HitRay hits[kHitBatch];
  size_t n_hits = 0;
  auto keep = [&](size_t sample, const TraceResult& res) {
    colors[sample] = res.color;
    if (samples[sample].data) fill_data(res, *samples[sample].data);
  };
  auto retrace_hits = [&] {
    struct JacobiLane {
      size_t sample;
      Vec4 k0;
      double y_start[kJacobiY1];  // x, k and the observer's screen s_a (jacobi_at_hit)
      RayState rs;
    };
    JacobiLane jacobi_lanes[kPacketLanes];
    size_t next_hit = 0;
    auto next_jacobi = [&](int lane, double* y) {
      if (next_hit == n_hits) return false;
      const HitRay& h = hits[next_hit++];
      JacobiLane& r = jacobi_lanes[lane];
      r.sample = h.sample;
      std::fill(y, y + kJacobiDim, 0.0);
      r.k0 = start_state(job_.observer, normalize(h.d), system_, y);
      std::copy(y, y + kJacobiY1, r.y_start);
      r.rs = RayState{};
      r.rs.metric = &m;
      r.rs.scene = job_.scene.get();
      r.rs.cull = &cull_;
      return true;
    };
    auto on_jacobi_step = [&](int lane, const StepView& st) { return test_step(jacobi_lanes[lane].rs, st); };
    auto on_jacobi_steps = [&](const PacketSteps& steps) {
      return coordinate_steps(steps, [&](int l) -> RayState& { return jacobi_lanes[l].rs; });
    };
    auto jacobi_done = [&](int lane, const double* y, const GeodesicResult& gr) {
      const JacobiLane& r = jacobi_lanes[lane];
      keep(r.sample, end_ray(system_, r.rs, r.k0, y, r.y_start, gr, stats));
    };
    // test_step reads the states of a step only in test_chord, after ensure_states.
    // The packets' solvers (packet_tracing) are the ones integrate_jacobi_packet takes.
    if (!m.integrate_jacobi_packet(cfg_,
                                   JacobiPacketRays{next_jacobi, on_jacobi_step, jacobi_done, true, on_jacobi_steps}))
      throw std::logic_error("Tracer: the Jacobi pass has no packet path for the packets' solver");
    n_hits = 0;
  };
  auto done = [&](int lane, const double* y, const GeodesicResult& gr) {
    const LaneRay& r = lanes[lane];
    const TraceResult res = end_ray(GeodesicSystem::Geodesic, r.rs, r.k0, y, r.y_start, gr, stats);
    if (jacobi_hits_only_ && res.hit) {
      hits[n_hits++] = HitRay{r.sample, r.d};
      if (n_hits == kHitBatch) retrace_hits();
      return;
    }
    keep(r.sample, res);
  };
  // test_step reads a step's states only in test_chord, which asks for them (ensure_states), and
  // its pseudo-Cartesian ends where given.
  m.integrate_packet(cfg_, PacketRays{next_ray, on_step, done, on_steps, true});
  if (n_hits > 0) retrace_hits();
}

Color Tracer::stop_color(StopReason reason) const {
  constexpr Color kBlack{0, 0, 0};
  switch (reason) {
    case StopReason::Invalid:
      if (job_.break_color) return *job_.break_color;
      return job_.constraint_color.value_or(kBlack);
    case StopReason::Constraint: return job_.constraint_color.value_or(kBlack);
    case StopReason::StepUnderflow:
    case StopReason::NotFinite: return job_.error_color.value_or(job_.background);
    case StopReason::None:
    case StopReason::Callback:
    case StopReason::Escaped:
    case StopReason::BoundingBox:
    case StopReason::LambdaMax:
    case StopReason::MaxSteps: break;
  }
  return job_.background;
}

void Tracer::fill_data(const TraceResult& r, PixelData& d) const {
  d = PixelData{};
  d.traced = r.traced;
  d.hit = r.hit;
  d.stop = r.reason;
  d.lambda = r.lambda;
  if (!r.hit) return;  // GeoViS: pixels without intersection are all zero
  // Everything known about the hit (the EXR data file stores it all); each GeoViS file layout
  // picks its own fields (render/data_files.cpp; write_filter_data keeps only pos and uv for
  // FilterRGBIntersec, as GeoViS).
  for (int i = 0; i < 4; ++i) d.pos[i] = r.pos[i];
  d.uv[0] = r.hit_info.u;
  d.uv[1] = r.hit_info.v;
  // dir = future-directed light direction at the hit (minus the past-directed tangent).
  for (int i = 0; i < 4; ++i) d.dir[i] = -r.k[i];
  d.object_id = r.hit_info.object_id;
  d.freqshift = r.freqshift;
  for (int i = 0; i < 5; ++i) d.jacobi[i] = r.jacobi[i];
  for (int i = 0; i < 4; ++i) d.jacobi_matrix[i] = r.jacobi_matrix[i];
}

void Tracer::trace_pixel(double px, double py, Color& color, PixelData* data, TraceStats& stats) const {
  Vec3 d;
  if (!job_.camera->direction(px, py, d)) {
    // No ray there (outside the dome circle): GeoViS GvsProjector::getSampleColor returns its error
    // colour (default black), not the background.
    color = job_.error_color.value_or(Color{0, 0, 0});
    if (data) *data = PixelData{};  // traced = false
    return;
  }
  const TraceResult r = trace_direction(d, stats);
  color = r.color;
  if (data) fill_data(r, *data);
}

}  // namespace geovis

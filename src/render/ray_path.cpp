#include "render/ray_path.h"

#include <cmath>

#include "spacetime/metric.h"

namespace geovis {

RayPath trace_ray_path(const RenderJob& job_in, double px, double py) {
  RenderJob job = job_in;
  job.filter = Filter::RGB;  // geodesic system only (see the header)
  job.keep_data = false;
  const Tracer tracer(job);
  RayPath path;
  path.escape_radius = tracer.escape_radius();
  Vec3 d;
  if (!job.camera->direction(px, py, d)) return path;
  path.traced = true;
  path.local_dir = normalize(d);

  const Metric& m = *job.metric;
  // Components of the initial k = −e_(0) + d̂ (eq. 7) in the natural tetrad E: k^(a) =
  // η^{aa} g(E_(a), k) (metric.h coord_to_local). k = s(−E_(0) + n) with s = −k^(0), |n| = 1.
  const Vec4 k0 = local_null_direction(job.observer.e, path.local_dir, true);
  try {
    const Tetrad E = m.natural_tetrad(job.observer.pos, TetradKind::Default);
    const Vec4 kl = coord_to_local(m, job.observer.pos, E, k0);
    path.natural_scale = -kl[0];
    path.natural_dir = Vec3{kl[1], kl[2], kl[3]} * (1.0 / path.natural_scale);
  } catch (const Error&) {
    path.natural_scale = std::nan("");  // no natural tetrad there (e.g. inside an ergoregion)
    path.natural_dir = {std::nan(""), std::nan(""), std::nan("")};
  }

  auto add = [&](double lambda, const double* y) {
    RayPoint p;
    p.lambda = lambda;
    for (int i = 0; i < 4; ++i) {
      p.x[i] = y[i];
      p.k[i] = y[4 + i];
    }
    p.chart = m.to_pseudo_cartesian(p.x, p.p);
    path.points.push_back(p);
  };
  auto on_step = [&](const StepView& st) {
    if (path.points.empty()) add(st.lambda0, st.y0);
    add(st.lambda1, st.y1);
  };
  TraceStats stats;
  path.result = tracer.trace_direction(path.local_dir, stats, on_step);
  if (path.points.empty()) {  // stopped before the first step (e.g. the observer is outside the box)
    double y[8];
    for (int i = 0; i < 4; ++i) y[i] = job.observer.pos[i], y[4 + i] = k0[i];
    add(0.0, y);
  }
  if (path.result.hit) {
    // The hit lies inside the last recorded step: end the path there.
    RayPoint& last = path.points.back();
    last.lambda = path.result.lambda;
    last.x = path.result.pos;
    last.k = path.result.k;
    last.chart = m.to_pseudo_cartesian(last.x, last.p);
  }
  return path;
}

}  // namespace geovis

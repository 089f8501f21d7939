// Per-pixel light-ray tracing (paper §2.2-2.4): camera direction -> initial null direction at the
// observer (eq. 7) -> backward geodesic integration with the metric's inlined integrator (in flat
// inertial coordinates the exact straight line, spacetime/straight_ray.h) -> every
// accepted step is a straight Segment in pseudo-Cartesian coordinates tested against the scene ->
// the first hit is refined on the curved step (Hermite dense output) -> shading and the filter data
// (catalogue §3).
//
// A Tracer is immutable after construction and shared by all render threads; tracing allocates
// nothing (all state lives on the stack, the step callback is a FunctionRef).
#pragma once

#include <span>

#include "render/camera.h"
#include "render/render_job.h"
#include "render/segment_cull.h"

namespace geovis {

struct TraceStats {
  long rays = 0;
  long steps = 0;
  long rhs_evals = 0;
  void operator+=(const TraceStats& o) {
    rays += o.rays;
    steps += o.steps;
    rhs_evals += o.rhs_evals;
  }
};

/// Everything known about one traced ray (tests and the calc-proj-ray style tools use it).
struct TraceResult {
  bool traced = false;  ///< false: the camera has no ray there (dome corner)
  bool hit = false;
  StopReason reason = StopReason::None;
  Hit hit_info;            ///< the refined hit (valid when hit)
  Vec4 pos{{0, 0, 0, 0}};  ///< hit event in metric coordinates (or the end of the ray)
  Vec4 k{{0, 0, 0, 0}};    ///< past-directed tangent there
  double lambda = 0;       ///< affine parameter there (0 at the observer)
  double freqshift = 0;    ///< ω_src/ω_obs (0 when it cannot be computed)
  double jacobi[5] = {0, 0, 0, 0, 0};
  double jacobi_matrix[4] = {0, 0, 0, 0};  ///< J at the hit (Jacobi system only)
  Color color;
};

/// One sample of an image position for Tracer::trace_pixels (data: where its filter data go, or null).
struct PixelSample {
  double px, py;
  PixelData* data;
};

struct RayState;

class Tracer {
 public:
  /// Checks the job (metric, camera present; solver settings sane) and throws Error otherwise.
  explicit Tracer(const RenderJob& job);

  /// Traces the ray through continuous image position (px, py) (pixel centre of (i, j) is
  /// (i + .5, j + .5)). Writes the colour and, when `data` is not null, the filter data. Where the
  /// camera has no ray (outside the 2PICam dome circle) the colour is errcolor, else black (GeoViS),
  /// and the data are zero.
  void trace_pixel(double px, double py, Color& color, PixelData* data, TraceStats& stats) const;

  /// trace_pixel for each sample (colour i to colors[i]), in packets of rays integrated on SIMD lanes
  /// where packet_tracing() (spacetime/geodesic_packet.h), with the same results to the bit.
  void trace_pixels(std::span<const PixelSample> samples, Color* colors, TraceStats& stats) const;
  /// Light rays go in packets: the geodesic system with a solver packet_solver accepts (CashKarp45,
  /// Fehlberg45, DormandPrince54, DormandPrince853), in coordinates or through Carter's separated equations (RGBjac:
  /// its first, geodesic pass; the rays that hit are traced again with their Jacobi fields, in
  /// packets too, Metric::integrate_jacobi_packet).
  bool packet_tracing() const { return packets_; }

  /// Traces the ray leaving the observer in local direction `d` (need not be unit).
  TraceResult trace_direction(const Vec3& d, TraceStats& stats) const;

  /// The same, and `on_step` sees every accepted step of the ray up to and including the step of
  /// the hit, before the scene is tested on it (the viewer's ray, render/ray_path.h).
  TraceResult trace_direction(const Vec3& d, TraceStats& stats, FunctionRef<void(const StepView&)> on_step) const;

  /// Hit refinement stops once the curved sub-step deviates from its chord by less than this
  /// fraction of the distance from the origin (plus an absolute floor of the same size).
  static constexpr double kRefineTolerance = 1e-9;

  /// Colour of a ray that stopped without a hit for `reason` (GeoViS GvsProjector::getSampleColor):
  ///  - Invalid (the metric's break condition: horizon, singularity, edge of the chart):
  ///    breakcolor, else cstrcolor, else black. GeoViS paints rays stopped by the break condition
  ///    with its constraint colour (default black) and parses but never uses breakcolor; black is
  ///    also the physics: a ray that ends at a horizon brings no light from the sky;
  ///  - Constraint (the null constraint drifted): cstrcolor, else black (GeoViS);
  ///  - StepUnderflow / NotFinite (integration error): errcolor, else the background (GeoViS
  ///    gives a step-size break the background; its errcolor is for rays that cannot start);
  ///  - Escaped, BoundingBox, MaxSteps, LambdaMax (the ray escaped or ran out of budget): the
  ///    background.
  Color stop_color(StopReason reason) const;
  /// The escape radius of the rays: the scene's bounding sphere (SolverConfig::escape_radius).
  double escape_radius() const { return cfg_.escape_radius; }
  /// The capture radius of the rays: the scene's innermost radius, or its empty ball's radius where
  /// larger (SolverConfig::capture_radius).
  double capture_radius() const { return cfg_.capture_radius; }
  static constexpr int kMaxRefineLevels = 16;
  /// The steps that are not tested against the scene (render/segment_cull.h).
  const SegmentCull& segment_cull() const { return cull_; }

 private:
  void fill_data(const TraceResult& r, PixelData& d) const;
  /// One ray in local direction d integrated as `system` (trace_direction without counting the ray).
  TraceResult trace_system(GeodesicSystem system, const Vec3& d, TraceStats& stats,
                           FunctionRef<void(const StepView&)> observe_step) const;
  /// The end of a traced ray (trace_direction): hit refinement result, shading, data. y_start: the
  /// ray's start state, x and k, and for the Jacobi system also the screen s_a (jacobi.h layout).
  TraceResult end_ray(GeodesicSystem system, const RayState& rs, const Vec4& k0, const double* y, const double* y_start,
                      const GeodesicResult& gr, TraceStats& stats) const;
  const RenderJob& job_;
  SolverConfig cfg_;
  GeodesicSystem system_;
  bool point_lights_;  ///< shadow rays possible: Minkowski, lights with shadows on
  bool straight_;      ///< straight rays without integrator: Minkowski (spacetime/straight_ray.h)
  bool packets_;       ///< packet_tracing()
  /// RGBjac: every ray is first traced as a geodesic and only a ray that hits is traced again with
  /// its Jacobi fields (trace_direction): the lensing data exist only at hits (fill_data).
  bool jacobi_hits_only_;
  /// The scene's empty balls: steps inside them are not tested (render/segment_cull.h); none for
  /// the reference path.
  SegmentCull cull_;
};

}  // namespace geovis

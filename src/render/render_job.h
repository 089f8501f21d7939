// One image to render: everything the tracer needs, already built (no Scheme, no strings on the
// hot path). scene/builder creates one per device (= frame); tests build them in C++.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/image.h"
#include "render/color.h"
#include "render/object.h"
#include "render/shader.h"
#include "spacetime/geodesic.h"
#include "spacetime/metric.h"

namespace geovis {

class Camera;

/// GeoViS camera filters (catalogue §3): what is stored besides the RGB image.
enum class Filter { RGB = 0, RGBpdz = 1, RGBjac = 2, RGBpt = 3, RGBIntersec = 4 };

/// The observer (GeoViS projector): position and local tetrad (paper eq. 7).
struct Observer {
  Vec4 pos{{0, 0, 0, 0}};
  Tetrad e{};
};

struct RenderJob {
  std::shared_ptr<const Metric> metric;
  SolverConfig solver;  ///< lightlike; includes the bounding box and max_steps (maxNumPoints)
  Observer observer;
  std::shared_ptr<const Camera> camera;
  SceneObjectPtr scene;  ///< root object (compound); may be null (empty scene)
  LightManager lights;
  Color background{0, 0, 0};
  /// GeoViS projector errcolor / cstrcolor / breakcolor: pixel colour when the ray stopped without
  /// a hit because of an integration error (step underflow, non-finite state), a constraint
  /// violation, or the metric's break condition (horizon, singularity); Tracer::stop_color()
  /// gives the precedence and the GeoViS defaults (a black shadow).
  std::optional<Color> error_color, constraint_color, break_color;
  Filter filter = Filter::RGB;
  /// Also keep the per-pixel data without a data filter (`geovis render --data`: the EXR data
  /// file, render/data_exr.h).
  bool keep_data = false;
  int supersample = 1;  ///< n x n samples per pixel
  /// Trace every ray alone through the geodesic integrator, without the shortcuts that must not
  /// change the picture: no SIMD packets, no straight lines in flat inertial coordinates, no
  /// escape or capture stops, every step tested against the scene (Tracer, render/segment_cull.h).
  /// The reference the benchmark compares the fast path with
  /// (bench/scenes/bench_geovis_scenes.cpp).
  bool reference_tracing = false;
};

struct RenderOptions {
  int threads = 0;  ///< 0 = all cores
  int tile_size = 16;
  bool progress = true;  ///< progress bar (only shown on a terminal)
  std::string label;     ///< shown in the progress line (e.g. frame number)
  /// When set (e.g. by a SIGINT handler), the workers stop before their next tile and render()
  /// throws RenderInterrupted (render/renderer.h).
  const std::atomic<bool>* cancel = nullptr;
};

/// Per-pixel physics data of the pixel-centre ray (the RGBpdz/RGBjac/RGBpt filters and the EXR
/// data file). GeoViS fills pixels without a hit with zeros; `hit`, `stop` and `lambda` say what
/// happened to the ray, so that the EXR file can tell a miss from a hit at the origin.
struct PixelData {
  double pos[4] = {0, 0, 0, 0};  ///< hit event (coordinates)
  double dir[4] = {0, 0, 0, 0};  ///< future-directed light direction at the hit (coordinates)
  double object_id = 0;
  double freqshift = 0;                ///< 1+z = ω_src/ω_obs (paper eq. 15); 0 when unknown
  double jacobi[5] = {0, 0, 0, 0, 0};  ///< d+, d-, μ, angle, ellipticity (jacobi_params)
  double uv[2] = {0, 0};
  bool traced = false;  ///< false where the camera has no ray (dome corner)
  bool hit = false;
  StopReason stop = StopReason::None;      ///< why the integration ended (Callback for a hit)
  double lambda = 0;                       ///< affine parameter at the hit or at the end of the ray
  double jacobi_matrix[4] = {0, 0, 0, 0};  ///< J11 J12 J21 J22 at the hit (RGBjac only)
};

struct RenderStats {
  double seconds = 0;
  long rays = 0;
  long steps = 0;
  long rhs_evals = 0;
};

struct RenderResult {
  Image image;
  std::vector<PixelData> data;  ///< width*height entries (row 0 = top) when the filter stores data
  RenderStats stats;
};

}  // namespace geovis

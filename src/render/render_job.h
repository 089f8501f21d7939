// One image to render: everything the tracer needs, already built (no Scheme, no strings on the
// hot path). scene/builder creates one per device (= frame); tests build them in C++.
#pragma once

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
  int supersample = 1;  ///< n x n samples per pixel
};

struct RenderOptions {
  int threads = 0;      ///< 0 = all cores
  int tile_size = 16;
  bool progress = true; ///< progress bar (only shown on a terminal)
  std::string label;    ///< shown in the progress line (e.g. frame number)
};

/// Why a pixel's ray ended (the `stop` of the data files; tracer.h pixel_stop gives the mapping).
enum class PixelStop : unsigned char {
  Hit = 0,     ///< hit an object
  Escaped,     ///< left the objects' bounding sphere for good (asymptotically flat metrics)
  Horizon,     ///< the metric's break condition: horizon, singularity, edge of the chart
  Box,         ///< left the scene's bounding box
  MaxSteps,    ///< ran out of steps (maxNumPoints) or affine parameter
  Constraint,  ///< the null constraint drifted beyond tolerance
  Error,       ///< integration error (step underflow, NaN) or no ray at this pixel
};

/// Per-pixel physics data (the RGBpdz/RGBjac/RGBpt filters).
struct PixelData {
  double pos[4] = {0, 0, 0, 0};
  double dir[4] = {0, 0, 0, 0};
  double object_id = 0;
  double freqshift = 0;
  double jacobi[5] = {0, 0, 0, 0, 0};
  double uv[2] = {0, 0};
  PixelStop stop = PixelStop::Error;
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

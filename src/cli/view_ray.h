// `geovis view`: the light ray behind a pixel of a data file. The data file's header
// (docs/data-format.md) names the scene, its hash, the --define overrides, the frame and the
// resolution; the scene is evaluated again (refused when its text changed: the hash differs), the
// frame's job built, and the pixel-centre ray traced by the renderer's own tracer
// (render/ray_path.h).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

#include "io/image.h"
#include "scene/builder.h"

namespace geovis::cli {

class PixelRayTracer {
 public:
  /// `scene_override`: the scene file to use instead of the one the header names ("" = the header's:
  /// its absolute path scene.path, else scene.file next to the data file, else in the current folder).
  explicit PixelRayTracer(std::string scene_override = "");

  /// The ray through the centre of pixel (x, y) of `data` (read from `data_path`) as JSON:
  /// points (metric and pseudo-Cartesian coordinates), stop reason, hit, the central surface,
  /// the objects' bounds, the observer, and the matching `geovis geodesic` command. Throws Error
  /// when the data file carries no scene (a GeoViS file), the scene is missing or changed, or the
  /// pixel is outside the image.
  nlohmann::json trace(const ChannelImage& data, const std::string& data_path, int x, int y);

 private:
  struct Loaded;
  std::shared_ptr<const Loaded> load(const ChannelImage& data, const std::string& data_path);
  std::string scene_override_;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const Loaded>> cache_;  ///< by scene hash, defines, resolution
};

/// "A=1 B=2" (the header's scene.defines) -> {"A=1", "B=2"}; a value may contain spaces when the
/// next word has no '=' (it is appended to the previous define).
std::vector<std::string> split_defines(const std::string& defines);

}  // namespace geovis::cli

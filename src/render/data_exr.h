// The self-describing data file of a rendered frame (docs/data-format.md): an OpenEXR image with
// one named 32-bit float channel per quantity of the pixel-centre ray and header metadata that say
// what was rendered. Written next to the image with a data filter (FilterRGBpdz, ...) or
// `geovis render --data`; `geovis post` reads it (and the GeoViS binary files, data_files.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "io/image.h"
#include "render/render_job.h"

namespace geovis {

/// Value of the `stop` channel: why the ray ended. `NoRay` marks pixels where the camera has no
/// ray (outside a dome camera's circle).
enum class RayStop { Hit = 0, Escaped = 1, Horizon = 2, Box = 3, MaxSteps = 4, Constraint = 5, Error = 6, NoRay = 7 };
constexpr int kRayStopCount = 8;
const char* ray_stop_name(RayStop s);  ///< "hit", "escaped", "horizon", "box", "max-steps", ...

/// The stop code of a traced pixel (the one place where the integrator's StopReason is mapped).
RayStop ray_stop(const PixelData& d);

/// What the caller knows about the frame beyond the job (goes into the header).
struct DataFileInfo {
  std::string version;     ///< geovis version
  std::string scene_file;  ///< scene file name ("" for the built-in scene)
  std::string scene_hash;  ///< FNV-1a 64 of the scene text, hex
  std::string defines;     ///< the --define overrides, "NAME=VALUE ..." (they change what the scene renders)
  int frame = 0;
  std::string scene_path;  ///< absolute path of the scene file ("" for the built-in scene; `geovis view`)
};

/// FNV-1a 64-bit hash of `text` as 16 hex digits (scene identity in the header; not a security hash).
std::string fnv1a_hex(const std::string& text);

/// The channels of the data file: R,G,B, x0..x3, k0..k3, z, objid, stop, lambda, u, v, and for
/// the Jacobi filter jac.dplus, jac.dminus, jac.mu, jac.angle, jac.ellipticity, jac.J11 .. jac.J22.
/// Hit channels are NaN where the ray hit nothing.
std::vector<std::string> data_channel_names(bool jacobi);

/// The data file contents of a rendered frame.
ChannelImage make_data_image(const RenderJob& job, const Image& rgb, const std::vector<PixelData>& data,
                             const DataFileInfo& info);

/// "dir/out.png" -> "dir/out.exr"; an image that is itself an .exr gets "dir/out.data.exr".
std::string data_exr_path(const std::string& image_path);

/// Writes the data file of image `image_path` (atomically, io/image.h); returns its path.
std::string write_data_exr(const std::string& image_path, const RenderJob& job, const Image& rgb,
                           const std::vector<PixelData>& data, const DataFileInfo& info);

/// Reads a data file: an EXR data file, or a GeoViS .pdz/.jac/.pt/.dat file converted to the same
/// channel names (hit channels NaN where GeoViS stored a zero record; no R,G,B, stop or lambda).
/// Throws Error naming the file when it is neither.
ChannelImage read_data_file(const std::string& path);

}  // namespace geovis

// The HTTP server of `geovis view` (cpp-httplib): bound to 127.0.0.1 only; it serves the page's
// embedded files (cli/view_assets.h) by exact path and the named data by frame number, so no URL
// reaches the file system (no path traversal). Routes (docs/viewer.md):
//   GET /                      the page (index.html)
//   GET /<asset>               one of the page's files
//   GET /api/info              frames (name, index) and the colour maps
//   GET /api/frame/N           size, channel names, header and the post shaders of frame N
//   GET /api/frame/N/data      all channels of frame N, float32 little-endian, interleaved
//   GET /api/post?frame=N&shader=S[&mass=M]   the value of `geovis post --shader S` per pixel (float32)
//   GET /api/ray?frame=N&x=X&y=Y              the light ray of pixel (X, Y) (cli/view_ray.h), JSON
#pragma once

#include <list>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "cli/view_assets.h"
#include "cli/view_ray.h"
#include "io/image.h"

namespace httplib {
class Server;
}

namespace geovis::cli {

struct ViewFrame {
  std::string name;  ///< file name shown on the page
  std::string path;
};

/// The frames of DATA: the file itself, or the data files of a folder sorted by name (.exr, .pdz,
/// .jac, .pt, .dat; an image X.exr is left out when X.data.exr is there; entries whose real path
/// lies outside the folder, e.g. symbolic links out of it, are left out). Throws Error when there
/// is none.
std::vector<ViewFrame> find_view_frames(const std::string& data);

class ViewServer {
 public:
  ViewServer(std::vector<ViewFrame> frames, std::span<const ViewAsset> assets, std::string scene_override = "");
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// Reads the first frame (so that a file that is no data file is refused before serving);
  /// throws Error naming the file.
  void load_first_frame();
  /// Binds 127.0.0.1:port (0 = a free port); returns the port. Throws Error when it cannot.
  int bind(int port);
  /// Serves until stop() (call from another thread). Returns false when listening failed.
  bool run();
  void stop();

 private:
  std::shared_ptr<const ChannelImage> frame(size_t index);
  void add_routes();
  std::vector<ViewFrame> frames_;
  std::span<const ViewAsset> assets_;
  PixelRayTracer rays_;
  std::unique_ptr<httplib::Server> server_;
  int port_ = 0;
  std::mutex cache_mutex_;
  std::list<std::pair<size_t, std::shared_ptr<const ChannelImage>>> cache_;  ///< recently used frames
};

}  // namespace geovis::cli

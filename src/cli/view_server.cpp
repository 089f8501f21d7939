#include "cli/view_server.h"

#include <httplib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "render/colormap.h"
#include "render/data_exr.h"
#include "render/post.h"

namespace geovis::cli {

namespace fs = std::filesystem;

namespace {

constexpr size_t kCachedFrames = 4;

bool is_data_extension(const std::string& ext) {
  const std::string e = to_lower(ext);
  return e == ".exr" || e == ".pdz" || e == ".jac" || e == ".pt" || e == ".dat";
}

std::string mime_type(const std::string& path) {
  const std::string ext = to_lower(fs::path(path).extension().string());
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".json") return "application/json";
  return "application/octet-stream";
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

/// A non-negative integer parameter, or -1.
long index_param(const httplib::Request& req, const char* name) {
  if (!req.has_param(name)) return -1;
  const std::string v = req.get_param_value(name);
  if (v.empty() || v.size() > 9 || v.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(v);
}

}  // namespace

std::vector<ViewFrame> find_view_frames(const std::string& data) {
  std::error_code ec;
  if (!fs::exists(data, ec)) throw Error("\"" + data + "\" does not exist");
  if (!fs::is_directory(data, ec)) {
    if (!is_data_extension(fs::path(data).extension().string()))
      throw Error("\"" + data +
                  "\" is not a data file: expected an OpenEXR data file (.exr of geovis render --data or a "
                  "data filter), a GeoViS .pdz, .jac, .pt or .dat file, or a folder of them");
    return {ViewFrame{fs::path(data).filename().string(), data}};
  }
  const fs::path root = fs::canonical(data, ec);
  if (ec) throw Error("cannot read the folder \"" + data + "\": " + ec.message());
  std::vector<ViewFrame> frames;
  for (const auto& entry : fs::directory_iterator(root, ec)) {
    const fs::path p = entry.path();
    if (!is_data_extension(p.extension().string())) continue;
    std::error_code ec2;
    const fs::path real = fs::canonical(p, ec2);
    // Only files that really are in the folder: a link out of it is not served.
    if (ec2 || real.parent_path() != root || !fs::is_regular_file(real, ec2)) continue;
    const std::string name = p.filename().string();
    // An image rendered as .exr has its data file X.data.exr next to it.
    if (to_lower(p.extension().string()) == ".exr" && name.find(".data.exr") == std::string::npos &&
        fs::exists(root / (p.stem().string() + ".data.exr"), ec2))
      continue;
    frames.push_back(ViewFrame{name, p.string()});
  }
  if (ec) throw Error("cannot read the folder \"" + data + "\": " + ec.message());
  std::sort(frames.begin(), frames.end(), [](const ViewFrame& a, const ViewFrame& b) { return a.name < b.name; });
  if (frames.empty())
    throw Error("the folder \"" + data + "\" has no data files (.exr of geovis render --data, .pdz, .jac, .pt, .dat)");
  return frames;
}

ViewServer::ViewServer(std::vector<ViewFrame> frames, std::span<const ViewAsset> assets, std::string scene_override)
    : frames_(std::move(frames)),
      assets_(assets),
      rays_(std::move(scene_override)),
      server_(std::make_unique<httplib::Server>()) {
  // SO_REUSEADDR only: cpp-httplib's default also sets SO_REUSEPORT, with which a second server
  // (of this user) could bind the same port and receive part of the requests.
  server_->set_socket_options([](socket_t sock) {
    const int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  add_routes();
}

ViewServer::~ViewServer() { stop(); }

int ViewServer::bind(int port) {
  // Loopback only: the data and the scene stay on this machine (over SSH: ssh -L port:127.0.0.1:port).
  if (port == 0) {
    port_ = server_->bind_to_any_port("127.0.0.1");
    if (port_ < 0) throw Error("cannot listen on 127.0.0.1: no free port");
  } else {
    if (port < 0 || port > 65535) throw Error("--port: expected 0..65535, found " + std::to_string(port));
    if (!server_->bind_to_port("127.0.0.1", port))
      throw Error("cannot listen on 127.0.0.1:" + std::to_string(port) + " (in use? try another --port, or 0)");
    port_ = port;
  }
  return port_;
}

bool ViewServer::run() { return server_->listen_after_bind(); }

void ViewServer::load_first_frame() { frame(0); }

void ViewServer::stop() {
  if (server_) server_->stop();
}

std::shared_ptr<const ChannelImage> ViewServer::frame(size_t index) {
  std::lock_guard<std::mutex> lock(cache_mutex_);
  for (auto it = cache_.begin(); it != cache_.end(); ++it)
    if (it->first == index) {
      cache_.splice(cache_.begin(), cache_, it);
      return cache_.front().second;
    }
  auto img = std::make_shared<const ChannelImage>(read_data_file(frames_[index].path));
  cache_.emplace_front(index, img);
  if (cache_.size() > kCachedFrames) cache_.pop_back();
  return img;
}

void ViewServer::add_routes() {
  httplib::Server& s = *server_;
  // Requests for another host name are refused (DNS rebinding: a web page must not reach the
  // server through a name of its own that resolves to 127.0.0.1).
  s.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const std::string host = req.get_header_value("Host");
    const std::string port = std::string(":").append(std::to_string(port_));
    if (host == "127.0.0.1" + port || host == "localhost" + port || host == "127.0.0.1" || host == "localhost")
      return httplib::Server::HandlerResponse::Unhandled;
    // Appended piecewise: GCC 12 reports a false -Wrestrict on `"..." + std::string`.
    std::string why = "host \"";
    why.append(host).append("\" is not served");
    send_error(res, 403, why);
    return httplib::Server::HandlerResponse::Handled;
  });

  auto frame_or_404 = [this](long index, httplib::Response& res) -> std::shared_ptr<const ChannelImage> {
    if (index < 0 || size_t(index) >= frames_.size()) {
      send_error(res, 404, "no such frame");
      return nullptr;
    }
    try {
      return frame(size_t(index));
    } catch (const Error& e) {
      send_error(res, 422, e.what());
      return nullptr;
    }
  };

  s.Get("/api/info", [this](const httplib::Request&, httplib::Response& res) {
    nlohmann::json j;
    nlohmann::json frames = nlohmann::json::array();
    for (size_t i = 0; i < frames_.size(); ++i) frames.push_back({{"index", i}, {"name", frames_[i].name}});
    j["frames"] = frames;
    // The colour maps of `geovis post` (render/colormap.h), 256 entries each, so that the page
    // maps exactly as the command does.
    nlohmann::json maps = nlohmann::json::object();
    for (const auto& name : colormap_names()) {
      nlohmann::json table = nlohmann::json::array();
      for (int i = 0; i < 256; ++i) {
        const Color c = colormap(name, (i + 0.5) / 256.0);
        table.push_back({c.r, c.g, c.b});
      }
      maps[name] = table;
    }
    j["colormaps"] = maps;
    nlohmann::json cats = nlohmann::json::array();
    for (int i = 0; i < 8; ++i) {
      const Color c = category_color(i);
      cats.push_back({c.r, c.g, c.b});
    }
    j["categories"] = cats;
    nlohmann::json stops = nlohmann::json::array();
    for (int i = 0; i < kRayStopCount; ++i) stops.push_back(ray_stop_name(RayStop(i)));
    j["stop_names"] = stops;
    res.set_header("Cache-Control", "no-store");
    res.set_content(j.dump(), "application/json");
  });

  s.Get(R"(/api/frame/(\d{1,9}))", [frame_or_404](const httplib::Request& req, httplib::Response& res) {
    const auto img = frame_or_404(std::stol(req.matches[1].str()), res);
    if (!img) return;
    nlohmann::json j;
    j["width"] = img->width;
    j["height"] = img->height;
    j["channels"] = img->names;
    nlohmann::json meta = nlohmann::json::object();
    for (const auto& [k, v] : img->metadata) meta[k] = v;
    j["metadata"] = meta;
    nlohmann::json shaders = nlohmann::json::array();
    for (const auto& name : post_shader_names()) {
      nlohmann::json sh = {{"name", name}};
      try {
        const PostField f = post_field(*img, name);
        sh["label"] = f.label;
        sh["colormap"] = f.colormap;
        sh["categorical"] = f.categorical;
        sh["available"] = true;
      } catch (const Error& e) {
        sh["available"] = false;
        sh["why"] = e.what();
      }
      shaders.push_back(sh);
    }
    j["shaders"] = shaders;
    res.set_header("Cache-Control", "no-store");
    res.set_content(j.dump(), "application/json");
  });

  s.Get(R"(/api/frame/(\d{1,9})/data)", [frame_or_404](const httplib::Request& req, httplib::Response& res) {
    const auto img = frame_or_404(std::stol(req.matches[1].str()), res);
    if (!img) return;
    static_assert(sizeof(float) == 4);
    std::string bytes(img->pixels.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), img->pixels.data(), bytes.size());  // x86-64 and ARM: little-endian
    res.set_header("Cache-Control", "no-store");
    res.set_content(std::move(bytes), "application/octet-stream");
  });

  s.Get("/api/post", [frame_or_404](const httplib::Request& req, httplib::Response& res) {
    const auto img = frame_or_404(index_param(req, "frame"), res);
    if (!img) return;
    try {
      std::optional<double> mass;
      if (req.has_param("mass")) mass = std::stod(req.get_param_value("mass"));
      const PostField f = post_field(*img, req.get_param_value("shader"), mass);
      std::vector<float> v(f.values.begin(), f.values.end());
      std::string bytes(v.size() * sizeof(float), '\0');
      std::memcpy(bytes.data(), v.data(), bytes.size());
      res.set_header("Cache-Control", "no-store");
      res.set_content(std::move(bytes), "application/octet-stream");
    } catch (const std::exception& e) {
      send_error(res, 400, e.what());
    }
  });

  s.Get("/api/ray", [this, frame_or_404](const httplib::Request& req, httplib::Response& res) {
    const long f = index_param(req, "frame");
    const auto img = frame_or_404(f, res);
    if (!img) return;
    const long x = index_param(req, "x"), y = index_param(req, "y");
    if (x < 0 || y < 0) return send_error(res, 400, "expected x=X&y=Y (pixel column and row)");
    try {
      const nlohmann::json j = rays_.trace(*img, frames_[size_t(f)].path, int(x), int(y));
      res.set_header("Cache-Control", "no-store");
      res.set_content(j.dump(), "application/json");
    } catch (const std::exception& e) {
      send_error(res, 422, e.what());
    }
  });

  // The page: only its own files, looked up by exact path (no file system access).
  s.Get(".*", [this](const httplib::Request& req, httplib::Response& res) {
    const std::string path = req.path == "/" ? "/index.html" : req.path;
    for (const ViewAsset& a : assets_)
      if (path == a.path) {
        res.set_header("Content-Security-Policy",
                       "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'");
        res.set_header("X-Content-Type-Options", "nosniff");
        res.set_content(reinterpret_cast<const char*>(a.data), a.size, mime_type(a.path).c_str());
        return;
      }
    send_error(res, 404, "not found");
  });
}

}  // namespace geovis::cli

// `geovis view`: the HTTP server (cli/view_server.h) with a real HTTP client (cpp-httplib), the
// pixel ray of cli/view_ray.h against `geovis geodesic`, and Ctrl-C on the real program.
#include <gtest/gtest.h>
#include <httplib.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cli/command.h"
#include "cli/view_server.h"
#include "core/error.h"

extern char** environ;

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

const unsigned char kPage[] = "<html>geovis test page</html>";
const ViewAsset kTestAssets[] = {{"/index.html", kPage, sizeof kPage - 1}};

class ViewServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_view_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "served");
  }
  void TearDown() override {
    if (server_) server_->stop();
    if (thread_.joinable()) thread_.join();
    fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  int run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "geovis");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    return run(static_cast<int>(argv.size()), argv.data());
  }

  /// Renders the disk scene of the paper's Fig. 9 (examples/) small, with its data file.
  std::string render_disk(const std::string& scene, const std::string& out) {
    EXPECT_EQ(run_args({"render", scene, "-o", out, "--data", "--res", "24x16", "-q"}), 0);
    return fs::path(out).replace_extension(".exr").string();
  }

  httplib::Client& serve(const std::vector<ViewFrame>& frames) {
    server_ = std::make_unique<ViewServer>(frames, std::span<const ViewAsset>(kTestAssets));
    port_ = server_->bind(0);
    thread_ = std::thread([this] { server_->run(); });
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    for (int i = 0; i < 100 && !client_->Get("/"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return *client_;
  }

  fs::path dir_;
  std::unique_ptr<ViewServer> server_;
  std::thread thread_;
  std::unique_ptr<httplib::Client> client_;
  int port_ = 0;
};

int status(httplib::Client& c, const std::string& target) {
  auto r = c.Get(target);
  return r ? r->status : -1;
}

TEST_F(ViewServerTest, ServesOnlyThePageAndTheNamedFrames) {
  // The served folder: one data file and a symbolic link to a file outside it.
  std::ofstream(path("secret.exr")) << "outside";
  std::ofstream(path("served/a.exr")) << "not read in this test";
  fs::create_symlink(dir_ / "secret.exr", dir_ / "served" / "b.exr");
  const auto frames = find_view_frames(path("served"));
  ASSERT_EQ(frames.size(), 1u);  // the link out of the folder is not a frame
  EXPECT_EQ(frames[0].name, "a.exr");

  httplib::Client& c = serve(frames);
  auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->body, "<html>geovis test page</html>");
  EXPECT_EQ(status(c, "/index.html"), 200);
  auto info = c.Get("/api/info");
  ASSERT_TRUE(info);
  const auto j = nlohmann::json::parse(info->body);
  ASSERT_EQ(j["frames"].size(), 1u);
  EXPECT_EQ(j["frames"][0]["name"], "a.exr");

  // Traversal in every spelling: never a file of the system, the folder or the link.
  for (const std::string& t : std::vector<std::string>{"/../../etc/passwd",
                                                       "/%2e%2e/%2e%2e/etc/passwd",
                                                       "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd",
                                                       "/..%2f..%2fetc%2fpasswd",
                                                       "/etc/passwd",
                                                       "//etc/passwd",
                                                       "/a.exr",
                                                       "/served/a.exr",
                                                       "/b.exr",
                                                       "/secret.exr",
                                                       "/api/frame/1",
                                                       "/api/frame/1/data",
                                                       "/api/frame/-1",
                                                       "/api/frame/99999999",
                                                       "/api/frame/0/../../secret.exr",
                                                       "/api/frame/..%2f..%2fsecret.exr",
                                                       "/index.html/../../etc/passwd",
                                                       "/assets/../../../etc/passwd",
                                                       "/" + (dir_ / "secret.exr").string(),
                                                       "/%2F" + (dir_ / "secret.exr").string().substr(1)}) {
    SCOPED_TRACE(t);
    auto r = c.Get(t);
    if (!r) continue;  // refused by the client or server as malformed: also nothing served
    EXPECT_TRUE(r->status == 404 || r->status == 403 || r->status == 400) << r->status;
    EXPECT_EQ(r->body.find("outside"), std::string::npos);
    EXPECT_EQ(r->body.find("root:"), std::string::npos);
  }
  // The port is this server's alone.
  ViewServer second(frames, std::span<const ViewAsset>(kTestAssets));
  EXPECT_THROW(second.bind(port_), Error);
  // A page from elsewhere reaching 127.0.0.1 through its own host name (DNS rebinding).
  auto evil = c.Get("/api/info", httplib::Headers{{"Host", "attacker.example:" + std::to_string(port_)}});
  ASSERT_TRUE(evil);
  EXPECT_EQ(evil->status, 403);
}

TEST_F(ViewServerTest, FolderOfFramesSortedWithoutTheImageOfAnExrRender) {
  for (const char* n : {"f_0002.exr", "f_0001.exr", "img.exr", "img.data.exr", "notes.txt", "g.pdz"})
    std::ofstream(path("served/") + n) << "x";
  const auto frames = find_view_frames(path("served"));
  std::vector<std::string> names;
  for (const auto& f : frames) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"f_0001.exr", "f_0002.exr", "g.pdz", "img.data.exr"}));
  EXPECT_THROW(find_view_frames(path("missing")), Error);
  EXPECT_THROW(find_view_frames(path("served/notes.txt")), Error);  // a single file must be a data file
  fs::create_directories(dir_ / "empty");
  EXPECT_THROW(find_view_frames(path("empty")), Error);
}

/// The numbers of a `geovis geodesic` command line (the ray endpoint's "command"), run in-process.
nlohmann::json run_geodesic_json(const std::string& command) {
  std::stringstream ss(command);
  std::vector<std::string> args;
  std::string w;
  while (ss >> w) args.push_back(w);
  EXPECT_EQ(args.at(0), "geovis");
  args.push_back("--format");
  args.push_back("json");
  std::vector<const char*> argv;
  for (auto& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStdout();
  const int code = run(static_cast<int>(argv.size()), argv.data());
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(code, 0);
  return nlohmann::json::parse(out);
}

/// Relative agreement of the ray's points with `geovis geodesic`'s: the same steps from a start
/// that differs in the last bits (rounding of the tetrad transformation, and of the conserved
/// quantities of Carter's equations derived from it), i.e. round-off grown along the ray (measured
/// up to 4e-10); the criterion is a tenth of the scene's integrator tolerance eps_abs = 1e-8, so
/// a different step or a different ray would fail it.
constexpr double kSameRay = 1e-9;

TEST_F(ViewServerTest, PixelRayIsTheGeodesicOfGeovisGeodesic) {
  const std::string scene = std::string(GEOVIS_SOURCE_DIR) + "/examples/fig9_disk_flux.scm";
  const std::string data = render_disk(scene, path("served/disk.png"));
  httplib::Client& c = serve(find_view_frames(data));

  int checked_hits = 0;
  // A ray onto the disk (image centre row below the hole), one that passes above it, the corner.
  for (auto [x, y] : {std::pair{12, 10}, std::pair{12, 4}, std::pair{0, 0}, std::pair{20, 8}}) {
    SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
    auto r = c.Get("/api/ray?frame=0&x=" + std::to_string(x) + "&y=" + std::to_string(y));
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const auto ray = nlohmann::json::parse(r->body);
    ASSERT_TRUE(ray["traced"].get<bool>());
    EXPECT_EQ(ray["surface"]["radius"], 2.0);  // r_s = 2M, M = 1
    ASSERT_EQ(ray["objects"].size(), 1u);      // the disk, 3 r_s .. 7.5 r_s in the plane z = 0
    EXPECT_EQ(ray["objects"][0]["hi"][0], 15.0);
    EXPECT_TRUE(ray["geodesic"]["differences"].empty());  // a static observer, default steps

    const auto geo = run_geodesic_json(ray["geodesic"]["command"]);
    const auto& rp = ray["points"];
    const auto& gp = geo["points"];
    ASSERT_GE(rp.size(), 2u);
    // Every accepted step is the same step: the tracer stops at the hit (its last point is the
    // refined hit inside the last step), at the scene's box or at the escape radius; geodesic
    // runs on to its own limits.
    const size_t n = rp.size() - (ray["hit"].get<bool>() ? 1 : 0);
    ASSERT_LE(n, gp.size());
    // The start differs by rounding only: the tracer builds k from the scene's tetrad, geodesic from
    // the natural one and the direction printed with 17 digits.
    double worst = 0;
    for (size_t i = 0; i < n; ++i) {
      auto close = [&worst](double a, double b) {
        const double d = std::fabs(a - b) / (1 + std::fabs(b));
        worst = std::max(worst, d);
        return d <= kSameRay;
      };
      EXPECT_TRUE(close(rp[i]["lambda"].get<double>(), gp[i]["lambda"].get<double>())) << i;
      for (int a = 0; a < 4; ++a) {
        EXPECT_TRUE(close(rp[i]["x"][a].get<double>(), gp[i]["x"][a].get<double>())) << i;
        EXPECT_TRUE(close(rp[i]["k"][a].get<double>(), gp[i]["k"][a].get<double>())) << i;
      }
    }
    std::cerr << "pixel " << x << "," << y << ": " << n << " steps, largest relative difference " << worst << "\n";
    // The pseudo-Cartesian points are the spherical coordinates' x = r sinθ cosφ, ...
    for (const auto& p : rp) {
      const double rr = p["x"][1], th = p["x"][2], ph = p["x"][3];
      EXPECT_NEAR(p["p"][0].get<double>(), rr * std::sin(th) * std::cos(ph), 1e-12 * rr);
      EXPECT_NEAR(p["p"][2].get<double>(), rr * std::cos(th), 1e-12 * rr);
    }
    if (ray["hit"].get<bool>()) {
      ++checked_hits;
      const double lam = rp.back()["lambda"];
      EXPECT_GE(lam, gp[n - 1]["lambda"].get<double>());
      EXPECT_LE(lam, gp[n]["lambda"].get<double>());
      // The hit is the one the data file stored (32-bit floats there).
      for (int a = 0; a < 4; ++a) {
        const double stored = ray["stored"]["x" + std::to_string(a)];
        EXPECT_NEAR(rp.back()["x"][a].get<double>(), stored, 2e-7 * (1 + std::fabs(stored)));
      }
      EXPECT_NEAR(std::fabs(rp.back()["p"][2].get<double>()), 0.0, 1e-6);  // on the disk plane z = 0
    } else {
      EXPECT_TRUE(ray["stored"]["x1"].is_null());
    }
  }
  EXPECT_GE(checked_hits, 1);

  // Malformed requests.
  EXPECT_EQ(status(c, "/api/ray?frame=0&x=24&y=0"), 422);  // outside the 24x16 image
  EXPECT_EQ(status(c, "/api/ray?frame=0&x=-1&y=0"), 400);
  EXPECT_EQ(status(c, "/api/ray?frame=1&x=0&y=0"), 404);
}

TEST_F(ViewServerTest, RefusesARayWhenTheSceneChanged) {
  const std::string scene = path("disk.scm");
  fs::copy_file(std::string(GEOVIS_SOURCE_DIR) + "/examples/fig9_disk_flux.scm", scene);
  const std::string data = render_disk(scene, path("served/disk.png"));
  std::ofstream(scene, std::ios::app) << "\n(define incl 60.0)\n";
  httplib::Client& c = serve(find_view_frames(data));
  auto r = c.Get("/api/ray?frame=0&x=12&y=10");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_NE(r->body.find("changed since"), std::string::npos) << r->body;
}

TEST_F(ViewServerTest, PostValuesAndFrameDescription) {
  const std::string data =
      render_disk(std::string(GEOVIS_SOURCE_DIR) + "/examples/fig9_disk_flux.scm", path("served/disk.png"));
  httplib::Client& c = serve(find_view_frames(data));
  auto f = c.Get("/api/frame/0");
  ASSERT_TRUE(f);
  const auto j = nlohmann::json::parse(f->body);
  EXPECT_EQ(j["width"], 24);
  EXPECT_EQ(j["height"], 16);
  const size_t nc = j["channels"].size();
  auto d = c.Get("/api/frame/0/data");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->body.size(), 24u * 16u * nc * 4u);
  auto p = c.Get("/api/post?frame=0&shader=disk-flux");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->body.size(), 24u * 16u * 4u);
  EXPECT_EQ(status(c, "/api/post?frame=0&shader=lensing"), 400);  // no jac.mu in a pdz render
}

TEST(ViewCommand, CtrlCStopsTheServerCleanly) {
  const std::string exe = std::string(GEOVIS_BINARY_DIR) + "/geovis";
  const std::string data =
      (fs::temp_directory_path() / ("geovis_view_cc_" + std::to_string(::getpid()) + ".pdz")).string();
  {
    // A 1x1 GeoViS .pdz file (docs/data-format.md): int32 W, H, nc = 10, then 10 float64.
    std::ofstream f(data, std::ios::binary);
    const int32_t head[3] = {1, 1, 10};
    const double rec[10] = {0, 10, 1, 0, 1, 1, 0, 0, 1, 1};
    f.write(reinterpret_cast<const char*>(head), sizeof head);
    f.write(reinterpret_cast<const char*>(rec), sizeof rec);
  }
  int out[2];
  ASSERT_EQ(::pipe(out), 0);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_addclose(&fa, out[0]);
  std::vector<std::string> args = {exe, "view", data, "--port", "0"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(out[1]);
  ASSERT_EQ(rc, 0);
  std::string line;
  char ch;
  while (::read(out[0], &ch, 1) == 1 && ch != '\n') line += ch;
  ::close(out[0]);
  const size_t at = line.find("http://127.0.0.1:");
  if (line.find("page is not part of this build") != std::string::npos) GTEST_SKIP() << line;
  ASSERT_NE(at, std::string::npos) << line;
  const int port = std::stoi(line.substr(at + 17));
  httplib::Client c("127.0.0.1", port);
  auto r = c.Get("/api/info");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  // A GeoViS file names no scene: its rays cannot be traced again, and the reply says why.
  auto ray = c.Get("/api/ray?frame=0&x=0&y=0");
  ASSERT_TRUE(ray);
  EXPECT_EQ(ray->status, 422);
  EXPECT_NE(ray->body.find("names no scene"), std::string::npos) << ray->body;
  ::kill(pid, SIGINT);
  int st = 0;
  ASSERT_EQ(::waitpid(pid, &st, 0), pid);
  EXPECT_TRUE(WIFEXITED(st));
  EXPECT_EQ(WEXITSTATUS(st), 0);
  EXPECT_FALSE(c.Get("/api/info"));  // nothing listens any more
  fs::remove(data);
}

}  // namespace
}  // namespace geovis::cli

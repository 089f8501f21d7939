// `geovis render` and its outputs under faults: --resume that verifies what is on disk, size
// limits instead of std::bad_alloc, an unwritable or full output folder, leftovers of killed runs,
// and SIGINT/SIGTERM (a real child process on a pseudo-terminal).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "io/image.h"

extern char** environ;

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

class RenderOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_render_outputs_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (mounted_) ::umount2(mount_.c_str(), MNT_DETACH);
    fs::remove_all(dir_);
  }

  /// Runs in-process; returns the exit status, stderr in err_.
  int run_args(std::vector<std::string> args) {
    args.insert(args.begin(), "geovis");
    std::vector<const char*> argv;
    for (auto& a : args) argv.push_back(a.c_str());
    testing::internal::CaptureStderr();
    const int rc = run(static_cast<int>(argv.size()), argv.data());
    err_ = testing::internal::GetCapturedStderr();
    return rc;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  bool exists(const std::string& name) const { return fs::exists(dir_ / name); }
  static std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
  }
  static ino_t inode(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
  }

  /// A small flat-space scene with `frames` devices and a top-level `shade` that --define changes.
  std::string write_scene(int frames) {
    const std::string p = path("scene.scm");
    std::ofstream f(p);
    f << "(define shade 0.2)\n"
         "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(step_ctrl #f) '(step_size 0.5))\n"
         "(init-camera '(type \"PinHoleCam\") '(dir #(1 0 0)) '(vup #(0 0 1)) '(fov #(40 30)) '(res #(8 6))\n"
         "  '(filter \"FilterRGB\") '(id \"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(maxNumPoints 200)\n"
         "  `(boundBoxLL ,(vector (- gpDBLMAX) -30.0 -30.0 -30.0)) `(boundBoxUR ,(vector gpDBLMAX 30.0 30.0 30.0)))\n"
         "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
         "  '(incoords #f) '(id \"locTedObs\"))\n"
         "(init-projector '(localTetrad \"locTedObs\") '(color #(0 0 0)) '(id \"proj\"))\n"
         "(init-light-mgr '(ambient #(1 1 1)))\n"
         "(init-texture '(type \"UniTex\") `(color ,(vector 0.8 shade 0.2)) '(id \"red\"))\n"
         "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(ambient 1.0) '(id \"sh\"))\n"
         "(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0 0 0)) '(axlen #(2 2 2)) '(shader \"sh\")\n"
         "  '(id \"ball\"))\n"
         "(do ((i 0 (+ i 1))) ((= i "
      << frames
      << "))\n"
         "  (init-device '(type \"standard\") '(obj \"ball\")\n"
         "               `(setparam (\"locTedObs\" \"pos\" ,(vector 0.0 (- -10.0 i) 0.0 0.0)))))\n";
    return p;
  }

  /// Mounts a small tmpfs at `name` (root only); false with `why_not` set otherwise.
  bool mount_tmpfs(const std::string& name, const std::string& options, unsigned long flags, std::string& why_not) {
    mount_ = path(name);
    fs::create_directories(mount_);
    if (::geteuid() != 0) {
      why_not = "mounting a small tmpfs needs root";
      return false;
    }
    if (::mount("tmpfs", mount_.c_str(), "tmpfs", flags, options.c_str()) != 0) {
      why_not = std::string("cannot mount a tmpfs: ") + std::strerror(errno);
      return false;
    }
    mounted_ = true;
    return true;
  }

  fs::path dir_;
  std::string err_;
  std::string mount_;
  bool mounted_ = false;
};

/// The lines of `text` that contain `needle`.
int count_lines_with(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.find(needle) != std::string::npos;
  return n;
}

// ---- --resume ------------------------------------------------------------------------------------

TEST_F(RenderOutputs, ResumeRendersAgainWhatIsNotAGenuineCompleteFrame) {
  const std::string scene = write_scene(5);
  const std::string out = path("f_%d.png");
  ASSERT_EQ(run_args({"render", scene, "-o", out, "-q"}), 0) << err_;
  const std::string genuine = slurp(path("f_0.png"));
  const ino_t genuine_inode = inode(path("f_0.png"));
  const std::string png = slurp(path("f_1.png"));
  { std::ofstream(path("f_1.png"), std::ios::binary) << png.substr(0, png.size() / 2); }  // truncated
  { std::ofstream(path("f_2.png"), std::ios::binary); }                                   // 0 bytes
  { std::ofstream(path("f_3.png")) << "not an image\n"; }                                 // text
  ASSERT_EQ(run_args({"render", scene, "-o", out, "--frames", "4", "--res", "16x12", "-q"}), 0) << err_;
  ASSERT_EQ(read_image(path("f_4.png")).width, 16);  // another resolution

  ASSERT_EQ(run_args({"render", scene, "-o", out, "--resume"}), 0) << err_;
  EXPECT_EQ(count_lines_with(err_, "--resume: frame"), 4) << err_;
  EXPECT_EQ(count_lines_with(err_, "--resume: frame 0"), 0) << err_;
  EXPECT_NE(err_.find("--resume: frame 1 is rendered again: cannot read image \"" + path("f_1.png")), std::string::npos)
      << err_;
  EXPECT_NE(err_.find("--resume: frame 2 is rendered again: cannot read image \"" + path("f_2.png") +
                      "\": the file is empty"),
            std::string::npos)
      << err_;
  EXPECT_NE(err_.find("--resume: frame 3 is rendered again: cannot read image \"" + path("f_3.png")), std::string::npos)
      << err_;
  EXPECT_NE(err_.find("--resume: frame 4 is rendered again: \"" + path("f_4.png") + "\" is 16x12, expected 8x6"),
            std::string::npos)
      << err_;
  EXPECT_NE(err_.find("4 frame(s) rendered, 1 skipped"), std::string::npos) << err_;
  // The genuine frame was not touched (same file, not rewritten); the others are complete now.
  EXPECT_EQ(inode(path("f_0.png")), genuine_inode);
  EXPECT_EQ(slurp(path("f_0.png")), genuine);
  for (int f = 1; f <= 4; ++f) {
    const Image img = read_image(path("f_" + std::to_string(f) + ".png"));
    EXPECT_EQ(img.width, 8);
    EXPECT_EQ(img.height, 6);
  }
}

TEST_F(RenderOutputs, ResumeComparesTheSceneSettings) {
  const std::string scene = write_scene(2);
  const std::string out = path("g_%d.png");
  ASSERT_EQ(run_args({"render", scene, "-o", out, "--define", "shade=0.5", "-q"}), 0) << err_;
  const ino_t i0 = inode(path("g_0.png")), i1 = inode(path("g_1.png"));
  // Same settings: both frames are skipped without a word.
  ASSERT_EQ(run_args({"render", scene, "-o", out, "--define", "shade=0.5", "--resume"}), 0) << err_;
  EXPECT_EQ(count_lines_with(err_, "--resume: frame"), 0) << err_;
  EXPECT_EQ(inode(path("g_0.png")), i0);
  EXPECT_EQ(inode(path("g_1.png")), i1);
  // Another --define: both are rendered again, each with its reason.
  ASSERT_EQ(run_args({"render", scene, "-o", out, "--define", "shade=0.9", "--resume"}), 0) << err_;
  EXPECT_EQ(count_lines_with(err_, "was written with other settings"), 2) << err_;
  EXPECT_NE(inode(path("g_0.png")), i0);
  // The scene file changed: rendered again too.
  { std::ofstream(scene, std::ios::app) << "; edited\n"; }
  ASSERT_EQ(run_args({"render", scene, "-o", out, "--define", "shade=0.9", "--resume"}), 0) << err_;
  EXPECT_EQ(count_lines_with(err_, "was written with other settings"), 2) << err_;
}

// ---- limits --------------------------------------------------------------------------------------

TEST_F(RenderOutputs, ResolutionLimitsAreClearErrors) {
  const std::string scene = write_scene(1);
  EXPECT_EQ(run_args({"render", scene, "-o", path("a.png"), "--res", "100000x100000", "-q"}), 1);
  EXPECT_NE(err_.find("geovis: error: --res 100000x100000: a 100000x100000 frame needs 112 GiB for the frame buffer"),
            std::string::npos)
      << err_;
  EXPECT_NE(err_.find("the limit is"), std::string::npos) << err_;
  EXPECT_EQ(run_args({"render", scene, "-o", path("a.png"), "--res", "2147483647x1", "-q"}), 1);
  EXPECT_NE(err_.find("--res 2147483647x1: the width 2147483647 is larger than the limit of 1000000 pixels per side"),
            std::string::npos)
      << err_;
  EXPECT_EQ(run_args({"render", scene, "-o", path("a.png"), "--res", "1x99999999999999999999", "-q"}), 1);
  EXPECT_NE(err_.find("larger than the limit of 1000000 pixels per side"), std::string::npos) << err_;
  // The scene's own camera resolution is checked before anything is allocated, too.
  {
    std::ofstream(scene, std::ios::app)
        << "(init-camera '(type \"PinHoleCam\") '(res #(100000 100000)) '(id \"big\"))\n"
           "(init-device '(type \"standard\") '(obj \"ball\") '(camera \"big\"))\n";
  }
  EXPECT_EQ(run_args({"render", scene, "-o", path("b_%d.png"), "--frames", "1", "-q"}), 1);
  EXPECT_NE(err_.find("needs 112 GiB for the frame buffer"), std::string::npos) << err_;
  EXPECT_EQ(err_.find("internal error"), std::string::npos) << err_;
  EXPECT_FALSE(exists("a.png"));
}

TEST_F(RenderOutputs, AddressSpaceLimitIsAClearErrorNotBadAlloc) {
  // A real child process under `ulimit -v` 2 GiB: a frame that needs 3.2 GiB is refused before
  // anything is allocated (before: "internal error: std::bad_alloc", exit status 2).
  int err_pipe[2];
  ASSERT_EQ(::pipe(err_pipe), 0);
  const std::string exe = std::string(GEOVIS_BINARY_DIR) + "/geovis", out = path("x.png");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const struct rlimit as = {2UL << 30, 2UL << 30};
    ::setrlimit(RLIMIT_AS, &as);
    ::dup2(err_pipe[1], 2);
    ::close(err_pipe[0]);
    ::execl(exe.c_str(), exe.c_str(), "--res", "12000x12000", "-q", "-o", out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(err_pipe[1]);
  std::string err;
  char buf[1024];
  for (ssize_t n; (n = ::read(err_pipe[0], buf, sizeof buf)) > 0;) err.append(buf, size_t(n));
  ::close(err_pipe[0]);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 1) << err;
  EXPECT_NE(err.find("a 12000x12000 frame needs 1.6 GiB for the frame buffer"), std::string::npos) << err;
  EXPECT_NE(err.find("the limit is 2.0 GiB"), std::string::npos) << err;
  EXPECT_EQ(err.find("internal error"), std::string::npos) << err;
  EXPECT_FALSE(exists("x.png"));
}

// ---- output folders ------------------------------------------------------------------------------

TEST_F(RenderOutputs, ReadOnlyOutputFolderFailsBeforeRendering) {
  const std::string scene = write_scene(1);
  std::string folder, reason, why_not;
  if (::geteuid() == 0) {  // root may write into any folder whatever its mode: a read-only mount
    if (!mount_tmpfs("ro", "size=64k", MS_RDONLY, why_not)) GTEST_SKIP() << why_not;
    folder = mount_;
    reason = "Read-only file system";
  } else {
    folder = path("ro");
    fs::create_directories(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    reason = "Permission denied";
  }
  // Not quiet: the progress summary ("... px in ...") would show that the frame was traced.
  EXPECT_EQ(run_args({"render", scene, "-o", folder + "/out.png"}), 1);
  EXPECT_NE(err_.find("the output folder \"" + folder + "\" is not writable: " + reason), std::string::npos) << err_;
  EXPECT_EQ(err_.find(" px in "), std::string::npos) << "rendered before failing: " << err_;
  if (::geteuid() != 0) fs::permissions(folder, fs::perms::owner_all);
}

TEST_F(RenderOutputs, FullFileSystemFailsAndKeepsTheExistingImage) {
  std::string why_not;
  if (!mount_tmpfs("full", "size=256k", 0, why_not)) GTEST_SKIP() << why_not;
  const std::string target = mount_ + "/target.png";
  ASSERT_EQ(run_args({"render", "-o", target, "--res", "64x48", "-q"}), 0) << err_;
  const std::string before = slurp(target);
  {  // fill the file system to the last byte
    std::ofstream filler(mount_ + "/filler", std::ios::binary);
    const std::string block(4096, 'x');
    while (filler.write(block.data(), std::streamsize(block.size())) && filler.flush()) {
    }
  }
  for (const std::string& out : {target, mount_ + "/fresh.png"}) {
    EXPECT_EQ(run_args({"render", "-o", out, "--res", "128x96", "-q"}), 1) << out;
    // The first file to hit the full disk is the frame's tile checkpoint (OUT.tiles) or the image.
    const bool named = err_.find("cannot write \"" + out + "\": No space left on device") != std::string::npos ||
                       err_.find("cannot write \"" + out + ".tiles\": No space left on device") != std::string::npos;
    EXPECT_TRUE(named) << err_;
  }
  EXPECT_EQ(slurp(target), before);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(mount_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"filler", "target.png"}));
}

TEST_F(RenderOutputs, TemporaryFilesOfKilledRunsAreRemoved) {
  const std::string scene = write_scene(1);
  { std::ofstream(path(".out.geovis-tmp-4242-0.png")); }  // left by a killed run (nobody holds it)
  { std::ofstream(path(".out.tmp-4242-0.png")); }         // not our pattern: kept
  ASSERT_EQ(run_args({"render", scene, "-o", path("out.png")}), 0) << err_;
  EXPECT_FALSE(exists(".out.geovis-tmp-4242-0.png"));
  EXPECT_TRUE(exists(".out.tmp-4242-0.png"));
  EXPECT_NE(
      err_.find("removed \"" + path(".out.geovis-tmp-4242-0.png") + "\", a temporary file left by an interrupted run"),
      std::string::npos)
      << err_;
}

TEST_F(RenderOutputs, FailedMovieLeavesNoTemporaryFile) {
  const std::string scene = write_scene(2);
  if (::access("/usr/bin/ffmpeg", X_OK) != 0) GTEST_SKIP() << "ffmpeg is not installed";
  // ffmpeg knows no container for ".xyz" and fails; the frames stay, nothing else is left.
  EXPECT_EQ(run_args({"render", scene, "-o", path("m_%d.png"), "--movie", path("m.xyz"), "-q"}), 1);
  EXPECT_NE(err_.find("--movie: ffmpeg failed"), std::string::npos) << err_;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"m_0.png", "m_1.png", "scene.scm"}));
}

TEST_F(RenderOutputs, TruncatedTexturePngIsOneErrorWithoutCodecLines) {
  // A texture cut off in the middle (an interrupted download).
  Image tex(64, 64, 3);
  for (size_t i = 0; i < tex.pixels.size(); ++i) tex.pixels[i] = float((i * 7919) % 251) / 250.0f;
  write_image(path("tex.png"), tex);
  const std::string png = slurp(path("tex.png"));
  { std::ofstream(path("tex.png"), std::ios::binary) << png.substr(0, png.size() / 2); }
  const std::string scene = write_scene(1);
  std::string text = slurp(scene);
  const size_t shader = text.find("(init-shader");
  ASSERT_NE(shader, std::string::npos);
  text.insert(shader, "(init-texture '(type \"Image\") '(file \"tex.png\") '(id \"cut\"))\n");
  const size_t red = text.find("'(objcolor \"red\")");
  ASSERT_NE(red, std::string::npos);
  text.replace(red, 18, "'(objcolor \"cut\")");
  { std::ofstream(scene) << text; }
  EXPECT_EQ(run_args({"render", scene, "-o", path("out.png"), "-q"}), 1);
  EXPECT_NE(err_.find("geovis: error: "), std::string::npos) << err_;
  EXPECT_NE(err_.find("tex.png"), std::string::npos) << err_;
  EXPECT_EQ(err_.find("libpng"), std::string::npos) << "raw codec output: " << err_;
  EXPECT_EQ(count_lines_with(err_, ""), 1) << err_;  // one line: the geovis error
  EXPECT_FALSE(exists("out.png"));
}

// ---- signals -------------------------------------------------------------------------------------

/// Starts build/geovis with stderr on a pseudo-terminal (so that it draws its progress bar), waits
/// until the bar shows that the render is running, sends `sig`, and collects what was printed.
struct InterruptedRun {
  int status = 0;
  std::string terminal;
};

InterruptedRun interrupt_render(const std::vector<std::string>& args, int sig) {
  InterruptedRun r;
  int master = -1, slave = -1;
  if (::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) {
    ADD_FAILURE() << "openpty: " << std::strerror(errno);
    return r;
  }
  std::vector<std::string> full = {std::string(GEOVIS_BINARY_DIR) + "/geovis"};
  full.insert(full.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : full) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, slave, 2);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addclose(&fa, master);
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(slave);
  if (rc != 0) {
    ADD_FAILURE() << "cannot start " << argv[0] << ": " << std::strerror(rc);
    ::close(master);
    return r;
  }
  bool sent = false;
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;  // EIO: the child closed the terminal (exited)
    r.terminal.append(buf, size_t(n));
    // The bar ("[###...] 12.3%") is drawn only while tiles are being traced.
    if (!sent && r.terminal.find("%  ") != std::string::npos) {
      ::kill(pid, sig);
      sent = true;
    }
  }
  ::close(master);
  ::waitpid(pid, &r.status, 0);
  EXPECT_TRUE(sent) << "the render ended before it drew a progress bar: " << r.terminal;
  return r;
}

TEST_F(RenderOutputs, SigintAndSigtermStopAtTheNextTile) {
  for (const auto& [sig, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    SCOPED_TRACE("signal " + std::to_string(sig));
    const std::string out = path("big.png");
    // Large enough to take minutes uninterrupted: the signal always arrives mid-render.
    const InterruptedRun r =
        interrupt_render({"render", "-o", out, "--res", "4096x3072", "--supersample", "4", "--threads", "1"}, sig);
    ASSERT_TRUE(WIFEXITED(r.status)) << "killed by the signal instead of stopping: " << r.terminal;
    EXPECT_EQ(WEXITSTATUS(r.status), code) << r.terminal;
    const size_t msg = r.terminal.find("geovis: interrupted: ");
    ASSERT_NE(msg, std::string::npos) << r.terminal;
    EXPECT_NE(r.terminal.find(" of 49152 tiles done, nothing written", msg), std::string::npos) << r.terminal;
    // The progress line was ended before the message (a pty turns "\n" into "\r\n").
    EXPECT_TRUE(msg >= 2 && r.terminal.compare(msg - 2, 2, "\r\n") == 0) << r.terminal;
    EXPECT_FALSE(fs::exists(out));
    // Only the tile checkpoint stays, and the message says where it is (--resume continues from it).
    EXPECT_NE(r.terminal.find("the finished tiles are in \"" + out + ".tiles\""), std::string::npos) << r.terminal;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path() != fs::path(out + ".tiles")) ADD_FAILURE() << "left behind: " << e.path();
  }
}

}  // namespace
}  // namespace geovis::cli

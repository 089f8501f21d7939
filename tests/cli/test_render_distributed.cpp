// Tile checkpoints (--resume inside a frame) and MPI rendering (mpirun -np N geovis render), run
// as the real program: a render is killed with SIGKILL half-way (the test hook
// GEOVIS_TEST_KILL_AFTER_TILES, render/tile_schedule.h) and resumed; MPI jobs run under
// `mpirun --oversubscribe` and are skipped, with the reason, when mpirun or MPI is missing.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace geovis::cli {
namespace {

namespace fs = std::filesystem;

const std::string kGeovis = std::string(GEOVIS_BINARY_DIR) + "/geovis";
const std::string kMpirun = "mpirun --oversubscribe --allow-run-as-root -np ";

struct ProgramRun {
  int exit_code = -1;  ///< exit status; 128 + signal when killed by a signal
  std::string output;  ///< stdout and stderr
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class RenderDistributed : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_render_distributed_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // An unbalanced scene: a Kerr disk seen almost edge-on (the photon ring costs most), 64x56
    // pixels = 4x4 tiles of 16 (the last row clipped), two frames.
    std::ofstream(path("kerr.scm"))
        << "(init-metric '(type \"KerrBL\") '(mass 1.0) '(angmom 0.9) '(id \"metric\"))\n"
           "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(eps_abs 1.0e-8)\n"
           "  '(step_size 0.01) '(id \"raytracing\"))\n"
           "(init-camera '(type \"PinHoleCam\") '(dir #(1.0 0.0 0.0)) '(vup #(0.0 0.0 1.0)) '(fov #(38.0 33.0))\n"
           "  '(res #(64 56)) '(filter \"FilterRGBpdz\") '(id \"cam\"))\n"
           "(init-raygen '(type \"RayGenSimple\") `(boundBoxLL ,(vector (- gpDBLMAX) 0.0 (- gpDBLMAX) (- gpDBLMAX)))\n"
           "  `(boundBoxUR ,(vector gpDBLMAX 70.0 gpDBLMAX gpDBLMAX)) '(solver \"raytracing\") '(maxNumPoints 3000))\n"
           "(init-projector '(localTetrad \"obs\") '(color #(0.1 0.1 0.15)) '(id \"proj\"))\n"
           "(init-light-mgr '(ambient #(1.0 1.0 1.0)))\n"
           "(init-texture '(type \"UniTex\") '(color #(0.95 0.55 0.1)) '(id \"hot\"))\n"
           "(init-texture '(type \"UniTex\") '(color #(0.6 0.15 0.05)) '(id \"cool\"))\n"
           "(init-shader '(type \"SurfShader\") `(objcolor ,(init-texture '(type \"CheckerT2D\") '(texture \"hot\")\n"
           "  '(texture \"cool\") `(transform ,(scale-obj #(36.0 6.0))))) '(ambient 1.0) '(diffuse 0.0) '(id \"sh\"))\n"
           "(plane-ring `(objtype ,gpObjTypeInCoords) '(center #(0.0 0.0 0.0)) '(normal #(0.0 0.0 1.0))\n"
           "  '(rin 3.0) '(rout 15.0) '(shader \"sh\") '(id \"disk\"))\n"
           "(local-tetrad `(pos ,(vector 0.0 50.0 (radians 85.0) 0.0)) '(e0 #(1.0 0.0 0.0 0.0))\n"
           "  '(e1 #(0.0 -1.0 0.0 0.0)) '(e2 #(0.0 0.0 0.0 -1.0)) '(e3 #(0.0 0.0 -1.0 0.0)) '(incoords #f) '(id "
           "\"obs\"))\n"
           "(do ((i 0 (+ i 1))) ((= i 2))\n"
           "  (init-device '(type \"standard\") '(obj \"disk\") '(camera \"cam\")\n"
           "    `(setparam (\"obs\" \"pos\" ,(vector 0.0 (+ 50.0 (* 5.0 i)) (radians 85.0) 0.0)))))\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Runs a shell command in the test folder (environment assignments may precede it); `timeout`
  /// turns a hang into a failure instead of a stuck test.
  ProgramRun sh(const std::string& cmd) const {
    const std::string log = path("run.log");
    const std::string full = "cd '" + dir_.string() + "' && timeout 120 env " + cmd + " > '" + log + "' 2>&1";
    const int status = std::system(full.c_str());
    ProgramRun r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    r.output = read_file(log);
    return r;
  }

  /// The tiles listed in a --tile-stats file (one per rendered tile).
  std::vector<int> stats_tiles(const std::string& csv_name) const {
    std::istringstream in(read_file(path(csv_name)));
    std::string line;
    std::getline(in, line);  // header
    std::vector<int> tiles;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream ls(line);
      for (std::string x; std::getline(ls, x, ',');) f.push_back(x);
      tiles.push_back(std::stoi(f.at(0)) * 1000 + std::stoi(f.at(1)) * 100 + std::stoi(f.at(2)));
    }
    return tiles;
  }

  static bool has_mpirun() { return std::system("command -v mpirun > /dev/null 2>&1") == 0; }

  fs::path dir_;
};

#define SKIP_WITHOUT_MPI()                                                                         \
  do {                                                                                             \
    if (!GEOVIS_HAVE_MPI) GTEST_SKIP() << "geovis was built without MPI (install libopenmpi-dev)"; \
    if (!has_mpirun()) GTEST_SKIP() << "mpirun is not installed (Debian: openmpi-bin)";            \
  } while (0)

TEST_F(RenderDistributed, SigkillHalfWayThroughAFrameThenResumeIsByteIdentical) {
  const std::string args = " render kerr.scm --frames 0 --threads 2 -v -o ";
  ASSERT_EQ(sh(kGeovis + args + "full.png --tile-stats full.csv").exit_code, 0);
  ASSERT_EQ(stats_tiles("full.csv").size(), 16u);

  // Killed right after its 7th tile is durable: no image, a checkpoint with the 7 tiles.
  const ProgramRun killed = sh("GEOVIS_TEST_KILL_AFTER_TILES=7 " + kGeovis + args + "out.png");
  ASSERT_EQ(killed.exit_code, 128 + 9) << killed.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
  ASSERT_TRUE(fs::exists(path("out.png.tiles")));

  const ProgramRun resumed = sh(kGeovis + args + "out.png --resume --tile-stats resumed.csv");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("9 rendered, 7 restored from the checkpoint"), std::string::npos) << resumed.output;
  // Counted: only the 9 missing tiles were rendered, each once.
  const std::vector<int> tiles = stats_tiles("resumed.csv");
  EXPECT_EQ(tiles.size(), 9u);
  EXPECT_EQ(std::set<int>(tiles.begin(), tiles.end()).size(), tiles.size());
  EXPECT_EQ(read_file(path("out.png")), read_file(path("full.png")));
  EXPECT_EQ(read_file(path("out.pdz")), read_file(path("full.pdz")));
  EXPECT_FALSE(fs::exists(path("out.png.tiles"))) << "the checkpoint is removed once the frame is written";
}

TEST_F(RenderDistributed, CheckpointOfAnotherSceneIsIgnoredWithAMessage) {
  ASSERT_EQ(
      sh("GEOVIS_TEST_KILL_AFTER_TILES=5 " + kGeovis + " render kerr.scm --frames 0 --threads 1 -o out.png").exit_code,
      128 + 9);
  const ProgramRun r = sh(kGeovis + " render kerr.scm --frames 0 --threads 1 -v -o out.png --resume --define x=1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("was made for a different scene, options or resolution; ignored"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("16 rendered, 0 restored"), std::string::npos) << r.output;
}

TEST_F(RenderDistributed, WithoutResumeAnOldCheckpointIsNotUsed) {
  ASSERT_EQ(
      sh("GEOVIS_TEST_KILL_AFTER_TILES=5 " + kGeovis + " render kerr.scm --frames 0 --threads 1 -o out.png").exit_code,
      128 + 9);
  const ProgramRun r = sh(kGeovis + " render kerr.scm --frames 0 --threads 1 -v -o out.png");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("16 rendered, 0 restored"), std::string::npos) << r.output;
}

TEST_F(RenderDistributed, MpiFourRanksAreByteIdenticalToSerial) {
  SKIP_WITHOUT_MPI();
  ASSERT_EQ(sh(kGeovis + " render kerr.scm --threads 1 -o serial.png").exit_code, 0);
  // Two frames (the second ordered by the costs measured in the first), hybrid: 2 threads a rank.
  const ProgramRun r = sh(kMpirun + "4 " + kGeovis + " render kerr.scm --threads 2 -v -o mpi.png --tile-stats mpi.csv");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f : {"_0000.png", "_0001.png", "_0000.pdz", "_0001.pdz"}) {
    ASSERT_TRUE(fs::exists(path(std::string("mpi") + f))) << f;
    EXPECT_EQ(read_file(path(std::string("mpi") + f)), read_file(path(std::string("serial") + f))) << f;
  }
  EXPECT_NE(r.output.find("rank 0:"), std::string::npos) << "not run as an MPI job:\n" << r.output;
  // Every tile of both frames rendered exactly once, by some rank.
  const std::vector<int> tiles = stats_tiles("mpi.csv");
  EXPECT_EQ(tiles.size(), 32u);
  EXPECT_EQ(std::set<int>(tiles.begin(), tiles.end()).size(), 32u);
}

TEST_F(RenderDistributed, MpiFramesOverlapAndMatchSerial) {
  SKIP_WITHOUT_MPI();
  // Four frames of the Kerr disk (the observer moves out): frames are not a barrier, so a rank that
  // finds no tile of frame N left is given one of a later frame while N's last tiles finish.
  std::string scene = read_file(path("kerr.scm"));
  const std::string two = "((= i 2))";
  scene.replace(scene.find(two), two.size(), "((= i 4))");
  std::ofstream(path("kerr4.scm")) << scene;
  ASSERT_EQ(sh(kGeovis + " render kerr4.scm --threads 1 -q -o serial.png").exit_code, 0);
  const ProgramRun r =
      sh(kMpirun + "3 " + kGeovis + " render kerr4.scm --threads 1 -v -o mpi.png --tile-stats mpi.csv");
  ASSERT_EQ(r.exit_code, 0) << (r.exit_code == 124 ? "the job hung\n" : "") << r.output;
  for (int f = 0; f < 4; ++f)
    for (const char* ext : {".png", ".pdz"}) {
      char name[32];
      std::snprintf(name, sizeof name, "_%04d%s", f, ext);
      ASSERT_TRUE(fs::exists(path(std::string("mpi") + name))) << name;
      EXPECT_EQ(read_file(path(std::string("mpi") + name)), read_file(path(std::string("serial") + name))) << name;
    }
  // Every tile of every frame rendered exactly once.
  const std::vector<int> tiles = stats_tiles("mpi.csv");
  EXPECT_EQ(tiles.size(), 64u);
  EXPECT_EQ(std::set<int>(tiles.begin(), tiles.end()).size(), 64u);
  // Counted by rank 0 for each image: tiles of later frames handed out before the image's last
  // tile was done. With frames as a barrier this is 0 for every frame.
  const std::string needle = "tiles of later images were handed out before its last tile was done";
  int images = 0, overlapped = 0;
  for (size_t p = r.output.find(needle); p != std::string::npos; p = r.output.find(needle, p + 1)) {
    const size_t number_end = r.output.rfind(' ', p - 1);
    const size_t number_start = r.output.rfind(' ', number_end - 1) + 1;
    overlapped += std::stoi(r.output.substr(number_start, number_end - number_start));
    ++images;
  }
  EXPECT_EQ(images, 4) << r.output;
  EXPECT_GT(overlapped, 0) << r.output;
}

TEST_F(RenderDistributed, MpiSequenceOfCheapFramesEndsAndMatchesSerial) {
  SKIP_WITHOUT_MPI();
  // Many frames of 6 cheap tiles, 2 threads a rank: the frame changes while threads of every rank
  // still ask for work (a thread waiting for work once kept its rank from starting the next
  // frame, and the job hung).
  std::ofstream(path("flat.scm"))
      << "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(step_ctrl #f) '(step_size 0.5))\n"
         "(init-camera '(type \"PinHoleCam\") '(dir #(1 0 0)) '(vup #(0 0 1)) '(fov #(40 30)) '(res #(40 30)) '(id "
         "\"cam\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(maxNumPoints 200)\n"
         "  `(boundBoxLL ,(vector (- gpDBLMAX) -30.0 -30.0 -30.0)) `(boundBoxUR ,(vector gpDBLMAX 30.0 30.0 30.0)))\n"
         "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
         "  '(incoords #f) '(id \"obs\"))\n"
         "(init-projector '(localTetrad \"obs\") '(color #(0 0 0)) '(id \"proj\"))\n"
         "(init-light-mgr '(ambient #(1 1 1)))\n"
         "(init-texture '(type \"UniTex\") '(color #(0.8 0.2 0.2)) '(id \"red\"))\n"
         "(init-shader '(type \"SurfShader\") '(objcolor \"red\") '(ambient 1.0) '(id \"sh\"))\n"
         "(solid-ellipsoid `(objtype ,gpObjTypeInCoords) '(center #(0 0 0)) '(axlen #(2 2 2)) '(shader \"sh\") '(id "
         "\"ball\"))\n"
         "(do ((i 0 (+ i 1))) ((= i 12))\n"
         "  (init-device '(type \"standard\") '(obj \"ball\") `(setparam (\"obs\" \"pos\" ,(vector 0.0 (- -10.0 i) 0.0 "
         "0.0)))))\n";
  ASSERT_EQ(sh(kGeovis + " render flat.scm --threads 1 -q -o serial.png").exit_code, 0);
  const ProgramRun r = sh(kMpirun + "3 " + kGeovis + " render flat.scm --threads 2 -q -o mpi.png");
  ASSERT_EQ(r.exit_code, 0) << (r.exit_code == 124 ? "the job hung\n" : "") << r.output;
  for (int f = 0; f < 12; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "_%04d.png", f);
    EXPECT_EQ(read_file(path(std::string("mpi") + name)), read_file(path(std::string("serial") + name))) << name;
  }
}

TEST_F(RenderDistributed, MpiRankKilledEndsTheJobNamingFrameTileAndResumeCommand) {
  SKIP_WITHOUT_MPI();
  // At 4x the fixture's pixels (8x7 tiles a frame): at 64x56 rank 0 could render nearly every
  // tile before the other ranks had read the scene (28 of 32 tiles, rank 2 one, once in ~4 runs
  // on two cores), and rank 2 never reached its kill point.
  ASSERT_EQ(sh(kGeovis + " render kerr.scm --res 128x112 --threads 1 -o serial.png").exit_code, 0);
  // Rank 2 dies after its 1st tile; rank 0 has checkpointed what was returned so far, of every
  // frame in flight (both frames of the sequence may be).
  const std::string args = " render kerr.scm --res 128x112 --threads 1 -v -o mpi.png";
  const ProgramRun killed =
      sh(kMpirun + "4 -x GEOVIS_TEST_KILL_AFTER_TILES=1 -x GEOVIS_TEST_KILL_RANK=2 " + kGeovis + args);
  EXPECT_NE(killed.exit_code, 0);
  EXPECT_NE(killed.exit_code, 124) << "the job hung";
  EXPECT_NE(killed.output.find("while rendering frame "), std::string::npos) << killed.output;
  EXPECT_NE(killed.output.find("on rank 2"), std::string::npos) << killed.output;
  EXPECT_NE(killed.output.find("--resume"), std::string::npos) << killed.output;
  ASSERT_FALSE(fs::exists(path("mpi_0001.png")));

  const ProgramRun resumed = sh(kMpirun + "4 " + kGeovis + args + " --resume --tile-stats resumed.csv");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(read_file(path("mpi_0000.png")), read_file(path("serial_0000.png")));
  EXPECT_EQ(read_file(path("mpi_0001.png")), read_file(path("serial_0001.png")));
  EXPECT_LT(stats_tiles("resumed.csv").size(), 112u) << resumed.output;  // 2 frames of 56 tiles
}

TEST_F(RenderDistributed, MpiSceneErrorIsReportedOnce) {
  SKIP_WITHOUT_MPI();
  std::ofstream(path("bad.scm")) << "(init-metric (quote (type \"KerrBL\")))\n(no-such-command 1)\n";
  const ProgramRun r = sh(kMpirun + "3 " + kGeovis + " render bad.scm -o bad.png");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.exit_code, 124) << "the job hung";
  const std::string needle = "no-such-command";
  size_t count = 0;
  for (size_t p = r.output.find(needle); p != std::string::npos; p = r.output.find(needle, p + 1)) ++count;
  EXPECT_EQ(count, 1u) << r.output;
}

}  // namespace
}  // namespace geovis::cli

// The scene sandbox (docs/security.md): a scene sees only the scene language, pure Scheme and
// printing; load, getenv and the files of actions are confined; evaluation has a time and a memory
// limit that the scene cannot catch; SchemeOptions::trusted (--trust-scene) restores full Guile.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/builder.h"
#include "scene/scheme.h"
#include "support/temp_dir.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

using testing_support::TempDir;

// Error message of evaluating the file (or "" if none).
std::string error_of_file(const std::string& path, const SchemeOptions& opts = {}) {
  try {
    evaluate_scene_file(path, opts);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

std::string forbidden(const std::string& name) {
  return "\"" + name + "\" is not available in scenes (they run sandboxed; --trust-scene lifts this)";
}

TEST(Sandbox, SystemAccessIsNotAvailableAndNamedWithFileAndLine) {
  TempDir dir;
  const std::string victim = dir.write("victim.txt", "keep me\n");
  const std::string marker = (dir.path / "pwned").string();
  // Each way out of the sandbox a scene might try, on line 2 of its scene.
  const std::vector<std::pair<std::string, std::string>> calls = {
      {"system", "(system \"touch " + marker + "\")"},
      {"system*", "(system* \"touch\" \"" + marker + "\")"},
      {"open-input-pipe", "(open-input-pipe \"id\")"},
      {"delete-file", "(delete-file \"" + victim + "\")"},
      {"primitive-load", "(primitive-load \"" + victim + "\")"},
      {"open-output-file", "(open-output-file \"" + marker + "\")"},
      {"use-modules", "(use-modules (ice-9 popen))"},
      {"eval", "(eval 1 2)"},
      {"@", "((@ (guile) system) \"touch " + marker + "\")"},
      {"current-module", "(define m (current-module))"},
      {"socket", "(socket 2 1 0)"},
  };
  for (const auto& [name, call] : calls) {
    SCOPED_TRACE(call);
    const std::string scene = dir.write("scene.scm", "(define x 1)\n" + call + "\n");
    EXPECT_NE(error_of_file(scene).find(scene + ":2: " + forbidden(name)), std::string::npos) << error_of_file(scene);
  }
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_TRUE(fs::exists(victim));
}

TEST(Sandbox, TrustedScenesHaveFullGuile) {
  TempDir dir;
  const std::string victim = dir.write("victim.txt", "delete me\n");
  const std::string scene = dir.write("scene.scm", "(delete-file \"" + victim + "\")\n(init-device '(n 1))\n");
  EXPECT_NE(error_of_file(scene).find(forbidden("delete-file")), std::string::npos);
  SchemeOptions trusted;
  trusted.trusted = true;
  EXPECT_EQ(evaluate_scene_file(scene, trusted).calls.size(), 1u);
  EXPECT_FALSE(fs::exists(victim));
}

TEST(Sandbox, PureSchemeAndTheSceneLanguageWork) {
  // What scenes use: arithmetic, strings, lists, vectors, do with definitions, set!, display.
  const SceneDescription d = evaluate_scene_string(
      "(define n 0)\n"
      "(do ((i 0 (+ i 1))) ((= i 3)) (define k (* 2 i)) (set! n (+ n k)))\n"
      "(define s (string-append \"a\" (number->string (inexact->exact (round 2.0)))))\n"
      "(define v (list->vector (map (lambda (x) (sqrt x)) (iota 3))))\n"
      "(define a (assoc \"b\" '((\"a\" . 1) (\"b\" . 2))))\n"
      "(init-texture `(n ,n) `(s ,s) `(v ,v) `(a ,(cdr a)) `(pi ,PI))\n",
      "pure.scm");
  ASSERT_EQ(d.calls.size(), 1u);
  EXPECT_DOUBLE_EQ(d.calls[0].params.get_number("n"), 6.0);
  EXPECT_EQ(d.calls[0].params.get_string("s"), "a2");
  EXPECT_DOUBLE_EQ(d.calls[0].params.get_number("a"), 2.0);
}

TEST(Sandbox, SetOfABuiltinChangesOnlyThatScene) {
  // Procedures are the scene's own copies: (set! car ...) must not reach the next scene.
  EXPECT_EQ(evaluate_scene_string("(set! car 5)\n(set! display 6)\n", "a.scm").calls.size(), 0u);
  const SceneDescription d = evaluate_scene_string("(init-texture `(x ,(car '(7 8))))\n", "b.scm");
  EXPECT_DOUBLE_EQ(d.calls.at(0).params.get_number("x"), 7.0);
}

TEST(Sandbox, LoadReadsOnlySceneFilesBelowTheSceneFolderOrTheScenePath) {
  TempDir dir;
  dir.write("scenes/include/part.scm", "(define part 1)\n");
  dir.write("lib/shared_part.scm", "(define shared 2)\n");
  dir.write("outside.scm", "(define outside 3)\n");
  dir.write("scenes/data.txt", "(define data 4)\n");
  fs::create_symlink(dir.path / "outside.scm", dir.path / "scenes" / "link.scm");

  const std::string ok = dir.write("scenes/ok.scm", "(load \"include/part.scm\")\n(init-device `(p ,part))\n");
  EXPECT_EQ(evaluate_scene_file(ok).calls.size(), 1u);

  // Another folder is allowed through --scene-path, where a relative name is also looked up.
  const std::string lib = dir.write("scenes/lib.scm", "(load \"shared_part.scm\")\n(init-device `(s ,shared))\n");
  EXPECT_NE(error_of_file(lib).find("no such file"), std::string::npos);
  SchemeOptions with_path;
  with_path.load_paths = {(dir.path / "lib").string()};
  EXPECT_EQ(evaluate_scene_file(lib, with_path).calls.size(), 1u);

  // Outside the folder (by .., by an absolute name, through a symbolic link) or not a .scm file.
  for (const std::string& name : {std::string("../outside.scm"), (dir.path / "outside.scm").string(),
                                  std::string("link.scm"), std::string("data.txt")}) {
    SCOPED_TRACE(name);
    const std::string scene = dir.write("scenes/bad.scm", "(define x 1)\n(load \"" + name + "\")\n");
    const std::string msg = error_of_file(scene);
    EXPECT_NE(msg.find(scene + ":2: load: cannot load \"" + name + "\": not allowed"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--trust-scene lifts this"), std::string::npos) << msg;
    SchemeOptions trusted;
    trusted.trusted = true;
    EXPECT_EQ(error_of_file(scene, trusted), "");
  }
}

TEST(Sandbox, LoadOfADeviceSaysWhatItIsNotNoSuchFile) {
  TempDir dir;
  const std::string scene = dir.write("scene.scm", "(define x 1)\n(load \"/dev/urandom\")\n");
  const std::string sandboxed = error_of_file(scene);
  EXPECT_NE(sandboxed.find(scene + ":2: load: cannot load \"/dev/urandom\": not allowed"), std::string::npos)
      << sandboxed;
  SchemeOptions trusted;
  trusted.trusted = true;
  const std::string full = error_of_file(scene, trusted);
  EXPECT_NE(full.find("/dev/urandom is a character device, not a regular file"), std::string::npos) << full;
  EXPECT_EQ(sandboxed.find("no such file"), std::string::npos);
  EXPECT_EQ(full.find("no such file"), std::string::npos);
}

TEST(Sandbox, GetenvReadsOnlyTheAllowList) {
  ::setenv("GEOVIS_SANDBOX_TEST", "yes", 1);
  ::setenv("SECRET_SANDBOX_TEST", "token", 1);
  const SceneDescription d = evaluate_scene_string(
      "(init-texture `(home ,(getenv \"HOME\")) `(g ,(getenv \"GEOVIS_SANDBOX_TEST\")))\n", "env.scm");
  EXPECT_EQ(d.calls.at(0).params.get_string("g"), "yes");
  try {
    evaluate_scene_string("(define x 1)\n(define s (getenv \"SECRET_SANDBOX_TEST\"))\n", "env.scm");
    ADD_FAILURE() << "getenv of a variable outside the allow-list must fail";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("env.scm:2: getenv: the environment variable \"SECRET_SANDBOX_TEST\" is "
                                         "not available in scenes"),
              std::string::npos)
        << e.what();
  }
  SchemeOptions trusted;
  trusted.trusted = true;
  EXPECT_EQ(evaluate_scene_string("(init-texture `(s ,(getenv \"SECRET_SANDBOX_TEST\")))\n", "env.scm", trusted)
                .calls.at(0)
                .params.get_string("s"),
            "token");
  EXPECT_TRUE(scene_may_read_env("HOME"));
  EXPECT_TRUE(scene_may_read_env("GEOVIS_TEXTURES"));
  EXPECT_FALSE(scene_may_read_env("PATH"));
  EXPECT_FALSE(scene_may_read_env("AWS_SECRET_ACCESS_KEY"));
}

std::string error_of_string(const std::string& text, const SchemeOptions& opts) {
  try {
    evaluate_scene_string(text, "limit.scm", opts);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Sandbox, AnEndlessLoopIsStoppedEvenIfTheSceneCatchesEverything) {
  SchemeOptions opts;
  opts.time_limit_seconds = 0.3;
  EXPECT_NE(error_of_string("(define x 1)\n(let loop () (loop))\n", opts)
                .find("limit.scm:2: the scene ran longer than the time limit of 0.3 s"),
            std::string::npos);
  const std::string catching =
      "(define x 1)\n(catch #t (lambda () (let loop () (loop))) (lambda _ (let loop () (loop))))\n";
  EXPECT_NE(error_of_string(catching, opts).find("time limit"), std::string::npos);
}

TEST(Sandbox, AnUnboundedAllocationIsStopped) {
  SchemeOptions opts;
  opts.memory_limit_bytes = size_t{48} << 20;
  opts.time_limit_seconds = 120;  // the memory limit must be what stops these
  // Growing without bound ...
  EXPECT_NE(error_of_string("(define x 1)\n(let grow ((l '())) (grow (cons (make-vector 1000 0) l)))\n", opts)
                .find("limit.scm:2: the scene needs more memory than the limit of 48 MiB"),
            std::string::npos);
  // ... or one huge allocation (8 GB) ...
  EXPECT_NE(error_of_string("(define x 1)\n(define v (make-vector 1000000000 0))\n", opts)
                .find("limit.scm:2: the scene needs more memory than the limit of 48 MiB"),
            std::string::npos);
  // ... and the limit is lifted afterwards.
  EXPECT_EQ(
      evaluate_scene_string("(define v (make-vector 10000000 0))\n(init-device `(n ,(vector-length v)))\n", "after.scm")
          .calls.size(),
      1u);
}

TEST(Sandbox, QuietDiscardsWhatTheScenePrints) {
  SchemeOptions quiet;
  quiet.print_output = false;
  testing::internal::CaptureStdout();
  evaluate_scene_string("(display \"scene-says-hello\")\n(newline)\n(m4d-metriclist)\n", "q.scm", quiet);
  const std::string silent = testing::internal::GetCapturedStdout();
  EXPECT_EQ(silent, "");
  testing::internal::CaptureStdout();
  evaluate_scene_string("(display \"scene-says-hello\")\n(newline)\n", "q.scm");
  EXPECT_NE(testing::internal::GetCapturedStdout().find("scene-says-hello"), std::string::npos);
}

TEST(Sandbox, DefineValueErrorsNameTheOption) {
  SchemeOptions opts;
  opts.defines = {{"fview", "("}};
  const std::string msg = error_of_string("(define fview 40)\n", opts);
  EXPECT_NE(msg.find("--define fview=(: the value is not a Scheme datum"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("#<unknown port>"), std::string::npos) << msg;
}

// A scene with one calc-ray action writing `file`.
std::string calc_ray_scene(const std::string& file) {
  return "(init-metric '(type \"Minkowski\") '(id \"metric\"))\n"
         "(init-solver '(type \"GSL_RK_Cash-Karp\") '(geodType \"lightlike\") '(step_ctrl #f) '(step_size 0.5)"
         " '(id \"solver\"))\n"
         "(init-raygen '(type \"RayGenSimple\") '(maxNumPoints 20) '(solver \"solver\")\n"
         "  `(boundBoxLL ,(vector (- gpDBLMAX) -30.0 -30.0 -30.0)) `(boundBoxUR ,(vector gpDBLMAX 30.0 30.0 30.0))"
         " '(id \"rg\"))\n"
         "(local-tetrad '(pos #(0 -10 0 0)) '(e0 #(1 0 0 0)) '(e1 #(0 1 0 0)) '(e2 #(0 0 1 0)) '(e3 #(0 0 0 1))\n"
         "  '(incoords #f) '(id \"obs\"))\n"
         "(calc-ray '(filename \"" +
         file + "\") '(raygen \"rg\") '(locted \"obs\") '(dir #(0.0 80.0)))\n";
}

void run_actions_of(const std::string& text, const BuildOptions& bopts) {
  SceneBuilder builder(evaluate_scene_string(text, "ray.scm"), bopts);
  std::ostringstream log;
  builder.run_actions(log);
}

TEST(Sandbox, ActionsWriteOnlyBelowTheOutputFolder) {
  TempDir dir;
  BuildOptions bopts;
  bopts.output_dir = (dir.path / "out").string();
  fs::create_directories(dir.path / "out" / "sub");
  run_actions_of(calc_ray_scene("ray.txt"), bopts);  // relative to the output folder
  EXPECT_TRUE(fs::exists(dir.path / "out" / "ray.txt"));
  run_actions_of(calc_ray_scene("sub/../ray2.txt"), bopts);
  EXPECT_TRUE(fs::exists(dir.path / "out" / "ray2.txt"));

  fs::create_symlink(dir.path, dir.path / "out" / "up");
  for (const std::string& name :
       {std::string("../escaped.txt"), (dir.path / "escaped.txt").string(), std::string("up/escaped.txt")}) {
    SCOPED_TRACE(name);
    try {
      run_actions_of(calc_ray_scene(name), bopts);
      ADD_FAILURE() << "a file outside the output folder must be refused";
    } catch (const Error& e) {
      EXPECT_NE(
          std::string(e.what()).find("ray.scm:7: calc-ray: filename: \"" + name + "\" is outside the output folder"),
          std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(fs::exists(dir.path / "escaped.txt"));
  }
  BuildOptions trusted = bopts;
  trusted.confine_output = false;
  run_actions_of(calc_ray_scene("../escaped.txt"), trusted);
  EXPECT_TRUE(fs::exists(dir.path / "escaped.txt"));
}

TEST(Sandbox, DryRunActionsWriteNothing) {
  TempDir dir;
  BuildOptions bopts;
  bopts.output_dir = dir.path.string();
  bopts.write_action_files = false;
  run_actions_of(calc_ray_scene("ray.txt"), bopts);
  EXPECT_FALSE(fs::exists(dir.path / "ray.txt"));
}

}  // namespace
}  // namespace geovis

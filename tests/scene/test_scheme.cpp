// The embedded Guile evaluator: the scene language (case folding, quasiquote, do, load,
// --define), the prelude, the commands and their values, and error reporting.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <unistd.h>

#include "scene/scheme.h"
#include "support/temp_dir.h"

namespace geovis {
namespace {

SceneDescription eval(const std::string& text, const SchemeOptions& opts = {}) {
  return evaluate_scene_string(text, "test.scm", opts);
}

// Error message of evaluating `text` ("" if none).
std::string error_of(const std::string& text, const SchemeOptions& opts = {}) {
  try {
    eval(text, opts);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The value of a Scheme expression, via a recorded command.
Value value_of(const std::string& expr) {
  const SceneDescription d = eval("(init-texture `(v ," + expr + "))");
  EXPECT_EQ(d.calls.size(), 1u);
  return d.calls.at(0).params.find("v")->value;
}
double number_of(const std::string& expr) { return std::get<double>(value_of(expr).v); }
Transform transform_of(const std::string& expr) { return std::get<Transform>(value_of(expr).v); }

std::array<double, 3> apply(const Transform& t, std::array<double, 3> p) {
  std::array<double, 3> r{};
  for (int i = 0; i < 3; ++i) r[i] = t(i, 0) * p[0] + t(i, 1) * p[1] + t(i, 2) * p[2] + t(i, 3);
  return r;
}

using testing_support::TempDir;

// ------------------------------------------------------------------------------------------
// Language

TEST(Scheme, SymbolsAreCaseInsensitiveStringsKeepTheirCase) {
  const SceneDescription d = eval(
      "(define fView 3)\n"
      "(init-raygen '(boundBoxLL #(1 2 3 4)) `(MaxNumPoints ,FVIEW) '(Solver \"RayTracing\") '(kind PinHoleCam))");
  ASSERT_EQ(d.calls.size(), 1u);
  const ParamSet& ps = d.calls[0].params;
  EXPECT_EQ(ps.get_vector("boundboxll", 4), (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(ps.get_number("maxnumpoints"), 3.0);
  EXPECT_EQ(ps.get_string("solver"), "RayTracing");  // strings keep their case
  EXPECT_EQ(ps.get_string("kind"), "pinholecam");    // symbols become lower-case strings
  EXPECT_EQ(ps.entries()[0].key, "boundboxll");
}

TEST(Scheme, ValuesConvert) {
  EXPECT_EQ(std::get<bool>(value_of("#t").v), true);
  EXPECT_EQ(std::get<bool>(value_of("#f").v), false);
  EXPECT_EQ(number_of("3"), 3.0);
  EXPECT_EQ(number_of("1/4"), 0.25);  // exact rationals become doubles
  EXPECT_EQ(number_of("(- 1e300 1)"), 1e300);
  EXPECT_EQ(std::get<std::string>(value_of("\"MiXed\"").v), "MiXed");
  EXPECT_EQ(std::get<std::vector<double>>(value_of("#(1 2.5 -3)").v), (std::vector<double>{1, 2.5, -3}));
  const ValueList l = std::get<ValueList>(value_of("'(\"a\" (1 2) #(3))").v);
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(std::get<std::string>(l[0].v), "a");
  EXPECT_EQ(std::get<ValueList>(l[1].v).size(), 2u);
  EXPECT_EQ(std::get<std::vector<double>>(l[2].v), (std::vector<double>{3}));
}

TEST(Scheme, RepeatedKeysAndSeveralValuesAreKeptInOrder) {
  const SceneDescription d = eval("(init-texture '(texture \"a\") '(texture \"b\" \"c\") '(type \"CheckerT2D\"))");
  const ParamSet& ps = d.calls[0].params;
  EXPECT_EQ(ps.get_strings("texture"), (std::vector<std::string>{"a", "b", "c"}));
  std::vector<std::string> keys;
  for (const auto& p : ps.entries()) keys.push_back(p.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"texture", "texture", "texture", "type", "id"}));
}

TEST(Scheme, SetparamIsAList) {
  const SceneDescription d = eval(
      "(init-metric '(type \"Schwarzschild\") '(id \"m\"))\n"
      "(do ((i 0 (+ i 1))) ((= i 2))\n"
      "  (init-device `(setparam (\"m\" \"mass\" ,(* 2 i))) '(setparam (\"cam\" \"fov\" #(1 2)))))");
  ASSERT_EQ(d.calls.size(), 3u);
  const auto sps = d.calls[2].params.find_all("setparam");
  ASSERT_EQ(sps.size(), 2u);
  const ValueList& a = std::get<ValueList>(sps[0]->value.v);
  EXPECT_EQ(std::get<std::string>(a[0].v), "m");
  EXPECT_EQ(std::get<std::string>(a[1].v), "mass");
  EXPECT_EQ(std::get<double>(a[2].v), 2.0);
  EXPECT_EQ(std::get<std::vector<double>>(std::get<ValueList>(sps[1]->value.v)[2].v), (std::vector<double>{1, 2}));
}

TEST(Scheme, CommandsReturnIdsAndGenerateMissingOnes) {
  const SceneDescription d = eval(
      "(define t (init-texture '(type \"UniTex\")))\n"
      "(init-shader `(objcolor ,(init-texture '(type \"UniTex\") '(id \"named\"))) `(normalmap ,t))\n"
      "(init-texture `(obj ,(solid-box '(id \"box\"))))");
  ASSERT_EQ(d.calls.size(), 5u);
  const std::string first = d.calls[0].params.get_string("id");
  EXPECT_EQ(first.rfind("unknown", 0), 0u);
  EXPECT_EQ(d.calls[2].params.get_string("objcolor"), "named");
  EXPECT_EQ(d.calls[2].params.get_string("normalmap"), first);
  EXPECT_EQ(d.calls[4].params.get_string("obj"), "box");  // `(obj ,(solid-box ...)) form of the paper
  std::set<std::string> ids;
  for (const auto& c : d.calls) EXPECT_TRUE(ids.insert(c.params.get_string("id")).second);
}

TEST(Scheme, CommandsAreUsableAsProcedures) {
  const SceneDescription d = eval(
      "(for-each (lambda (c) (init-texture '(type \"UniTex\") `(color ,c))) (list #(1 0 0) #(0 1 0)))\n"
      "(apply solid-box (list '(id \"b\")))");
  ASSERT_EQ(d.calls.size(), 3u);
  EXPECT_EQ(d.calls[1].params.get_vector("color", 3), (std::vector<double>{0, 1, 0}));
  EXPECT_EQ(d.calls[2].command, "solid-box");
}

TEST(Scheme, DoBodyMayContainDefinitions) {
  // TinyScheme allows (define ...) in a do body (minkWheel.scm relies on it).
  const SceneDescription d = eval(
      "(do ((count 0 (+ count 1))) ((= count 3))\n"
      "  (define angle (* 45.0 count))\n"
      "  (solid-box `(angle ,angle)))");
  ASSERT_EQ(d.calls.size(), 3u);
  EXPECT_EQ(d.calls[2].params.get_number("angle"), 90.0);
}

TEST(Scheme, FullSchemeIsAvailable) {
  const SceneDescription d = eval(
      "(define (sq x) (* x x))\n"
      "(let loop ((i 0)) (when (< i 2) (init-light `(n ,(sq i)) `(s ,(string-append \"p\" (number->string i)))) (loop "
      "(+ i 1))))\n"
      "(init-light `(v ,(vector 1 (sqrt 16) (expt 2 3))) `(l ,@(list 7 8)))");
  ASSERT_EQ(d.calls.size(), 3u);
  EXPECT_EQ(d.calls[1].params.get_number("n"), 1.0);
  EXPECT_EQ(d.calls[1].params.get_string("s"), "p1");
  EXPECT_EQ(d.calls[2].params.get_vector("v", 3), (std::vector<double>{1, 4, 8}));
  EXPECT_EQ(d.calls[2].params.find_all("l").size(), 2u);  // ,@ splices two values
  // Unquote inside a vector literal of a quasiquoted list.
  const SceneDescription v = eval("(define r 7)\n(local-tetrad `(pos #(0.0 ,r ,(* 2 r) 0.0)))");
  EXPECT_EQ(v.calls[0].params.get_vector("pos", 4), (std::vector<double>{0, 7, 14, 0}));
}

TEST(Scheme, EachSceneGetsAFreshModule) {
  eval("(define leaked 1) (define PI 3) (define (init-metric . x) 0)");
  EXPECT_NE(error_of("(init-light `(v ,leaked))").find("unbound variable \"leaked\""), std::string::npos);
  EXPECT_EQ(number_of("PI"), 3.141592653589793);
  EXPECT_EQ(eval("(init-metric '(type \"Minkowski\"))").calls.size(), 1u);
}

TEST(Scheme, FinishedSceneModulesAreReleased) {
  // Guile registers an anonymous module in the module root when it first expands code in it;
  // the evaluator unregisters each scene's module afterwards, so repeated evaluations (a
  // long-running process, the fuzzer) do not accumulate modules.
  // Counting needs full Guile; the scenes counted run in the sandbox and with full Guile.
  const std::string count_modules =
      "(init-light `(n ,(hash-count (const #t) (module-submodules (resolve-module '() #f)))))";
  SchemeOptions trusted;
  trusted.trusted = true;
  const double first = eval(count_modules, trusted).calls[0].params.get_number("n");
  for (int i = 0; i < 5; ++i) eval("(define x " + std::to_string(i) + ")", i % 2 ? trusted : SchemeOptions{});
  EXPECT_EQ(eval(count_modules, trusted).calls[0].params.get_number("n"), first);
}

TEST(Scheme, SourceLocationsOfCallsAndArguments) {
  const SceneDescription d = eval(
      ";; comment\n"
      "(init-metric '(type \"Minkowski\")\n"
      "             '(id \"m\"))\n"
      "(do ((i 0 (+ i 1))) ((= i 2))\n"
      "  (init-device\n"
      "     `(setparam (\"m\" \"x\" ,i))))\n");
  ASSERT_EQ(d.calls.size(), 3u);
  EXPECT_EQ(d.calls[0].params.loc().file, "test.scm");
  EXPECT_EQ(d.calls[0].params.loc().line, 2);
  EXPECT_EQ(d.calls[0].params.find("type")->loc.line, 2);
  EXPECT_EQ(d.calls[0].params.find("id")->loc.line, 3);
  EXPECT_EQ(d.calls[2].params.loc().line, 5);
  EXPECT_EQ(d.calls[2].params.find("setparam")->loc.line, 6);
}

TEST(Scheme, LoadIsRelativeToTheLoadingFile) {
  TempDir dir;
  dir.write("parts/metric.scm", "(define mass 2.5)\n(load \"more.scm\")\n");
  dir.write("parts/more.scm", "\n\n(init-metric '(type \"Schwarzschild\") `(mass ,mass))\n");
  const std::string scene = dir.write("scene.scm", "(load \"parts/metric.scm\")\n(init-device `(x ,mass))\n");
  // Evaluate from another working directory: the paths must not depend on it.
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const SceneDescription d = evaluate_scene_file(scene);
  std::filesystem::current_path(cwd);
  ASSERT_EQ(d.calls.size(), 2u);
  EXPECT_EQ(d.calls[0].params.get_number("mass"), 2.5);
  EXPECT_EQ(d.calls[0].params.loc().line, 3);
  EXPECT_EQ(d.calls[0].params.loc().file, (dir.path / "parts/more.scm").string());
  EXPECT_EQ(d.calls[1].params.loc().file, scene);
  EXPECT_EQ(d.dir, dir.path.string());
}

TEST(Scheme, ErrorsInsideLoadedFilesNameThatFile) {
  TempDir dir;
  dir.write("part.scm", "\n(init-metrik '(type \"Minkowski\"))\n");
  const std::string scene = dir.write("scene.scm", "(define x 1)\n(load \"part.scm\")\n");
  try {
    evaluate_scene_file(scene);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir.path / "part.scm").string() + ":2: unknown command \"init-metrik\""),
              std::string::npos)
        << e.what();
  }
}

TEST(Scheme, DefineOverridesATopLevelDefine) {
  SchemeOptions opts;
  opts.defines = {{"fView", "30"}, {"name", "\"Text\""}, {"flag", "#t"}};
  Diagnostics diag;
  opts.diag = &diag;
  const SceneDescription d = eval(
      "(define fview 2.5)\n(define name \"x\")\n(define flag #f)\n"
      "(init-camera `(fov ,(vector fview fview)) `(n ,name) `(f ,flag))",
      opts);
  EXPECT_EQ(d.calls[0].params.get_vector("fov", 2), (std::vector<double>{30, 30}));
  EXPECT_EQ(d.calls[0].params.get_string("n"), "Text");
  EXPECT_EQ(d.calls[0].params.get_bool("f"), true);
  EXPECT_TRUE(diag.warnings().empty());
}

TEST(Scheme, DefineOfAnUndefinedNameWarnsWithTheClosestDefine) {
  SchemeOptions opts;
  opts.defines = {{"fveiw", "30"}};
  Diagnostics diag;
  opts.diag = &diag;
  eval("(define fview 2.5)\n(define r_obs 30)\n(init-camera `(fov ,fview))", opts);
  ASSERT_EQ(diag.warnings().size(), 1u);
  const std::string& w = diag.warnings()[0];
  EXPECT_NE(w.find("fveiw"), std::string::npos) << w;
  EXPECT_NE(w.find("did you mean \"fview\""), std::string::npos) << w;
  EXPECT_NE(w.find("fview, r_obs"), std::string::npos) << w;
}

TEST(Scheme, DefineValueMustBeOneDatum) {
  SchemeOptions opts;
  opts.defines = {{"fview", "1 2"}};
  EXPECT_NE(error_of("(define fview 2)", opts).find("--define fview=1 2: the value must be a single Scheme datum"),
            std::string::npos);
  opts.defines = {{"fview", "(1"}};
  EXPECT_NE(error_of("(define fview 2)", opts).find("end of input"), std::string::npos);
}

TEST(Scheme, EvaluationsFromSeveralThreads) {
  std::vector<std::thread> threads;
  std::vector<size_t> counts(4);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &counts] {
      const SceneDescription d =
          eval("(do ((i 0 (+ i 1))) ((= i " + std::to_string(10 * (t + 1)) + ")) (init-device `(n ,i)))");
      counts[t] = d.calls.size();
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(counts, (std::vector<size_t>{10, 20, 30, 40}));
}

// ------------------------------------------------------------------------------------------
// Prelude (catalogue §1, Parser/init.scm)

TEST(SchemePrelude, ConstantsOfInitScm) {
  EXPECT_EQ(number_of("gpObjTypeLocal"), 0.0);
  EXPECT_EQ(number_of("gpObjTypeInCoords"), 1.0);
  EXPECT_EQ(number_of("gpCSGDifferObj"), 1.0);
  EXPECT_EQ(number_of("gpCSGUnifiedObj"), 2.0);
  EXPECT_EQ(number_of("gpCSGIntersecObj"), 3.0);
  EXPECT_EQ(number_of("gpTetradDefault"), 0.0);
  EXPECT_EQ(number_of("gpTetradStatic"), 1.0);
  EXPECT_EQ(number_of("gpTetradLNRF"), 2.0);
  EXPECT_EQ(number_of("gpTetradFreefall"), 3.0);
  EXPECT_EQ(number_of("gpTetradComoving"), 4.0);
  EXPECT_EQ(number_of("gpTetradCylinder"), 5.0);
  EXPECT_EQ(number_of("gpTetradCartesian"), 6.0);
  EXPECT_NEAR(number_of("PI"), M_PI, 1e-15);
  EXPECT_NEAR(number_of("PIhalf"), M_PI / 2, 1e-15);
  EXPECT_NEAR(number_of("PI2"), 2 * M_PI, 1e-15);
  EXPECT_EQ(number_of("gpDBLMAX"), 1.844674407370955616e19);
  EXPECT_NEAR(number_of("DEG_TO_RAD"), M_PI / 180, 1e-18);
  EXPECT_NEAR(number_of("RAD_TO_DEG"), 180 / M_PI, 1e-13);
  EXPECT_NEAR(number_of("(radians 90)"), M_PI / 2, 1e-15);
  EXPECT_NEAR(number_of("(degrees PI)"), 180.0, 1e-12);
}

TEST(SchemePrelude, CalcHFoVIsThePinholeRelation) {
  // tan(h/2) / tan(v/2) = resX / resY.
  EXPECT_NEAR(number_of("(calcHFoV 100 100 40)"), 40.0, 1e-12);
  EXPECT_NEAR(number_of("(calcHFoV 200 100 90)"), 2 * std::atan(2.0) * 180 / M_PI, 1e-12);
  const double h = number_of("(calcHFoV 720 576 48)");
  EXPECT_NEAR(std::tan(h / 2 * M_PI / 180) / std::tan(24 * M_PI / 180), 720.0 / 576.0, 1e-13);
}

TEST(SchemePrelude, EveryLanguageNameIsBound) {
  std::string text;
  for (const auto& n : scene_language_names())
    text += "(if (not (defined? '" + n + ")) (error \"missing\" '" + n + "))\n";
  SchemeOptions trusted;  // defined? needs full Guile; the sandbox binds the same names
  trusted.trusted = true;
  EXPECT_EQ(error_of(text, trusted), "");
  std::string uses;
  for (const auto& n : scene_language_names()) uses += "(define x-" + n + " " + n + ")\n";
  EXPECT_EQ(error_of(uses), "");
  for (const auto& n : scene_command_names()) EXPECT_EQ(n, to_lower(n));
}

// ------------------------------------------------------------------------------------------
// Immediate commands

TEST(SchemeCommands, Vec3Vec4) {
  EXPECT_EQ(std::get<std::vector<double>>(value_of("(vec3 1 2 3)").v), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(std::get<std::vector<double>>(value_of("(vec4 0 1/2 2 3)").v), (std::vector<double>{0, 0.5, 2, 3}));
  EXPECT_NE(error_of("(vec4 1 2 3)").find("test.scm:1: vec4: expected 4 numbers, found 3 arguments"),
            std::string::npos);
  EXPECT_NE(error_of("(vec3 1 \"2\" 3)").find("found the string \"2\""), std::string::npos);
}

TEST(SchemeCommands, RotationsAreProperAndRightHanded) {
  // "z" by 90 degrees maps x to y, y to -x (right-handed).
  const Transform rz = transform_of("(rotate-obj \"z\" 90)");
  EXPECT_EQ(rz.dim, 3);
  auto p = apply(rz, {1, 0, 0});
  EXPECT_NEAR(p[0], 0, 1e-15);
  EXPECT_NEAR(p[1], 1, 1e-15);
  EXPECT_NEAR(p[2], 0, 1e-15);
  p = apply(transform_of("(rotate-obj \"x\" 90)"), {0, 1, 0});
  EXPECT_NEAR(p[2], 1, 1e-15);
  p = apply(transform_of("(rotate-obj 'Y 90)"), {0, 0, 1});
  EXPECT_NEAR(p[0], 1, 1e-15);
  // An axis vector (any length) equals the named axis.
  const Transform rz2 = transform_of("(rotate-obj #(0 0 5) 90)");
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(rz2.m[i], rz.m[i], 1e-15);
  // Arbitrary axis: R R^T = I, det R = 1, R n = n, and n.(R v) = n.v.
  const Transform r = transform_of("(rotate-obj #(1 -2 0.5) 37)");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += r(i, k) * r(j, k);
      EXPECT_NEAR(s, i == j ? 1.0 : 0.0, 1e-15);
    }
  const double det = r(0, 0) * (r(1, 1) * r(2, 2) - r(1, 2) * r(2, 1)) -
                     r(0, 1) * (r(1, 0) * r(2, 2) - r(1, 2) * r(2, 0)) +
                     r(0, 2) * (r(1, 0) * r(2, 1) - r(1, 1) * r(2, 0));
  EXPECT_NEAR(det, 1.0, 1e-15);
  const double nl = std::sqrt(1 + 4 + 0.25);
  const std::array<double, 3> n{1 / nl, -2 / nl, 0.5 / nl};
  p = apply(r, n);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p[i], n[i], 1e-15);
  // Rotation angle: for v perpendicular to n, cos(angle) = v.(R v).
  const std::array<double, 3> v{2 / std::sqrt(5.0), 1 / std::sqrt(5.0), 0};  // n.v = 0
  p = apply(r, v);
  EXPECT_NEAR(v[0] * p[0] + v[1] * p[1] + v[2] * p[2], std::cos(37 * M_PI / 180), 1e-15);
}

TEST(SchemeCommands, TrailingMatrixIsAppliedFirst) {
  // (rotate-obj "z" 90 (translate-obj #(1 0 0))): translate, then rotate: origin -> (0 1 0).
  auto p = apply(transform_of("(rotate-obj \"z\" 90 (translate-obj #(1 0 0)))"), {0, 0, 0});
  EXPECT_NEAR(p[0], 0, 1e-15);
  EXPECT_NEAR(p[1], 1, 1e-15);
  // (translate-obj #(1 0 0) (rotate-obj "z" 90)): rotate, then translate: origin -> (1 0 0).
  p = apply(transform_of("(translate-obj #(1 0 0) (rotate-obj \"z\" 90))"), {0, 0, 0});
  EXPECT_NEAR(p[0], 1, 1e-15);
  EXPECT_NEAR(p[1], 0, 1e-15);
  p = apply(transform_of("(scale-obj #(2 3 4) (translate-obj #(1 1 1)))"), {0, 0, 0});
  EXPECT_EQ(p, (std::array<double, 3>{2, 3, 4}));
}

TEST(SchemeCommands, TwoDimensionalTransforms) {
  const Transform s = transform_of("(scale-obj #(-1 2))");
  EXPECT_EQ(s.dim, 2);
  EXPECT_EQ(s(0, 0), -1.0);
  EXPECT_EQ(s(1, 1), 2.0);
  EXPECT_EQ(s(2, 2), 1.0);
  const Transform t = transform_of("(translate-obj #(0.5 0.25) (scale-obj #(2 2)))");
  EXPECT_EQ(t.dim, 2);
  EXPECT_EQ(apply(t, {1, 1, 0}), (std::array<double, 3>{2.5, 2.25, 0}));
  // 2D rotation by 90 degrees about the centre (1, 1): (2, 1) -> (1, 2); the centre stays.
  const Transform r = transform_of("(rotate-obj #(1 1) 90)");
  EXPECT_EQ(r.dim, 2);
  auto p = apply(r, {2, 1, 0});
  EXPECT_NEAR(p[0], 1, 1e-15);
  EXPECT_NEAR(p[1], 2, 1e-15);
  p = apply(r, {1, 1, 0});
  EXPECT_NEAR(p[0], 1, 1e-15);
  EXPECT_NEAR(p[1], 1, 1e-15);
  p = apply(transform_of("(rotate-obj 90)"), {1, 0, 0});
  EXPECT_NEAR(p[1], 1, 1e-15);
}

TEST(SchemeCommands, MatricesSurviveQuasiquoteAndVariables) {
  const SceneDescription d = eval(
      "(define m (rotate-obj \"x\" 30))\n"
      "(solid-box `(transform ,m))\n"
      "(solid-box (list 'transform (scale-obj #(1 2 3) m)))");
  const Transform a = d.calls[0].params.get_transform("transform");
  const Transform b = d.calls[1].params.get_transform("transform");
  EXPECT_NEAR(a(2, 1), 0.5, 1e-15);
  EXPECT_NEAR(b(2, 1), 1.5, 1e-15);  // row z scaled by 3
}

TEST(SchemeCommands, TransformErrors) {
  EXPECT_NE(error_of("(rotate-obj \"q\" 30)").find("rotate-obj: expected the axis \"x\", \"y\" or \"z\""),
            std::string::npos);
  EXPECT_NE(error_of("(rotate-obj #(0 0 0) 30)").find("non-zero"), std::string::npos);
  EXPECT_NE(error_of("(rotate-obj \"x\")").find("the angle is missing"), std::string::npos);
  EXPECT_NE(
      error_of("(scale-obj #(1 2) (rotate-obj \"x\" 3))").find("cannot compose a 2D transform with the trailing 3D"),
      std::string::npos);
  EXPECT_NE(error_of("(translate-obj #(1 2 3) 5)").find("expected a trailing matrix"), std::string::npos);
  EXPECT_NE(error_of("(scale-obj)").find("found no argument"), std::string::npos);
}

TEST(SchemeCommands, GetParameterSeesLaterSetParameter) {
  const SceneDescription d = eval(
      "(init-metric '(type \"Schwarzschild\") '(mass 1.0) '(id \"m\"))\n"
      "(set-parameter '(id \"m\") '(mass 2.0))\n"
      "(init-light `(a ,(get-parameter '(id \"m\") '(param \"Mass\")))\n"
      "            `(b ,(cdr (assq 'type (get-parameter '(id \"m\"))))))");
  ASSERT_EQ(d.calls.size(), 3u);
  EXPECT_EQ(d.calls[1].command, "set-parameter");
  EXPECT_EQ(d.calls[2].params.get_number("a"), 2.0);
  EXPECT_EQ(d.calls[2].params.get_string("b"), "Schwarzschild");
}

TEST(SchemeCommands, MetricAndSolverListsPrint) {
  testing::internal::CaptureStdout();
  eval("(m4d-metriclist) (m4d-solverlist)");
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("Schwarzschild"), std::string::npos);
  EXPECT_NE(out.find("GSL_RK_Cash-Karp"), std::string::npos);
}

TEST(SchemeCommands, ExitStopsEvaluation) {
  try {
    eval("(init-metric '(type \"Minkowski\"))\n(exit 3)\n(init-metric '(type \"Kerr\"))");
    FAIL() << "no SceneExit";
  } catch (const SceneExit& e) {
    EXPECT_EQ(e.code(), 3);
    EXPECT_NE(std::string(e.what()).find("test.scm:2: exit:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(eval("(quit)"), SceneExit);
  EXPECT_THROW(eval("(primitive-exit 1)"), SceneExit);
}

TEST(SchemeCommands, GetenvOfUnsetVariableWarns) {
  unsetenv("GEOVIS_TEST_SURELY_UNSET");
  setenv("GEOVIS_TEST_SET", "Value", 1);
  Diagnostics diag;
  SchemeOptions opts;
  opts.diag = &diag;
  const SceneDescription d =
      eval("(init-texture `(a ,(getenv \"GEOVIS_TEST_SURELY_UNSET\")) `(b ,(getenv \"GEOVIS_TEST_SET\")))", opts);
  EXPECT_EQ(d.calls[0].params.get_string("a"), "");
  EXPECT_EQ(d.calls[0].params.get_string("b"), "Value");
  ASSERT_EQ(diag.warnings().size(), 1u);
  EXPECT_NE(diag.warnings()[0].find("GEOVIS_TEST_SURELY_UNSET is not set"), std::string::npos);
}

// ------------------------------------------------------------------------------------------
// Errors

TEST(SchemeErrors, UnknownCommandSuggestsTheClosest) {
  const std::string e = error_of("\n\n(init-metrik '(type \"Kerr\"))");
  EXPECT_NE(e.find("test.scm:3: unknown command \"init-metrik\"; did you mean \"init-metric\"?"), std::string::npos)
      << e;
  EXPECT_NE(error_of("(solid-sphere '(id \"s\"))").find("unknown command \"solid-sphere\""), std::string::npos);
}

TEST(SchemeErrors, SyntaxErrorsKeepGuilesPosition) {
  std::string e = error_of("(define x 1)\n(init-metric '(type \"Kerr\")\n");
  EXPECT_NE(e.find("test.scm:3:1: unexpected end of input"), std::string::npos) << e;
  EXPECT_NE(e.find("the ( at test.scm:2:1 is never closed"), std::string::npos) << e;
  e = error_of("(define x 1))\n");
  // Guile's column is the one after the stray ")".
  EXPECT_EQ(e.rfind("test.scm:1:", 0), 0u) << e;
  EXPECT_NE(e.find("unexpected \")\""), std::string::npos) << e;
}

TEST(SchemeErrors, ArgumentsMustBeKeyValueLists) {
  EXPECT_NE(error_of("(init-metric \"Kerr\")").find("test.scm:1: init-metric: argument 1: expected a (key value) list"),
            std::string::npos);
  EXPECT_NE(error_of("(init-metric '(type . \"Kerr\"))").find("dotted pair"), std::string::npos);
  EXPECT_NE(error_of("(init-metric '(3 \"Kerr\"))").find("starting with a symbol key"), std::string::npos);
  EXPECT_NE(error_of("(init-metric `(f ,init-metric))").find("init-metric: f: expected a number, string"),
            std::string::npos);
  EXPECT_NE(error_of("(init-metric `(f ,(if #f #f)))").find("#<unspecified>"), std::string::npos);
  EXPECT_NE(error_of("(init-metric '(f #(1 a)))").find("expected a vector of numbers, found the symbol a"),
            std::string::npos);
}

TEST(SchemeErrors, IdsMustBeUniqueAndReferencesMustExist) {
  EXPECT_NE(error_of("(init-camera '(id \"c\"))\n(solid-box '(id \"c\"))")
                .find("test.scm:2: solid-box: id: the id \"c\" is already used by the init-camera at test.scm:1"),
            std::string::npos);
  EXPECT_NE(error_of("(init-metric '(id \"metric\"))\n(gvs-print '(id \"metrc\"))")
                .find("no object with id \"metrc\" has been defined before; did you mean \"metric\"?"),
            std::string::npos);
  EXPECT_NE(error_of("(set-parameter '(mass 1))").find("set-parameter: id: this key is required"), std::string::npos);
  EXPECT_NE(error_of("(solid-box '(id 3))").find("solid-box: id: expected a string"), std::string::npos);
}

TEST(SchemeErrors, RuntimeErrorsNameTheTopLevelForm) {
  EXPECT_NE(error_of("(define a 1)\n(define b (car '()))").find("test.scm:2: in procedure car"), std::string::npos);
  EXPECT_NE(error_of("(error \"my message\" 42)").find("test.scm:1: my message 42"), std::string::npos);
  EXPECT_NE(error_of("(throw 'custom-key 1 2)").find("custom-key"), std::string::npos);
  EXPECT_NE(error_of("(define (f) (+ 1 (f)))\n(f)").find("test.scm:2: stack overflow"), std::string::npos);
  EXPECT_NE(error_of("(define fview 3)\n(init-camera\n  `(fov ,(vector fveiw)))")
                .find("test.scm:3: unbound variable \"fveiw\"; did you mean \"fview\"?"),
            std::string::npos);
}

TEST(SchemeErrors, RunawayLoopsHitTheCallLimit) {
  SchemeOptions opts;
  opts.max_calls = 100;
  EXPECT_NE(error_of("(do ((i 0 (+ i 1))) (#f) (init-device '(n 1)))", opts).find("more than 100 command calls"),
            std::string::npos);
}

TEST(SchemeErrors, EndlessLoopsHitTheTimeLimit) {
  SchemeOptions opts;
  opts.time_limit_seconds = 0.2;
  EXPECT_NE(
      error_of("(define x 1)\n(let loop () (loop))", opts).find("test.scm:2: the scene ran longer than the time limit"),
      std::string::npos);
  // A quick scene is unaffected, and a later evaluation is not interrupted by a stale limit.
  EXPECT_EQ(eval("(init-metric '(type \"Minkowski\"))", opts).calls.size(), 1u);
  EXPECT_EQ(eval("(do ((i 0 (+ i 1))) ((= i 100000)))").calls.size(), 0u);
}

TEST(SchemeErrors, MissingSceneFile) {
  EXPECT_THROW(evaluate_scene_file("/nonexistent/scene.scm"), Error);
  try {
    evaluate_scene_file("/nonexistent/scene.scm");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.scm: cannot read the scene file"), std::string::npos);
  }
}

TEST(SchemeErrors, ErrorsDoNotPoisonLaterEvaluations) {
  EXPECT_NE(error_of("(car 1)"), "");
  EXPECT_NE(error_of("(exit)"), "");
  EXPECT_NE(error_of("(("), "");
  EXPECT_EQ(eval("(init-metric '(type \"Minkowski\"))").calls.size(), 1u);
}

}  // namespace
}  // namespace geovis

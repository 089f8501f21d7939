// `geovis geodesic` and `geovis metrics`, run in-process (geovis::cli::run).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "spacetime/metric_registry.h"

namespace geovis::cli {
namespace {

struct Output {
  int code;
  std::string out, err;
};

Output run_captured(std::vector<std::string> args) {
  args.insert(args.begin(), "geovis");
  std::vector<const char*> argv;
  for (auto& a : args) argv.push_back(a.c_str());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int code = run(static_cast<int>(argv.size()), argv.data());
  Output o{code, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
  return o;
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string l;
  while (std::getline(ss, l)) out.push_back(l);
  return out;
}

std::vector<double> csv_numbers(const std::string& line) {
  std::vector<double> v;
  std::stringstream ss(line);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(std::stod(item));
  return v;
}

constexpr const char* kLambdaTo30 = "29.393876913398135";  // 24 / k^r, k^r = sqrt(1 − 2/6) = sqrt(2/3)

TEST(GeodesicCmd, ReproducesRadialLightTravelTime) {
  // Paper eq. (9): t(30) − t(6) = [r + r_s ln(r − r_s)] between the radii = 27.8918 (M = 1). For an
  // affinely parametrized radial null ray dr/dλ = k^r is constant, so λ = 24/k^r ends at r = 30.
  const double expected = (30.0 + 2.0 * std::log(28.0)) - (6.0 + 2.0 * std::log(4.0));
  EXPECT_NEAR(expected, 27.8918, 1e-4);
  EXPECT_NEAR(std::stod(kLambdaTo30), 24.0 / std::sqrt(2.0 / 3.0), 1e-14);
  // Both forms of the equations: Carter's in Mino time (default) and the coordinate geodesic equation.
  for (const std::string eq : {"separable", "coordinate"}) {
    SCOPED_TRACE(eq);
    const Output o = run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", "0,6,1.5707963267948966,0",
                                   "--dir", "1,0,0", "--forward", "--lambda-max", kLambdaTo30, "--eps-abs", "1e-10",
                                   "--equations", eq, "--no-escape"});
    ASSERT_EQ(o.code, 0) << o.err;
    const auto ls = lines(o.out);
    ASSERT_GE(ls.size(), 4u);
    EXPECT_EQ(ls.front(), "lambda,x0,x1,x2,x3,k0,k1,k2,k3,constraint");
    EXPECT_EQ(ls.back(), "# stop: lambda-max");
    const auto first = csv_numbers(ls[1]);
    const auto last = csv_numbers(ls[ls.size() - 2]);
    ASSERT_EQ(first.size(), 10u);
    ASSERT_EQ(last.size(), 10u);
    EXPECT_EQ(first[0], 0.0);
    EXPECT_EQ(first[2], 6.0);
    EXPECT_NEAR(last[2], 30.0, 1e-8);
    EXPECT_NEAR(last[1] - first[1], expected, 1e-4);
    EXPECT_NEAR(last[1] - first[1], expected, 1e-8);  // what the tolerance actually delivers
    for (size_t i = 1; i + 1 < ls.size(); ++i) EXPECT_LT(std::fabs(csv_numbers(ls[i])[9]), 1e-9) << ls[i];
  }
  EXPECT_NE(run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", "0,6,1.5,0", "--dir", "1,0,0",
                          "--equations", "carter"})
                .code,
            0);
}

TEST(GeodesicCmd, BackwardRayIsPastDirectedByDefault) {
  // Without --forward the ray is traced backwards in time, as the renderer does: t decreases.
  const Output o = run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", "0,6,1.5707963267948966,0", "--dir",
                                 "1,0,0", "--lambda-max", "5", "--solver", "DP54"});
  ASSERT_EQ(o.code, 0) << o.err;
  const auto ls = lines(o.out);
  const auto last = csv_numbers(ls[ls.size() - 2]);
  EXPECT_LT(last[1], 0.0);
  EXPECT_GT(last[2], 6.0);  // spatial direction along +e(r)
}

TEST(GeodesicCmd, CapturedRayStopsAtTheHorizon) {
  const Output o = run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", "0,10,1.5707963267948966,0", "--dir",
                                 "-1,0,0", "--forward", "--eps-rel", "1e-8", "--solver", "DOP853"});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(lines(o.out).back(), "# stop: horizon");
}

TEST(GeodesicCmd, EscapingRayStopsEscapedAtAModestRadius) {
  // It used to run to r ~ 1e12 and stop with step-underflow (19,543 lines). Outward at r = 10 > 3M:
  // escaped at once (no objects: --escape-radius 0), or just beyond a given bounding radius.
  const std::string pos = "0,10,1.5707963,0";
  for (const std::string eq : {"separable", "coordinate"}) {
    SCOPED_TRACE(eq);
    const Output o =
        run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", pos, "--dir", "1,0,0", "--equations", eq});
    ASSERT_EQ(o.code, 0) << o.err;
    const auto ls = lines(o.out);
    EXPECT_LT(ls.size(), 10u);
    ASSERT_EQ(ls.back().rfind("# stop: escaped at radius ", 0), 0u) << ls.back();
    const auto last = csv_numbers(ls[ls.size() - 2]);
    double radius = 0, lambda = 0;
    ASSERT_EQ(std::sscanf(ls.back().c_str(), "# stop: escaped at radius %lf, lambda %lf", &radius, &lambda), 2);
    EXPECT_EQ(radius, last[2]);
    EXPECT_EQ(lambda, last[0]);
    EXPECT_GT(radius, 10.0);
    EXPECT_LT(radius, 20.0);

    const Output o2 = run_captured({"geodesic", "--metric", "Schwarzschild", "--pos", pos, "--dir", "0.3,1,0",
                                    "--equations", eq, "--escape-radius", "100"});
    ASSERT_EQ(o2.code, 0) << o2.err;
    ASSERT_EQ(std::sscanf(lines(o2.out).back().c_str(), "# stop: escaped at radius %lf", &radius), 1) << o2.out;
    EXPECT_GT(radius, 100.0);
    EXPECT_LT(radius, 1000.0);
  }
  // JSON: radius and λ.
  const Output j =
      run_captured({"geodesic", "--metric", "KerrBL", "--pos", pos, "--dir", "1,0.2,0", "--format", "json"});
  ASSERT_EQ(j.code, 0) << j.err;
  const auto js = nlohmann::json::parse(j.out);
  EXPECT_EQ(js["stop"], "escaped");
  EXPECT_EQ(js["escape"]["radius"], js["points"].back()["x"][1]);
  EXPECT_EQ(js["escape"]["lambda"], js["points"].back()["lambda"]);
  // --no-escape: as before, no escape.
  const Output n = run_captured(
      {"geodesic", "--metric", "Schwarzschild", "--pos", pos, "--dir", "1,0,0", "--no-escape", "--max-steps", "50"});
  ASSERT_EQ(n.code, 0) << n.err;
  EXPECT_EQ(lines(n.out).back(), "# stop: max-steps");
}

TEST(GeodesicCmd, HelpStatesTheStopReasons) {
  const Output o = run_captured({"geodesic", "--help"});
  EXPECT_EQ(o.code, 0);
  for (const char* r : {"escaped", "horizon", "bounding-box", "lambda-max", "max-steps", "constraint", "step-underflow",
                        "not-finite", "--escape-radius", "--no-escape"})
    EXPECT_NE(o.out.find(r), std::string::npos) << r;
}

TEST(GeodesicCmd, NearAxisKerrRayThatUsedToStallGetsThrough) {
  // The Kerr ray that stalled at θ ≈ π − 7e-7 in the Mino equations and ended with max-steps.
  const Output o = run_captured({"geodesic", "--metric", "KerrBL", "--param", "angmom=0.9", "--pos",
                                 "0,1000,0.29670597283903605,0", "--dir", "-1,0.004989,-3e-7", "--eps-abs", "1e-9",
                                 "--max-steps", "30000", "--escape-radius", "1000"});
  ASSERT_EQ(o.code, 0) << o.err;
  const auto ls = lines(o.out);
  EXPECT_EQ(ls.back().rfind("# stop: escaped", 0), 0u) << ls.back();
  EXPECT_LT(ls.size(), 2000u);
}

TEST(GeodesicCmd, JsonCarriesTheSame) {
  const Output o = run_captured({"geodesic", "--metric", "Schwarzschild", "--param", "mass=0.5", "--pos",
                                 "0,10,1.5707963267948966,0", "--dir", "0,0.3,0", "--type", "timelike", "--max-steps",
                                 "20", "--format", "json"});
  ASSERT_EQ(o.code, 0) << o.err;
  const auto j = nlohmann::json::parse(o.out);
  EXPECT_EQ(j["metric"], "Schwarzschild");
  EXPECT_EQ(j["params"]["mass"], 0.5);
  EXPECT_EQ(j["type"], "timelike");
  EXPECT_EQ(j["stop"], "max-steps");
  EXPECT_EQ(j["steps"], 20);
  ASSERT_EQ(j["points"].size(), 21u);
  // u = γ(e0 + β e2) with β = 0.3: g(u,u) = −1 at the start.
  EXPECT_NEAR(j["points"][0]["constraint"].get<double>(), 0.0, 1e-14);
  EXPECT_EQ(j["points"][0]["x"][1], 10.0);
}

TEST(GeodesicCmd, ErrorsAreClear) {
  struct Case {
    std::vector<std::string> args;
    std::string expect;
  };
  const std::string eq = "1.5707963267948966";
  const std::vector<Case> cases = {
      {{"--metric", "Schwarzschlid", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0"}, "did you mean \"Schwarzschild\""},
      {{"--metric", "Schwarzschild", "--param", "mas=2", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0"},
       "did you mean \"mass\""},
      {{"--metric", "Schwarzschild", "--param", "mass", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0"},
       "--param: expected KEY=VALUE"},
      {{"--metric", "Schwarzschild", "--param", "mass=-1", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0"},
       "out of range"},
      {{"--metric", "Schwarzschild", "--solver", "GSL_RK_Cash-Krap", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0"},
       "did you mean \"GSL_RK_Cash-Karp\""},
      {{"--metric", "Schwarzschild", "--pos", "0,6,1.5", "--dir", "1,0,0"}, "--pos: expected 4 comma-separated"},
      {{"--metric", "Schwarzschild", "--pos", "0,6,x,0", "--dir", "1,0,0"}, "--pos: expected 4 comma-separated"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1,0"}, "--dir: expected 3"},
      {{"--metric", "Schwarzschild", "--pos", "0,1.5," + eq + ",0", "--dir", "1,0,0"}, "outside the validity domain"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "0.6,0.8,0", "--type", "timelike"},
       "|v| < 1"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "0,0,0"}, "non-zero direction"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1e155,0,0"}, "--dir: the length"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1e-160,1e-160,0"}, "is not null"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0", "--escape-radius", "-1"},
       "--escape-radius: expected"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0", "--type", "lightlik"},
       "did you mean \"lightlike\""},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0", "--eps-abs", "0"}, "eps_abs"},
      {{"--metric", "Schwarzschild", "--pos", "0,6," + eq + ",0", "--dir", "1,0,0", "--format", "xml"},
       "--format: expected csv or json"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"geodesic"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const Output o = run_captured(args);
    EXPECT_NE(o.code, 0) << c.expect;
    EXPECT_NE(o.err.find(c.expect), std::string::npos) << "expected \"" << c.expect << "\" in: " << o.err;
    EXPECT_TRUE(o.out.empty()) << o.out;
  }
}

TEST(MetricsCmd, ListsEveryMetric) {
  const Output o = run_captured({"metrics"});
  ASSERT_EQ(o.code, 0) << o.err;
  for (const auto& n : metric_names()) EXPECT_NE(o.out.find(n + "\n"), std::string::npos) << n;
  EXPECT_NE(o.out.find("mass"), std::string::npos);
  EXPECT_NE(o.out.find("coordinates: t, r, theta, phi (spherical)"), std::string::npos);
}

TEST(MetricsCmd, JsonHasCoordinatesTetradsAndParameters) {
  const Output o = run_captured({"metrics", "--json"});
  ASSERT_EQ(o.code, 0) << o.err;
  const auto j = nlohmann::json::parse(o.out);
  ASSERT_EQ(j.size(), metric_names().size());
  bool found = false;
  for (const auto& m : j) {
    EXPECT_EQ(m["coordinates"].size(), 4u);
    EXPECT_GE(m["tetrads"].size(), 1u);
    if (m["name"] != "Schwarzschild") continue;
    found = true;
    EXPECT_EQ(m["coordinate_type"], "spherical");
    ASSERT_EQ(m["params"].size(), 1u);
    EXPECT_EQ(m["params"][0]["name"], "mass");
    EXPECT_EQ(m["params"][0]["default"], 1.0);
    EXPECT_FALSE(m["params"][0]["doc"].get<std::string>().empty());
  }
  EXPECT_TRUE(found);
}

/// Without --pos and --dir every metric starts at its sample position along e(1), and the ray
/// keeps g(k,k) = 0 (the constraint column) to the integrator's accuracy.
TEST(GeodesicCmd, EveryMetricRunsFromItsSamplePosition) {
  for (const auto& n : metric_names()) {
    SCOPED_TRACE(n);
    const Output o = run_captured({"geodesic", "--metric", n, "--max-steps", "50"});
    ASSERT_EQ(o.code, 0) << o.err;
    const auto ls = lines(o.out);
    ASSERT_GE(ls.size(), 3u);
    const std::vector<double> first = csv_numbers(ls[1]);
    ASSERT_EQ(first.size(), 10u);
    const Vec4 x = make_metric(n)->info().sample_pos;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(first[1 + i], x[i]) << i;
    EXPECT_EQ(ls.back().rfind("# stop: ", 0), 0u) << ls.back();
  }
}

TEST(MetricsCmd, TextShowsSamplePositionAndReference) {
  const Output o = run_captured({"metrics"});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("sample position: (0, 6, 1.570796327, 0)"), std::string::npos) << o.out.substr(0, 2000);
  EXPECT_NE(o.out.find("arXiv:0904.4184"), std::string::npos);
}

/// `--info`: Schwarzschild's extras (effective potential, circular orbits, embedding) and the tidal
/// matrix of the static observer at r = 6: diag(−2M/r³, M/r³, M/r³) = (−0.00925926, 0.00462963, ...).
TEST(MetricsCmd, InfoPrintsExtrasAndTidalMatrix) {
  const Output o = run_captured({"metrics", "--info", "Schwarzschild"});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("effective potential"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("circular"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("embedding"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("tidal matrix"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("-0.009259259"), std::string::npos) << o.out;
  const Output none = run_captured({"metrics", "--info", "Minkowski"});
  ASSERT_EQ(none.code, 0) << none.err;
  EXPECT_NE(none.out.find("extras:      none"), std::string::npos) << none.out;
  const Output bad = run_captured({"metrics", "--info", "Schwarzschlid"});
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("did you mean \"Schwarzschild\""), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace geovis::cli

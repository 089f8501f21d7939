// The EXR data file (render/data_exr.h): channels, NaN and stop codes for rays without a hit,
// header metadata, reading back (also with tinyexr, an OpenEXR reader independent of
// OpenImageIO and of the OpenEXR library) and reading the GeoViS binary files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "core/error.h"
#include "render/data_exr.h"
#include "render/data_files.h"
#include "render/pinhole_camera.h"
#include "render/renderer.h"
#include "render/shapes.h"
#include "spacetime/metric_registry.h"

#ifdef GEOVIS_HAVE_TINYEXR
#include <tinyexr.h>
#endif

namespace geovis {
namespace {

namespace fs = std::filesystem;

class DataExr : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geovis_data_exr_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& n) const { return (dir_ / n).string(); }

  /// Schwarzschild (M = 1), static observer at r = 40 looking at a Keplerian disk 6 ≤ r ≤ 20
  /// (inclination 70°): rays hit the disk, fall into the hole or leave the box.
  static RenderJob job(Filter filter = Filter::RGB) {
    RenderJob j;
    j.metric = make_metric("Schwarzschild");
    j.observer.pos = Vec4{{5, 40, 70 * M_PI / 180, 0}};
    j.observer.e = j.metric->natural_tetrad(j.observer.pos, TetradKind::Static);
    j.camera = std::make_shared<PinholeCamera>(Vec3{-1, 0, 0}, Vec3{0, 0, 1}, 60, 40, 24, 16);
    auto ring = std::make_shared<PlaneRing>(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 6.0, 20.0);
    ring->object_id = 1;
    ring->keplerian_disk = true;
    j.scene = ring;
    j.filter = filter;
    j.keep_data = true;
    j.solver.max_steps = 5000;
    j.solver.box_ll = Vec4{{-1e300, 0, -1e300, -1e300}};
    j.solver.box_ur = Vec4{{1e300, 100, 1e300, 1e300}};
    return j;
  }
  static RenderResult render_quiet(const RenderJob& j) {
    RenderOptions ro;
    ro.progress = false;
    return render(j, ro);
  }
  fs::path dir_;
};

TEST(RayStop, OneCodePerStopReason) {
  PixelData d;
  EXPECT_EQ(ray_stop(d), RayStop::NoRay);  // not traced
  d.traced = true;
  d.hit = true;
  d.stop = StopReason::Callback;
  EXPECT_EQ(ray_stop(d), RayStop::Hit);
  d.hit = false;
  const std::map<StopReason, RayStop> expected = {
      {StopReason::Escaped, RayStop::Escaped},     {StopReason::Invalid, RayStop::Horizon},
      {StopReason::BoundingBox, RayStop::Box},     {StopReason::MaxSteps, RayStop::MaxSteps},
      {StopReason::LambdaMax, RayStop::MaxSteps},  {StopReason::Constraint, RayStop::Constraint},
      {StopReason::StepUnderflow, RayStop::Error}, {StopReason::NotFinite, RayStop::Error}};
  for (const auto& [reason, code] : expected) {
    d.stop = reason;
    EXPECT_EQ(ray_stop(d), code) << stop_reason_name(reason);
  }
  EXPECT_STREQ(ray_stop_name(RayStop::Escaped), "escaped");
  EXPECT_STREQ(ray_stop_name(RayStop::MaxSteps), "max-steps");
  EXPECT_EQ(int(RayStop::Error), 6);
}

TEST(DataExrPath, NextToTheImage) {
  EXPECT_EQ(data_exr_path("out/frame_0003.png"), "out/frame_0003.exr");
  EXPECT_EQ(data_exr_path("a.tif"), "a.exr");
  EXPECT_EQ(data_exr_path("a.exr"), "a.data.exr");  // never over the image itself
}

TEST(FnvHash, PublishedTestVectors) {
  // FNV-1a 64 test vectors (Fowler, Noll, Vo; the FNV reference test suite).
  EXPECT_EQ(fnv1a_hex(""), "cbf29ce484222325");
  EXPECT_EQ(fnv1a_hex("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(fnv1a_hex("foobar"), "85944171f73967e8");
}

TEST_F(DataExr, ChannelsMissesAndHeader) {
  const RenderJob j = job();
  const RenderResult r = render_quiet(j);
  ASSERT_EQ(r.data.size(), size_t(24 * 16));  // --data without a data filter keeps the data
  DataFileInfo info{"9.9.9", "scene.scm", "0123456789abcdef", "incl=70", 3, ""};
  const ChannelImage img = make_data_image(j, r.image, r.data, info);
  EXPECT_EQ(img.names, data_channel_names(false));
  for (const char* c : {"R", "G", "B", "x0", "x1", "x2", "x3", "k0", "k1", "k2", "k3", "z", "objid", "stop", "lambda"})
    EXPECT_GE(img.channel(c), 0) << c;
  const size_t nc = img.names.size();
  int hits = 0, misses = 0, horizon = 0;
  for (size_t i = 0; i < r.data.size(); ++i) {
    const PixelData& p = r.data[i];
    const float* o = &img.pixels[i * nc];
    EXPECT_EQ(o[img.channel("stop")], float(int(ray_stop(p))));
    EXPECT_EQ(o[img.channel("lambda")], float(p.lambda));
    if (p.hit) {
      ++hits;
      const char* x[4] = {"x0", "x1", "x2", "x3"};
      for (int k = 0; k < 4; ++k) EXPECT_EQ(o[img.channel(x[k])], float(p.pos[k]));
      EXPECT_EQ(o[img.channel("k0")], float(p.dir[0]));
      EXPECT_EQ(o[img.channel("z")], float(p.freqshift));
      EXPECT_EQ(o[img.channel("objid")], 1.f);
      EXPECT_GE(p.pos[1], 6.0 - 1e-9);
      EXPECT_LE(p.pos[1], 20.0 + 1e-9);
    } else {
      ++misses;
      horizon += ray_stop(p) == RayStop::Horizon;
      for (const char* c : {"x0", "x1", "x2", "x3", "k0", "k1", "k2", "k3", "z", "objid", "u", "v"})
        EXPECT_TRUE(std::isnan(o[img.channel(c)])) << c;
      EXPECT_NE(ray_stop(p), RayStop::Hit);
    }
  }
  EXPECT_GT(hits, 20);
  EXPECT_GT(misses, 20);
  EXPECT_GT(horizon, 0);  // the hole is in view
  EXPECT_EQ(img.meta("geovis:metric"), "Schwarzschild");
  EXPECT_EQ(img.meta("geovis:metric.mass"), "1");
  EXPECT_EQ(img.meta("geovis:metric.coordtype"), "spherical");
  EXPECT_EQ(img.meta("geovis:camera"), "PinHoleCam");
  EXPECT_EQ(img.meta("geovis:version"), "9.9.9");
  EXPECT_EQ(img.meta("geovis:scene.hash"), "0123456789abcdef");
  EXPECT_EQ(img.meta("geovis:scene.defines"), "incl=70");
  EXPECT_EQ(img.meta("geovis:frame"), "3");
  EXPECT_EQ(img.meta("geovis:observer.time"), "5");
  EXPECT_EQ(img.meta("geovis:solver.max_steps"), "5000");
  double fh = 0, fv = 0;
  ASSERT_EQ(std::sscanf(img.meta("geovis:camera.fov").c_str(), "%lf %lf", &fh, &fv), 2);
  EXPECT_NEAR(fh, 60, 1e-9);
  EXPECT_NEAR(fv, 40, 1e-9);
}

TEST_F(DataExr, JacobiChannelsWithTheJacobiFilter) {
  const RenderJob j = job(Filter::RGBjac);
  const RenderResult r = render_quiet(j);
  const ChannelImage img = make_data_image(j, r.image, r.data, {});
  EXPECT_EQ(img.names, data_channel_names(true));
  const size_t nc = img.names.size();
  int hits = 0;
  for (size_t i = 0; i < r.data.size(); ++i) {
    if (!r.data[i].hit) continue;
    ++hits;
    const float* o = &img.pixels[i * nc];
    EXPECT_EQ(o[img.channel("jac.mu")], float(r.data[i].jacobi[2]));
    // d+ d- = |det J| (singular values of J).
    const double* J = r.data[i].jacobi_matrix;
    EXPECT_NEAR(r.data[i].jacobi[0] * r.data[i].jacobi[1], std::fabs(J[0] * J[3] - J[1] * J[2]),
                1e-9 * std::fabs(J[0] * J[3] - J[1] * J[2]));
  }
  EXPECT_GT(hits, 20);
}

TEST_F(DataExr, WrittenAtomicallyAndReadBack) {
  const RenderJob j = job();
  const RenderResult r = render_quiet(j);
  const std::string written = write_data_exr(path("frame.png"), j, r.image, r.data, {"1", "s.scm", "ab", "", 0, ""});
  EXPECT_EQ(written, path("frame.exr"));
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.is_regular_file();
  EXPECT_EQ(files, 1);  // no temporary left behind
  const ChannelImage back = read_data_file(written);
  const ChannelImage orig = make_data_image(j, r.image, r.data, {"1", "s.scm", "ab", "", 0, ""});
  ASSERT_EQ(back.width, 24);
  ASSERT_EQ(back.height, 16);
  for (const auto& name : orig.names) {
    const int a = orig.channel(name), b = back.channel(name);
    ASSERT_GE(b, 0) << name;
    for (size_t i = 0; i < size_t(24 * 16); ++i) {
      const float va = orig.pixels[i * orig.names.size() + a], vb = back.pixels[i * back.names.size() + b];
      if (std::isnan(va))
        EXPECT_TRUE(std::isnan(vb)) << name;
      else
        EXPECT_EQ(va, vb) << name;
    }
  }
  EXPECT_EQ(back.meta("geovis:metric"), "Schwarzschild");
  EXPECT_EQ(back.meta("geovis:scene.file"), "s.scm");
}

TEST_F(DataExr, IndependentReaderSeesTheChannelsAndHeader) {
#ifndef GEOVIS_HAVE_TINYEXR
  GTEST_SKIP() << "tinyexr (Debian package libtinyexr-dev, an OpenEXR reader independent of the OpenEXR library) is not "
                  "installed";
#else
  const RenderJob j = job();
  const RenderResult r = render_quiet(j);
  const std::string file = write_data_exr(path("frame.png"), j, r.image, r.data, {"1", "s.scm", "ab", "", 0, ""});
  EXRVersion version;
  ASSERT_EQ(ParseEXRVersionFromFile(&version, file.c_str()), TINYEXR_SUCCESS);
  EXRHeader header;
  InitEXRHeader(&header);
  const char* err = nullptr;
  ASSERT_EQ(ParseEXRHeaderFromFile(&header, &version, file.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
  std::map<std::string, int> index;
  for (int c = 0; c < header.num_channels; ++c) {
    EXPECT_EQ(header.pixel_types[c], TINYEXR_PIXELTYPE_FLOAT) << header.channels[c].name;
    index[header.channels[c].name] = c;
  }
  std::map<std::string, std::string> attrs;
  for (int i = 0; i < header.num_custom_attributes; ++i) {
    const EXRAttribute& a = header.custom_attributes[i];
    // OpenEXR string attribute: the bytes of the string (no terminator).
    if (std::strcmp(a.type, "string") == 0)
      attrs[a.name] = std::string(reinterpret_cast<const char*>(a.value), size_t(a.size));
  }
  EXRImage image;
  InitEXRImage(&image);
  ASSERT_EQ(LoadEXRImageFromFile(&image, &header, file.c_str(), &err), TINYEXR_SUCCESS) << (err ? err : "");
  ASSERT_EQ(image.width, 24);
  ASSERT_EQ(image.height, 16);
  for (const char* c : {"R", "G", "B", "x0", "x1", "x2", "x3", "k0", "k1", "k2", "k3", "z", "objid", "stop", "lambda"})
    ASSERT_TRUE(index.count(c)) << c;
  auto value = [&](const char* c, size_t i) { return reinterpret_cast<float**>(image.images)[index[c]][i]; };
  int hits = 0;
  for (size_t i = 0; i < r.data.size(); ++i) {
    const PixelData& p = r.data[i];
    EXPECT_EQ(value("stop", i), float(int(ray_stop(p))));
    EXPECT_EQ(value("R", i), r.image.pixels[i * 3]);
    if (p.hit) {
      ++hits;
      EXPECT_EQ(value("x1", i), float(p.pos[1]));
      EXPECT_EQ(value("z", i), float(p.freqshift));
    } else {
      EXPECT_TRUE(std::isnan(value("x1", i)));
    }
  }
  EXPECT_GT(hits, 20);
  EXPECT_EQ(attrs["geovis:metric"], "Schwarzschild");
  EXPECT_EQ(attrs["geovis:metric.mass"], "1");
  EXPECT_EQ(attrs["geovis:solver"], solver_kind_name(j.solver.kind));
  FreeEXRImage(&image);
  FreeEXRHeader(&header);
#endif
}

TEST_F(DataExr, ReadsTheGeoViSFilesWithNaNForMisses) {
  const RenderJob j = job(Filter::RGBpdz);
  const RenderResult r = render_quiet(j);
  const std::string pdz = write_filter_data(path("frame.png"), Filter::RGBpdz, 24, 16, r.data);
  const ChannelImage d = read_data_file(pdz);
  EXPECT_EQ(d.channel("stop"), -1);
  ASSERT_GE(d.channel("z"), 0);
  for (size_t i = 0; i < r.data.size(); ++i) {
    const float x1 = d.pixels[i * d.names.size() + d.channel("x1")];
    if (r.data[i].hit)
      EXPECT_EQ(x1, float(r.data[i].pos[1]));
    else
      EXPECT_TRUE(std::isnan(x1));
  }
}

TEST_F(DataExr, ClearErrorsForFilesThatAreNotDataFiles) {
  auto message = [](const std::string& p) {
    try {
      read_data_file(p);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(path("missing.exr")).find("no such file"), std::string::npos);
  std::ofstream(path("junk.pdz")) << "abc";
  EXPECT_NE(message(path("junk.pdz")).find("is not a GeoViS .pdz data file"), std::string::npos);
  std::ofstream(path("notes.txt")) << "abc";
  EXPECT_NE(message(path("notes.txt")).find("is not a data file"), std::string::npos);
  Image plain(4, 4, 3);
  write_image(path("plain.exr"), plain);
  EXPECT_NE(message(path("plain.exr")).find("not a geovis data file"), std::string::npos);
}

}  // namespace
}  // namespace geovis

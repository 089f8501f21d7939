#include "render/post.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"
#include "render/colormap.h"
#include "render/data_exr.h"

namespace geovis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int need(const ChannelImage& d, const std::string& channel, const std::string& shader) {
  const int c = d.channel(channel);
  if (c < 0) {
    std::string why = "shader \"" + shader + "\" needs channel \"" + channel + "\", which the data file does not have";
    if (channel == "jac.mu")
      why += " (render with the FilterRGBjac camera filter)";
    else if (channel == "stop")
      why += " (GeoViS files have no stop reasons; use the EXR data file)";
    else if (channel == "z")
      why += " (GeoViS .pt files have no frequency shift; use .pdz, .jac or the EXR data file)";
    throw Error(why + "; channels: " + join(d.names));
  }
  return c;
}

double at(const ChannelImage& d, size_t pixel, int c) { return d.pixels[pixel * d.names.size() + size_t(c)]; }

std::string number_label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

/// Colour bar below the image: the colour map from the range's low to high end, five labelled
/// ticks and the quantity's label; for categories one labelled swatch per code.
void draw_colorbar(Image& img, const PostField& f, const std::string& cmap, double lo, double hi, bool log,
                   int base_height) {
  const int W = img.width;
  const int text = std::clamp(W / 40, 10, 18);  // font size in pixels
  const int pad = text / 2, bar = text;
  const int y0 = base_height + pad;
  const float white[3] = {1, 1, 1};
  if (f.categorical) {
    // One labelled swatch per stop code that occurs in the picture.
    std::vector<int> codes;
    for (double v : f.values)
      if (std::isfinite(v) && std::find(codes.begin(), codes.end(), int(v)) == codes.end()) codes.push_back(int(v));
    std::sort(codes.begin(), codes.end());
    const int cell = codes.empty() ? W : W / int(codes.size());
    for (size_t k = 0; k < codes.size(); ++k) {
      const int x0 = int(k) * cell;
      const Color c = category_color(codes[k]);
      for (int y = y0; y < y0 + bar; ++y)
        for (int x = x0 + 2; x < x0 + cell - 2 && x < W; ++x) {
          float* p = img.at(x, y);
          p[0] = float(c.r), p[1] = float(c.g), p[2] = float(c.b);
        }
      const bool known = codes[k] >= 0 && codes[k] < kRayStopCount;
      draw_text(img, x0 + 2, y0 + bar + pad + text, known ? ray_stop_name(RayStop(codes[k])) : std::to_string(codes[k]),
                text * 3 / 4, white);
    }
    draw_text(img, pad, y0 + bar + 2 * text + pad, f.label, text, white);
    return;
  }
  const int x0 = pad, x1 = W - pad;
  for (int x = x0; x < x1; ++x) {
    const Color c = colormap(cmap, (x - x0 + 0.5) / double(x1 - x0));
    for (int y = y0; y < y0 + bar; ++y) {
      float* p = img.at(x, y);
      p[0] = float(c.r), p[1] = float(c.g), p[2] = float(c.b);
    }
  }
  const int ticks = W >= 200 ? 5 : 2;
  for (int i = 0; i < ticks; ++i) {
    const double s = double(i) / (ticks - 1);
    const double v = log ? std::pow(10.0, std::log10(lo) + s * (std::log10(hi) - std::log10(lo))) : lo + s * (hi - lo);
    const int x = x0 + int(std::lround(s * (x1 - x0 - 1)));
    for (int y = y0 + bar; y < y0 + bar + pad / 2 + 1; ++y) {
      float* p = img.at(std::min(x, W - 1), y);
      p[0] = p[1] = p[2] = 1.f;
    }
    // Left-aligned at the first tick, right-aligned at the last, centred between.
    const int align = i == 0 ? 0 : (i == ticks - 1 ? 2 : 1);
    draw_text(img, i == 0 ? x0 : (i == ticks - 1 ? x1 : x), y0 + bar + pad + text, number_label(v), text * 3 / 4, white,
              align);
  }
  draw_text(img, pad, y0 + bar + 2 * text + pad, f.label + (log ? " (log scale)" : ""), text, white);
}

}  // namespace

const std::vector<std::string>& post_shader_names() {
  static const std::vector<std::string> names = {"redshift", "disk-flux", "time", "lensing", "stop"};
  return names;
}

void check_post_shader(const std::string& shader) {
  const auto& names = post_shader_names();
  if (std::find(names.begin(), names.end(), shader) == names.end())
    throw Error("unknown shader \"" + shader + "\"" + did_you_mean(shader, names) + " (valid: " + join(names) + ")");
}

double page_thorne_flux(double R) {
  // Paper eq. 16 (Page & Thorne, ApJ 191 (1974) 499, for a = 0), R = r/r_s.
  if (!(R > 3.0)) return 0.0;
  const double s32 = std::sqrt(1.5), s3 = std::sqrt(3.0), sR = std::sqrt(R);
  const double log_term = std::log((sR + s32) / (sR - s32) * (s3 - s32) / (s3 + s32));
  return (sR - s3 + 0.5 * s32 * log_term) / ((R - 1.5) * std::pow(R, 2.5));
}

PostField post_field(const ChannelImage& d, const std::string& shader, std::optional<double> mass) {
  check_post_shader(shader);
  const size_t n = size_t(d.width) * d.height;
  PostField f;
  f.values.assign(n, kNaN);
  if (shader == "redshift") {
    const int z = need(d, "z", shader);
    for (size_t i = 0; i < n; ++i) f.values[i] = at(d, i, z);
    f.label = "1+z = f_emitted / f_observed";
    f.colormap = "viridis";
  } else if (shader == "time") {
    const int t = need(d, "x0", shader);
    for (size_t i = 0; i < n; ++i) f.values[i] = at(d, i, t);
    f.label = "emission time x0 (coordinate time)";
    f.colormap = "plasma";
  } else if (shader == "lensing") {
    const int mu = need(d, "jac.mu", shader);
    for (size_t i = 0; i < n; ++i) f.values[i] = at(d, i, mu);
    f.label = "magnification mu (vs flat space)";
    f.colormap = "magma";
  } else if (shader == "stop") {
    const int s = need(d, "stop", shader);
    for (size_t i = 0; i < n; ++i) f.values[i] = at(d, i, s);
    f.label = "stop reason";
    f.categorical = true;
  } else {  // disk-flux
    const std::string coords = d.meta("geovis:metric.coordtype");
    if (!coords.empty() && coords != "spherical")
      throw Error("shader \"disk-flux\" needs r = x1 in spherical coordinates; the data were rendered in " +
                  d.meta("geovis:metric") + " (" + coords + " coordinates)");
    const int r = need(d, "x1", shader), z = need(d, "z", shader);
    double M = 1.0;
    if (mass) {
      M = *mass;
    } else if (const std::string m = d.meta("geovis:metric.mass"); !m.empty()) {
      M = std::stod(m);
    }
    if (!(M > 0)) throw Error("disk-flux: the mass must be positive, found " + number_label(M));
    const double rs = 2.0 * M;
    for (size_t i = 0; i < n; ++i) {
      const double R = at(d, i, r) / rs, opz = at(d, i, z);
      if (!(R > 3.0) || !(opz > 0)) continue;  // no disk matter inside the marginally stable orbit
      // Observed flux F_obs = F_src / (1+z)^4 (paper §5, Luminet 1979).
      f.values[i] = page_thorne_flux(R) / std::pow(opz, 4);
    }
    f.label = "observed flux F/(1+z)^4 [F0]";  // F_0 = 3GMṀ/(8π r_s³), docs/data-format.md
    f.colormap = "inferno";
  }
  return f;
}

Image post_image(const ChannelImage& d, const PostOptions& opt, std::pair<double, double>* range_used) {
  const PostField f = post_field(d, opt.shader, opt.mass);
  const std::string cmap = opt.colormap.empty() ? f.colormap : opt.colormap;
  if (!f.categorical) check_colormap(cmap);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  if (opt.range) {
    lo = opt.range->first;
    hi = opt.range->second;
    if (!(lo < hi)) throw Error("--range: expected MIN < MAX, found " + number_label(lo) + ", " + number_label(hi));
  } else {
    for (double v : f.values)
      if (std::isfinite(v) && (!opt.log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!(lo <= hi)) lo = 0, hi = 1;  // no value at all
    if (lo == hi) hi = lo + (lo == 0 ? 1.0 : std::fabs(lo) * 1e-6);
  }
  if (opt.log && !f.categorical && !(lo > 0))
    throw Error("--log: the range must be positive, found " + number_label(lo) + " to " + number_label(hi));
  if (range_used) *range_used = {lo, hi};

  const int bar_height = opt.colorbar ? std::clamp(d.width / 40, 10, 18) * 5 : 0;
  Image img(d.width, d.height + bar_height, 3);
  for (size_t i = 0; i < f.values.size(); ++i) {
    const double v = f.values[i];
    float* p = &img.pixels[i * 3];
    Color c;
    if (!std::isfinite(v)) {
      p[0] = opt.nan_color[0], p[1] = opt.nan_color[1], p[2] = opt.nan_color[2];
      continue;
    }
    if (f.categorical) {
      c = category_color(int(v));
    } else {
      const double t = opt.log ? (v > 0 ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : 0.0)
                               : (v - lo) / (hi - lo);
      c = colormap(cmap, t);
    }
    p[0] = float(c.r), p[1] = float(c.g), p[2] = float(c.b);
  }
  if (opt.colorbar) draw_colorbar(img, f, cmap, lo, hi, opt.log, d.height);
  return img;
}

std::string post_csv(const ChannelImage& d, const std::vector<std::string>& channels,
                     const std::vector<std::pair<int, int>>& pixels) {
  std::vector<int> cols;
  const std::vector<std::string>& names = channels.empty() ? d.names : channels;
  for (const auto& c : names) {
    const int i = d.channel(c);
    if (i < 0)
      throw Error("--channels: unknown channel \"" + c + "\"" + did_you_mean(c, d.names) +
                  " (channels: " + join(d.names) + ")");
    cols.push_back(i);
  }
  std::string out = "x,y";
  for (const auto& c : names) out += "," + c;
  out += "\n";
  auto line = [&](int x, int y) {
    out += std::to_string(x) + "," + std::to_string(y);
    const size_t pixel = size_t(y) * d.width + x;
    for (int c : cols) {
      const double v = at(d, pixel, c);
      char buf[40];
      if (std::isnan(v))
        std::snprintf(buf, sizeof buf, "nan");
      else
        std::snprintf(buf, sizeof buf, "%.9g", v);
      out += ",";
      out += buf;
    }
    out += "\n";
  };
  if (pixels.empty()) {
    for (int y = 0; y < d.height; ++y)
      for (int x = 0; x < d.width; ++x) line(x, y);
  }
  for (const auto& [x, y] : pixels) {
    if (x < 0 || y < 0 || x >= d.width || y >= d.height)
      throw Error("--pixel: " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                  std::to_string(d.width) + "x" + std::to_string(d.height) + " image");
    line(x, y);
  }
  return out;
}

}  // namespace geovis

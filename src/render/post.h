// Post-processing of data files without re-tracing (`geovis post`; the paper's §5 gvsViewer
// shaders): a "shader" turns the channels of every pixel into one physical value, which a
// perceptual colour map (render/colormap.h) turns into a colour.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/image.h"

namespace geovis {

/// "redshift", "disk-flux", "time", "lensing", "stop".
const std::vector<std::string>& post_shader_names();
/// Throws Error (with did-you-mean) for an unknown shader name.
void check_post_shader(const std::string& name);

/// Page–Thorne bolometric flux of a thin disk around a Schwarzschild black hole, F/F_0 at
/// R = r/r_s (paper eq. 16; F_0 = 3GMṀ/(8π r_s³)); 0 at and inside the marginally stable orbit
/// R = 3.
double page_thorne_flux(double R);

/// One value per pixel (NaN = no value there) and what it is.
struct PostField {
  std::vector<double> values;  ///< width*height, row 0 = top
  std::string label;           ///< quantity and unit, for the colour bar
  std::string colormap;        ///< default colour map
  bool categorical = false;    ///< stop codes: one colour per value, no range
};

/// Evaluates `shader` on the data (read_data_file). `mass` overrides the metric's mass (disk-flux;
/// default: the header's geovis:metric.mass, else 1). Throws Error naming the missing channel
/// when the data lack what the shader needs, or for an unknown shader (with did-you-mean).
PostField post_field(const ChannelImage& data, const std::string& shader, std::optional<double> mass = {});

struct PostOptions {
  std::string shader;
  std::string colormap;                            ///< "" = the shader's default
  std::optional<std::pair<double, double>> range;  ///< value range mapped to the colour map
  bool log = false;                                ///< map log10 of the value
  bool colorbar = false;                           ///< draw a labelled colour bar below the image
  std::optional<double> mass;
  float nan_color[3] = {0, 0, 0};  ///< pixels without a value
};

/// The picture; `range_used` receives the value range that was mapped (the data's finite
/// min/max when no range is given). Throws Error for a bad option (e.g. --log with values <= 0
/// in the range).
Image post_image(const ChannelImage& data, const PostOptions& opt, std::pair<double, double>* range_used = nullptr);

/// CSV of `channels` (all when empty) at `pixels` (all when empty): header "x,y,<channels>",
/// one line per pixel, NaN written as "nan". Throws Error for an unknown channel or a pixel
/// outside the image.
std::string post_csv(const ChannelImage& data, const std::vector<std::string>& channels,
                     const std::vector<std::pair<int, int>>& pixels);

}  // namespace geovis

// Perceptual colour maps for `geovis post`: viridis, inferno, magma and plasma (van der Walt &
// Smith, the 256-entry tables published with matplotlib 2.0, lib/matplotlib/_cm_listed.py, CC0)
// and the Okabe–Ito palette for categories (Okabe & Ito 2008, "Color Universal Design").
#pragma once

#include <string>
#include <vector>

#include "render/color.h"

namespace geovis {

const std::vector<std::string>& colormap_names();

/// Throws Error (with did-you-mean) for an unknown name.
void check_colormap(const std::string& name);

/// Colour of t in [0, 1] (clamped): table entry min(floor(256 t), 255), as matplotlib's
/// ListedColormap looks it up.
Color colormap(const std::string& name, double t);

/// Okabe–Ito colour i (0..7, wraps).
Color category_color(int i);

}  // namespace geovis

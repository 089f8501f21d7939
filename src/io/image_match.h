// Comparison of a rendered image with a reference image by the GeoViS fidelity match rule
// (tests/data/fidelity/README.md): small differences in colour are not counted, and pixels that
// differ only because a sub-pixel stripe or a line on a pixel edge fell to the neighbouring pixel
// (which happens with any integrator) are tolerated up to a limit.
#pragma once

#include <string>

#include "io/image.h"

namespace geovis {

/// The numbers the match rule looks at. Colours are compared as 8-bit values (round(255·c)).
struct ImageMatch {
  int width = 0, height = 0;
  /// Fraction of pixels with |a − b| > tolerance in at least one channel.
  double differ = 0;
  /// Fraction of pixels of which no reference pixel in the 3×3 neighbourhood (inside the image)
  /// is within the tolerance in every channel.
  double no_neighbour = 0;
  /// The rule: differ ≤ 2 %, or differ ≤ 4 % and no_neighbour ≤ 0.5 %.
  bool matches = false;
  /// One line for a test log: sizes, both fractions and the verdict.
  std::string summary() const;
};

/// Per-channel tolerance of the match rule in 8-bit units (25/255).
constexpr int kMatchTolerance8 = 25;

/// Applies the match rule to `image` against `reference`. Throws Error when the sizes differ.
ImageMatch match_images(const Image& image, const Image& reference);

}  // namespace geovis

// Textures map surface coordinates (u,v) to a colour (catalogue §5).
#pragma once

#include <memory>

#include "render/color.h"

namespace geovis {

class Texture {
 public:
  virtual ~Texture() = default;
  /// Colour at texture coordinates (u, v) (before the texture's own 2D transform is applied:
  /// implementations apply it), at coordinate time `time` (for time-dependent textures).
  virtual Color sample(double u, double v, double time = 0.0) const = 0;
  /// As sample(), knowing which part of the primitive was hit (Hit::part; DieT2D shows a
  /// different face of a die on each box face). Default: the part is irrelevant.
  virtual Color sample_part(double u, double v, double time, int /*part*/) const { return sample(u, v, time); }
};
using TexturePtr = std::shared_ptr<Texture>;

}  // namespace geovis

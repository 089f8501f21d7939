// The built-in scene `geovis` renders when run without arguments: a checkered sphere orbiting a
// Schwarzschild black hole on a circular geodesic, in front of a grid-textured sky sphere. It is
// GeoViS Scheme text evaluated by the real scene path (scheme -> builder -> renderer).
#pragma once

#include <string>

namespace geovis {

/// The scene program (GeoViS Scheme).
const std::string& default_scene_text();

/// Name used for the built-in scene in messages and for its default output ("geovis_default").
const std::string& default_scene_name();

}  // namespace geovis

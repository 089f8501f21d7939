// The camera filters (docs/geovis-catalogue.md §3, GeoViS GvsCamera filters): what a render stores besides the
// colour image. A filter is a mode of the tracer (render_job.h's Filter), not a plugin with a
// factory, so the five entries live together in filter_type.cpp; each is a FilterType in the
// FilterRegistry (core/type_registry.h) like every other kind the scene language names.
#pragma once

#include "core/type_registry.h"
#include "render/render_job.h"

namespace geovis {

struct FilterType : TypeDescription {
  Filter filter = Filter::RGB;
};
using FilterRegistry = TypeRegistry<FilterType>;

}  // namespace geovis

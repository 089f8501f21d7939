// The five GeoViS camera filters (docs/geovis-catalogue.md §3); the data files they write are
// render/data_files.h's.
#include "render/filter_type.h"

namespace geovis {

namespace {

const TypeRegistrar<FilterType> rgb{{{"FilterRGB", {}, "the colour image only", {}}, Filter::RGB}};
const TypeRegistrar<FilterType> rgb_pdz{
    {{"FilterRGBpdz", {}, "image + .pdz: per pixel hit event, light direction, object id, frequency shift", {}},
     Filter::RGBpdz}};
const TypeRegistrar<FilterType> rgb_jac{
    {{"FilterRGBjac", {}, "image + .jac: as .pdz plus the Jacobi (lensing) parameters", {}}, Filter::RGBjac}};
const TypeRegistrar<FilterType> rgb_pt{
    {{"FilterRGBpt", {}, "image + .pt: per pixel hit event, texture coordinates, object id", {}}, Filter::RGBpt}};
const TypeRegistrar<FilterType> rgb_intersec{{{"FilterIntersec",
                                               {"FilterRGBIntersec"},
                                               "image + .dat: GeoViS gvsData records (hit event, texture coordinates)",
                                               {}},
                                              Filter::RGBIntersec}};

}  // namespace

}  // namespace geovis

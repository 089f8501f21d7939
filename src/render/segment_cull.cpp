// SegmentCull (segment_cull.h). Its test of a packet's chords (chart0_chords_skipped) is compiled
// once per SIMD instruction set by Highway's foreach_target (this file includes itself per
// target), the rest once (the HWY_ONCE part).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/segment_cull.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: foreach_target must come first
#include <hwy/highway.h>
// clang-format on

#include "spacetime/simd.h"

#ifndef GEOVIS_RENDER_SEGMENT_CULL_ONCE_
#define GEOVIS_RENDER_SEGMENT_CULL_ONCE_
#include <limits>

#include "render/segment_cull.h"
#include "spacetime/geodesic_packet.h"
#endif  // GEOVIS_RENDER_SEGMENT_CULL_ONCE_

HWY_BEFORE_NAMESPACE();
namespace geovis {
namespace HWY_NAMESPACE {

/// SegmentCull::chart0_chords_skipped on SIMD lanes; `region` = the squared radius of chart 0's
/// empty ball, then the box's lo and hi (x, y, z each).
unsigned chart0_chords_skipped_lanes(const double* region, unsigned lanes, const double* p0, const double* r0_squared,
                                     const double* p1, double* next_p, double* next_r0_squared) {
  constexpr int W = kPacketLanes;
  const SimdTag d;
  const SimdD ball(region[0]);
  unsigned skipped = 0;
  for (size_t l = 0; l < static_cast<size_t>(W); l += SimdD::lanes()) {
    const uint8_t bits = static_cast<uint8_t>(lanes >> l);
    const SimdMask on{hn::LoadMaskBits(d, &bits)};
    SimdD a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = SimdD::load(p0 + i * W + l);
      b[i] = SimdD::load(p1 + i * W + l);
    }
    const SimdD r0 = SimdD::load(r0_squared + l);
    const SimdD r1 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];  // dot(p1, p1)
    SimdMask skip = r0 < ball && r1 < ball;
    for (int i = 0; i < 3; ++i) {
      const SimdD lo(region[1 + i]), hi(region[4 + i]);
      skip = skip || (a[i] < lo && b[i] < lo) || (a[i] > hi && b[i] > hi);
      select(on, b[i], a[i]).store(next_p + i * W + l);
    }
    select(on, r1, r0).store(next_r0_squared + l);
    skipped |= mask_bits(skip) << l;
  }
  return skipped & lanes;
}

}  // namespace HWY_NAMESPACE
}  // namespace geovis
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace geovis {

HWY_EXPORT(chart0_chords_skipped_lanes);

SegmentCull::SegmentCull(const SceneObject& scene) {
  for (double& r : radius_) r = std::numeric_limits<double>::infinity();
  scene.restrict_surface_free_radii(radius_, kCharts);
  for (int c = 0; c < kCharts; ++c) {
    double& r = radius_[c];
    r = r > 0 ? r * (1.0 - kMargin) : 0.0;  // also NaN -> 0: cull nothing
    radius2_[c] = r * r;
  }
  // Empty bounds (an object that can never be hit, e.g. disjoint solids intersected; compound.h
  // skips such children) become the box from +∞ to −∞, beyond which every chord lies; infinite
  // ones stay infinite (nothing is beyond them).
  box_ = scene.bounds();
  if (box_.empty()) {
    box_ = Bounds3{};
  } else {
    const double widen = kMargin * box_.farthest_distance_from_origin();
    box_.lo = box_.lo - Vec3{widen, widen, widen};
    box_.hi = box_.hi + Vec3{widen, widen, widen};
  }
}

unsigned SegmentCull::chart0_chords_skipped(unsigned lanes, const double* p0, const double* r0_squared,
                                            const double* p1, double* next_p, double* next_r0_squared) const {
  const double region[7] = {radius2_[0], box_.lo.x, box_.lo.y, box_.lo.z, box_.hi.x, box_.hi.y, box_.hi.z};
  return HWY_DYNAMIC_DISPATCH(chart0_chords_skipped_lanes)(region, lanes, p0, r0_squared, p1, next_p, next_r0_squared);
}

}  // namespace geovis
#endif  // HWY_ONCE

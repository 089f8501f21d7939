// Limits of one rendered frame, checked before anything is allocated: a resolution that does not
// fit in memory is a clear error ("needs 112 GiB for the frame buffer; the limit is ...") instead
// of std::bad_alloc in the middle of a render.
#pragma once

#include <cstdint>
#include <string>

namespace geovis {

/// Documented limits (README "Limits"): pixels per image side, samples per pixel side, frames.
inline constexpr int kMaxImageSide = 1'000'000;
inline constexpr int kMaxSupersample = 64;
inline constexpr int kMaxFrames = 1'000'000;

/// Bytes of the frame buffer (float RGB, 12 per pixel) plus the per-pixel filter data when
/// `with_data`.
std::uint64_t frame_buffer_bytes(int width, int height, bool with_data);
/// Bytes needed on top of the frame buffer to write the image (16-bit pixels and the encoded file).
std::uint64_t image_encoding_bytes(int width, int height);

/// The memory geovis may use: the physical memory, or the address-space limit (ulimit -v) or the
/// cgroup (container) limit when lower.
std::uint64_t memory_limit_bytes();

/// "112 GiB", "1.5 GiB", "640 MiB", "12 KiB".
std::string format_bytes(std::uint64_t bytes);

/// Throws Error "<what>: ... needs X for the frame buffer ...; the limit is Y ..." when a
/// width x height frame is outside the limits or does not fit in `limit` bytes.
void check_frame_size(const std::string& what, long long width, long long height, bool with_data,
                      std::uint64_t limit = memory_limit_bytes());

}  // namespace geovis

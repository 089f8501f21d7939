// FNV-1a (64 bit): a fast, stable change detector for settings and pixel checksums stored in
// output files. Not a cryptographic hash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace geovis {

inline constexpr std::uint64_t kFnv1a64Seed = 0xcbf29ce484222325ULL;

inline std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t h = kFnv1a64Seed) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    h ^= p[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

/// "fnv1a64:0123456789abcdef".
inline std::string fnv1a64_text(std::uint64_t h) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace geovis

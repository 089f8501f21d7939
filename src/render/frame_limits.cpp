#include "render/frame_limits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "core/error.h"
#include "render/render_job.h"

namespace geovis {

std::uint64_t frame_buffer_bytes(int width, int height, bool with_data) {
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  return pixels * (3 * sizeof(float) + (with_data ? sizeof(PixelData) : 0));
}

std::uint64_t image_encoding_bytes(int width, int height) {
  // 16-bit RGB pixels handed to the encoder, and the file it produces (at most about as large).
  return std::uint64_t(width) * std::uint64_t(height) * 3 * 2 * 2;
}

std::uint64_t memory_limit_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  std::uint64_t limit = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : UINT64_MAX;
  // An address-space limit (ulimit -v) also bounds what can be allocated.
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && as.rlim_cur < limit) limit = as.rlim_cur;
  // A container's memory limit (cgroup v2, then v1) is lower than the machine's memory.
  for (const char* file : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream f(file);
    unsigned long long v = 0;
    if (f >> v && v > 0 && v < limit) limit = v;
  }
  return limit;
}

std::string format_bytes(std::uint64_t bytes) {
  static const char* const kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = double(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 6) {
    v /= 1024.0;
    ++u;
  }
  char buf[32];
  if (u == 0)
    std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  else
    std::snprintf(buf, sizeof buf, v < 10 ? "%.1f %s" : "%.0f %s", v, kUnits[u]);
  return buf;
}

void check_frame_size(const std::string& what, long long width, long long height, bool with_data, std::uint64_t limit) {
  const std::string res = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || height < 1) throw Error(what + ": width and height must be positive, found " + res);
  if (width > kMaxImageSide || height > kMaxImageSide)
    throw Error(what + ": the " +
                (width > kMaxImageSide ? "width " + std::to_string(width) : "height " + std::to_string(height)) +
                " is larger than the limit of " + std::to_string(kMaxImageSide) + " pixels per side");
  const std::uint64_t buffer = frame_buffer_bytes(int(width), int(height), with_data);
  const std::uint64_t encoding = image_encoding_bytes(int(width), int(height));
  if (buffer + encoding > limit)
    throw Error(what + ": a " + res + " frame needs " + format_bytes(buffer) + " for the frame buffer" +
                (with_data ? " (with the filter data)" : "") + " and " + format_bytes(encoding) +
                " to write the image; the limit is " + format_bytes(limit) +
                ", the memory available to geovis (lower --res)");
}

}  // namespace geovis

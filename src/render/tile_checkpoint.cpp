#include "render/tile_checkpoint.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "io/atomic_file.h"

namespace geovis {

namespace {

constexpr char kFileMagic[8] = {'G', 'V', 'T', 'I', 'L', 'E', 'S', '1'};
constexpr uint32_t kRecordMagic = 0x52545647u;  // "GVTR"
constexpr int kDataDoubles = int(sizeof(PixelData) / sizeof(double));
static_assert(sizeof(PixelData) == kDataDoubles * sizeof(double), "PixelData must be plain doubles");

template <class T>
void put(std::string& s, const T& v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
bool get(const std::string& s, size_t& pos, T& v) {
  if (pos + sizeof v > s.size()) return false;
  std::memcpy(&v, s.data() + pos, sizeof v);
  pos += sizeof v;
  return true;
}

std::string header_bytes(const CheckpointKey& key) {
  std::string h(kFileMagic, sizeof kFileMagic);
  put(h, key.hash);
  put(h, int32_t(key.grid.width));
  put(h, int32_t(key.grid.height));
  put(h, int32_t(key.grid.tile_size));
  put(h, int32_t(key.with_data ? kDataDoubles : 0));
  put(h, fnv1a64(h.data(), h.size()));
  return h;
}

void write_all(int fd, const std::string& bytes, const std::string& path) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error("cannot write \"" + path + "\": " + std::strerror(errno));
    done += size_t(n);
  }
}

}  // namespace

TileCheckpoint::TileCheckpoint(std::string path, const CheckpointKey& key, bool resume, RenderResult& result)
    : path_(std::move(path)), key_(key), restored_(size_t(key.grid.count()), 0) {
  std::error_code ec;
  if (resume && std::filesystem::exists(path_, ec) && load(result)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw Error("checkpoint \"" + path_ + "\": cannot open for appending: " + std::strerror(errno));
    return;
  }
  create();
}

TileCheckpoint::~TileCheckpoint() {
  if (fd_ >= 0) ::close(fd_);
}

void TileCheckpoint::create() {
  // The header is written like every other file (io/atomic_file.h: temporary file, fsync, rename):
  // a checkpoint file that exists always has a complete header, and a failure names the checkpoint
  // and what the OS said ("cannot write "IMG.tiles": No space left on device").
  write_file_atomic(path_, header_bytes(key_));
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw Error("checkpoint \"" + path_ + "\": cannot open for appending: " + std::strerror(errno));
}

bool TileCheckpoint::load(RenderResult& result) {
  std::ifstream in(path_, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    note_ = "checkpoint \"" + path_ + "\" cannot be read; starting the frame from scratch";
    return false;
  }
  const std::string header = header_bytes(key_);
  if (bytes.compare(0, header.size(), header) != 0) {
    note_ = "checkpoint \"" + path_ +
            "\" was made for a different scene, options or resolution; ignored, "
            "starting the frame from scratch";
    return false;
  }
  const TileGrid& g = key_.grid;
  const int data_doubles = key_.with_data ? kDataDoubles : 0;
  size_t pos = header.size(), good_end = pos;
  std::vector<float> pixels;
  std::vector<double> data;
  while (pos < bytes.size()) {
    const size_t start = pos;
    uint32_t magic = 0;
    int32_t tile = -1, n_floats = -1, n_doubles = -1;
    if (!get(bytes, pos, magic) || magic != kRecordMagic || !get(bytes, pos, tile) || !get(bytes, pos, n_floats) ||
        !get(bytes, pos, n_doubles) || tile < 0 || tile >= g.count())
      break;
    const TileRect r = g.rect(tile);
    if (n_floats != r.pixels() * 3 || n_doubles != r.pixels() * data_doubles) break;
    const size_t payload = size_t(n_floats) * sizeof(float) + size_t(n_doubles) * sizeof(double);
    if (pos + payload + sizeof(uint64_t) > bytes.size()) break;
    uint64_t sum = 0;
    std::memcpy(&sum, bytes.data() + pos + payload, sizeof sum);
    if (sum != fnv1a64(bytes.data() + start, pos + payload - start)) break;
    const char* p = bytes.data() + pos;
    pos += payload + sizeof sum;
    good_end = pos;
    if (restored_[size_t(tile)]) continue;  // cannot happen with one writer; the first copy wins
    restored_[size_t(tile)] = 1;
    ++restored_count_;
    const int row_floats = (r.x1 - r.x0) * 3;
    for (int y = r.y0; y < r.y1; ++y, p += row_floats * sizeof(float))
      std::memcpy(result.image.at(r.x0, y), p, size_t(row_floats) * sizeof(float));
    if (data_doubles)
      for (int y = r.y0; y < r.y1; ++y, p += size_t(r.x1 - r.x0) * sizeof(PixelData))
        std::memcpy(&result.data[size_t(y) * g.width + r.x0], p, size_t(r.x1 - r.x0) * sizeof(PixelData));
  }
  if (good_end < bytes.size() && ::truncate(path_.c_str(), off_t(good_end)) != 0)
    throw Error("checkpoint \"" + path_ + "\": cannot drop its torn last record: " + std::strerror(errno));
  return true;
}

void TileCheckpoint::append(int tile, const RenderResult& result) {
  const TileGrid& g = key_.grid;
  const TileRect r = g.rect(tile);
  const int data_doubles = key_.with_data ? kDataDoubles : 0;
  std::string rec;
  rec.reserve(16 + size_t(r.pixels()) * (3 * sizeof(float) + size_t(data_doubles) * sizeof(double)) + 8);
  put(rec, kRecordMagic);
  put(rec, int32_t(tile));
  put(rec, int32_t(r.pixels() * 3));
  put(rec, int32_t(r.pixels() * data_doubles));
  for (int y = r.y0; y < r.y1; ++y)
    rec.append(reinterpret_cast<const char*>(result.image.at(r.x0, y)), size_t(r.x1 - r.x0) * 3 * sizeof(float));
  if (data_doubles)
    for (int y = r.y0; y < r.y1; ++y)
      rec.append(reinterpret_cast<const char*>(&result.data[size_t(y) * g.width + r.x0]),
                 size_t(r.x1 - r.x0) * sizeof(PixelData));
  put(rec, fnv1a64(rec.data(), rec.size()));

  std::lock_guard lock(mutex_);
  if (fd_ < 0) throw Error("checkpoint \"" + path_ + "\" is closed");
  write_all(fd_, rec, path_);
  // Once written, the record survives the process being killed (it is in the kernel); the sync
  // makes it survive the machine going down too. Records that arrive faster than one per
  // kSyncInterval share a sync (rank 0 receives hundreds of tiles a second from many ranks): a
  // machine crash may lose the tiles written since the last sync (they are rendered again; a
  // torn record is dropped on reading), a killed process loses none.
  const auto now = std::chrono::steady_clock::now();
  if (now - last_sync_ >= kSyncInterval) {
    if (::fdatasync(fd_) != 0) throw Error("checkpoint \"" + path_ + "\": fdatasync failed: " + std::strerror(errno));
    last_sync_ = now;
  }
  ++tiles_written_;
}

void TileCheckpoint::remove() {
  std::lock_guard lock(mutex_);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(path_.c_str());
}

}  // namespace geovis

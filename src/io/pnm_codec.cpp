// PBM/PGM/PPM through Netpbm's libnetpbm (io/image_codecs.h), on FILE streams over memory
// (fmemopen, open_memstream). Netpbm reports errors through pm_error, which calls our message
// hook and then longjmps to the buffer given to pm_setjmpbuf. Both are process-wide, so one mutex
// serialises every use of the library; between the setjmp and the library calls nothing with a
// destructor is created, so the jump skips no destructor. PNM has no metadata: the description is
// a header comment ("P6\n# text\n..."), which every PNM reader skips.
#include <pam.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include "io/image_codecs.h"

namespace geovis::codec {

namespace {

/// Netpbm's last error message (its other messages are dropped).
char netpbm_error[256];

void on_netpbm_error(const char* message) { std::snprintf(netpbm_error, sizeof netpbm_error, "%s", message); }
void on_netpbm_message(const char*) {}

std::mutex& netpbm_mutex() {
  static std::mutex m;
  return m;
}

/// Holds the library for one file: the mutex, the message hooks, a FILE, a row.
struct NetpbmSession {
  std::lock_guard<std::mutex> lock{netpbm_mutex()};
  FILE* file = nullptr;
  tuple* row = nullptr;
  char* memory = nullptr;  // open_memstream's buffer
  size_t memory_size = 0;
  NetpbmSession() {
    static std::once_flag init;
    std::call_once(init, [] {
      pm_init("geovis", 0);
      pm_setusererrormsgfn(on_netpbm_error);
      pm_setusermessagefn(on_netpbm_message);
    });
    netpbm_error[0] = 0;
  }
  ~NetpbmSession() {
    pm_setjmpbuf(nullptr);
    if (row) pnm_freepamrow(row);
    if (file) std::fclose(file);
    std::free(memory);
  }
};

/// The size of struct pam up to tuple_type, the part geovis uses (Netpbm's PAM_STRUCT_SIZE(tuple_type),
/// written with offsetof: the macro takes a member of a null pointer, which UBSan reports).
constexpr int kPamSize = int(offsetof(struct pam, tuple_type) + sizeof(pam::tuple_type));

/// The first comment line of a PNM header, "" when there is none.
std::string header_comment(const Bytes& file) {
  const auto eol = std::find(file.begin(), file.end(), '\n');
  if (eol == file.end() || eol + 1 == file.end() || eol[1] != '#') return {};
  const auto end = std::find(eol + 1, file.end(), '\n');
  std::string line(eol + 2, end);
  const size_t b = line.find_first_not_of(' ');
  return b == std::string::npos ? std::string() : line.substr(b);
}

}  // namespace

StoredImage decode_pnm(const std::string& path, const Bytes& file) {
  // PBM, PGM and PPM (P1 to P6). Not PAM (P7): Netpbm's PAM header parser loses memory when it
  // fails (it expects the process to exit), and geovis never read PAM.
  if (file.size() < 2 || file[0] != 'P' || file[1] < '1' || file[1] > '6')
    fail_read(path, "not a PBM, PGM or PPM file");
  NetpbmSession s;
  StoredImage img;
  struct pam pam {};
  std::jmp_buf jump;
  s.file = fmemopen(const_cast<unsigned char*>(file.data()), file.size(), "rb");
  if (!s.file) fail_read(path, std::strerror(errno));
  if (setjmp(jump)) fail_read(path, netpbm_error[0] ? netpbm_error : "not a PNM file");
  pm_setjmpbuf(&jump);
  pnm_readpaminit(s.file, &pam, kPamSize);
  // Samples of 8 or 16 bits as stored; other maximum values (PBM's 1, PGM's 15, ...) as float in [0, 1].
  const Sample kind = pam.maxval == 255 ? Sample::u8 : (pam.maxval == 65535 ? Sample::u16 : Sample::f32);
  img.allocate(path, pam.width, pam.height, pam.depth, kind);
  s.row = pnm_allocpamrow(&pam);
  const size_t n = size_t(pam.width) * pam.depth;
  for (int y = 0; y < pam.height; ++y) {
    pnm_readpamrow(&pam, s.row);
    unsigned char* out = img.bytes.data() + size_t(y) * n * sample_size(kind);
    for (size_t i = 0; i < n; ++i) {
      const sample v = s.row[i / pam.depth][i % pam.depth];
      if (kind == Sample::u8) {
        out[i] = static_cast<unsigned char>(v);
      } else if (kind == Sample::u16) {
        const std::uint16_t w = static_cast<std::uint16_t>(v);
        std::memcpy(out + 2 * i, &w, 2);
      } else {
        const float f = float(double(v) / double(pam.maxval));
        std::memcpy(out + 4 * i, &f, 4);
      }
    }
  }
  img.description = header_comment(file);
  return img;
}

Bytes encode_pnm(const std::string& path, const StoredImage& img) {
  if (img.channels != 1 && img.channels != 3) fail_write(path, "PPM stores grey or RGB pixels");
  NetpbmSession s;
  struct pam pam {};
  std::jmp_buf jump;
  s.file = open_memstream(&s.memory, &s.memory_size);
  if (!s.file) fail_write(path, std::strerror(errno));
  if (setjmp(jump)) fail_write(path, netpbm_error[0] ? netpbm_error : "the image could not be encoded");
  pm_setjmpbuf(&jump);
  pam.size = sizeof pam;
  pam.len = kPamSize;
  pam.file = s.file;
  pam.format = img.channels == 3 ? RPPM_FORMAT : RPGM_FORMAT;
  pam.plainformat = 0;
  pam.width = img.width;
  pam.height = img.height;
  pam.depth = unsigned(img.channels);
  pam.maxval = img.sample == Sample::u16 ? 65535 : 255;
  std::snprintf(pam.tuple_type, sizeof pam.tuple_type, "%s", img.channels == 3 ? PAM_PPM_TUPLETYPE : PAM_PGM_TUPLETYPE);
  pnm_writepaminit(&pam);
  s.row = pnm_allocpamrow(&pam);
  const size_t n = size_t(img.width) * size_t(img.channels);
  for (int y = 0; y < img.height; ++y) {
    for (size_t i = 0; i < n; ++i) {
      const size_t k = size_t(y) * n + i;
      std::uint16_t code = 0;
      if (img.sample == Sample::u16)
        std::memcpy(&code, &img.bytes[2 * k], 2);
      else
        code = img.bytes[k];
      s.row[i / img.channels][i % img.channels] = code;
    }
    pnm_writepamrow(&pam, s.row);
  }
  pm_setjmpbuf(nullptr);
  std::fclose(s.file);  // completes the memory buffer and its size
  s.file = nullptr;
  Bytes out(s.memory, s.memory + s.memory_size);
  if (!img.description.empty()) {
    // "P6\n..." -> "P6\n# description\n...".
    const auto eol = std::find(out.begin(), out.end(), '\n');
    if (eol == out.end()) fail_write(path, "unexpected PNM header from the encoder");
    std::string comment = "# " + img.description + "\n";
    std::replace(comment.begin(), comment.end() - 1, '\n', ' ');
    out.insert(eol + 1, comment.begin(), comment.end());
  }
  return out;
}

}  // namespace geovis::codec

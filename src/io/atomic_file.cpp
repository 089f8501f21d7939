// Atomic file output (io/atomic_file.h): temporary file + flock + fsync + rename.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.h"

namespace geovis {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTempMarker = ".geovis-tmp-";

std::atomic<long long> g_fail_at_byte{-1};
std::atomic<int> g_fail_errno{0};

std::string os_reason(int err) { return std::strerror(err); }

std::string folder_of(const std::string& path) {
  const std::string parent = fs::path(path).parent_path().string();
  return parent.empty() ? std::string(".") : parent;
}

/// ".<stem>.geovis-tmp-<pid>-<n><ext>" next to `target`: same folder (rename is atomic only within
/// one file system), hidden, unique per process and call, and keeping the extension so that a
/// writer that picks the format from the name (ffmpeg) still recognises it.
std::string temporary_name_for(const std::string& target) {
  static std::atomic<unsigned long> counter{0};
  const fs::path p(target);
  std::string stem = p.stem().string();
  if (stem.size() > 180) stem.resize(180);  // stay below NAME_MAX (255) with the marker added
  std::string name(1, '.');
  name.append(stem);
  name.append(kTempMarker);
  name.append(std::to_string(::getpid()));
  name.push_back('-');
  name.append(std::to_string(counter.fetch_add(1)));
  name.append(p.extension().string());
  return (p.parent_path() / name).string();
}

bool same_file(int fd, const std::string& path) {
  struct stat a {
  }, b{};
  return ::fstat(fd, &a) == 0 && ::lstat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/// Creates and locks a fresh temporary file for `target`; returns its descriptor, or -1 with
/// `err` set. The lock is taken right after creation; a cleaner that got the lock first (it then
/// removes the file) is detected because the name no longer refers to our file, and we retry.
int create_locked_temporary(const std::string& target, std::string& temp, int& err) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp = temporary_name_for(target);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      err = errno;
      return -1;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && same_file(fd, temp)) return fd;
    ::close(fd);
  }
  err = EEXIST;
  return -1;
}

void fsync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // makes the rename durable; some file systems refuse fsync on folders (EINVAL)
  ::close(fd);
}

}  // namespace

AtomicFile::AtomicFile(std::string target) : target_(std::move(target)) {
  int err = 0;
  fd_ = create_locked_temporary(target_, temp_, err);
  if (fd_ < 0)
    throw Error("cannot write \"" + target_ + "\": cannot create a file in the folder \"" + folder_of(target_) +
                "\": " + os_reason(err));
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
  if (done_) return;
  done_ = true;
  ::unlink(temp_.c_str());
  if (fd_ >= 0) ::close(fd_);  // after the unlink: the lock keeps cleaners away until the name is gone
  fd_ = -1;
}

void AtomicFile::fail(const std::string& what, int err) {
  discard();
  throw Error("cannot write \"" + target_ + "\": " + (what.empty() ? "" : what + ": ") + os_reason(err));
}

void AtomicFile::write(std::string_view bytes) {
  if (done_) throw Error("cannot write \"" + target_ + "\": the file is already closed");
  size_t limit = bytes.size();
  bool inject = false;
  if (const long long fail_at = g_fail_at_byte.load(); fail_at >= 0) {
    const off_t pos = ::lseek(fd_, 0, SEEK_CUR);
    if (pos >= 0 && pos + static_cast<long long>(bytes.size()) > fail_at) {
      limit = fail_at > pos ? size_t(fail_at - pos) : 0;
      inject = true;
    }
  }
  size_t done = 0;
  while (done < limit) {
    const ssize_t n = ::write(fd_, bytes.data() + done, limit - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("", errno);
    }
    done += size_t(n);
  }
  if (inject) fail("", g_fail_errno.load());
}

void AtomicFile::commit() {
  if (done_) throw Error("cannot write \"" + target_ + "\": the file is already closed");
  // An external writer (codec, ffmpeg) may have replaced the file instead of writing into it:
  // fsync whatever the temporary name refers to now.
  int sync_fd = fd_;
  if (!same_file(fd_, temp_)) {
    sync_fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
    if (sync_fd < 0) fail("the temporary file \"" + temp_ + "\" disappeared", errno);
  }
  const int sync_rc = ::fsync(sync_fd);
  const int sync_err = errno;
  if (sync_fd != fd_) ::close(sync_fd);
  if (sync_rc != 0) fail("", sync_err);
  if (::rename(temp_.c_str(), target_.c_str()) != 0) fail("", errno);
  done_ = true;
  const int close_rc = ::close(fd_);  // releases the lock; the data are on disk already (fsync)
  fd_ = -1;
  fsync_folder(folder_of(target_));
  if (close_rc != 0 && errno != EINTR) throw Error("cannot write \"" + target_ + "\": " + os_reason(errno));
}

void write_file_atomic(const std::string& path, std::string_view data) {
  AtomicFile f(path);
  f.write(data);
  f.commit();
}

void check_folder_writable(const std::string& folder) {
  const std::string f = folder.empty() ? std::string(".") : folder;
  std::string temp;
  int err = 0;
  const int fd = create_locked_temporary((fs::path(f) / "write-check").string(), temp, err);
  if (fd < 0) throw Error("the output folder \"" + f + "\" is not writable: " + os_reason(err));
  ::unlink(temp.c_str());
  ::close(fd);
}

bool is_temporary_file_name(std::string_view name) {
  if (name.size() < 2 || name[0] != '.') return false;
  const size_t m = name.rfind(kTempMarker);
  if (m == std::string_view::npos || m < 1) return false;
  std::string_view rest = name.substr(m + kTempMarker.size());
  auto digits = [&rest]() {
    size_t n = 0;
    while (n < rest.size() && rest[n] >= '0' && rest[n] <= '9') ++n;
    rest.remove_prefix(n);
    return n > 0;
  };
  if (!digits() || rest.empty() || rest[0] != '-') return false;
  rest.remove_prefix(1);
  if (!digits()) return false;
  if (rest.empty()) return true;
  if (rest[0] != '.' || rest.size() < 2) return false;
  for (size_t i = 1; i < rest.size(); ++i)
    if (!std::isalnum(static_cast<unsigned char>(rest[i]))) return false;
  return true;
}

std::vector<std::string> remove_stale_temporaries(const std::string& folder) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (fs::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!is_temporary_file_name(name) || !it->is_regular_file(ec)) continue;
    const std::string path = it->path().string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    // A live writer holds the lock; getting it means the writer is gone. The name must still be
    // this file (not a new one created under the same name meanwhile).
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && same_file(fd, path) && ::unlink(path.c_str()) == 0)
      removed.push_back(path);
    ::close(fd);
  }
  return removed;
}

void fail_writes_at_byte_for_testing(long long at_byte, int err) {
  g_fail_errno = err;
  g_fail_at_byte = at_byte;
}

}  // namespace geovis

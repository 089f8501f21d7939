// Atomic file output: every file geovis writes (images, data files, text outputs, movies,
// checkpoints) goes to a temporary file in the destination folder, is fsync'ed, and only then
// renamed over the destination. On any failure the destination is untouched, the temporary file is
// removed, and the Error names the destination and what the OS said ("No space left on device").
//
// Temporary files are named ".<name>.geovis-tmp-<pid>-<n><ext>" and hold an flock(2) lock while
// their writer lives, so a later run can tell the leftovers of a killed process (unlocked) from the
// file a concurrent render is writing right now (locked): remove_stale_temporaries().
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace geovis {

/// One atomic write of `target`. Either write the bytes through write(), or let an external writer
/// (a codec, ffmpeg) write temp_path() by name; then commit(). Destroyed without commit() (an error,
/// an exception), the temporary file is removed and the target is untouched.
class AtomicFile {
 public:
  /// Creates and locks the temporary file next to `target`. Throws Error naming the folder and the
  /// OS reason when the folder is not writable.
  explicit AtomicFile(std::string target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& target() const { return target_; }
  const std::string& temp_path() const { return temp_; }

  /// Appends `bytes` (write(2) until done; EINTR retried). Throws Error naming the target and the
  /// OS reason; the temporary file is then removed.
  void write(std::string_view bytes);
  /// fsync, close, rename over the target, fsync the folder. Throws Error (target untouched).
  void commit();
  /// Removes the temporary file now (idempotent; the destructor does it too).
  void discard() noexcept;

 private:
  [[noreturn]] void fail(const std::string& what, int err);
  std::string target_, temp_;
  int fd_ = -1;
  bool done_ = false;
};

/// Writes `data` to `path` atomically (AtomicFile). Throws Error on failure.
void write_file_atomic(const std::string& path, std::string_view data);

/// Throws Error "cannot write to the output folder "F": <OS reason>" unless a file can be created
/// in `folder` (checked by creating and removing a temporary file).
void check_folder_writable(const std::string& folder);

/// True for names of our temporary files (".<name>.geovis-tmp-<pid>-<n>[.ext]").
bool is_temporary_file_name(std::string_view file_name);

/// Removes the temporary files in `folder` that no live process holds (left by a killed or crashed
/// run); files of a concurrently running writer are locked and kept, other files are never
/// touched. Returns the paths removed.
std::vector<std::string> remove_stale_temporaries(const std::string& folder);

/// Fault injection for tests (a writer that fails at byte N): AtomicFile::write() writes a file up
/// to byte `at_byte`, then fails with errno `err`; at_byte < 0 turns it off.
void fail_writes_at_byte_for_testing(long long at_byte, int err);

}  // namespace geovis

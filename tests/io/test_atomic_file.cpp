// Atomic output (io/atomic_file.h) and the image writer on top of it: every format on a full file
// system and with a writer that fails at byte N (new file, and over an existing file that must
// stay byte-identical), read-only folders, the leftovers of a killed writer, image checks for
// --resume, and codec messages kept off the terminal.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image.h"
#include "support/temp_dir.h"

namespace geovis {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kFormats = {".png", ".jpg", ".tif", ".ppm", ".exr"};

using testing_support::TempDir;

/// A small tmpfs mounted for the test (needs root); `ok` false with `why` set otherwise.
struct TinyFileSystem {
  fs::path path;
  bool ok = false;
  std::string why;
  explicit TinyFileSystem(const std::string& options, unsigned long flags = 0) {
    path = fs::temp_directory_path() / ("geovis_tinyfs_" + std::to_string(::getpid()) + "_" +
                                        testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path);
    if (::geteuid() != 0) {
      why = "mounting a small tmpfs needs root (run the tests as root to test a full file system)";
    } else if (::mount("tmpfs", path.c_str(), "tmpfs", flags, options.c_str()) != 0) {
      why = std::string("cannot mount a small tmpfs: ") + std::strerror(errno);
    } else {
      ok = true;
    }
  }
  ~TinyFileSystem() {
    if (ok) ::umount2(path.c_str(), MNT_DETACH);
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& n) const { return (path / n).string(); }
};

std::string slurp(const std::string& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

/// Files in `dir` (names), to show that nothing (no temporary file) is left behind.
std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// Noise compresses badly: every format needs tens of kilobytes for it.
Image noise_image(int w, int h, unsigned seed) {
  Image img(w, h, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (float& v : img.pixels) v = u(rng);
  return img;
}

void expect_names_file_and_reason(const Error& e, const std::string& file, const std::string& reason) {
  const std::string m = e.what();
  EXPECT_NE(m.find("\"" + file + "\""), std::string::npos) << m;
  EXPECT_NE(m.find(reason), std::string::npos) << m;
  EXPECT_EQ(m.find("geovis-tmp"), std::string::npos) << "names the temporary file: " << m;
}

// ---- AtomicFile --------------------------------------------------------------------------------

TEST(AtomicFile, CommitReplacesTheTargetAndLeavesNothingElse) {
  TempDir d;
  write_file_atomic(d.file("a.txt"), "old");
  {
    AtomicFile f(d.file("a.txt"));
    f.write("new ");
    f.write("content");
    EXPECT_TRUE(is_temporary_file_name(fs::path(f.temp_path()).filename().string())) << f.temp_path();
    EXPECT_EQ(slurp(d.file("a.txt")), "old");  // not yet committed
    f.commit();
  }
  EXPECT_EQ(slurp(d.file("a.txt")), "new content");
  EXPECT_EQ(listing(d.path), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, WithoutCommitTheTargetIsUntouched) {
  TempDir d;
  write_file_atomic(d.file("a.txt"), "old");
  {
    AtomicFile f(d.file("a.txt"));
    f.write("half a fi");
  }  // e.g. an exception between the writes
  EXPECT_EQ(slurp(d.file("a.txt")), "old");
  EXPECT_EQ(listing(d.path), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, MissingFolderNamesTheFolderAndTheReason) {
  TempDir d;
  try {
    write_file_atomic(d.file("missing/x.bin"), "abc");
    FAIL();
  } catch (const Error& e) {
    expect_names_file_and_reason(e, d.file("missing/x.bin"), "No such file or directory");
  }
  EXPECT_TRUE(listing(d.path).empty());
}

TEST(AtomicFile, TemporaryNamePattern) {
  EXPECT_TRUE(is_temporary_file_name(".f_0003.geovis-tmp-123-0.png"));
  EXPECT_TRUE(is_temporary_file_name(".a.b.geovis-tmp-1-22.tiff"));
  EXPECT_TRUE(is_temporary_file_name(".data.geovis-tmp-9-9"));
  EXPECT_FALSE(is_temporary_file_name("f.geovis-tmp-123-0.png"));   // not hidden
  EXPECT_FALSE(is_temporary_file_name(".f.geovis-tmp-12a-0.png"));  // pid not a number
  EXPECT_FALSE(is_temporary_file_name(".f.geovis-tmp-123.png"));    // no counter
  EXPECT_FALSE(is_temporary_file_name(".f.geovis-tmp-1-2.png.bak"));
  EXPECT_FALSE(is_temporary_file_name(".f_0003.tmp-123-0.png"));  // not our pattern
  EXPECT_FALSE(is_temporary_file_name("notes.txt"));
}

// ---- a writer that fails at byte N --------------------------------------------------------------

struct FailingWrites {
  FailingWrites(long long at, int err) { fail_writes_at_byte_for_testing(at, err); }
  ~FailingWrites() { fail_writes_at_byte_for_testing(-1, 0); }
};

TEST(AtomicFile, WriterFailingAtByteNKeepsTheOldFileForEveryFormat) {
  TempDir d;
  const Image first = noise_image(40, 30, 1), second = noise_image(40, 30, 2);
  for (const std::string& ext : kFormats) {
    for (long long n : {0LL, 1LL, 100LL, 1000LL}) {
      SCOPED_TRACE(ext + " failing at byte " + std::to_string(n));
      const std::string fresh = d.file("new" + ext), existing = d.file("old" + ext);
      write_image(existing, first);
      const std::string before = slurp(existing);
      const FailingWrites fail(n, ENOSPC);
      for (const std::string& target : {fresh, existing}) {
        try {
          write_image(target, second);
          ADD_FAILURE() << "no error for " << target;
        } catch (const Error& e) {
          expect_names_file_and_reason(e, target, "No space left on device");
        }
      }
      EXPECT_FALSE(fs::exists(fresh));
      EXPECT_EQ(slurp(existing), before);
      EXPECT_EQ(listing(d.path), std::vector<std::string>{"old" + ext});
      fs::remove(existing);
    }
  }
  // Data files and text outputs go through the same writer.
  write_file_atomic(d.file("x.pdz"), std::string(64, 'a'));
  const FailingWrites fail(10, EIO);
  try {
    write_file_atomic(d.file("x.pdz"), std::string(64, 'b'));
    FAIL();
  } catch (const Error& e) {
    expect_names_file_and_reason(e, d.file("x.pdz"), "Input/output error");
  }
  EXPECT_EQ(slurp(d.file("x.pdz")), std::string(64, 'a'));
}

// ---- a full file system -------------------------------------------------------------------------

/// Fills the tiny file system with a filler file until at most `leave_free` bytes are free.
void fill(const TinyFileSystem& t, long long leave_free) {
  std::ofstream filler(t.file("filler"), std::ios::binary);
  const std::string block(4096, 'x');
  for (;;) {
    filler.flush();
    const auto space = fs::space(t.path);
    if (static_cast<long long>(space.available) <= leave_free || !filler) break;
    filler.write(block.data(), std::streamsize(block.size()));
  }
}

TEST(AtomicFile, FullFileSystemEveryFormatNewAndExisting) {
  for (long long free_bytes : {0LL, 4096LL, 8192LL}) {
    for (const std::string& ext : kFormats) {
      SCOPED_TRACE(ext + " with " + std::to_string(free_bytes) + " bytes free");
      TinyFileSystem t("size=512k,mode=0700");
      if (!t.ok) GTEST_SKIP() << t.why;
      const std::string existing = t.file("target" + ext), fresh = t.file("fresh" + ext);
      write_image(existing, noise_image(64, 64, 3), 8);
      const std::string before = slurp(existing);
      fill(t, free_bytes);
      for (const std::string& target : {fresh, existing}) {
        testing::internal::CaptureStderr();
        try {
          write_image(target, noise_image(96, 96, 4), 16);  // needs more than the space left
          ADD_FAILURE() << "no error for " << target;
        } catch (const Error& e) {
          expect_names_file_and_reason(e, target, "No space left on device");
        }
        EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "the codec printed its own message";
      }
      EXPECT_FALSE(fs::exists(fresh));
      EXPECT_EQ(slurp(existing), before) << "the existing file changed";
      EXPECT_EQ(listing(t.path), (std::vector<std::string>{"filler", "target" + ext}));
    }
  }
}

// ---- read-only folders ---------------------------------------------------------------------------

TEST(AtomicFile, ReadOnlyFolderIsReportedWithTheReason) {
  std::string folder, reason;
  std::unique_ptr<TinyFileSystem> ro;
  TempDir d;
  if (::geteuid() == 0) {  // root writes into any folder whatever its mode: use a read-only mount
    ro = std::make_unique<TinyFileSystem>("size=64k", MS_RDONLY);
    if (!ro->ok) GTEST_SKIP() << ro->why;
    folder = ro->path.string();
    reason = "Read-only file system";
  } else {
    folder = d.file("ro");
    fs::create_directories(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    reason = "Permission denied";
  }
  try {
    check_folder_writable(folder);
    FAIL();
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("\"" + folder + "\""), std::string::npos) << m;
    EXPECT_NE(m.find(reason), std::string::npos) << m;
  }
  try {
    write_image(folder + "/a.png", noise_image(4, 4, 1));
    FAIL();
  } catch (const Error& e) {
    expect_names_file_and_reason(e, folder + "/a.png", reason);
  }
  EXPECT_NO_THROW(check_folder_writable(d.path.string()));
  EXPECT_TRUE(listing(d.path).size() <= 1);  // only "ro" (the check leaves nothing)
  if (!ro) fs::permissions(folder, fs::perms::owner_all);
}

// ---- leftovers of a killed writer ----------------------------------------------------------------

TEST(AtomicFile, StaleTemporariesOfAKilledProcessAreRemovedLiveOnesKept) {
  TempDir d;
  // A child process starts writing a frame and is killed (SIGKILL: no destructor runs).
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ready[0]);
    AtomicFile f(d.file("f_0003.png"));
    f.write("partial frame");
    const char ok = '1';
    if (::write(ready[1], &ok, 1) != 1) ::_exit(3);
    for (;;) ::pause();
  }
  ::close(ready[1]);
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  ::close(ready[0]);
  ::kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  std::vector<std::string> left = listing(d.path);
  ASSERT_EQ(left.size(), 1u);
  ASSERT_TRUE(is_temporary_file_name(left[0])) << left[0];
  const std::string stale = d.file(left[0]);

  // Files that are not ours, and the temporary file of a writer that is still running.
  write_file_atomic(d.file("notes.txt"), "keep");
  write_file_atomic(d.file("f.geovis-tmp-1-2.png"), "keep");  // not hidden: not our pattern
  AtomicFile live(d.file("f_0004.png"));
  live.write("in progress");

  const std::vector<std::string> removed = remove_stale_temporaries(d.path.string());
  EXPECT_EQ(removed, std::vector<std::string>{stale});
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live.temp_path()));
  EXPECT_TRUE(fs::exists(d.file("notes.txt")));
  EXPECT_TRUE(fs::exists(d.file("f.geovis-tmp-1-2.png")));
  live.commit();
  EXPECT_EQ(slurp(d.file("f_0004.png")), "in progress");
}

// ---- checking an image for --resume --------------------------------------------------------------

TEST(ImageFileCheck, DescriptionRoundTripsInEveryFormat) {
  TempDir d;
  for (const std::string& ext : kFormats) {
    write_image(d.file("a" + ext), noise_image(20, 10, 5), 8, "geovis settings 0123456789abcdef");
    const ImageFileCheck c = check_image_file(d.file("a" + ext));
    EXPECT_TRUE(c.readable) << ext << ": " << c.problem;
    EXPECT_EQ(c.width, 20) << ext;
    EXPECT_EQ(c.height, 10) << ext;
    EXPECT_EQ(c.description, "geovis settings 0123456789abcdef") << ext;
  }
}

TEST(ImageFileCheck, TruncatedEmptyAndTextFilesAreNotReadable) {
  TempDir d;
  for (const std::string& ext : kFormats) {
    SCOPED_TRACE(ext);
    // As geovis render writes frames: with a description, hence with the pixel checksum (JPEG and
    // TIFF decode a truncated file without an error; the checksum finds it).
    write_image(d.file("full" + ext), noise_image(64, 64, 6), 8, "geovis-settings test");
    const std::string bytes = slurp(d.file("full" + ext));
    write_file_atomic(d.file("half" + ext), bytes.substr(0, bytes.size() / 2));
    write_file_atomic(d.file("empty" + ext), "");
    write_file_atomic(d.file("text" + ext), "this is not an image\n");
    EXPECT_TRUE(check_image_file(d.file("full" + ext)).readable);
    for (const std::string name : {"half", "empty", "text"}) {
      testing::internal::CaptureStderr();
      const ImageFileCheck c = check_image_file(d.file(name + ext));
      const std::string printed = testing::internal::GetCapturedStderr();
      EXPECT_FALSE(c.readable) << name;
      EXPECT_NE(c.problem.find(d.file(name + ext)), std::string::npos) << c.problem;
      EXPECT_EQ(printed, "") << "the codec printed its own messages";
    }
  }
}

TEST(ImageRead, TruncatedPngIsOneErrorAndNoCodecOutput) {
  TempDir d;
  write_image(d.file("tex.png"), noise_image(64, 64, 7));
  const std::string bytes = slurp(d.file("tex.png"));
  write_file_atomic(d.file("tex.png"), bytes.substr(0, bytes.size() / 2));
  testing::internal::CaptureStderr();
  std::string message;
  try {
    read_image(d.file("tex.png"));
  } catch (const Error& e) {
    message = e.what();
  }
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "") << "raw libpng lines on stderr";
  EXPECT_NE(message.find("cannot read image \"" + d.file("tex.png") + "\""), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace
}  // namespace geovis

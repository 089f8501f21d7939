// Progress reporting for long renders: a bar with percentage, rate and ETA redrawn in place on
// stderr when stderr is a terminal, otherwise a single summary line when the work is done (logs and
// CI output stay readable). Thread-safe: workers call add() concurrently.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace geovis {

class Progress {
 public:
  /// `total` work units (pixels); `unit` names them in the rate ("px/s"). When `enabled` is false
  /// nothing is ever printed. `out` defaults to stderr; `force_terminal` overrides the isatty test
  /// (tests).
  Progress(long total, std::string label, bool enabled, std::FILE* out = stderr, std::string unit = "px",
           int force_terminal = -1);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Records `n` finished units; redraws the bar at most every 100 ms (never blocks a worker:
  /// a worker that finds another one drawing skips the redraw).
  void add(long n);
  /// Prints the final line (bar at 100 % on a terminal, the summary line otherwise). Idempotent.
  void finish();

  long done() const { return done_.load(std::memory_order_relaxed); }
  double elapsed_seconds() const;

  /// "label [#######.......]  45.0%  1234 px/s  ETA 0:12" (pure function, for tests).
  static std::string format_bar(const std::string& label, long done, long total, double seconds,
                                const std::string& unit, int bar_width = 30);
  /// "label: 65536 px in 1.23 s (53280 px/s)".
  static std::string format_summary(const std::string& label, long done, double seconds, const std::string& unit);
  /// "1:02:03" or "2:03".
  static std::string format_duration(double seconds);

 private:
  void draw(bool final_line);
  const long total_;
  const std::string label_;
  const bool enabled_;
  std::FILE* out_;
  const std::string unit_;
  bool terminal_ = false;
  std::atomic<long> done_{0};
  std::atomic<long long> last_draw_ns_{0};
  std::mutex draw_mutex_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace geovis

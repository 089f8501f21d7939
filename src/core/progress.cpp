#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace geovis {

Progress::Progress(long total, std::string label, bool enabled, std::FILE* out, std::string unit, int force_terminal)
    : total_(total < 0 ? 0 : total),
      label_(std::move(label)),
      enabled_(enabled && out != nullptr),
      out_(out),
      unit_(std::move(unit)),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_) terminal_ = force_terminal >= 0 ? force_terminal != 0 : ::isatty(::fileno(out_)) != 0;
}

Progress::~Progress() { finish(); }

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::add(long n) {
  done_.fetch_add(n, std::memory_order_relaxed);
  if (!enabled_ || !terminal_) return;
  const long long now =
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_).count();
  long long last = last_draw_ns_.load(std::memory_order_relaxed);
  if (now - last < 100'000'000LL) return;
  if (!last_draw_ns_.compare_exchange_strong(last, now)) return;  // another worker draws
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (lock.owns_lock() && !finished_) draw(false);
}

void Progress::finish() {
  std::lock_guard lock(draw_mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void Progress::draw(bool final_line) {
  const double secs = elapsed_seconds();
  const long d = done();
  if (terminal_) {
    // \r + clear-to-end-of-line redraws in place.
    std::fprintf(out_, "\r%s\033[K", format_bar(label_, d, total_, secs, unit_).c_str());
    if (final_line) std::fputc('\n', out_);
  } else if (final_line) {
    std::fprintf(out_, "%s\n", format_summary(label_, d, secs, unit_).c_str());
  }
  std::fflush(out_);
}

std::string Progress::format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

std::string Progress::format_bar(const std::string& label, long done, long total, double seconds,
                                 const std::string& unit, int bar_width) {
  const double frac = total > 0 ? std::min(1.0, double(done) / double(total)) : 1.0;
  const int filled = int(frac * bar_width);
  std::string bar(size_t(filled), '#');
  bar += std::string(size_t(bar_width - filled), '.');
  const double rate = seconds > 0 ? double(done) / seconds : 0.0;
  const double eta = rate > 0 ? double(total - done) / rate : NAN;
  char buf[160];
  std::snprintf(buf, sizeof buf, " [%s] %5.1f%%  %.0f %s/s  ETA %s", bar.c_str(), 100.0 * frac, rate, unit.c_str(),
                done >= total ? "0:00" : format_duration(eta).c_str());
  return label.empty() ? std::string(buf + 1) : label + buf;
}

std::string Progress::format_summary(const std::string& label, long done, double seconds, const std::string& unit) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%ld %s in %.2f s (%.0f %s/s)", done, unit.c_str(), seconds,
                seconds > 0 ? double(done) / seconds : 0.0, unit.c_str());
  return label.empty() ? std::string(buf) : label + ": " + buf;
}

}  // namespace geovis

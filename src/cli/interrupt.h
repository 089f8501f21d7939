// SIGINT / SIGTERM during a render: the handler only raises a flag; the renderer stops before its
// next tile (RenderOptions::cancel) and the command reports what was done and exits 128 + signal
// (130 for Ctrl-C, 143 for SIGTERM), as shells expect of an interrupted program.
#pragma once

#include <atomic>

namespace geovis::cli {

/// Installs the handlers for its lifetime (the previous ones are restored after). A second signal
/// of the same kind ends the process at once (the handler is reset on first use).
class InterruptHandler {
 public:
  InterruptHandler();
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

  /// Set once a signal arrived (pass to RenderOptions::cancel).
  const std::atomic<bool>* flag() const;
  /// The signal that arrived (SIGINT, SIGTERM), 0 when none.
  int signal_number() const;
};

}  // namespace geovis::cli

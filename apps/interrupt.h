/// \file
/// Ctrl-C and `kill` during a render: the work done so far is kept. While an Interrupt lives,
/// the first SIGINT or SIGTERM sets a flag that chapter 14's renderer reads before each tile
/// (RenderOptions::stop) and that the viewer's loop reads every frame; the command then writes
/// what was rendered, says so on stderr and exits with 128 + the signal's number (130 for
/// SIGINT, 143 for SIGTERM), as a shell reports a program that a signal ended. A second signal
/// ends the process at once, as if no handler were installed.
#pragma once

#include <atomic>

namespace rtk::cli {

/// The signal handlers of a render, installed for the object's lifetime (one at a time).
class Interrupt {
 public:
  /// Installs the handlers for SIGINT and SIGTERM.
  Interrupt();
  /// Restores the handlers that were there before.
  ~Interrupt();
  Interrupt(const Interrupt&) = delete;
  Interrupt& operator=(const Interrupt&) = delete;

  /// The flag the first signal sets, for RenderOptions::stop.
  const std::atomic<bool>* flag() const;
  /// Whether a signal arrived.
  bool requested() const;
  /// The signal that arrived (0 if none).
  int signal() const;
  /// Its name, "SIGINT" or "SIGTERM".
  const char* signal_name() const;
  /// The exit status that reports it: 128 + the signal's number.
  int exit_status() const;
};

}  // namespace rtk::cli

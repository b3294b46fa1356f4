// The progress display of `acute mesh` and `acute repair`: one updating line on stderr with the
// phase, the iteration, the count of bad triangles and the elapsed time, redrawn a few times a
// second so the clock moves during long phases. Only when stderr is a terminal and -q is not
// given, so that logs, pipes and tests never see it. With -v, each phase change (and, off a
// terminal, each repair iteration) is also logged on its own line.
#pragma once

#include "commands/commands.h"

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace acute::cli {

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  ProgressLine(const GlobalOptions& global, Clock::time_point start);
  /// Clears the line (also when an exception unwinds the command).
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Is there anything to show (a terminal line or -v logging)? Observers are installed only then.
  bool wanted() const { return terminal_ || verbose_; }

  /// A report from the library; `bad` is shown in the repair phase only.
  void update(const std::string& phase, int iteration, std::size_t bad);
  /// A CVT iteration: with -v off a terminal, logged with its energy and gradient norm.
  void update_cvt(int iteration, const char* step, double energy, double gradient_norm);

  /// Prints `line` (a whole message with its newline) on stderr above the progress line, which
  /// goes on; plain output when there is no line.
  void print(const std::string& line);

  /// Stops the redrawing and clears the line; later updates are ignored.
  void finish();

 private:
  void draw_locked();
  double elapsed() const;

  bool terminal_ = false, verbose_ = false;
  Clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread ticker_;
  bool stopped_ = false, drawn_ = false;
  std::string phase_;
  int iteration_ = 0;
  std::size_t bad_ = 0;
};

}  // namespace acute::cli

#include "commands/progress.h"

#include <cstdio>
#include <unistd.h>

namespace acute::cli {

namespace {

/// What the user reads for a phase name of the library.
const char* phase_label(const std::string& phase) {
  if (phase == "check") return "reading and checking";
  if (phase == "cdt") return "triangulating (CDT)";
  if (phase == "refine") return "Delaunay refinement";
  if (phase == "cvt") return "CVT smoothing";
  if (phase == "repair") return "acute repair";
  if (phase == "prune") return "pruning Steiner points";
  return phase.c_str();
}

}  // namespace

ProgressLine::ProgressLine(const GlobalOptions& global, Clock::time_point start)
    : terminal_(!global.quiet && isatty(STDERR_FILENO)), verbose_(global.verbose && !global.quiet), start_(start) {
  if (!terminal_) return;
  ticker_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopped_) {
      wake_.wait_for(lock, std::chrono::milliseconds(250));
      if (!stopped_ && !phase_.empty()) draw_locked();
    }
  });
}

ProgressLine::~ProgressLine() { finish(); }

double ProgressLine::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void ProgressLine::update(const std::string& phase, int iteration, std::size_t bad) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (stopped_) return;
  const bool new_phase = phase != phase_;
  phase_ = phase;
  iteration_ = iteration;
  bad_ = bad;
  if (verbose_ && new_phase)
    std::fprintf(stderr, "%s[%8.3f s] %s\n", drawn_ ? "\r\033[K" : "", elapsed(), phase_label(phase));
  else if (verbose_ && !terminal_ && phase == "repair")
    std::fprintf(stderr, "[%8.3f s] repair iteration %d: %zu bad\n", elapsed(), iteration, bad);
  if (terminal_ && new_phase) draw_locked();  // the ticker redraws the rest
}

void ProgressLine::update_cvt(int iteration, const char* step, double energy, double gradient_norm) {
  update("cvt", iteration, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!stopped_ && verbose_ && !terminal_ && iteration > 0)
    std::fprintf(stderr, "[%8.3f s] cvt iteration %d (%s): energy %.9g, gradient norm %.6g\n", elapsed(), iteration, step, energy,
                 gradient_norm);
}

void ProgressLine::print(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "%s%s", drawn_ && !stopped_ ? "\r\033[K" : "", line.c_str());
  if (terminal_ && !stopped_) draw_locked();
  std::fflush(stderr);
}

void ProgressLine::draw_locked() {
  char line[160];
  int n = std::snprintf(line, sizeof line, "acute: %-22s", phase_label(phase_));
  auto append = [&](const char* format, auto value) {
    if (n >= 0 && n < int(sizeof line)) n += std::snprintf(line + n, sizeof line - std::size_t(n), format, value);
  };
  if (iteration_ > 0) append("  iteration %5d", iteration_);
  // The phase's first report (iteration 0, nothing counted yet) has no count to show.
  if (phase_ == "repair" && (iteration_ > 0 || bad_ > 0)) append("  bad triangles %7zu", bad_);
  append("  %7.1f s", elapsed());
  std::fprintf(stderr, "\r\033[K%s", line);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) return;
    stopped_ = true;
    if (drawn_) {
      std::fprintf(stderr, "\r\033[K");
      std::fflush(stderr);
    }
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

}  // namespace acute::cli

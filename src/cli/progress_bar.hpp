#pragma once
// Progress on stderr, as output.progress asks. bar: a bar redrawn in place, only when
// stderr is a terminal so that logs and pipelines stay quiet; a timed bar (long jobs
// such as sweeps) adds the rate and the time left, and when stderr is not a terminal
// (mpirun's pipes, a batch log) writes the same as a plain line every ten seconds.
// lines: a plain line every 10 % (a timed one every ten seconds), terminal or not.
// none: nothing.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "common/progress_display.hpp"

namespace crux::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, long total, ProgressDisplay display, bool timed = false)
      : label_(std::move(label)),
        total_(total),
        terminal_(display == ProgressDisplay::Bar && ::isatty(2) == 1),
        timed_(timed),
        enabled_(display == ProgressDisplay::Lines || (display == ProgressDisplay::Bar && (terminal_ || timed))),
        step_(display == ProgressDisplay::Lines ? 10 : 1) {}
  ~ProgressBar() { finish(); }

  // `first`: where a resumed job starts, left out of the rate.
  void start_at(long first) { first_ = first; }

  void update(long done) {
    if (!enabled_ || total_ <= 0) return;
    const int percent = static_cast<int>(100 * done / total_) / step_ * step_;
    const auto now = std::chrono::steady_clock::now();
    const double since_shown = std::chrono::duration<double>(now - shown_).count();
    if (timed_ ? since_shown < (terminal_ ? 0.25 : 10.0) && done < total_ : percent == last_percent_) return;
    last_percent_ = percent;
    shown_ = now;
    std::string rate;
    if (timed_) {
      const double seconds = std::chrono::duration<double>(now - started_).count();
      const double per_second = seconds > 0 ? static_cast<double>(done - first_) / seconds : 0.0;
      const long left = per_second > 0 ? static_cast<long>(static_cast<double>(total_ - done) / per_second) : -1;
      rate = fmt::format(", {:.2f}/s, {} left", per_second,
                         left < 0 ? std::string("?") : fmt::format("{}m{:02}s", left / 60, left % 60));
    }
    constexpr int width = 40;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "%s%s [%s%s] %3d%% (%ld/%ld%s)%s", terminal_ ? "\r" : "", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), percent, done, total_,
                 rate.c_str(), terminal_ ? "" : "\n");
    std::fflush(stderr);
  }

  void finish() {
    if (enabled_ && terminal_ && last_percent_ >= 0) std::fputc('\n', stderr);
    enabled_ = false;
  }

 private:
  std::string label_;
  long total_;
  bool terminal_, timed_, enabled_;
  int step_;  // percent between two lines
  int last_percent_ = -1;
  long first_ = 0;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now(), shown_ = started_;
};

}  // namespace crux::cli

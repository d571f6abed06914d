#pragma once
// Progress on stderr, as output.progress asks, so that stdout and every file stay the same.
// bar: on a terminal, a bar redrawn in place with the rate and the time left; elsewhere (a
// pipe, a batch log, mpirun's pipes) the same as a plain line every ten seconds, and a last
// one at the end once one was written, so that a command shorter than ten seconds writes
// nothing there. lines: a plain line every 10 % (a sweep's every ten seconds), terminal or
// not. none: nothing (also --quiet).

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "common/progress_display.hpp"

namespace crux::cli {

class ProgressBar {
 public:
  // `timed_lines`: lines every ten seconds rather than every 10 % (a sweep, whose tasks
  // can take minutes each). `sink` and `line_seconds` are stderr's and ten but in tests.
  ProgressBar(std::string label, long total, ProgressDisplay display, bool timed_lines = false,
              std::FILE* sink = stderr, double line_seconds = 10.0)
      : label_(std::move(label)),
        total_(total),
        sink_(sink),
        line_seconds_(line_seconds),
        terminal_(display == ProgressDisplay::Bar && ::isatty(::fileno(sink)) == 1),
        timed_(display == ProgressDisplay::Bar || timed_lines),
        enabled_(display != ProgressDisplay::None),
        silent_when_short_(display == ProgressDisplay::Bar && !terminal_),
        step_(display == ProgressDisplay::Lines ? 10 : 1) {}
  ~ProgressBar() { finish(); }

  // `first`: where a resumed job starts, left out of the rate.
  void start_at(long first) { first_ = first; }

  void update(long done) {
    if (!enabled_ || total_ <= 0) return;
    const int percent = static_cast<int>(100 * done / total_) / step_ * step_;
    const auto now = std::chrono::steady_clock::now();
    const double since_shown = std::chrono::duration<double>(now - shown_).count();
    if (timed_) {
      const bool finished = done >= total_;
      if (finished ? silent_when_short_ && last_percent_ < 0 : since_shown < (terminal_ ? 0.25 : line_seconds_)) return;
    } else if (percent == last_percent_) {
      return;
    }
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
    std::fprintf(sink_, "%s%s [%s%s] %3d%% (%ld/%ld%s)%s", terminal_ ? "\r" : "", label_.c_str(),
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), percent, done, total_,
                 rate.c_str(), terminal_ ? "" : "\n");
    std::fflush(sink_);
  }

  void finish() {
    if (enabled_ && terminal_ && last_percent_ >= 0) std::fputc('\n', sink_);
    enabled_ = false;
  }

 private:
  std::string label_;
  long total_;
  std::FILE* sink_;
  double line_seconds_;
  bool terminal_, timed_, enabled_;
  bool silent_when_short_;  // a bar off a terminal: no line for a job shorter than ten seconds
  int step_;                // percent between two lines
  int last_percent_ = -1;
  long first_ = 0;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now(), shown_ = started_;
};

}  // namespace crux::cli

#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal so that logs and
// pipelines stay quiet.

#include <unistd.h>

#include <cstdio>
#include <string>

namespace crux::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, long total) : label_(std::move(label)), total_(total), enabled_(::isatty(2) == 1) {}
  ~ProgressBar() { finish(); }

  void update(long done) {
    if (!enabled_ || total_ <= 0) return;
    const int percent = static_cast<int>(100 * done / total_);
    if (percent == last_percent_) return;
    last_percent_ = percent;
    constexpr int width = 40;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "\r%s [%s%s] %3d%% (%ld/%ld)", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), percent, done, total_);
    std::fflush(stderr);
  }

  void finish() {
    if (enabled_ && last_percent_ >= 0) std::fputc('\n', stderr);
    enabled_ = false;
  }

 private:
  std::string label_;
  long total_;
  bool enabled_;
  int last_percent_ = -1;
};

}  // namespace crux::cli

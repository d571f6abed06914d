#include "cli/progress_bar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "support/output_text.hpp"
#include "support/test_models.hpp"

namespace crux::cli {
namespace {

// What a ProgressBar writes into a file (never a terminal) for a job of 20 steps.
std::string written(const std::string& name, ProgressDisplay display, double line_seconds, bool timed_lines = false) {
  const auto path = testing::temporary_path(name);
  std::FILE* sink = std::fopen(path.string().c_str(), "w");
  {
    ProgressBar progress("train", 20, display, timed_lines, sink, line_seconds);
    for (long done = 1; done <= 20; ++done) progress.update(done);
  }
  std::fclose(sink);
  return testing::read_output_text(path);
}

long lines_of(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(ProgressBar, OffATerminalABarWritesATimedLineAndNothingForAShortJob) {
  // A job shorter than the line interval: nothing, so that scripts see a clean stderr.
  EXPECT_EQ(written("progress-short", ProgressDisplay::Bar, 1e9), "");
  // A job longer than it (an interval of 0 makes every step "ten seconds later"): a line
  // per step with its rate and the time left, the last at 100 %.
  const std::string long_job = written("progress-long", ProgressDisplay::Bar, 0.0);
  EXPECT_EQ(lines_of(long_job), 20) << long_job;
  EXPECT_EQ(long_job.rfind("train [##", 0), 0u) << long_job;
  EXPECT_NE(long_job.find("100% (20/20, "), std::string::npos) << long_job;
  EXPECT_NE(long_job.find(" left)\n"), std::string::npos) << long_job;
  EXPECT_EQ(long_job.find('\r'), std::string::npos) << "redrawing is for terminals";
}

TEST(ProgressBar, LinesWriteEveryTenPercentAndNoneNothing) {
  const std::string lines = written("progress-lines", ProgressDisplay::Lines, 1e9);
  EXPECT_EQ(lines_of(lines), 11) << "the first step, then every 10 %: " << lines;
  EXPECT_NE(lines.find("train [########################################] 100% (20/20)\n"), std::string::npos) << lines;
  EXPECT_EQ(written("progress-none", ProgressDisplay::None, 0.0), "");
  // A sweep's lines are timed: with a long interval, only its last.
  const std::string sweep = written("progress-sweep-lines", ProgressDisplay::Lines, 1e9, true);
  EXPECT_EQ(lines_of(sweep), 1) << sweep;
}

}  // namespace
}  // namespace crux::cli

#include "jobs/paper_job.hpp"

#include <gtest/gtest.h>

#include "support/sweep_cells.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// The job's summary is the folder's, and with no folder it runs the same experiment.
TEST(PaperJob, WritesTheExperimentFolderOrOnlyReturnsItsSummary) {
  const fs::path folder = testing::sweep_scratch("paper-job");
  PaperJob job{testing::small_sweep_config(1, 300), {}, folder, false};
  int progress_calls = 0;
  const PaperJobOutcome written = run_paper_job(job, {"a test", [&](int) { ++progress_calls; }, {}, {}});
  EXPECT_EQ(progress_calls, 3) << "one per run: training, transfer and control";
  EXPECT_TRUE(fs::exists(folder / "summary.json"));
  EXPECT_TRUE(fs::exists(folder / "runs/transfer_0/iterations.csv"));
  EXPECT_EQ(written.summary.at("provenance").at("produced_by"), "a test");
  job.output.reset();
  EXPECT_EQ(run_paper_job(job, {"a test", {}, {}, {}}).summary, written.summary);
}

}  // namespace
}  // namespace crux

#include "reports/report_figures.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "outputs/run_config_file.hpp"
#include "support/test_models.hpp"
#include "support/trained_run.hpp"

namespace crux {
namespace {

// A run folder has no paper figures: its report shows Fig. 1 at its wall's start.
TEST(ReportFigures, ARunFolderHasFigOneOnly) {
  RunFolder run = locate_run_folder(testing::trained_run_folder());
  const auto figures = report_figures({}, testing::human_model(), run,
                                      read_run_config(run.config_file).settings.learning.climbing.reachability);
  ASSERT_EQ(figures.size(), 1u);
  EXPECT_NE(figures[0].title.find("Fig. 1"), std::string::npos) << figures[0].title;
  EXPECT_NE(figures[0].svg.find("<svg"), std::string::npos);
}

TEST(ReportFigures, OnlyAPaperFolderHasPaperFiguresToWrite) {
  try {
    write_paper_figure_files(testing::trained_run_folder());
    FAIL() << "wrote paper figures into a run folder";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("not a crux paper folder"), std::string::npos) << e.what();
  }
}

TEST(ReportFigures, TheFilesWrittenAreListed) {
  const std::vector<std::filesystem::path> written{"p/figures/a.svg", "p/figures/b.svg"};
  EXPECT_EQ(figure_files_json(written)["figures"], nlohmann::ordered_json({"p/figures/a.svg", "p/figures/b.svg"}));
  EXPECT_EQ(figure_files_text(written), "wrote p/figures/a.svg\nwrote p/figures/b.svg\n");
}

}  // namespace
}  // namespace crux

#include "outputs/paper_figure_data.hpp"

#include <fmt/format.h>

#include "outputs/iterations_file.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/summary_file.hpp"

namespace crux {

PaperFigureData read_paper_figure_data(const std::filesystem::path& folder) {
  PaperFigureData data;
  data.grid = read_run_config(folder / "config.toml").settings.learning.climbing.grid;
  read_paper_summary(folder, data);
  for (PaperConditionData& condition : data.conditions) {
    for (std::size_t i = 0; i < condition.runs.size(); ++i) {
      const std::filesystem::path file =
          folder / "runs" / fmt::format("{}_{}", condition_name(condition.condition), i) / "iterations.csv";
      for (const RunStep& step : read_iterations_file(file, data.iterations))
        condition.runs[i].regimes.push_back(step.regime);
    }
  }
  return data;
}

}  // namespace crux

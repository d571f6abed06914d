#include "outputs/iterations_file.hpp"

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "common/csv_rows.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"

namespace crux {
namespace {

Regime iteration_regime(std::string_view name, const std::string& file, std::size_t line) {
  if (const auto regime = parse_enum<Regime>(name)) return *regime;
  throw InputError(file, fmt::format("line {}: unknown regime '{}'", line, printable(name.substr(0, 40))));
}

}  // namespace

std::vector<RunStep> read_iterations_file(const std::filesystem::path& path, int recorded_iterations,
                                          PhysicsModel model) {
  const std::string file = path.string();
  const std::string text = read_input_file(file, "iterations file");
  // The run's config says which header: a static or dynamic run's falls are what its replays show.
  const bool with_falls = checks_stances(model);
  const std::vector<std::string_view> rows =
      csv_rows(text, file, with_falls ? kIterationsHeaderWithFalls : kIterationsHeader);
  std::vector<RunStep> steps;
  steps.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t line = csv_line_number(i);
    const std::vector<std::string_view> cells = csv_cells(rows[i], i, with_falls ? 8 : 7, file);
    if (cells[4] != "0" && cells[4] != "1") {
      throw InputError(file, fmt::format("line {}: success must be 0 or 1", line));
    }
    if (with_falls && cells[7] != "0" && cells[7] != "1") {
      throw InputError(file, fmt::format("line {}: fell must be 0 or 1", line));
    }
    if (with_falls && cells[7] == "1" && cells[4] == "1") {
      throw InputError(file, fmt::format("line {}: a reached move cannot fall", line));
    }
    const RunStep step{csv_integer(cells[0], file, line),
                       csv_integer(cells[1], file, line),
                       iteration_regime(cells[2], file, line),
                       csv_integer(cells[3], file, line),
                       cells[4] == "1",
                       csv_number(cells[5], file, line),
                       csv_number(cells[6], file, line),
                       with_falls && cells[7] == "1"};
    if (step.iteration != static_cast<int>(i) + 1) {
      throw InputError(file, fmt::format("line {}: iteration {} where {} was due", line, step.iteration, i + 1));
    }
    if (step.episode < 0) throw InputError(file, fmt::format("line {}: episodes count from 0", line));
    const int previous_episode = steps.empty() ? 0 : steps.back().episode;
    if (step.episode != previous_episode && step.episode != previous_episode + 1) {
      throw InputError(file, fmt::format("line {}: episode {} after episode {}", line, step.episode, previous_episode));
    }
    steps.push_back(step);
  }
  if (steps.size() != static_cast<std::size_t>(recorded_iterations)) {
    throw InputError(file, fmt::format("has {} iterations, but summary.json records {}: the file was cut short or "
                                       "belongs to another run",
                                       steps.size(), recorded_iterations));
  }
  return steps;
}

}  // namespace crux

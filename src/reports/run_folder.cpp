#include "reports/run_folder.hpp"

#include <charconv>
#include <regex>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> cells;
  for (std::size_t start = 0;;) {
    const std::size_t end = line.find(separator, start);
    cells.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return cells;
    start = end + 1;
  }
}

// The lines of a CSV file after its header, which must be `header`.
std::vector<std::string_view> csv_rows(const std::string& text, const fs::path& file, const std::string& header) {
  std::vector<std::string_view> lines = split(text, '\n');
  if (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty() || lines.front() != header) {
    throw InputError(file.string(), fmt::format("the first line must be the header '{}'", header.substr(0, 200)));
  }
  lines.erase(lines.begin());
  return lines;
}

template <typename T>
T number(std::string_view cell, const fs::path& file, std::size_t line) {
  T value{};
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size() || cell.empty()) {
    throw InputError(file.string(), fmt::format("line {}: '{}' is not a number", line, cell.substr(0, 40)));
  }
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) throw InputError(file.string(), fmt::format("line {}: '{}' is not finite", line, cell));
  }
  return value;
}

// runs/<condition>_<i> of a crux paper folder.
const std::regex& run_name_pattern() {
  static const std::regex pattern("(training|transfer|control)_([0-9]{1,9})");
  return pattern;
}

Regime regime_of(std::string_view name, const fs::path& file, std::size_t line) {
  for (int r = 0; r < kRegimeCount; ++r) {
    if (name == regime_name(static_cast<Regime>(r))) return static_cast<Regime>(r);
  }
  throw InputError(file.string(), fmt::format("line {}: unknown regime '{}'", line, name.substr(0, 40)));
}

}  // namespace

nlohmann::json read_summary(const fs::path& folder) {
  const fs::path file = folder / "summary.json";
  const std::string text = read_input_file(file.string(), "summary file");
  nlohmann::json summary = nlohmann::json::parse(text, nullptr, false);
  if (summary.is_discarded() || !summary.is_object() || summary.value("format", "") != "crux-summary") {
    throw InputError(file.string(), "not a crux summary (format \"crux-summary\")");
  }
  if (summary.value("version", 0) != 3) {
    throw InputError(file.string(), "summary version 3 is the one this crux reads; write the folder again");
  }
  return summary;
}

std::string climb_description(const RecordedClimb& climb) {
  return climb.kind == "greedy" ? std::string("the greedy policy's climb after learning")
                                : fmt::format("the climb of episode {}{}", climb.episode + 1,  // from 1, as in Fig. 4
                                              climb.finished ? "" : " (unfinished)");
}

const RecordedClimb& chosen_climb(const RunFolder& folder, std::string_view kind) {
  return kind == "greedy" && !folder.greedy.postures.empty() ? folder.greedy : folder.last;
}

RunFolder locate_run_folder(const fs::path& directory) {
  RunFolder folder;
  folder.directory = fs::absolute(directory).lexically_normal();
  if (!folder.directory.has_filename()) folder.directory = folder.directory.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder.directory, error)) throw InputError(directory.string(), "no such run folder");
  folder.name = folder.directory.filename().string();
  if (fs::exists(folder.directory / "wall.json", error)) {
    folder.wall_file = folder.directory / "wall.json";
    folder.summary_file = folder.directory / "summary.json";
    folder.config_file = folder.directory / "config.toml";
  } else {
    std::smatch match;
    const fs::path experiment = folder.directory.parent_path().parent_path();
    if (!std::regex_match(folder.name, match, run_name_pattern()) || folder.directory.parent_path().filename() != "runs") {
      throw InputError(directory.string(),
                       "not a run folder: it holds no wall.json (crux train, crux transfer) and is not "
                       "runs/<condition>_<i> of a crux paper folder");
    }
    folder.summary_file = experiment / "summary.json";
    folder.config_file = experiment / "config.toml";
    folder.summary = read_summary(experiment);
    const auto seeds = folder.summary.find("seeds_per_wall");
    if (seeds == folder.summary.end() || !seeds->is_number_unsigned() || seeds->get<std::uint64_t>() < 1 ||
        seeds->get<std::uint64_t>() > 1'000'000) {
      throw InputError(folder.summary_file.string(), "seeds_per_wall must be an integer from 1 to 1000000");
    }
    const int run = std::stoi(match[2]);
    folder.wall_file = experiment / "walls" /
                       fmt::format("{}_{}.json", match[1] == "training" ? "training" : "transfer",
                                   run / seeds->get<int>());
  }
  if (folder.summary.is_null()) folder.summary = read_summary(folder.directory);
  const nlohmann::json& summary = folder.summary;
  if (const auto provenance = summary.find("provenance"); provenance != summary.end() && provenance->is_object()) {
    if (const auto urdf = provenance->find("urdf"); urdf != provenance->end() && urdf->is_string()) {
      folder.urdf = urdf->get<std::string>();
    }
  }
  folder.wall = load_wall(folder.wall_file.string());
  return folder;
}

ExperimentConfig read_run_config(const RunFolder& folder) {
  static const ParameterSet kEveryKey{{"experiment", "learning", "reward", "ik", "compare", "filter", "grid", "wall"},
                                      {}};
  ExperimentConfig config;
  const std::string file = folder.config_file.string();
  const ConfigLines lines = apply_config_file(file, config, kEveryKey, "the run's config");
  try {
    finalize_config(config);
  } catch (const InputError& e) {
    const auto line = lines.find(e.source());
    throw InputError(line == lines.end() ? file : fmt::format("{}: line {}: {}", file, line->second, e.source()),
                     e.problem());
  }
  return config;
}

ReportedRun locate_reported_run(const fs::path& folder, const std::string& run_name, const std::string& flag) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) throw InputError(folder.string(), "no such output folder");
  ReportedRun out;
  out.experiment = !fs::exists(folder / "wall.json", error) && fs::exists(folder / "summary.json", error);
  if (!out.experiment) {
    if (!fs::exists(folder / "wall.json", error)) {
      throw InputError(folder.string(), fmt::format("not an output folder of crux paper, train or transfer (for one "
                                                    "run of a crux paper folder, give the paper folder and {} "
                                                    "<condition>_<i>)",
                                                    flag));
    }
    out.run_directory = folder;
    return out;
  }
  if (!std::regex_match(run_name, run_name_pattern())) {
    throw InputError(flag, fmt::format("'{}' is not a run name: <condition>_<i>, condition training, transfer or "
                                       "control",
                                       run_name.substr(0, 200)));
  }
  out.run_directory = folder / "runs" / run_name;
  if (!fs::is_directory(out.run_directory, error)) {
    throw InputError(flag, fmt::format("'{}' is not a run of {}", run_name, folder.string()));
  }
  return out;
}

namespace {

// The postures of a climb file: `columns` before the joints, returned as text.
std::vector<Posture> read_postures(const fs::path& file, const BodyModel& model, const std::vector<std::string>& columns,
                                   std::vector<std::vector<std::string_view>>& cells, std::string& text) {
  text = read_input_file(file.string(), "climb file");
  std::string header = "step";
  for (const std::string& column : columns) header += "," + column;
  for (const BodyJoint& joint : model.joints) header += "," + joint.name;
  const std::vector<std::string_view> rows = csv_rows(text, file, header);
  std::vector<Posture> postures;
  const std::size_t first = 1 + columns.size();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<std::string_view> row = split(rows[i], ',');
    if (row.size() != first + kConfigurationDof) {
      throw InputError(file.string(), fmt::format("line {}: expected {} columns", i + 2, first + kConfigurationDof));
    }
    Posture posture;
    for (int k = 0; k < kConfigurationDof; ++k) posture[k] = number<double>(row[first + k], file, i + 2);
    // A climb stays near its wall and within the joints' limits; anything else is not a
    // posture crux wrote (and would give the drawings absurd extents).
    constexpr double kRootLimit = 1000, kAngleSlack = 1e-6;
    for (int k = 0; k < kConfigurationDof; ++k) {
      const bool root = k < kRootDof;
      if (root ? std::abs(posture[k]) > kRootLimit
               : posture[k] < model.lower_limits[k] - kAngleSlack || posture[k] > model.upper_limits[k] + kAngleSlack) {
        throw InputError(file.string(), fmt::format("line {}: {} = {} is outside {}", i + 2, model.joints[k].name,
                                                    posture[k], root ? "[-1000, 1000] m" : "the joint's limits"));
      }
    }
    postures.push_back(posture);
    row.resize(first);
    cells.push_back(std::move(row));
  }
  return postures;
}

}  // namespace

std::vector<int> read_episode_lengths(const fs::path& directory) {
  const fs::path episodes_file = directory / "episodes.csv";
  const std::string episodes_text = read_input_file(episodes_file.string(), "episodes file");
  const std::vector<std::string_view> rows = csv_rows(episodes_text, episodes_file, "episode,length");
  std::vector<int> lengths;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<std::string_view> cells = split(rows[i], ',');
    if (cells.size() != 2) throw InputError(episodes_file.string(), fmt::format("line {}: expected 2 columns", i + 2));
    if (number<int>(cells[0], episodes_file, i + 2) != static_cast<int>(i)) {
      throw InputError(episodes_file.string(), fmt::format("line {}: episode {} was due", i + 2, i));
    }
    lengths.push_back(number<int>(cells[1], episodes_file, i + 2));
    if (lengths.back() <= 0) throw InputError(episodes_file.string(), fmt::format("line {}: length must be positive", i + 2));
  }
  return lengths;
}

std::vector<RunStep> read_run_steps(const fs::path& directory) {
  const fs::path iterations_file = directory / "iterations.csv";
  const std::string iterations_text = read_input_file(iterations_file.string(), "iterations file");
  const std::vector<std::string_view> rows =
      csv_rows(iterations_text, iterations_file, "iteration,episode,regime,hold,success,root_rise_cm,reward");
  std::vector<RunStep> steps;
  steps.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t line = i + 2;
    const std::vector<std::string_view> cells = split(rows[i], ',');
    if (cells.size() != 7) throw InputError(iterations_file.string(), fmt::format("line {}: expected 7 columns", line));
    // Every row is checked, not only the climb's: a file crux did not write is refused whole.
    if (cells[4] != "0" && cells[4] != "1") {
      throw InputError(iterations_file.string(), fmt::format("line {}: success must be 0 or 1", line));
    }
    const RunStep step{number<int>(cells[0], iterations_file, line), number<int>(cells[1], iterations_file, line),
                       regime_of(cells[2], iterations_file, line),   number<int>(cells[3], iterations_file, line),
                       cells[4] == "1",                              number<double>(cells[5], iterations_file, line),
                       number<double>(cells[6], iterations_file, line)};
    if (step.episode < 0) throw InputError(iterations_file.string(), fmt::format("line {}: episodes count from 0", line));
    if (step.iteration != static_cast<int>(i) + 1) {
      throw InputError(iterations_file.string(), fmt::format("line {}: iteration {} where {} was due", line,
                                                             step.iteration, i + 1));
    }
    const int previous_episode = steps.empty() ? 0 : steps.back().episode;
    if (step.episode != previous_episode && step.episode != previous_episode + 1) {
      throw InputError(iterations_file.string(), fmt::format("line {}: episode {} after episode {}", line,
                                                             step.episode, previous_episode));
    }
    steps.push_back(step);
  }
  return steps;
}

void read_run_climb(RunFolder& folder, const BodyModel& model) {
  const std::vector<int> episodes = read_episode_lengths(folder.directory);
  RecordedClimb& last = folder.last;
  last = {"last", -1, true, {}, {}};
  if (!episodes.empty()) last.episode = static_cast<int>(episodes.size()) - 1;
  folder.steps = read_run_steps(folder.directory);
  std::size_t reached = 0;
  for (const RunStep& step : folder.steps) {
    if (step.episode != last.episode) continue;
    last.steps.push_back(step);
    reached += step.success ? 1 : 0;
  }

  const fs::path climb_file = folder.directory / "climb.csv";
  std::string climb_text;
  std::vector<std::vector<std::string_view>> unused;
  last.postures = read_postures(climb_file, model, {}, unused, climb_text);
  if (last.postures.size() != (last.episode >= 0 ? reached + 1 : 0)) {
    throw InputError(climb_file.string(),
                     fmt::format("holds {} postures, but episode {} in iterations.csv reaches {} holds (expected the "
                                 "start and one posture per reached hold; a folder of crux 0.1 before the replay "
                                 "lacks the finishing posture: run it again)",
                                 last.postures.size(), last.episode, reached));
  }

  const fs::path greedy_file = folder.directory / "greedy_climb.csv";
  std::string greedy_text;
  std::vector<std::vector<std::string_view>> cells;
  RecordedClimb& greedy = folder.greedy;
  greedy = {"greedy", -1, true, {}, {}};
  greedy.postures = read_postures(greedy_file, model, {"hold", "reward"}, cells, greedy_text);
  for (std::size_t i = 1; i < greedy.postures.size(); ++i) {
    const double rise_cm = 100 * (greedy.postures[i][2] - greedy.postures[i - 1][2]);
    greedy.steps.push_back({0, -1, Regime::WGreedy, number<int>(cells[i][1], greedy_file, i + 2), true, rise_cm,
                            number<double>(cells[i][2], greedy_file, i + 2)});
  }
}

}  // namespace crux

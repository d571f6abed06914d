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

Regime regime_of(std::string_view name, const fs::path& file, std::size_t line) {
  for (int r = 0; r < kRegimeCount; ++r) {
    if (name == regime_name(static_cast<Regime>(r))) return static_cast<Regime>(r);
  }
  throw InputError(file.string(), fmt::format("line {}: unknown regime '{}'", line, name.substr(0, 40)));
}

nlohmann::json read_json(const fs::path& file) {
  const std::string text = read_input_file(file.string(), "summary file");
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw InputError(file.string(), "not a JSON object");
  return json;
}

}  // namespace

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
  } else {
    static const std::regex run_name("(training|transfer|control)_([0-9]{1,9})");
    std::smatch match;
    const fs::path experiment = folder.directory.parent_path().parent_path();
    if (!std::regex_match(folder.name, match, run_name) || folder.directory.parent_path().filename() != "runs") {
      throw InputError(directory.string(),
                       "not a run folder: it holds no wall.json (crux train, crux transfer) and is not "
                       "runs/<condition>_<i> of a crux paper folder");
    }
    folder.summary_file = experiment / "summary.json";
    const nlohmann::json summary = read_json(folder.summary_file);
    const auto seeds = summary.find("seeds_per_wall");
    if (seeds == summary.end() || !seeds->is_number_unsigned() || seeds->get<int>() < 1) {
      throw InputError(folder.summary_file.string(), "seeds_per_wall must be a positive integer");
    }
    const int run = std::stoi(match[2]);
    folder.wall_file = experiment / "walls" /
                       fmt::format("{}_{}.json", match[1] == "training" ? "training" : "transfer", run / seeds->get<int>());
  }
  const nlohmann::json summary = read_json(folder.summary_file);
  if (const auto provenance = summary.find("provenance"); provenance != summary.end() && provenance->is_object()) {
    if (const auto urdf = provenance->find("urdf"); urdf != provenance->end() && urdf->is_string()) {
      folder.urdf = urdf->get<std::string>();
    }
  }
  folder.wall = load_wall(folder.wall_file.string());
  return folder;
}

void read_run_climb(RunFolder& folder, const BodyModel& model) {
  const fs::path episodes_file = folder.directory / "episodes.csv";
  const std::string episodes_text = read_input_file(episodes_file.string(), "episodes file");
  const std::vector<std::string_view> episodes = csv_rows(episodes_text, episodes_file, "episode,length");
  folder.climb_episode = -1;
  if (!episodes.empty()) {
    folder.climb_episode = number<int>(split(episodes.back(), ',').front(), episodes_file, episodes.size() + 1);
  }

  const fs::path iterations_file = folder.directory / "iterations.csv";
  const std::string iterations_text = read_input_file(iterations_file.string(), "iterations file");
  const std::vector<std::string_view> rows =
      csv_rows(iterations_text, iterations_file, "iteration,episode,regime,hold,success,root_rise_cm,reward");
  folder.climb_steps.clear();
  std::size_t reached = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t line = i + 2;
    const std::vector<std::string_view> cells = split(rows[i], ',');
    if (cells.size() != 7) throw InputError(iterations_file.string(), fmt::format("line {}: expected 7 columns", line));
    const int episode = number<int>(cells[1], iterations_file, line);
    if (episode != folder.climb_episode) continue;
    RunStep step{number<int>(cells[0], iterations_file, line), episode, regime_of(cells[2], iterations_file, line),
                 number<int>(cells[3], iterations_file, line), cells[4] == "1",
                 number<double>(cells[5], iterations_file, line), number<double>(cells[6], iterations_file, line)};
    reached += step.success ? 1 : 0;
    folder.climb_steps.push_back(step);
  }

  const fs::path climb_file = folder.directory / "climb.csv";
  const std::string climb_text = read_input_file(climb_file.string(), "climb file");
  std::string header = "step";
  for (const BodyJoint& joint : model.joints) header += "," + joint.name;
  const std::vector<std::string_view> climb = csv_rows(climb_text, climb_file, header);
  folder.climb.clear();
  for (std::size_t i = 0; i < climb.size(); ++i) {
    const std::vector<std::string_view> cells = split(climb[i], ',');
    if (cells.size() != 1 + kConfigurationDof) {
      throw InputError(climb_file.string(), fmt::format("line {}: expected {} columns", i + 2, 1 + kConfigurationDof));
    }
    Posture posture;
    for (int k = 0; k < kConfigurationDof; ++k) posture[k] = number<double>(cells[1 + k], climb_file, i + 2);
    folder.climb.push_back(posture);
  }
  if (folder.climb_episode >= 0 && folder.climb.size() != reached + 1) {
    throw InputError(climb_file.string(),
                     fmt::format("holds {} postures, but episode {} in iterations.csv reaches {} holds (expected the "
                                 "start and one posture per reached hold; a folder of crux 0.1 before the replay "
                                 "lacks the finishing posture: run it again)",
                                 folder.climb.size(), folder.climb_episode, reached));
  }
}

}  // namespace crux

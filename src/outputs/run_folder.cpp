#include "outputs/run_folder.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <regex>
#include <set>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "common/counted.hpp"
#include "common/csv_rows.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"
#include "experiments/paper_experiment.hpp"
#include "outputs/run_config_file.hpp"
#include "outputs/summary_file.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// runs/<condition>_<i> of a crux paper folder.
const std::regex& run_name_pattern() {
  static const std::regex pattern("(training|transfer|control)_([0-9]{1,9})");
  return pattern;
}

// The runs of a crux paper folder, each condition's consecutive runs as one range:
// "training_0..training_3, transfer_0..transfer_3, control_0, control_2".
std::string paper_run_names(const fs::path& folder) {
  std::map<std::string, std::set<int>> runs;  // condition -> run indices
  std::error_code error;
  for (fs::directory_iterator entry(folder / "runs", error), end; !error && entry != end; entry.increment(error)) {
    std::smatch match;
    const std::string name = entry->path().filename().string();
    if (std::regex_match(name, match, run_name_pattern()) && entry->is_directory(error)) {
      runs[match[1]].insert(std::stoi(match[2]));
    }
  }
  std::vector<std::string> ranges;
  for (const Condition c : kConditions) {
    const char* condition = enum_name(c);
    const std::set<int>& indices = runs[condition];
    for (auto first = indices.begin(); first != indices.end();) {
      auto last = first;
      while (std::next(last) != indices.end() && *std::next(last) == *last + 1) ++last;
      ranges.push_back(last == first ? fmt::format("{}_{}", condition, *first)
                                     : fmt::format("{0}_{1}..{0}_{2}", condition, *first, *last));
      first = std::next(last);
    }
  }
  return ranges.empty() ? std::string("no runs") : fmt::format("{}", fmt::join(ranges, ", "));
}

}  // namespace

std::string climb_description(const RecordedClimb& climb) {
  return climb.kind == "greedy"
             ? std::string("the greedy policy's climb after learning")
             : fmt::format("the climb of episode {}{}{}", climb.episode + 1,  // from 1, as in Fig. 4
                           climb.attempt > 1 ? fmt::format(", attempt {} (after {} back to the start)", climb.attempt,
                                                           counted(climb.attempt - 1, "fall"))
                                             : "",
                           climb.finished ? "" : " (unfinished)");
}

const RecordedClimb& chosen_climb(const RunFolder& folder, std::string_view kind) {
  return kind == "greedy" && !folder.greedy.postures.empty() ? folder.greedy : folder.last;
}

RunFolder locate_run_folder(const fs::path& directory) {
  RunFolder folder;
  OrderedJson summary;
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
    if (!std::regex_match(folder.name, match, run_name_pattern()) ||
        folder.directory.parent_path().filename() != "runs") {
      throw InputError(directory.string(),
                       "not a run folder: it holds no wall.json (crux train, crux transfer) and is not "
                       "runs/<condition>_<i> of a crux paper folder");
    }
    folder.summary_file = experiment / "summary.json";
    folder.config_file = experiment / "config.toml";
    summary = read_summary(experiment);
    const int run = std::stoi(match[2]);
    folder.wall_file = experiment / "walls" /
                       fmt::format("{}_{}.json", match[1] == "training" ? "training" : "transfer",
                                   run / summary_seeds_per_wall(summary, folder.summary_file.string()));
  }
  if (summary.is_null()) summary = read_summary(folder.directory);
  folder.urdf = summary_urdf(summary);
  folder.iterations = summary_iterations(summary, folder.summary_file.string());
  folder.summary = nlohmann::json(summary);
  folder.wall = load_wall(folder.wall_file.string());
  return folder;
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
                                       printable(run_name.substr(0, 200))));
  }
  out.run_directory = folder / "runs" / run_name;
  if (!fs::is_directory(out.run_directory, error)) {
    throw InputError(flag, fmt::format("'{}' is not a run of {}; it has {}", printable(run_name), folder.string(),
                                       paper_run_names(folder)));
  }
  return out;
}

namespace {

// The postures of a climb file: `columns` before the joints, returned as text.
std::vector<Posture> read_postures(const fs::path& file, const BodyModel& model,
                                   const std::vector<std::string>& columns,
                                   std::vector<std::vector<std::string_view>>& cells, std::string& text) {
  text = read_input_file(file.string(), "climb file");
  std::string header = "step";
  for (const std::string& column : columns) header += "," + column;
  for (const BodyJoint& joint : model.joints) header += "," + joint.name;
  const std::vector<std::string_view> rows = csv_rows(text, file.string(), header);
  std::vector<Posture> postures;
  const std::size_t first = 1 + columns.size();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<std::string_view> row = csv_cells(rows[i], i, first + kConfigurationDof, file.string());
    Posture posture;
    for (int k = 0; k < kConfigurationDof; ++k) posture[k] = csv_number(row[first + k], file.string(), i + 2);
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
  const std::vector<std::string_view> rows = csv_rows(episodes_text, episodes_file.string(), "episode,length");
  std::vector<int> lengths;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<std::string_view> cells = csv_cells(rows[i], i, 2, episodes_file.string());
    if (csv_integer(cells[0], episodes_file.string(), i + 2) != static_cast<int>(i)) {
      throw InputError(episodes_file.string(), fmt::format("line {}: episode {} was due", i + 2, i));
    }
    lengths.push_back(csv_integer(cells[1], episodes_file.string(), i + 2));
    if (lengths.back() <= 0)
      throw InputError(episodes_file.string(), fmt::format("line {}: length must be positive", i + 2));
  }
  return lengths;
}

void read_run_climb(RunFolder& folder, const BodyModel& model) {
  const std::vector<int> episodes = read_episode_lengths(folder.directory);
  RecordedClimb& last = folder.last;
  last = {"last", -1, true, {}, {}};
  if (!episodes.empty()) last.episode = static_cast<int>(episodes.size()) - 1;
  folder.steps = read_iterations_file(folder.directory / "iterations.csv", folder.iterations,
                                      read_run_config(folder.config_file).settings.learning.climbing.physics.model);
  for (const RunStep& step : folder.steps) {
    if (step.episode != last.episode) continue;
    last.steps.push_back(step);
    if (step.fell) last.start_again();  // climb.csv holds the episode's last attempt
  }
  const auto reached = static_cast<std::size_t>(
      std::count_if(last.steps.begin(), last.steps.end(), [](const RunStep& step) { return step.success; }));

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
    greedy.steps.push_back({0, -1, Regime::WGreedy, csv_integer(cells[i][1], greedy_file.string(), i + 2), true,
                            rise_cm, csv_number(cells[i][2], greedy_file.string(), i + 2)});
  }
}

RecordedClimb climb_to_show(const RunFolder& folder, const BodyModel& model, const ClimbingParameters& parameters,
                            const std::string& choice, const std::string& flag) {
  if (choice == "greedy" || choice == "last") return chosen_climb(folder, choice);
  int number = 0;
  const auto [end, error] = std::from_chars(choice.data(), choice.data() + choice.size(), number);
  if (error != std::errc() || end != choice.data() + choice.size() || choice.empty()) {
    throw InputError(flag, fmt::format("expected greedy, last or an episode number (from 1), got '{}'",
                                       printable(choice.substr(0, 40))));
  }
  if (number < 1) throw InputError(flag, fmt::format("episodes are numbered from 1, not {}", number));
  return replay_episode(model, folder.wall, parameters, folder.steps, number - 1,
                        (folder.directory / "iterations.csv").string(), flag);
}

namespace {

// shown_climb_reason's words for the choice, whatever the attempt.
std::string chosen_climb_reason(const RunFolder& folder, const RecordedClimb& shown, const std::string& choice,
                                int greedy_cap, const std::string& flag) {
  const std::string last = fmt::format("the last completed episode (episode {})", folder.last.episode + 1);
  if (shown.kind == "greedy") {
    return fmt::format("the greedy policy's climb after learning, which reaches the top in {}",
                       counted(shown.steps.size(), "action"));
  }
  if (choice == "greedy") {
    const std::string unfinished = fmt::format(
        "the greedy policy did not reach the top within {} (experiment.greedy_cap)", counted(greedy_cap, "action"));
    return shown.postures.empty() ? unfinished + " and the run completed no episode"
                                  : fmt::format("{}, since {}", last, unfinished);
  }
  if (choice == "last") {
    return shown.postures.empty() ? std::string("the run completed no episode")
                                  : fmt::format("{}, as {} last asks", last, flag);
  }
  return fmt::format("episode {}, as {} {} asks{}", shown.episode + 1, flag, choice,
                     shown.finished ? "" : "; the run ended during it, so it does not reach the top");
}

}  // namespace

std::string shown_climb_reason(const RunFolder& folder, const RecordedClimb& shown, const std::string& choice,
                               int greedy_cap, const std::string& flag) {
  const std::string reason = chosen_climb_reason(folder, shown, choice, greedy_cap, flag);
  if (shown.attempt == 1) return reason;
  return fmt::format("{}; it shows the episode's last attempt, attempt {}, after {} back to the start", reason,
                     shown.attempt, counted(shown.attempt - 1, "fall"));
}

}  // namespace crux

#include "reports/report_page.hpp"

#include <cmath>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"
#include "common/counted.hpp"
#include "experiments/episode_replay.hpp"
#include "reports/replay_data.hpp"
#include "reports/report_figures.hpp"
#include "reports/view_description.hpp"
#include "views/effort_plot.hpp"

namespace crux {

EffortAlongClimb effort_along_climb(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                    const PhysicsParameters& physics, const std::string& title) {
  StanceCheck check(model, wall, physics);
  EffortAlongClimb efforts{fmt::format("Effort along the climb: {}", title), {}, {}};
  const std::vector<HoldConfiguration> configurations = climb_configurations(wall, climb);
  for (std::size_t k = 0; k < climb.postures.size(); ++k) {
    const HoldConfiguration& configuration = configurations[k];
    // Posture k was reached by the k-th move, of the limb (k - 1) mod 4 in the cycle, so the
    // next to let go is k mod 4; the start's is the right hand.
    const Limb next = static_cast<Limb>(k % kLimbCount);
    efforts.on_four_holds.push_back(check.solve(climb.postures[k], configuration).effort);
    efforts.on_three_holds.push_back(check.solve(climb.postures[k], configuration.with(next, kFree)).effort);
  }
  return efforts;
}

ReportPage report_page(const std::filesystem::path& folder, const ReportedRun& reported, RunFolder& run,
                       const BodyModel& model, const ExperimentConfig& recorded, const std::string& climb_choice,
                       int replay_moves) {
  namespace fs = std::filesystem;
  const ClimbingParameters& climbing = recorded.settings.learning.climbing;
  ReportPage page;
  page.summary = std::move(run.summary);
  page.title = fmt::format("crux report: {}", fs::absolute(folder).lexically_normal().filename().string());
  page.figures = report_figures(reported.experiment ? folder : fs::path(), model, run, climbing.reachability);
  const RecordedClimb climb = climb_to_show(run, model, climbing, climb_choice, "--climb");
  page.replay_title = fmt::format("{} on '{}': {}", run.name, run.wall.name, climb_description(climb));
  page.replay_climb = climb.kind;
  page.replay_episode = climb.episode;
  page.replay_reason = shown_climb_reason(run, climb, climb_choice, recorded.settings.learning.greedy_cap, "--climb");
  if (climbing.physics.model == PhysicsModel::Static && !climb.postures.empty()) {
    const EffortAlongClimb efforts = effort_along_climb(model, run.wall, climb, climbing.physics, page.replay_title);
    page.stance_effort_four = efforts.on_four_holds;
    page.stance_effort_three = efforts.on_three_holds;
    page.figures.push_back({"Effort along the climb",
                            "The static model's effort of each stance of the replayed climb (the largest joint torque "
                            "over its limit), on its four holds and on the three left when the next limb lets go; "
                            "above 1 the stance could not be held.",
                            render_effort_plot(efforts)});
  }
  BodyData data(model);
  page.climb_postures = climb.postures.size();
  for (std::size_t k = 0; k < climb.postures.size(); ++k) {
    forward_kinematics(model, data, climb.postures[k]);
    const WallPenetration penetration = wall_penetration(model, data);
    if (!penetration.passes_through()) continue;
    ++page.postures_in_wall;
    if (page.deepest_in_wall_posture < 0 || penetration.depth_m > page.deepest_in_wall_m) {
      page.deepest_in_wall_m = penetration.depth_m;
      page.deepest_in_wall = wall_penetration_note(model, penetration);
      page.deepest_in_wall_posture = static_cast<int>(k);
    }
  }
  if (!climb.postures.empty()) {
    ReplayOptions options;
    options.max_moves = replay_moves;
    options.physics = climbing.physics;
    page.replay =
        replay_data(model, run.wall, climb, climbing.reachability, page.replay_title, run.directory.string(), options);
  }
  return page;
}

namespace {

int replay_frames(const ReportPage& page) {
  return page.replay.is_null() ? 0 : page.replay["frames"]["count"].get<int>();
}

std::size_t replay_moves(const ReportPage& page) { return page.replay.is_null() ? 0 : page.replay["moves"].size(); }

std::size_t climb_moves(const ReportPage& page) {
  return page.replay.is_null() ? 0 : page.replay.value("climb_moves", replay_moves(page));
}

}  // namespace

nlohmann::ordered_json written_report_json(const ReportPage& page, const std::string& run_name, const std::string& file,
                                           std::size_t bytes, double seconds) {
  nlohmann::ordered_json out;
  out["report"] = file;
  out["bytes"] = bytes;
  out["figures"] = page.figures.size();
  out["replay_run"] = run_name;
  out["replay_climb"] = page.replay.is_null() ? nlohmann::ordered_json() : nlohmann::ordered_json(page.replay_climb);
  // Episodes are numbered from 1 wherever crux shows one, as in the paper's Fig. 4.
  out["replay_episode"] = page.replay_episode < 0 ? -1 : page.replay_episode + 1;
  out["replay_reason"] = page.replay_reason;
  out["replay_moves"] = replay_moves(page);
  out["climb_moves"] = climb_moves(page);
  out["replay_frames"] = replay_frames(page);
  out["climb_postures"] = page.climb_postures;
  out["postures_in_wall"] = page.postures_in_wall;
  out["deepest_in_wall_m"] =
      page.deepest_in_wall_posture < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(page.deepest_in_wall_m);
  if (!page.stance_effort_four.empty()) {
    // +infinity (no balance) is null in JSON.
    const auto series = [](const std::vector<double>& values) {
      nlohmann::ordered_json out = nlohmann::ordered_json::array();
      for (const double v : values)
        out.push_back(std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json());
      return out;
    };
    out["stance_effort"] = {{"on_four_holds", series(page.stance_effort_four)},
                            {"on_three_holds", series(page.stance_effort_three)}};
  }
  out["seconds"] = seconds;
  return out;
}

std::string written_report_text(const ReportPage& page, const std::string& run_name, const std::string& file,
                                std::size_t bytes, double seconds) {
  const std::string written = fmt::format("wrote {} ({:.1f} MB, {}", file, static_cast<double>(bytes) / 1e6,
                                          counted(page.figures.size(), "figure"));
  if (page.replay.is_null()) {
    return fmt::format("{}, no replay) in {:.2f} s\nno replay: {}\n", written, seconds, page.replay_reason);
  }
  const std::string moves = replay_moves(page) < climb_moves(page)
                                ? fmt::format("the first {} of {} moves", replay_moves(page), climb_moves(page))
                                : counted(replay_moves(page), "move");
  return fmt::format("{}, a replay of {} with {}) in {:.2f} s\nreplayed: {}\n", written, run_name, moves, seconds,
                     page.replay_reason);
}

}  // namespace crux

#include "jobs/report_job.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"
#include "common/counted.hpp"
#include "common/printable.hpp"
#include "experiments/climb_stances.hpp"
#include "experiments/performed_replay.hpp"
#include "outputs/run_folder.hpp"
#include "reports/perform_description.hpp"
#include "reports/replay_data.hpp"
#include "reports/report_figures.hpp"
#include "reports/view_description.hpp"
#include "views/effort_plot.hpp"

namespace crux {

ReportPage report_page(const std::filesystem::path& folder, const ReportedRun& reported, RunFolder& run,
                       const BodyModel& model, const ExperimentConfig& recorded, const std::string& climb_choice,
                       int replay_moves) {
  namespace fs = std::filesystem;
  const ClimbingParameters& climbing = recorded.settings.learning.climbing;
  ReportPage page;
  page.summary = std::move(run.summary);
  page.title = fmt::format("crux report: {}", folder_name(folder));
  page.figures = report_figures(reported.experiment ? folder : fs::path(), model, run, climbing.reachability);
  const RecordedClimb climb = climb_to_show(run, model, climbing, climb_choice, "--climb");
  page.replay_title = fmt::format("{} on '{}': {}", run.name, run.wall.name, climb_description(climb));
  page.replay_climb = climb.kind;
  page.replay_episode = climb.episode;
  page.replay_attempt = climb.attempt;
  page.replay_reason = shown_climb_reason(run, climb, climb_choice, recorded.settings.learning.greedy_cap, "--climb");
  const std::optional<ClimbStances> stances = climb_stances(model, run.wall, climb, climbing.physics);
  if (stances && !climb.postures.empty()) {
    const EffortAlongClimb efforts{fmt::format("Effort along the climb: {}", page.replay_title),
                                   stances->effort_on_four_holds, stances->effort_on_three_holds};
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
    const ClimbReplay replay =
        replay_climb(model, run.wall, climb, climbing.reachability, run.directory.string(), options);
    page.replay = replay_data(model, run.wall, replay, stances ? &*stances : nullptr, page.replay_title);
  }
  return page;
}

std::string folder_name(const std::filesystem::path& folder) {
  std::filesystem::path normal = std::filesystem::absolute(folder).lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();
  return normal.filename().string();
}

namespace {

std::string performed_outcome(const PerformFolder& folder) {
  if (!folder.found) return "No plan was found, so nothing was performed.";
  if (!folder.start_held) {
    return fmt::format("The start stance did not hold still: {}.", failure_words(folder.start_cause));
  }
  const auto performed =
      std::count_if(folder.moves.begin(), folder.moves.end(), [](const AttemptedMove& move) { return move.performed; });
  const std::string effort = fmt::format("largest torque {:.2f} of its limit, {:.1f} s simulated",
                                         folder.max_torque_ratio, folder.simulated_s);
  if (folder.reached_top) {
    return fmt::format("All {} performed, to the top; {}.", counted(folder.planned_moves, "move"), effort);
  }
  if (folder.moves.empty()) return "No move was performed.";
  const AttemptedMove& failed = folder.moves.back();
  return fmt::format("{} of {} performed; move {} ({} to hold {}) failed: {}; {}.", performed,
                     counted(folder.planned_moves, "move"), folder.moves.size(), enum_name(failed.limb),
                     folder.wall.holds[failed.hold].id, failure_words(failed.cause), effort);
}

}  // namespace

PerformedSection performed_section(const PerformFolder& folder, const BodyModel& model, double grasp_radius) {
  PerformedSection section;
  section.title =
      fmt::format("{} under the {} model on '{}'", folder.climb, folder.physics, printable(folder.wall.name));
  section.outcome = performed_outcome(folder);
  section.folder = folder.directory.string();
  for (const AttemptedMove& move : folder.moves) {
    section.moves.push_back({enum_name(move.limb), folder.wall.holds[move.hold].id, move.performed,
                             failure_words(move.cause), move.max_torque_ratio});
  }
  if (!folder.trajectory.empty()) {
    const PerformedReplay replay = replay_performed_climb(model, folder.wall, folder.moves, folder.trajectory,
                                                          (folder.directory / "trajectory.csv").string());
    section.replay =
        performed_replay_data(model, folder.wall, replay, folder.planned_moves, grasp_radius, section.title);
  }
  return section;
}

ReportPage perform_report_page(const PerformFolder& folder, const BodyModel& model, double grasp_radius) {
  ReportPage page;
  page.title = fmt::format("crux report: {}", folder_name(folder.directory));
  page.performed = performed_section(folder, model, grasp_radius);
  return page;
}

}  // namespace crux

#include "jobs/report_job.hpp"

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "body/wall_penetration.hpp"
#include "experiments/climb_stances.hpp"
#include "outputs/run_folder.hpp"
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
  page.title = fmt::format("crux report: {}", fs::absolute(folder).lexically_normal().filename().string());
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

}  // namespace crux

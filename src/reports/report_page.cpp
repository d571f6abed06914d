#include "reports/report_page.hpp"

#include <fmt/format.h>

#include "reports/episode_replay.hpp"
#include "reports/replay_data.hpp"
#include "reports/report_figures.hpp"

namespace crux {

ReportPage report_page(const std::filesystem::path& folder, const ReportedRun& reported, RunFolder& run,
                       const BodyModel& model, const ExperimentConfig& recorded, const std::string& climb_choice) {
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
  if (!climb.postures.empty()) {
    page.replay = replay_data(model, run.wall, climb, climbing.reachability, page.replay_title, run.directory.string());
  }
  return page;
}

}  // namespace crux

#pragma once
// What `crux report` shows for an output folder: its summary, its figures and the replay
// of one run's climb, assembled from the folder's files (html_report renders it).

#include <filesystem>
#include <string>

#include "experiments/experiment_config.hpp"
#include "outputs/run_folder.hpp"
#include "reports/html_report.hpp"
#include "reports/replay_data.hpp"
#include "views/effort_plot.hpp"

namespace crux {

// The static model's effort of each stance of `climb` on `wall`, the start first, for the
// report's figure: on its four holds, and on the three left when the next limb lets go.
EffortAlongClimb effort_along_climb(const BodyModel& model, const Wall& wall, const RecordedClimb& climb,
                                    const PhysicsParameters& physics, const std::string& title);

// The page's style and script are left to the caller (crux_web_assets, which only the
// binary embeds). `run` is the replayed run of `reported`, its climb read with `model`
// (its summary is moved into the page); `recorded` the parameters the run was written
// with (read_run_config). `climb_choice` as climb_to_show; the replay shows the climb's
// first `replay_moves` moves.
ReportPage report_page(const std::filesystem::path& folder, const ReportedRun& reported, RunFolder& run,
                       const BodyModel& model, const ExperimentConfig& recorded, const std::string& climb_choice,
                       int replay_moves = kDefaultReplayMoves);

// What crux report says once `page` is written to `file`: its size, figures and replay.
nlohmann::ordered_json written_report_json(const ReportPage& page, const std::string& run_name, const std::string& file,
                                           std::size_t bytes, double seconds);
std::string written_report_text(const ReportPage& page, const std::string& run_name, const std::string& file,
                                std::size_t bytes, double seconds);

}  // namespace crux

#pragma once
// What `crux report` shows for an output folder, assembled from the folder's files: its
// summary, its figures and the replay of one run's climb (the episode replayed, its
// movement and, under the static model, what holds each stance, computed by the layers
// that own them), for reports/html_report to render.

#include <filesystem>
#include <string>

#include "experiments/climb_replay.hpp"
#include "experiments/experiment_config.hpp"
#include "outputs/perform_folder.hpp"
#include "outputs/run_folder.hpp"
#include "reports/html_report.hpp"

namespace crux {

// The page's style and script are left to the caller (crux_web_assets, which only the
// binary embeds). `run` is the replayed run of `reported`, its climb read with `model`
// (its summary is moved into the page); `recorded` the parameters the run was written
// with (read_run_config). `climb_choice` as climb_to_show; the replay shows the climb's
// first `replay_moves` moves.
ReportPage report_page(const std::filesystem::path& folder, const ReportedRun& reported, RunFolder& run,
                       const BodyModel& model, const ExperimentConfig& recorded, const std::string& climb_choice,
                       int replay_moves = kDefaultReplayMoves);

// The climb performed in a crux perform folder read with `model`, as a page shows it, its
// replay drawing grasp spheres of `grasp_radius` (the folder's ik.grasp_radius).
PerformedSection performed_section(const PerformFolder& folder, const BodyModel& model, double grasp_radius);

// A folder's name as a page names it: "perform" for out/perform and out/perform/.
std::string folder_name(const std::filesystem::path& folder);

// A page of its own for a crux perform folder.
ReportPage perform_report_page(const PerformFolder& folder, const BodyModel& model, double grasp_radius);

}  // namespace crux

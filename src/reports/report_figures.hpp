#pragma once
// The figures of an output folder as SVG: the paper's Figs. 2b, 3 and 4 and the
// transfer-minus-control plot of a `crux paper` folder, written into its figures/, and
// the report's figures, which add the climber at the start of the replayed climb (Fig. 1).

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "configurations/reachability.hpp"
#include "outputs/run_folder.hpp"
#include "reports/html_report.hpp"

namespace crux {

// Draws the figures of the `crux paper` folder from its files and writes them into its
// figures/ atomically; returns the files written.
std::vector<std::filesystem::path> write_paper_figure_files(const std::filesystem::path& experiment_folder);

// crux figures' output: the files written.
nlohmann::ordered_json figure_files_json(const std::vector<std::filesystem::path>& written);
std::string figure_files_text(const std::vector<std::filesystem::path>& written);

// The report's figures: those of `experiment_folder` when it is not empty, then Fig. 1 at
// the start posture of `run`'s wall, solved by IK from standing.
std::vector<ReportFigure> report_figures(const std::filesystem::path& experiment_folder, const BodyModel& model,
                                         const RunFolder& run, const ReachabilityParameters& reach);

}  // namespace crux

#pragma once
// A sweep's results, read back from its finished task folders so that the same folders
// give the same bytes however many workers wrote them, and whenever (docs/OUTPUTS.md):
//   results.csv: a row per run (cell, every listed key, condition, run, wall pair, seeds,
//     every transfer metric and the run's facts);
//   summary.json: per cell, crux paper's clustered transfer-versus-control analysis, its
//     p-values also Holm-adjusted over the cells (one family per metric).

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweeps/sweep_plan.hpp"

namespace crux {

// Writes results.csv and summary.json into `folder`, whose task folders must all be in
// place; `provenance` is summary.json's (the sweep's inputs and crux build).
// Returns summary.json's contents.
nlohmann::ordered_json write_sweep_results(const SweepPlan& plan, const std::filesystem::path& folder,
                                           const nlohmann::ordered_json& provenance);

// Writes figures/c<C>_episode_lengths.svg per cell (Fig. 4 of its transfer and control
// runs, read from their episodes.csv, with their walls' plans when known) and report.html (reports/sweep_report.hpp);
// `summary` is write_sweep_results' return. Returns the files written.
std::vector<std::filesystem::path> write_sweep_report(const SweepPlan& plan, const std::filesystem::path& folder,
                                                      const nlohmann::ordered_json& summary);

}  // namespace crux

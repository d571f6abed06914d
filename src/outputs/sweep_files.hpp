#pragma once
// A sweep folder's own files (docs/OUTPUTS.md), beside its run folders (run_files): each
// wall task's wall_facts.json, and results.csv, summary.json, the cells' figures and
// report.html once every task is done. Their one writer, and the facts' one reader.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace crux {

inline constexpr const char* kWallFactsFile = "wall_facts.json";

// folder/wall_facts.json: `facts` (the drawn wall's name, seed, rejected seeds, filtered
// pairs and plan) under format "crux-sweep-wall", version 1.
void write_sweep_wall_facts(const std::filesystem::path& folder, const nlohmann::ordered_json& facts);
// folder/wall_facts.json read back, checked to be crux's; InputError(file, problem) otherwise.
nlohmann::json read_sweep_wall_facts(const std::filesystem::path& folder);

// folder/results.csv (`csv`, already rows) and folder/summary.json (format
// "crux-sweep-summary", version 1: `provenance`, the listed keys and `cells`). Returns
// summary.json's contents.
nlohmann::ordered_json write_sweep_results_files(const std::filesystem::path& folder, const std::string& csv,
                                                 const nlohmann::ordered_json& provenance,
                                                 const std::vector<std::string>& listed_keys,
                                                 const nlohmann::ordered_json& cells);

// folder/figures/c<C>_episode_lengths.svg per cell and folder/report.html. Returns the files
// written, the figures first.
std::vector<std::filesystem::path> write_sweep_report_files(const std::filesystem::path& folder,
                                                            const std::vector<std::string>& cell_figures,
                                                            const std::string& report_html);

}  // namespace crux

#pragma once
// The output folder of an experiment (docs/OUTPUTS.md). Every file is written to a
// temporary name and renamed, so an interrupted run leaves no half-written file.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "experiments/paper_experiment.hpp"
#include "experiments/experiment_analysis.hpp"

namespace crux {

// iterations.csv, episodes.csv, q_grid.bin and climb.csv of one run.
void write_run_files(const std::filesystem::path& directory, const RunResult& run, const BodyModel& model);

// summary.json's contents (Table I, the transfer metrics with their clustered
// statistics, take-off, paired divergence, episode lengths, per-run facts, Fig. 2b maps).
nlohmann::ordered_json experiment_summary(const ExperimentResult& result, const ExperimentAnalysis& analysis,
                                          const ExperimentSettings& settings);

// Everything: config.toml (given), walls/, runs/, figures/ and summary.json.
void write_experiment(const std::filesystem::path& directory, const ExperimentResult& result,
                      const ExperimentAnalysis& analysis, const ExperimentSettings& settings, const BodyModel& model,
                      const std::string& config_toml);

// The paper's Table I, for printing beside ours: [window][regime] for training and
// transfer; success rates as fractions, displacements in cm.
struct PaperTableOne {
  double vertical_cm[2][2][kRegimeCount];   // [condition: training, transfer][window][regime]
  double success_rate[2][2][kRegimeCount];
};
const PaperTableOne& paper_table_one();

}  // namespace crux

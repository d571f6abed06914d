#pragma once
// summary.json (docs/OUTPUTS.md), one shape for a `crux paper` experiment and for a
// single `crux train` or `crux transfer` run: the provenance, the settings that shape
// the numbers, Table I, episode lengths, per-run facts, Fig. 2b's maps and the walls,
// per condition present. An experiment adds Table I's intervals over walls, the
// transfer metrics with their clustered statistics, take-off, transfer's choices and
// the paired divergence.

#include <nlohmann/json.hpp>

#include "experiments/experiment_analysis.hpp"
#include "experiments/paper_experiment.hpp"
#include "outputs/provenance.hpp"

namespace crux {

// One run as an experiment of one wall, one seed and one condition, so that it is
// summarised and drawn like one.
ExperimentResult single_run_result(RunResult run, const Wall& wall, std::optional<std::uint64_t> wall_seed,
                                   std::uint64_t learning_seed, Condition condition);

// `analysis` is null for a single run.
nlohmann::ordered_json summary_json(const ExperimentResult& result, const ExperimentAnalysis* analysis,
                                    const ExperimentParameters& parameters, const Provenance& provenance);

// Parts of an experiment's summary, also written per cell of a sweep: the transfer
// metrics with their clustered statistics, take-off, and where paired runs part ways.
nlohmann::ordered_json transfer_vs_control_json(const ExperimentAnalysis& analysis);
nlohmann::ordered_json take_off_json(const ExperimentAnalysis& analysis);
nlohmann::ordered_json divergence_json(const ExperimentAnalysis& analysis);

}  // namespace crux

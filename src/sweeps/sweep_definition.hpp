#pragma once
// From a sweep file to what crux sweep runs: each cell's finalized config, the tasks and
// the effective sweep.toml that the output folder keeps (lists written back as lists,
// experiment.threads left out since results do not depend on it) with its provenance.

#include <functional>
#include <string>

#include "outputs/provenance.hpp"
#include "sweeps/sweep_grid.hpp"
#include "sweeps/sweep_plan.hpp"

namespace crux {

// The keys crux sweep takes: crux paper's.
extern const ParameterSet kSweepKeys;

struct SweepDefinition {
  SweepPlan plan;
  std::string sweep_toml;
  Provenance provenance;
};

// `resolve` gives the finalized config of a choice of list values (flags over file over
// defaults), called once per cell; InputError as it throws them, the grid's when it has
// too many cells, before any call, and plan_sweep's as soon as the cells built so far
// have more than `max_tasks` tasks, so that no cell is built past the task bound.
SweepDefinition define_sweep(const SweepGrid& grid, const std::function<ExperimentConfig(const ListChoice&)>& resolve,
                             std::size_t max_tasks = kMaxSweepTasks);

}  // namespace crux

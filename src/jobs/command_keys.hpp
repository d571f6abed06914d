#pragma once
// The config keys (docs/OUTPUTS.md) that each job and each command shared by the CLI and
// the Python module takes, so that both take, and write back, the same parameters. A
// command's own set, used by it alone, stays beside it in src/cli/.

#include "experiments/experiment_config.hpp"

namespace crux {

// One learning run on one wall (crux train); transfer adds the Q_grid it starts from.
// Under physics.model = dynamic each move is performed in MuJoCo (the perform.* keys).
inline const ParameterSet kTrainKeys{
    {"experiment.urdf", "experiment.seed", "experiment.iterations", "experiment.beginning",
     "experiment.threshold_length", "experiment.greedy_cap", "experiment.checkpoint_every", "experiment.transfer",
     "experiment.policy", "learning", "reward", "ik", "physics", "perform", "filter", "grid", "wall"},
    {"wall.name", "wall.count"},
    true};
inline const ParameterSet kTransferKeys{
    {"experiment.urdf", "experiment.seed", "experiment.iterations", "experiment.beginning",
     "experiment.threshold_length", "experiment.greedy_cap", "experiment.checkpoint_every", "experiment.q_grid",
     "experiment.transfer", "learning", "reward", "ik", "physics", "perform", "filter", "grid", "wall"},
    {"wall.name", "wall.count"},
    true};
// The paper's experiment (crux paper): its walls are drawn from the experiment seed.
inline const ParameterSet kPaperKeys{
    {"experiment", "learning", "reward", "ik", "physics", "filter", "grid", "wall", "training_wall"},
    {"experiment.q_grid", "experiment.policy", "experiment.checkpoint_every", "experiment.plan_max_replans",
     "experiment.run", "experiment.climb", "wall.file", "wall.seed", "wall.name", "wall.count"}};

// An exact plan (crux plan), and a climb performed in MuJoCo (crux perform): under
// physics.model = dynamic, the plan repaired by performing it.
inline const ParameterSet kPlanKeys{{"experiment.urdf", "experiment.plan_max_solves", "experiment.plan_check_moves",
                                     "experiment.plan_max_replans", "ik", "physics", "perform", "filter", "wall"},
                                    {"wall.name", "wall.count", "physics.fall_when_stuck"},
                                    true};
inline const ParameterSet kPerformKeys{
    {"experiment.urdf", "experiment.plan_max_solves", "experiment.plan_check_moves", "experiment.plan_max_replans",
     "experiment.run", "experiment.climb", "ik", "physics", "perform", "filter", "wall"},
    {"wall.name", "wall.count", "physics.fall_when_stuck"},
    true};

// The IK's own keys (crux.solve_ik, crux.root_target); crux ik adds experiment.urdf,
// the body that Python takes as a model object instead.
inline const ParameterSet kIkKeys{{"ik"}, {"ik.cache_unreachable", "ik.guess"}};

}  // namespace crux

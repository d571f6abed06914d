// Compiled by the ctests Design.AnUpwardIncludeFailsToBuild and
// Design.TheSameIncludeBuildsFromItsOwnLayer: as a source of body/ it
// must fail (experiments/ is above body/ in docs/DESIGN.md's table, so body's include
// root has no such folder); as a source of experiments/ it must build.
#include "experiments/experiment_config.hpp"

int main() { return crux::ExperimentConfig{}.checkpoint_every; }

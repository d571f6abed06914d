#pragma once
// A `config` argument of the Python API, read into the CLI's parameters: None (the
// defaults), the path of a config.toml (as --config FILE), or a dict whose keys are
// the config file's, dotted ("learning.epsilon") or nested ({"learning": {...}}). The
// values are checked as the CLI checks them; an error names the key.

#include <string>

#include <pybind11/pybind11.h>

#include "experiments/experiment_config.hpp"

namespace crux::python {

// The keys of one config section: what the functions over the grid or the filter take.
inline const ParameterSet kGridKeys{{"grid"}, {}};
inline const ParameterSet kFilterKeys{{"filter"}, {}};
// What the climbing environments take, single or vector; learning.gamma is the discount
// that reward.height's shaping uses, the learner's own (0.9, the paper's, by default).
inline const ParameterSet kClimbMdpKeys{
    {"experiment.urdf", "learning.gamma", "reward", "ik", "physics", "filter", "grid"}, {}};

// `caller` names the Python function in errors: "ClimbMdp" gives "crux.ClimbMdp does
// not take wall.seed". `defaults`: the function's own defaults, which the config overrides.
ExperimentConfig config_from_python(const pybind11::handle& config, const ParameterSet& accepted,
                                    const std::string& caller, const ExperimentConfig& defaults = {});

}  // namespace crux::python

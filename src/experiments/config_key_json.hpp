#pragma once
// One declared key as JSON: what crux.config_keys() and a command's --dry-run --json show,
// so that a script (or a test that walks every key) reads each key's type, value and
// bounds from the one declaration.

#include <nlohmann/json.hpp>

#include "experiments/experiment_config.hpp"

namespace crux {

// {key, flag, type, value (null when unset), unit, min, max (null when unbounded),
// min_open, max_open, sizes_work, choices (null unless a choice), help}.
nlohmann::ordered_json config_key_json(const ConstConfigField& field);

}  // namespace crux

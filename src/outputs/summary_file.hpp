#pragma once
// summary.json of a crux output folder read back (docs/OUTPUTS.md): the one reader of the
// file, each key read by one rule, for the reports (a run folder, the HTML report), the
// views (the paper's figures) and the sweeps.

#include <filesystem>
#include <string>

#include "common/json_field.hpp"

namespace crux {

// folder/summary.json, checked to be crux's: a JSON object of format "crux-summary",
// version 3. InputError(file, problem) otherwise.
OrderedJson read_summary(const std::filesystem::path& folder);

// seeds_per_wall: an integer from 1 to 1000000; InputError(file, problem) otherwise.
int summary_seeds_per_wall(const OrderedJson& summary, const std::string& file);

// iterations: the iterations each run learnt for, an integer from 0; InputError(file,
// problem) otherwise.
int summary_iterations(const OrderedJson& summary, const std::string& file);

// kind: "experiment" (crux paper) or "run" (train, transfer); InputError(file, problem)
// for another value.
std::string summary_kind(const OrderedJson& summary, const std::string& file);

// The body model recorded in provenance.urdf; "" when the summary records none.
std::string summary_urdf(const OrderedJson& summary);

}  // namespace crux

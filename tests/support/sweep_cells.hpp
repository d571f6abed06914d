#pragma once
// Small sweeps written inline for the sweep tests: short runs on few walls, no plan.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sweeps/sweep_plan.hpp"

namespace crux::testing {

// A finalized config of `walls` wall pairs, `iterations` iterations, no plan, a small
// bootstrap, then `toml` applied over it (keys of crux paper).
ExperimentConfig small_sweep_config(int walls, int iterations, const std::string& toml = "");

// A cell of that config with the listed keys' values.
SweepCell sweep_cell(ExperimentConfig config, std::vector<std::string> values = {});

// Every file under `folder`, by path relative to it, with its bytes.
std::map<std::string, std::string> folder_contents(const std::filesystem::path& folder);

// A fresh folder for this test process (removed first if it exists).
std::filesystem::path sweep_scratch(const std::string& name);

}  // namespace crux::testing

// libFuzzer harness for sweep files (crux sweep --config): the listed keys, then every
// cell's config resolved as crux sweep resolves it, the effective sweep.toml and the
// plan; a sweep definition or an InputError, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.hpp"
#include "experiments/experiment_config.hpp"
#include "sweeps/sweep_definition.hpp"
#include "sweeps/sweep_grid.hpp"

namespace {

// Larger grids only slow the fuzzer down: their cells are resolved as these are.
constexpr std::size_t kMostFuzzedCells = 64;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const crux::ConfigDocument document(text, "fuzz.toml");
    const crux::SweepGrid grid{crux::listed_keys(document, crux::kSweepKeys), "fuzz.toml"};
    const std::size_t cells = grid.cells();
    if (cells == 0 || cells > kMostFuzzedCells) return 0;
    const crux::SweepDefinition sweep = crux::define_sweep(grid, [&](const crux::ListChoice& choice) {
      crux::ExperimentConfig config;
      crux::apply_config_document(document, config, crux::kSweepKeys, "sweep", choice);
      crux::finalize_config(config);
      return config;
    });
    if (sweep.plan.cells.size() != cells) __builtin_trap();
  } catch (const crux::InputError&) {
  }
  return 0;
}

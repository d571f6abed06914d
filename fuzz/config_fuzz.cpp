// libFuzzer harness for config files: every key of every command, then the range
// checks that run before any work; a config or an InputError, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.hpp"
#include "experiments/experiment_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const crux::ParameterSet kEveryKey{
      {"experiment", "learning", "reward", "ik", "physics", "filter", "grid", "wall", "training_wall", "output"}, {}};
  crux::ExperimentConfig config;
  try {
    crux::apply_config_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.toml", config, kEveryKey,
                            "fuzz");
    crux::finalize_config(config);
    crux::config_to_toml(config, kEveryKey);
  } catch (const crux::InputError&) {
  }
  return 0;
}

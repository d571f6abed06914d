// libFuzzer harness for a long run's checkpoint file: read_checkpoint, then the learning
// state it holds, resumed by run_learning as crux train resumes it. Either step may
// refuse the input with an InputError, nothing else. Each input is read as given, then
// with its SHA-256 made right and read as the checkpoint of the run it names, since random
// bytes almost never match the digest or the identity and would not reach the framing of
// the identity and state. The seed is a real checkpoint.bin of a crux train run
// (fuzz/corpus/checkpoint: wall.seed 1, seed 1, every other key at its default, 15
// iterations done); its state is resumed on that run's wall, to 20 iterations so that
// each input stays fast.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "experiments/experiment_config.hpp"
#include "experiments/learning_run.hpp"
#include "experiments/run_checkpoint.hpp"
#include "experiments/run_inputs.hpp"

namespace {

constexpr std::string_view kMagic = "crux-checkpoint 1\n";
constexpr std::size_t kDigestLine = 7 + 64 + 1;  // "sha256 <hex>\n"

const std::filesystem::path& checkpoint_scratch() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("crux-checkpoint-fuzz-" + std::to_string(::getpid()) + ".bin");
  return file;
}

struct CorpusRun {
  crux::ExperimentConfig config;
  crux::BodyModel model;
  crux::Wall wall;
};

const CorpusRun& corpus_run() {
  static const CorpusRun run = [] {
    crux::ExperimentConfig config;
    crux::apply_config_text("[wall]\nseed = 1\n[experiment]\nseed = 1\niterations = 20\n", "fuzz", config,
                            crux::ParameterSet{{"wall", "experiment"}, {}}, "fuzz");
    crux::finalize_config(config);
    return CorpusRun{config, crux::load_configured_body(config), crux::load_configured_wall(config)};
  }();
  return run;
}

void resume(const std::string& state) {
  const CorpusRun& run = corpus_run();
  crux::RunCheckpoints checkpoints;
  checkpoints.resume = state;
  checkpoints.source = checkpoint_scratch().string();
  crux::run_learning(run.model, run.wall, run.config.settings.learning, run.config.settings.seed, nullptr, {},
                     &checkpoints);
}

void read_as_checkpoint(const std::string& bytes, const std::string& identity) {
  std::ofstream(checkpoint_scratch(), std::ios::binary | std::ios::trunc) << bytes;
  try {
    const std::optional<std::string> state = crux::read_checkpoint(checkpoint_scratch(), identity);
    if (state && !state->empty()) resume(*state);
  } catch (const crux::InputError&) {
  }
}

// The identity that `payload` (what follows the digest line) starts with; "" if none.
std::string named_identity(std::string_view payload) {
  try {
    crux::CheckpointReader in(payload, "fuzz");
    return in.text();
  } catch (const crux::InputError&) {
    return {};
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_as_checkpoint(bytes, "");
  if (bytes.size() < kMagic.size() + kDigestLine) return 0;
  const std::string payload = bytes.substr(kMagic.size() + kDigestLine);
  const std::string fixed = std::string(kMagic) + "sha256 " + crux::sha256_hex(payload) + "\n" + payload;
  read_as_checkpoint(fixed, named_identity(payload));
  return 0;
}

#include "cli/parameter_binding.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "jobs/command_keys.hpp"
#include "support/test_models.hpp"

namespace crux::cli {
namespace {

// Issue 25: crux sweep resolved each cell by reading and parsing its whole file again,
// so expanding a sweep cost the cells times the file. The binding reads and parses the
// file once, at its first use, whatever the number of cells resolved from it.
TEST(ParameterBinding, ASweepFileIsReadAndParsedOnceForAllItsCells) {
  const auto file = testing::write_temporary(
      "binding_sweep.toml",
      "[experiment]\nwalls = 1\nplan = false\nseed = [1, 2, 3]\n[learning]\nepsilon = [0.1, 0.2]\n");
  CLI::App app;
  ParameterBinding binding("sweep", kPaperKeys);
  binding.bind(&app);
  std::vector<std::string> arguments{"--config", file.string()};
  std::reverse(arguments.begin(), arguments.end());
  app.parse(arguments);
  const std::size_t parses_before = ConfigDocument::parses();
  const std::vector<ListedKey> listed = binding.listed_keys();
  ASSERT_EQ(listed.size(), 2u);
  const std::vector<double> epsilons{0.1, 0.2};
  for (std::size_t seed = 0; seed < 3; ++seed) {
    for (std::size_t epsilon = 0; epsilon < 2; ++epsilon) {
      const ExperimentConfig config = binding.resolve({{"experiment.seed", seed}, {"learning.epsilon", epsilon}});
      EXPECT_EQ(config.settings.seed, seed + 1);
      EXPECT_DOUBLE_EQ(config.settings.learning.dyna.epsilon, epsilons[epsilon]);
    }
  }
  EXPECT_EQ(ConfigDocument::parses() - parses_before, 1u) << "6 cells";
}

// Parses `arguments` for a command that shows progress; "" when they are refused.
std::string progress_after(std::vector<std::string> arguments) {
  CLI::App app;
  ParameterBinding binding("paper", with_progress(kPaperKeys));
  binding.bind(&app);
  std::reverse(arguments.begin(), arguments.end());
  try {
    app.parse(arguments);
  } catch (const CLI::ParseError&) {
    return "";
  }
  return std::string(enum_name(binding.resolve().progress));
}

TEST(ParameterBinding, QuietIsProgressNoneAndExcludesTheProgressFlag) {
  EXPECT_EQ(progress_after({}), "bar");
  EXPECT_EQ(progress_after({"--quiet"}), "none");
  EXPECT_EQ(progress_after({"-q"}), "none");
  EXPECT_EQ(progress_after({"--output-progress", "lines"}), "lines");
  EXPECT_EQ(progress_after({"--quiet", "--output-progress", "lines"}), "");
  // A config file's progress gives way to --quiet, as any key to its flag.
  const auto file = testing::write_temporary("binding_progress.toml", "[output]\nprogress = \"lines\"\n");
  EXPECT_EQ(progress_after({"--config", file.string()}), "lines");
  EXPECT_EQ(progress_after({"--config", file.string(), "--quiet"}), "none");
  // A command without progress has no --quiet.
  CLI::App plain;
  ParameterBinding plan("plan", kPaperKeys);
  plan.bind(&plain);
  EXPECT_THROW(plain.parse(std::vector<std::string>{"--quiet"}), CLI::ParseError);
}

// --dry-run prints the effective parameters as a config file that crux reads back, or as
// each key's declaration with --json, and ends the command before it runs.
std::string dry_run_output(std::vector<std::string> arguments, bool json_flag) {
  CLI::App app;
  ParameterBinding binding("train", kTrainKeys);
  binding.bind(&app);
  bool json = false;
  if (json_flag) app.add_flag("--json", json);
  std::reverse(arguments.begin(), arguments.end());
  app.parse(arguments);
  ::testing::internal::CaptureStdout();
  EXPECT_THROW(binding.resolve(), DryRunDone);
  return ::testing::internal::GetCapturedStdout();
}

TEST(ParameterBinding, DryRunPrintsAConfigFileThatReadsBackToTheSameParameters) {
  const std::string text = dry_run_output(
      {"--dry-run", "--learning-epsilon", "0.3", "--wall-seed", "4", "--physics-friction", "0.7"}, false);
  ExperimentConfig read_back;
  apply_config_text(text, "dry-run", read_back, kTrainKeys, "train");
  finalize_config(read_back);
  EXPECT_DOUBLE_EQ(read_back.settings.learning.dyna.epsilon, 0.3);
  EXPECT_DOUBLE_EQ(read_back.settings.learning.climbing.physics.friction, 0.7);
  EXPECT_EQ(read_back.wall_seed, 4u);
}

TEST(ParameterBinding, DryRunWithJsonGivesEveryKeyOfTheCommandWithItsBounds) {
  const auto json = nlohmann::json::parse(dry_run_output({"--dry-run", "--json", "--iterations", "77"}, true));
  EXPECT_EQ(json["command"], "train");
  std::size_t taken = 0;
  for (const ConstConfigField& field : config_fields(ExperimentConfig{})) taken += kTrainKeys.accepts(field.key);
  ASSERT_EQ(json["keys"].size(), taken);
  for (const auto& key : json["keys"]) {
    if (key["key"] == "experiment.iterations") {
      EXPECT_EQ(key["value"], 77);
      EXPECT_TRUE(key["sizes_work"]);
    }
  }
}

TEST(ParameterBinding, ABadValueIsRefusedUnderDryRunAsWithoutIt) {
  CLI::App app;
  ParameterBinding binding("train", kTrainKeys);
  binding.bind(&app);
  app.parse(std::vector<std::string>{"1e20", "--physics-friction", "--dry-run"});
  EXPECT_THROW(binding.resolve(), InputError);
}

}  // namespace
}  // namespace crux::cli

#include "experiments/experiment_config.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(ExperimentConfig, FileSetsValuesAndTheWrittenConfigReadsBackTheSame) {
  const auto path = testing::write_temporary("config.toml",
                                             "[experiment]\nwalls = 3\nseeds_per_wall = 2\nseed = 12\n[learning]\nepsilon = 0.2\n"
                                             "[ik]\nsolver = \"paper\"\n[walls]\nfinish_height = 2\n");
  ExperimentConfig config;
  apply_config_file(path.string(), config);
  finalize_config(config);
  EXPECT_EQ(config.settings.wall_pairs, 3);
  EXPECT_EQ(config.settings.runs(), 6);
  EXPECT_EQ(config.settings.seed, 12u);
  EXPECT_DOUBLE_EQ(config.settings.learning.dyna.epsilon, 0.2);
  EXPECT_EQ(config.settings.learning.climbing.reachability.ik.solver, IkSolverKind::Paper);
  EXPECT_DOUBLE_EQ(config.settings.walls.finish_height, 2.0);
  const std::string written = config_to_toml(config);
  const auto again = testing::write_temporary("config_again.toml", written);
  ExperimentConfig reread;
  apply_config_file(again.string(), reread);
  EXPECT_EQ(config_to_toml(reread), written);
}

struct BadConfig {
  const char* name;
  const char* text;
  const char* expected;
};

class BadConfigFile : public ::testing::TestWithParam<BadConfig> {};

TEST_P(BadConfigFile, IsOneClearInputError) {
  const auto path = testing::write_temporary(std::string("bad_") + GetParam().name + ".toml", GetParam().text);
  try {
    ExperimentConfig config;
    apply_config_file(path.string(), config);
    finalize_config(config);
    FAIL() << "accepted a bad config";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadConfigFile,
    ::testing::Values(BadConfig{"syntax", "[experiment]\nwalls = = 3\n", "line 2"},
                      BadConfig{"unknown_key", "[learning]\nalpah = 0.2\n", "unknown key learning.alpah"},
                      BadConfig{"wrong_type", "[experiment]\nwalls = \"six\"\n", "experiment.walls must be an integer"},
                      BadConfig{"too_many_runs", "[experiment]\nwalls = 2000000\nseeds_per_wall = 2000000\n",
                                "at most 1000000 runs"},
                      BadConfig{"not_a_section", "walls = 3\n", "must be a [section]"},
                      BadConfig{"bad_solver", "[ik]\nsolver = \"kdl\"\n", "unknown solver 'kdl'"},
                      BadConfig{"bad_range", "[learning]\ngamma = 1.5\n", "learning.gamma"},
                      BadConfig{"negative_seed", "[experiment]\nseed = -4\n", "non-negative"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ExperimentConfig, MissingFileIsAnInputError) {
  ExperimentConfig config;
  EXPECT_THROW(apply_config_file("/nonexistent/crux.toml", config), InputError);
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

TEST(ExperimentConfig, SeedsBeyondTomlIntegersRoundTripAsStrings) {
  ExperimentConfig config;
  config.settings.seed = 18000000000000000000ULL;  // above 2^63
  const auto path = testing::write_temporary("big_seed.toml", config_to_toml(config));
  ExperimentConfig reread;
  apply_config_file(path.string(), reread);
  EXPECT_EQ(reread.settings.seed, 18000000000000000000ULL);
}

TEST(ExperimentConfig, RangesThatWouldBreakWallsOrCodesAreRefused) {
  ExperimentConfig small_wall;
  small_wall.settings.walls.rows = 2;  // the hands start on row 3
  EXPECT_THROW(finalize_config(small_wall), InputError);
  ExperimentConfig huge_grid;
  huge_grid.settings.learning.climbing.grid.columns = 40;
  huge_grid.settings.learning.climbing.grid.rows = 40;  // 4 x 1601^3 codes overflow 32 bits
  EXPECT_THROW(finalize_config(huge_grid), InputError);
  ExperimentConfig bad_anchor;
  bad_anchor.settings.learning.climbing.grid.anchors[0] = {5, 4};
  EXPECT_THROW(finalize_config(bad_anchor), InputError);
}

}  // namespace
}  // namespace crux

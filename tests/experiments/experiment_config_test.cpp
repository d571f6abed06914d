#include "experiments/experiment_config.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

const ParameterSet kEverything{{"experiment", "learning", "reward", "ik", "filter", "grid", "wall"}, {}};

TEST(ExperimentConfig, FileSetsValuesAndTheWrittenConfigReadsBackTheSame) {
  const auto path =
      testing::write_temporary("config.toml",
                               "[experiment]\nwalls = 3\nseeds_per_wall = 2\nseed = 12\n[learning]\nepsilon = 0.2\n"
                               "[ik]\nsolver = \"paper\"\n[wall]\nfinish_height = 2\nseed = 7\n");
  ExperimentConfig config;
  const ConfigLines lines = apply_config_file(path.string(), config, kEverything, "test");
  EXPECT_EQ(lines.at("learning.epsilon"), 6);
  finalize_config(config);
  EXPECT_EQ(config.settings.wall_pairs, 3);
  EXPECT_EQ(config.settings.runs(), 6);
  EXPECT_EQ(config.settings.seed, 12u);
  EXPECT_DOUBLE_EQ(config.settings.learning.dyna.epsilon, 0.2);
  EXPECT_EQ(config.settings.learning.climbing.reachability.ik.solver, IkSolverKind::Paper);
  EXPECT_DOUBLE_EQ(config.settings.walls.finish_height, 2.0);
  EXPECT_EQ(config.wall_seed, 7u);
  const std::string written = config_to_toml(config, kEverything);
  const auto again = testing::write_temporary("config_again.toml", written);
  ExperimentConfig reread;
  apply_config_file(again.string(), reread, kEverything, "test");
  finalize_config(reread);
  EXPECT_EQ(config_to_toml(reread, kEverything), written);
}

TEST(ExperimentConfig, EveryKeyHasItsOwnFlagMirroringIt) {
  ExperimentConfig config;
  std::set<std::string> flags;
  for (const ConfigField& field : config_fields(config)) {
    const std::string flag = flag_for_key(field.key);
    EXPECT_TRUE(flags.insert(flag).second) << "two keys share " << flag;
    std::string section = field.key.substr(0, field.key.find('.'));
    std::string name = field.key.substr(field.key.find('.') + 1);
    std::replace(name.begin(), name.end(), '_', '-');
    std::replace(section.begin(), section.end(), '_', '-');
    EXPECT_EQ(flag, section == "experiment" ? "--" + name : "--" + section + "-" + name) << field.key;
  }
  EXPECT_EQ(flag_for_key("ik.time_step"), "--ik-time-step");
  EXPECT_EQ(flag_for_key("experiment.seeds_per_wall"), "--seeds-per-wall");
  EXPECT_EQ(flag_for_key("wall.seed"), "--wall-seed");
}

TEST(ExperimentConfig, AParameterSetTakesSectionsAndKeysMinusExclusions) {
  const ParameterSet set{{"ik", "experiment.seed"}, {"ik.solver"}};
  EXPECT_TRUE(set.accepts("ik.alpha"));
  EXPECT_TRUE(set.accepts("experiment.seed"));
  EXPECT_FALSE(set.accepts("ik.solver"));
  EXPECT_FALSE(set.accepts("experiment.walls"));
  EXPECT_FALSE(set.accepts("grid.rows"));
}

TEST(ExperimentConfig, AKeyTheCommandDoesNotTakeIsRefusedWithItsLine) {
  const auto path = testing::write_temporary("config_foreign_key.toml", "[ik]\nalpha = 0.3\n[experiment]\nwalls = 2\n");
  ExperimentConfig config;
  try {
    apply_config_file(path.string(), config, ParameterSet{{"ik"}, {}}, "ik");
    FAIL() << "accepted experiment.walls for crux ik";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": line 4: crux ik does not take experiment.walls");
  }
}

TEST(ExperimentConfig, TheWrittenConfigHoldsOnlyTheCommandsKeysAndSetValues) {
  ExperimentConfig config;
  const std::string text = config_to_toml(config, ParameterSet{{"wall"}, {}});
  EXPECT_EQ(text.find("seed ="), std::string::npos) << "an unset wall seed is left out";
  EXPECT_EQ(text.find("file ="), std::string::npos) << "an empty file name is left out";
  EXPECT_EQ(text.find("[ik]"), std::string::npos);
  config.wall_file = "walls/w.json";
  const std::string with_file = config_to_toml(config, ParameterSet{{"wall"}, {}});
  EXPECT_NE(with_file.find("file = \"" + std::filesystem::absolute("walls/w.json").string() + "\""), std::string::npos)
      << "file names are written absolute, to replay from anywhere";
}

// Unlike the other input files, an empty config file is valid: TOML that sets nothing,
// so the defaults hold (docs/RELIABILITY.md).
TEST(ExperimentConfig, AnEmptyFileSetsNothingSoTheDefaultsHold) {
  const auto path = testing::write_temporary("config_empty.toml", "");
  ExperimentConfig defaults, config;
  apply_config_file(path.string(), config, kEverything, "paper");
  EXPECT_EQ(config_to_toml(config, kEverything), config_to_toml(defaults, kEverything));
}

TEST(ExperimentConfig, TheProvenanceTableIsKeptForTheReplaysCheck) {
  const auto path =
      testing::write_temporary("config_provenance.toml", "[ik]\nalpha = 0.3\n[provenance]\nurdf_sha256 = \"abc\"\n");
  ExperimentConfig config;
  apply_config_file(path.string(), config, ParameterSet{{"ik"}, {}}, "ik");
  EXPECT_EQ(config.recorded_provenance.at("urdf_sha256"), "abc");
}

TEST(ExperimentConfig, RunsSetsWallsWithOneSeedAndMustBePositive) {
  ExperimentConfig config;
  config.runs = 4;
  config.settings.seeds_per_wall = 3;
  finalize_config(config);
  EXPECT_EQ(config.settings.wall_pairs, 4);
  EXPECT_EQ(config.settings.seeds_per_wall, 1);
  EXPECT_FALSE(config.runs) << "cleared: the written config says walls and seeds_per_wall";
  ExperimentConfig zero;
  zero.runs = 0;
  try {
    finalize_config(zero);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "experiment.runs");
  }
}

TEST(ExperimentConfig, TheBeginningDefaultsTo2000OrTheRunAndMayNotExceedIt) {
  ExperimentConfig paper;
  finalize_config(paper);
  EXPECT_EQ(paper.settings.analysis.beginning, 2000);
  EXPECT_EQ(paper.beginning, 0) << "kept as the default, which follows the iterations";
  ExperimentConfig short_run;
  short_run.settings.learning.iterations = 500;
  finalize_config(short_run);
  EXPECT_EQ(short_run.settings.analysis.beginning, 500);
  ExperimentConfig too_long;
  too_long.settings.learning.iterations = 500;
  too_long.beginning = 501;
  try {
    finalize_config(too_long);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "experiment.beginning");
  }
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
    apply_config_file(path.string(), config, kEverything, "test");
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
    ::testing::Values(
        BadConfig{"syntax", "[experiment]\nwalls = = 3\n", "line 2"},
        BadConfig{"unknown_key", "[learning]\nalpah = 0.2\n", "unknown key learning.alpah"},
        BadConfig{"old_section", "[walls]\nsigma = 0.1\n", "unknown key walls.sigma (it is now wall.sigma)"},
        BadConfig{"wrong_type", "[experiment]\nwalls = \"six\"\n", "experiment.walls must be an integer"},
        BadConfig{"too_many_runs", "[experiment]\nwalls = 2000\nseeds_per_wall = 2000\n", "at most 1000000 runs"},
        BadConfig{"not_a_section", "walls = 3\n", "must be a [section]"},
        BadConfig{"bad_solver", "[ik]\nsolver = \"kdl\"\n", "unknown solver 'kdl'"},
        BadConfig{"bad_range", "[learning]\ngamma = 1.5\n", "learning.gamma"},
        BadConfig{"negative_sigma", "[wall]\nsigma = -1.0\n", "wall.sigma"},
        BadConfig{"negative_grasp", "[ik]\ngrasp_radius = -0.04\n", "ik.grasp_radius"},
        BadConfig{"negative_seed", "[experiment]\nseed = -4\n", "an integer from 0"},
        BadConfig{"signed_seed_text", "[wall]\nseed = \"-4\"\n", "an integer from 0"},
        BadConfig{"int_out_of_range", "[experiment]\nplan_max_solves = 9999999999\n",
                  "an integer from -2147483648 to 2147483647"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ExperimentConfig, MissingFileIsAnInputError) {
  ExperimentConfig config;
  EXPECT_THROW(apply_config_file("/nonexistent/crux.toml", config, kEverything, "test"), InputError);
}

TEST(ExperimentConfig, SeedsBeyondTomlIntegersRoundTripAsStrings) {
  ExperimentConfig config;
  config.settings.seed = 18000000000000000000ULL;  // above 2^63
  config.wall_seed = 18000000000000000001ULL;
  const auto path = testing::write_temporary("big_seed.toml", config_to_toml(config, kEverything));
  ExperimentConfig reread;
  apply_config_file(path.string(), reread, kEverything, "test");
  EXPECT_EQ(reread.settings.seed, 18000000000000000000ULL);
  EXPECT_EQ(reread.wall_seed, 18000000000000000001ULL);
}

TEST(ExperimentConfig, RangesThatWouldBreakWallsOrCodesAreRefusedNamingTheKey) {
  const auto refused_key = [](ExperimentConfig config) {
    try {
      finalize_config(config);
    } catch (const InputError& e) {
      return e.source();
    }
    return std::string("accepted");
  };
  ExperimentConfig small_wall;
  small_wall.settings.walls.rows = 2;  // the hands start on row 3
  EXPECT_EQ(refused_key(small_wall), "wall.rows");
  ExperimentConfig huge_grid;
  huge_grid.settings.learning.climbing.grid.columns = 40;
  huge_grid.settings.learning.climbing.grid.rows = 40;  // 4 x 1601^3 codes overflow 32 bits
  EXPECT_EQ(refused_key(huge_grid), "grid.columns");
  ExperimentConfig huge_wall;
  huge_wall.settings.walls.columns = 100000;
  huge_wall.settings.walls.rows = 100000;  // 10^10 holds, and an int overflow if multiplied as ints
  EXPECT_EQ(refused_key(huge_wall), "wall.columns");
  ExperimentConfig no_plan_budget;
  no_plan_budget.settings.plan_search.max_ik_solves = 0;
  EXPECT_EQ(refused_key(no_plan_budget), "experiment.plan_max_solves");
  ExperimentConfig overflowing_grid;
  overflowing_grid.settings.learning.climbing.grid.columns = 65536;
  overflowing_grid.settings.learning.climbing.grid.rows = 65536;  // the tile count wraps to 0 as an int
  EXPECT_EQ(refused_key(overflowing_grid), "grid.columns");
  ExperimentConfig bad_anchor;
  bad_anchor.settings.learning.climbing.grid.anchors[0] = {5, 4};
  EXPECT_EQ(refused_key(bad_anchor), "grid.right_hand_anchor_column");
}

// [training_wall]: a key left unset follows its [wall] key, and only keys set are
// written, so a default config.toml keeps no such section and every config.toml replays
// to the same bytes.
// physics.strength sets the hands' grip from its level unless physics.grip is given
// (a flag, a file or Python alike mark it given); config.toml records the level only
// when set, so that the default's config stays byte for byte.
TEST(ExperimentConfig, AStrengthLevelSetsTheGripUnlessTheGripIsGiven) {
  const ParameterSet keys{{"physics"}, {}};
  ExperimentConfig defaults;
  finalize_config(defaults);
  EXPECT_DOUBLE_EQ(defaults.settings.learning.climbing.physics.grip, 575.7);
  EXPECT_EQ(config_to_toml(defaults, keys).find("strength"), std::string::npos);

  ExperimentConfig level;
  apply_config_text("[physics]\nstrength = \"intermediate\"\n", "level.toml", level, keys, "test");
  finalize_config(level);
  EXPECT_DOUBLE_EQ(level.settings.learning.climbing.physics.grip, 383.0);
  const std::string written = config_to_toml(level, keys);
  EXPECT_NE(written.find("strength = \"intermediate\"  #"), std::string::npos) << written;
  EXPECT_NE(written.find("grip = 383.0  #"), std::string::npos) << written;

  ExperimentConfig both;
  apply_config_text("[physics]\nstrength = \"elite\"\ngrip = 300\n", "both.toml", both, keys, "test");
  finalize_config(both);
  EXPECT_DOUBLE_EQ(both.settings.learning.climbing.physics.grip, 300.0) << "an explicit grip overrides the level";

  ExperimentConfig unknown;
  try {
    apply_config_text("[physics]\nstrength = \"pro\"\n", "unknown.toml", unknown, keys, "test");
    FAIL() << "an unknown level is refused where the file gives it";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "unknown.toml");
    EXPECT_EQ(e.problem(),
              "line 2: physics.strength: unknown strength 'pro' (expected intermediate (383.0 N), advanced (575.7 N) "
              "or elite (563.1 N))");
  }
  ExperimentConfig empty;
  EXPECT_THROW(apply_config_text("[physics]\nstrength = \"\"\n", "empty.toml", empty, keys, "test"), InputError)
      << "an empty level is no level";
}

TEST(ExperimentConfig, TrainingWallKeysFollowTheWallKeysUnlessSet) {
  const ParameterSet keys{{"wall", "training_wall"}, {}};
  ExperimentConfig defaults;
  finalize_config(defaults);
  EXPECT_FALSE(defaults.settings.training_wall.has_value());
  EXPECT_EQ(config_to_toml(defaults, keys).find("training_wall"), std::string::npos);

  ExperimentConfig wall_only;
  apply_config_text("[wall]\nsigma = 0.2\n", "wall.toml", wall_only, keys, "test");
  finalize_config(wall_only);
  EXPECT_FALSE(wall_only.settings.training_wall.has_value());
  EXPECT_DOUBLE_EQ(wall_only.settings.training_wall_parameters().sigma, 0.2);

  ExperimentConfig own;
  apply_config_text("[wall]\nsigma = 0.2\ncolumns = 5\n[training_wall]\nsigma = 0.3\ntile_width = 0.4\n", "own.toml",
                    own, keys, "test");
  finalize_config(own);
  ASSERT_TRUE(own.settings.training_wall.has_value());
  EXPECT_DOUBLE_EQ(own.settings.training_wall->sigma, 0.3);
  EXPECT_DOUBLE_EQ(own.settings.training_wall->tile_width, 0.4);
  EXPECT_EQ(own.settings.training_wall->columns, 5) << "unset: wall.columns";
  EXPECT_DOUBLE_EQ(own.settings.walls.sigma, 0.2) << "the transfer walls keep [wall]";
  const std::string written = config_to_toml(own, keys);
  EXPECT_NE(written.find("[training_wall]\ntile_width = 0.4  #"), std::string::npos) << written;
  EXPECT_EQ(written.find("training_wall.columns"), std::string::npos);
  ExperimentConfig replayed;
  apply_config_text(written, "written.toml", replayed, keys, "test");
  finalize_config(replayed);
  EXPECT_EQ(config_to_toml(replayed, keys), written);

  ExperimentConfig narrow;
  narrow.training_wall.rows = 2;  // the hands start on row 3
  EXPECT_THROW(
      {
        try {
          finalize_config(narrow);
        } catch (const InputError& e) {
          EXPECT_EQ(e.source(), "training_wall.rows");
          throw;
        }
      },
      InputError);
  EXPECT_EQ(flag_for_key("training_wall.tile_width"), "--training-wall-tile-width");
}

// Issue 25: a thread per value aborted crux sweep, and a run's memory grows with its
// iterations until bad_alloc; both are refused above a stated bound.
TEST(ExperimentConfig, ThreadsAndIterationsAboveTheirBoundsAreRefused) {
  const auto problem = [](int threads, int iterations) {
    ExperimentConfig config;
    config.settings.threads = threads;
    config.settings.learning.iterations = iterations;
    try {
      finalize_config(config);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(problem(kMaxThreads, kMaxIterations), "accepted");
  EXPECT_EQ(problem(kMaxThreads + 1, 8000), "experiment.threads: must be from 0 to 1024 (0: all cores)");
  EXPECT_EQ(problem(100000, 8000), "experiment.threads: must be from 0 to 1024 (0: all cores)");
  EXPECT_EQ(problem(0, 2147483647),
            "experiment.iterations: must be from 1 to 10000000 (a run keeps every iteration's record in memory)");
  EXPECT_EQ(problem(0, kMaxIterations + 1),
            "experiment.iterations: must be from 1 to 10000000 (a run keeps every iteration's record in memory)");
  EXPECT_LE(8000 * 1250, kMaxIterations) << "the paper's runs stay far inside the bound";
}

// A sweep applies its file once per cell: the document is parsed once, whatever the
// number of choices applied.
TEST(ExperimentConfig, ADocumentIsParsedOnceForEveryChoiceAppliedFromIt) {
  const std::size_t before = ConfigDocument::parses();
  const ConfigDocument document("[experiment]\nwalls = 2\n[learning]\nepsilon = [0.1, 0.2, 0.4]\n", "sweep.toml");
  const std::vector<double> epsilons{0.1, 0.2, 0.4};
  for (std::size_t value = 0; value < epsilons.size(); ++value) {
    ExperimentConfig config;
    apply_config_document(document, config, kEverything, "sweep", {{"learning.epsilon", value}});
    EXPECT_DOUBLE_EQ(config.settings.learning.dyna.epsilon, epsilons[value]);
  }
  EXPECT_EQ(listed_keys(document, kEverything).size(), 1u);
  EXPECT_EQ(ConfigDocument::parses() - before, 1u);
}

TEST(ExperimentConfig, AListTakesTheChosenValueAndOnlyWhenChosen) {
  const std::string text =
      "[experiment]\nwalls = 2\n[learning]\nepsilon = [0.1, 0.2, 0.4]\nplanner = [\"uniform\", \"prioritized\"]\n";
  const std::vector<ListedKey> listed = listed_keys(ConfigDocument(text, "sweep.toml"), kEverything);
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[0].key, "learning.epsilon");
  EXPECT_EQ(listed[0].values, 3u);
  EXPECT_EQ(listed[1].key, "learning.planner");
  EXPECT_EQ(listed[1].values, 2u);
  ExperimentConfig config;
  apply_config_text(text, "sweep.toml", config, kEverything, "sweep",
                    {{"learning.epsilon", 2}, {"learning.planner", 1}});
  finalize_config(config);
  EXPECT_DOUBLE_EQ(config.settings.learning.dyna.epsilon, 0.4);
  EXPECT_EQ(config.settings.learning.dyna.planner, Planner::Prioritized);
  EXPECT_EQ(config_value_text(config, "learning.planner"), "\"prioritized\"");
  EXPECT_EQ(config_value_text(config, "learning.planner", false), "prioritized");
  EXPECT_EQ(config_value_text(config, "learning.epsilon"), "0.4");
  try {
    ExperimentConfig other;
    apply_config_text(text, "sweep.toml", other, kEverything, "paper");
    FAIL() << "a list without a choice must be refused";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "sweep.toml: line 4: learning.epsilon must be one value; only crux sweep takes lists");
  }
}

TEST(ExperimentConfig, ListsThatMakeNoSweepAreRefused) {
  const auto problem = [](const std::string& text) {
    try {
      listed_keys(ConfigDocument(text, "sweep.toml"), kEverything);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(problem("[experiment]\nthreads = [1, 2]\n"),
            "sweep.toml: line 2: experiment.threads takes one value, not a list");
  EXPECT_EQ(problem("[learning]\nepsilon = []\n"), "sweep.toml: line 2: learning.epsilon lists no value");
  EXPECT_EQ(problem("[experiment]\nruns = [2, 3]\n"),
            "sweep.toml: line 2: experiment.runs takes one value, not a list");
  ExperimentConfig config;
  EXPECT_THROW(apply_config_text("[learning]\nepsilon = [\"a\"]\n", "sweep.toml", config, kEverything, "sweep",
                                 {{"learning.epsilon", 0}}),
               InputError)
      << "each value is checked as a single value would be";
}

TEST(ExperimentConfig, ConfigToTomlWritesAListInPlaceOfItsValue) {
  ExperimentConfig config;
  const std::string text = config_to_toml(config, kEverything, {{"learning.epsilon", "[0.1, 0.2]"}});
  EXPECT_NE(text.find("epsilon = [0.1, 0.2]  #"), std::string::npos) << text;
  EXPECT_EQ(text.find("epsilon = 0.1"), std::string::npos);
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

const ParameterSet kEveryKeyAndOutput{{"experiment", "learning", "reward", "ik", "physics", "perform", "compare",
                                       "stances", "filter", "grid", "wall", "training_wall", "output"},
                                      {}};

// A number's field set to `value`, whatever its type.
void set_number(const ConfigField& field, double value) {
  std::visit(
      [&](auto target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
          *target = value;
        } else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) {
          *target = static_cast<int>(value);
        }
      },
      field.target);
}

// finalize_config's refusal of `key`, or "" when it accepts the config or refuses another key.
std::string refusal_of(ExperimentConfig& config, const std::string& key) {
  try {
    finalize_config(config);
  } catch (const InputError& e) {
    return e.source() == key ? e.problem() : std::string();
  }
  return {};
}

TEST(ExperimentConfig, EveryKeyIsDeclaredOnceWithItsHelpTypeAndChoices) {
  const ExperimentConfig defaults;
  std::set<std::string> keys;
  for (const ConstConfigField& field : config_fields(defaults)) {
    EXPECT_TRUE(keys.insert(field.key).second) << field.key << " is declared twice";
    EXPECT_FALSE(field.help.empty()) << field.key;
    EXPECT_TRUE(kEveryKeyAndOutput.accepts(field.key)) << field.key << " is in no known section";
    EXPECT_EQ(field.help.find(" (m)"), std::string::npos) << field.key << ": the unit goes in its own column";
    if (std::holds_alternative<ChoiceTarget<true>>(field.target)) {
      EXPECT_STREQ(field.type_name(), "choice") << field.key;
      EXPECT_NE(field.described_help().find(std::get<ChoiceTarget<true>>(field.target).type->choices()),
                std::string::npos)
          << field.key;
    }
  }
  ExperimentConfig config;
  const auto fields = config_fields(config);
  const ConfigField* radius = find_field(fields, "ik.grasp_radius");
  ASSERT_NE(radius, nullptr);
  EXPECT_EQ(radius->described_help(), "Radius of the grasp spheres (m; (0, 100])");
  EXPECT_EQ(find_field(fields, "ik.grasp"), nullptr);
  EXPECT_EQ(find_field(fields, "learning.gamma")->described_help(), "Discount factor gamma ([0, 1))");
  EXPECT_EQ(find_field(fields, "experiment.training_walls")->bounds.summary(true), "1 to 1000");
  EXPECT_STREQ(find_field(fields, "wall.file")->type_name(), "path");
  EXPECT_STREQ(find_field(fields, "wall.seed")->type_name(), "seed");
}

// Each bounded number, set just outside its bounds, is refused naming its key with the
// declared problem; set on an included edge, the bounds let it pass.
TEST(ExperimentConfig, EveryDeclaredBoundIsEnforcedAtBothEdges) {
  int checked = 0;
  for (const ConstConfigField& declared : config_fields(ExperimentConfig{})) {
    const bool integer = declared.is_integer();
    const Bounds& b = declared.bounds;
    const double step = integer ? 1.0 : 1e-9 * std::max(1.0, std::abs(b.min));
    for (const bool low : {true, false}) {
      const double edge = low ? b.min : b.max;
      if (!std::isfinite(edge)) continue;
      const bool open = low ? b.min_open : b.max_open;
      const double outside = open ? edge : (low ? edge - step : edge + (integer ? 1.0 : 1e-9 * std::max(1.0, edge)));
      ExperimentConfig config;
      const auto fields = config_fields(config);
      set_number(*find_field(fields, declared.key), outside);
      EXPECT_EQ(refusal_of(config, declared.key), b.problem(integer)) << declared.key << " = " << outside;
      if (!open) {
        ExperimentConfig inside;
        const auto inside_fields = config_fields(inside);
        set_number(*find_field(inside_fields, declared.key), edge);
        EXPECT_NE(refusal_of(inside, declared.key), b.problem(integer)) << declared.key << " = " << edge;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 50) << "every bounded key's edges";
}

// Issue 39: a key accepted at any finite value reached a computation that could not take
// it (friction 1e308, a reward weight of 1e308, a tile of 1e20 m). Every number now has a
// finite bound on each side, with its default inside.
TEST(ExperimentConfig, EveryNumberKeyIsBoundedOnBothSidesAroundItsDefault) {
  int numbers = 0;
  const ExperimentConfig defaults;  // the fields point into it: it outlives the loop
  for (const ConstConfigField& field : config_fields(defaults)) {
    bool is_number = false;
    std::optional<double> value;  // none for an optional key, unset by default
    std::visit(
        [&](auto target) {
          using T = std::remove_cvref_t<std::remove_pointer_t<decltype(target)>>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int>) {
            is_number = true;
            value = static_cast<double>(*target);
          } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
            is_number = true;
          }
        },
        field.target);
    if (!is_number) continue;
    ++numbers;
    EXPECT_TRUE(std::isfinite(field.bounds.min) && std::isfinite(field.bounds.max)) << field.key;
    if (value) {
      EXPECT_TRUE(field.bounds.contains(*value)) << field.key << " = " << *value;
    }
  }
  EXPECT_GE(numbers, 60);
}

// The paper's solver iterates timeout / time_step times: each key within its bounds, the
// two together could ask for 3.6e9 iterations a solve.
TEST(ExperimentConfig, TheIkTimeoutIsBoundedInIterationsOfItsTimeStep) {
  ExperimentConfig config;
  config.settings.learning.climbing.reachability.ik.paper.timeout_s = 3600;
  config.settings.learning.climbing.reachability.ik.time_step_s = 0.002;
  EXPECT_NE(refusal_of(config, "ik.timeout").find("must be at most 100000 x ik.time_step"), std::string::npos);
  ExperimentConfig coarse;
  coarse.settings.learning.climbing.reachability.ik.paper.timeout_s = 3600;
  coarse.settings.learning.climbing.reachability.ik.time_step_s = 0.1;
  EXPECT_EQ(refusal_of(coarse, "ik.timeout"), "");
}

TEST(ExperimentConfig, BoundsSayWhatTheyTakeInWordsAndSymbols) {
  EXPECT_EQ(kPositive.problem(false), "must be positive");
  EXPECT_EQ(kNonNegative.problem(true), "must be 0 or positive");
  EXPECT_EQ(kNonNegative.summary(false), ">= 0");
  EXPECT_EQ(closed_range(1, 64).problem(true), "must be from 1 to 64");
  EXPECT_EQ(closed_range(1, 64).summary(false), "[1, 64]");
  const Bounds half_open{.min = 0, .max = 1, .max_open = true};
  EXPECT_EQ(half_open.problem(false), "must be in [0, 1)");
  EXPECT_FALSE(half_open.contains(1.0));
  EXPECT_TRUE(half_open.contains(0.0));
  EXPECT_EQ(closed_range(0, 8, "0: all").problem(true), "must be from 0 to 8 (0: all)");
  EXPECT_EQ(kAnyNumber.summary(false), "");
  EXPECT_EQ((Bounds{.min = -2, .min_open = true}).problem(false), "must be > -2");
}

TEST(ExperimentConfig, AChoiceIsParsedWhereItIsGivenAndWrittenByName) {
  ExperimentConfig config;
  apply_config_text("[ik]\nwall = \"reject\"\n[grid]\nagent_space = \"reach\"\n", "choices.toml", config,
                    kEveryKeyAndOutput, "test");
  EXPECT_EQ(config.settings.learning.climbing.reachability.ik.wall, WallRule::Reject);
  EXPECT_EQ(config.settings.learning.climbing.grid.space, AgentSpaceKind::Reach);
  EXPECT_EQ(config_value_text(config, "ik.wall"), "\"reject\"");
  try {
    apply_config_text("[ik]\nguess = 3\n", "typed.toml", config, kEveryKeyAndOutput, "test");
    FAIL() << "a choice is text";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "line 2: ik.guess must be one of previous or standing");
  }
  const auto fields = config_fields(config);
  try {
    assign_text(*find_field(fields, "learning.planner"), "greedy");
    FAIL() << "an unknown planner is refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "learning.planner");
    EXPECT_EQ(e.problem(), "unknown planner 'greedy' (expected uniform or prioritized)");
  }
}

TEST(ExperimentConfig, TheStaticModelKeepsTheBodyOutOfTheWallAndRecordsIt) {
  const ParameterSet keys{{"ik", "physics"}, {}};
  ExperimentConfig implied;
  apply_config_text("[physics]\nmodel = \"static\"\n", "static.toml", implied, keys, "test");
  finalize_config(implied);
  EXPECT_EQ(implied.settings.learning.climbing.reachability.ik.wall, WallRule::Avoid);
  EXPECT_NE(config_to_toml(implied, keys).find("wall = \"avoid\"  #"), std::string::npos)
      << "config.toml records what ran";

  ExperimentConfig contradicted;
  apply_config_text("[physics]\nmodel = \"static\"\n[ik]\nwall = \"ignore\"\n", "both.toml", contradicted, keys,
                    "test");
  EXPECT_EQ(refusal_of(contradicted, "ik.wall"),
            "must be avoid under physics.model = static (its default there): a stance that holds still keeps the "
            "body out of the wall");

  ExperimentConfig kinematic;
  finalize_config(kinematic);
  EXPECT_EQ(kinematic.settings.learning.climbing.reachability.ik.wall, WallRule::Ignore) << "the paper's default";
}

TEST(ExperimentConfig, OutputProgressIsTakenButNeverRecorded) {
  ExperimentConfig config;
  apply_config_text("[output]\nprogress = \"lines\"\n", "progress.toml", config, kEveryKeyAndOutput, "test");
  finalize_config(config);
  EXPECT_EQ(config.progress, ProgressDisplay::Lines);
  const std::string written = config_to_toml(config, kEveryKeyAndOutput);
  EXPECT_EQ(written.find("progress"), std::string::npos) << "an output folder's bytes do not depend on its display";
  EXPECT_EQ(written.find("[output]"), std::string::npos);
  ExperimentConfig refused;
  EXPECT_THROW(
      apply_config_text("[output]\nprogress = \"quiet\"\n", "progress.toml", refused, kEveryKeyAndOutput, "test"),
      InputError);
}

}  // namespace
}  // namespace crux

// The crux binary end to end: JSON keys, one-line errors and exit codes.

#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "support/repository_docs.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(Cli, ModelJsonHasTheDocumentedKeys) {
  const testing::Outcome run = testing::run_crux("model --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["dof_root"], 3);
  EXPECT_EQ(json["dof_revolute"], 32);
  EXPECT_NEAR(json["height_m"].get<double>(), 1.70, 0.005);
  EXPECT_GT(json["mass_kg"].get<double>(), 0.0);
  ASSERT_EQ(json["joints"].size(), 32u);
  for (const auto& joint : json["joints"]) {
    EXPECT_TRUE(joint.contains("name"));
    EXPECT_LT(joint["lower"].get<double>(), joint["upper"].get<double>());
  }
}

TEST(Cli, BadModelIsOneLineAndExitCode2) {
  const auto bad = testing::write_temporary("cli_bad.urdf", "<robot name='x'><link name='a'/>");
  for (const std::string& command :
       std::vector<std::string>{"model --urdf " + bad.string(), "model --urdf /nonexistent.urdf",
                                "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --urdf " + bad.string()}) {
    const testing::Outcome run = testing::run_crux(command);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << run.err;
    EXPECT_EQ(run.err.rfind("crux: ", 0), 0u) << run.err;
    EXPECT_TRUE(run.out.empty());
  }
}

TEST(Cli, BadArgumentsExitWithCode2) {
  for (const std::string command :
       {"ik --rh 0.3 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0", "ik --rh 0.3,1.5",
        "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --ik-solver kdl", "frobnicate"}) {
    const testing::Outcome run = testing::run_crux(command);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << run.err;
  }
  const testing::Outcome too_large = testing::run_crux("plan --wall-seed 3 --plan-max-solves 99999999999");
  EXPECT_EQ(too_large.exit_code, 2);
  EXPECT_EQ(too_large.err.rfind("crux: --plan-max-solves: '99999999999' is out of range", 0), 0u) << too_large.err;
  const testing::Outcome huge_grid =
      testing::run_crux("train --wall-seed 3 --grid-columns 65536 --grid-rows 65536 --iterations 5 -o " +
                        (testing::test_folder() / "never").string());
  EXPECT_EQ(huge_grid.exit_code, 2) << huge_grid.err;
  EXPECT_EQ(huge_grid.err.rfind("crux: --grid-columns: ", 0), 0u) << huge_grid.err;
}

// The static model's parameters: one line naming the flag, exit code 2, nothing written.
TEST(Cli, BadPhysicsParametersAreOneLineNamingTheFlag) {
  const std::filesystem::path never = testing::temporary_path("physics_never");
  const struct {
    std::string flags, message;
  } cases[] = {
      {"--physics-model quantum",
       "crux: --physics-model: unknown model 'quantum' (expected kinematic, static or dynamic)"},
      {"--physics-friction -0.5",
       "crux: --physics-friction: must be in [0, 10] (ten times rubber on rock; the equilibrium program stays "
       "well conditioned)"},
      {"--physics-grip 0", "crux: --physics-grip: must be in (0, 10000] (17 times elite climbers' mean finger force)"},
      {"--physics-strength pro",
       "crux: --physics-strength: unknown strength 'pro' (expected intermediate (383.0 N), advanced (575.7 N) or elite "
       "(563.1 N))"},
      {"--physics-support-angle 91", "crux: --physics-support-angle: must be in [-90, 90]"},
      {"--reward-effort 1", "crux: --reward-effort: needs physics.model = static: the kinematic model has no effort"},
      {"--physics-model static --reward-effort -1",
       "crux: --reward-effort: must be in [0, 1000000000] (a run's sums of rewards must stay finite)"},
      {"--reward-height -1",
       "crux: --reward-height: must be in [0, 1000000000] (a run's sums of rewards must stay finite)"},
      {"--ik-guess last", "crux: --ik-guess: unknown guess 'last' (expected previous or standing)"},
      {"--plan-check-moves true",
       "crux: --plan-check-moves: needs physics.model = static or dynamic: the kinematic model checks no stance"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> commands;
    if (c.flags.find("plan") == std::string::npos) {
      commands.push_back("train --wall-seed 3 --iterations 5 -o " + never.string() + " " + c.flags);
    }
    if (c.flags.find("reward") == std::string::npos) commands.push_back("plan --wall-seed 3 " + c.flags);
    for (const std::string& command : commands) {
      const testing::Outcome run = testing::run_crux(command);
      EXPECT_EQ(run.exit_code, 2) << command;
      EXPECT_EQ(run.err, c.message + "\n") << command;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(never));
}

// Issue 39's reports, as typed: each key was accepted at a value that a computation
// downstream could not take (CLP failing or running for minutes, NaN rewards written, a
// figure hanging). Each is now one line naming the flag or the file's line, exit 2,
// nothing written.
TEST(Cli, TheValuesIssue39FoundUnboundedAreRefusedBeforeAnyOutput) {
  const std::filesystem::path never = testing::temporary_path("issue39_never");
  const std::string wall = CRUX_SOURCE_DIR "/walls/home_12.json";
  const std::string friction_sweep =
      testing::write_temporary("issue39_friction.toml",
                               "[physics]\nmodel = \"static\"\nfriction = [1.0, 1e20]\n[experiment]\nwalls = 1\n")
          .string();
  const std::string strength_sweep =
      testing::write_temporary("issue39_strength.toml", "[physics]\nstrength = [\"\", \"elite\"]\n").string();
  const struct {
    std::string command, message_start;
  } cases[] = {
      {"train --wall-file " + wall + " --iterations 50 --physics-model static --physics-friction 1e308 -o " +
           never.string(),
       "crux: --physics-friction: must be in [0, 10]"},
      {"plan --wall-file " + wall + " --physics-model static --physics-friction 1e20",
       "crux: --physics-friction: must be in [0, 10]"},
      {"stances --physics-friction 1e15", "crux: --physics-friction: must be in [0, 10]"},
      {"train --wall-seed 1 --iterations 300 --reward-height 1e308 -o " + never.string(),
       "crux: --reward-height: must be in [0, 1000000000]"},
      {"paper --walls 1 --iterations 200 --plan false --grid-tile-height 1e20 -o " + never.string(),
       "crux: --grid-tile-height: must be in [0.01, 10]"},
      {"paper --walls 1 --iterations 200 --plan false --grid-agent-space reach --grid-tile-height 1e10 -o " +
           never.string(),
       "crux: --grid-tile-height: must be in [0.01, 10]"},
      {"train --wall-seed 1 --physics-model static --physics-strength '' -o " + never.string(),
       "crux: --physics-strength: unknown strength ''"},
      {"sweep -o " + never.string() + " --config " + friction_sweep,
       "crux: " + friction_sweep + ": line 3: physics.friction: must be in"},
      {"sweep -o " + never.string() + " --config " + strength_sweep,
       "crux: " + strength_sweep + ": line 2: physics.strength: unknown strength ''"},
  };
  for (const auto& c : cases) {
    const testing::Outcome run = testing::run_crux(c.command);
    EXPECT_EQ(run.exit_code, 2) << c.command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << c.command << ": " << run.err;
    EXPECT_EQ(run.err.rfind(c.message_start, 0), 0u) << c.command << ": " << run.err;
    EXPECT_FALSE(std::filesystem::exists(never)) << c.command;
  }
}

// crux stances surveys the stances of kinematic climbs under the static model's
// parameters: its JSON adds up, and its own bound is one line naming the flag.
TEST(Cli, StancesSurveysAndRefusesABadMoveCount) {
  const testing::Outcome run = testing::run_crux("stances --wall-count 2 --stances-moves 40 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["format"], "crux-stances");
  EXPECT_EQ(json["moves_per_wall"], 40);
  EXPECT_GT(json["stances"].get<int>(), 0);
  int failures = 0;
  for (const auto& [name, count] : json["four_failures"].items()) failures += count.get<int>();
  EXPECT_EQ(json["four_held"].get<int>() + failures, json["stances"].get<int>());
  const testing::Outcome refused = testing::run_crux("stances --stances-moves 0");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "crux: --stances-moves: must be from 1 to 100000\n");
}

// crux view under the static model draws and lists what holds the posture; a run's
// physics come from its own config, so --physics-* beside --run is refused.
TEST(Cli, ViewUnderTheStaticModelShowsTheLoads) {
  const std::filesystem::path svg = testing::temporary_path("static_view.svg");
  const testing::Outcome run =
      testing::run_crux(std::string("view --wall-file " CRUX_SOURCE_DIR "/walls/home_12.json") +
                        " --physics-model static --json -o " + svg.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["stance"]["feasible"], true);
  EXPECT_EQ(json["stance"]["contact_forces_n"].size(), 4u);
  EXPECT_NE(json["subtitle"].get<std::string>().find("static model: held at effort"), std::string::npos);
  std::ifstream file(svg);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("class=\"contact-forces\""), std::string::npos);
  const testing::Outcome refused =
      testing::run_crux("view --run " + testing::test_folder().string() + " --physics-model static -o " + svg.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "crux: --physics-model: not used with --run: a run is drawn with its own config.toml\n");
}

// A refused value is quoted on one line with its control bytes escaped: a newline in it
// cannot make two lines, nor an escape byte reach the terminal.
TEST(Cli, RefusedValuesAreQuotedEscaped) {
  const std::string value = "'q\n\x1b[31m'";  // in single quotes for the shell
  const std::string escaped = "q\\x0a\\x1b[31m";
  const std::filesystem::path sweep =
      testing::write_temporary("escaped_sweep.toml", "[experiment]\ntransfer = [\"paper\", \"q\\n\\u001b[31m\"]\n");
  const std::filesystem::path reading =
      testing::write_temporary("escaped_reading.toml", "[filter]\nreading = \"q\\n\\u001b[31m\"\n");
  const std::filesystem::path never = testing::temporary_path("escaped_never");
  for (const std::string& command :
       {"plan --wall-seed 3 --ik-solver " + value,
        "train --wall-seed 3 --learning-planner " + value + " -o " + never.string(),
        "paper --transfer " + value + " -o " + never.string(), "plan --wall-seed 3 --config " + reading.string(),
        "sweep --config " + sweep.string() + " -o " + never.string(), "plan --wall-seed " + value,
        "plan --wall-seed 3 --wall-fil" + value, "pl" + value}) {
    const testing::Outcome run = testing::run_crux(command);
    EXPECT_EQ(run.exit_code, 2) << command;
    EXPECT_EQ(testing::count_lines(run.err), 1) << run.err;
    EXPECT_NE(run.err.find(escaped), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\x1b'), std::string::npos) << run.err;
  }
  EXPECT_FALSE(std::filesystem::exists(never));
}

TEST(Cli, IkReportsTheIssuesKeysForBothSolvers) {
  for (const std::string solver : {"paper", "fast"}) {
    const testing::Outcome run =
        testing::run_crux("ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --json --ik-solver " + solver);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["solver"], solver);
    EXPECT_TRUE(json["reached"].get<bool>());
    EXPECT_GT(json["iterations"].get<int>(), 0);
    EXPECT_GT(json["simulated_time_s"].get<double>(), 0.0);
    EXPECT_LE(json["residual_m"].get<double>(), 0.08);
  }
}

TEST(Cli, IkOnUnreachableHoldsSaysSo) {
  const testing::Outcome run =
      testing::run_crux("ik --rh 0.3,4.5 --lh 0.9,4.5 --rf 0.3,0 --lf 0.9,0 --json --ik-solver fast");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(nlohmann::json::parse(run.out)["reached"].get<bool>());
}

TEST(Cli, IkCompareReportsAgreement) {
  const testing::Outcome run = testing::run_crux("ik-compare --compare-queries 30 --seed 3 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = nlohmann::json::parse(run.out);
  EXPECT_EQ(json["queries"], 30);
  const double agreement = json["agreement"].get<double>();
  EXPECT_GE(agreement, 0.0);
  EXPECT_LE(agreement, 1.0);
  EXPECT_LE(json["paper_reached"].get<int>(), 30);
  EXPECT_LE(json["fast_reached"].get<int>(), 30);
}

TEST(Cli, IkPathIsWrittenAsCsv) {
  const auto out = testing::test_folder() / "path.csv";
  std::filesystem::remove(out);
  const testing::Outcome run = testing::run_crux(
      "ik --rh 0.3,1.5 --lh 0.9,1.5 --rf 0.3,0 --lf 0.9,0 --ik-solver paper --path-every 5 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(std::filesystem::exists(out));
  EXPECT_GT(std::filesystem::file_size(out), 100u);
}

// docs/OUTPUTS.md's smallest legal wall, which the wall errors below start from.
const std::string kFourHoldWall = R"({
  "format": "crux-wall",
  "version": 1,
  "name": "four holds",
  "finish_height": 1.5,
  "start": {"right_hand": 3, "left_hand": 4, "right_foot": 1, "left_foot": 2},
  "holds": [
    {"id": 1, "position": [0.0, 0.3, 0.2], "radius": 0.04},
    {"id": 2, "position": [0.0, 0.9, 0.2], "radius": 0.04},
    {"id": 3, "position": [0.0, 0.35, 1.7], "radius": 0.04},
    {"id": 4, "position": [0.0, 0.85, 1.7], "radius": 0.04}
  ]
}
)";

// Every error line the docs quote, with a command and files that make crux print it: the
// docs must quote it as crux prints it, word for word, and crux must print it alone, on
// stderr, with exit code 2.
TEST(Cli, TheDocsQuoteErrorLinesAsCruxPrintsThem) {
  struct QuotedError {
    std::vector<std::string> docs;
    std::string line;
    std::string command;
    std::vector<std::pair<std::string, std::string>> files;
  };
  const std::string train = "train --wall-seed 3 --iterations 10 --config my.toml -o out";
  const std::vector<QuotedError> quoted{
      {{"README.md", "docs/DESIGN.md", "docs/OUTPUTS.md"},
       "crux: --runs: must be from 1 to 1000000",
       "paper --runs 0",
       {}},
      {{"README.md"},
       "crux: wall.json: holds[3].radius must be positive, got -0.01",
       "wall show --wall-file wall.json",
       {{"wall.json",
         testing::replaced(kFourHoldWall, "0.85, 1.7], \"radius\": 0.04", "0.85, 1.7], \"radius\": -0.01")}}},
      {{"README.md", "docs/DESIGN.md", "docs/OUTPUTS.md"},
       "crux: my.toml: line 3: learning.gamma: must be in [0, 1)",
       train,
       {{"my.toml", "[learning]\nalpha = 0.1\ngamma = 1.5\n"}}},
      {{"docs/DESIGN.md", "docs/OUTPUTS.md"},
       "crux: unknown command 'trian' (did you mean 'train'?) (see 'crux --help')",
       "trian",
       {}},
      {{"docs/OUTPUTS.md"}, "crux: unknown option --runs of 'crux plan' (see 'crux plan --help')", "plan --runs 3", {}},
      {{"docs/OUTPUTS.md"},
       "crux: unknown option --wall-fil of 'crux plan' (did you mean '--wall-file'?) (see 'crux plan --help')",
       "plan --wall-fil wall.json",
       {}},
      {{"docs/OUTPUTS.md"},
       "crux: --ik-solver: unknown solver 'quick' (expected fast or paper)",
       "plan --wall-seed 3 --ik-solver quick",
       {}},
      {{"docs/OUTPUTS.md"},
       "crux: my.toml: line 2: crux plan does not take experiment.iterations",
       "plan --wall-seed 3 --config my.toml",
       {{"my.toml", "[experiment]\niterations = 5\n"}}},
      {{},
       "crux: my.toml: line 2: crux plan does not take wall.count",
       "plan --wall-seed 3 --config my.toml",
       {{"my.toml", "[wall]\ncount = 2\n"}}},
      {{"docs/OUTPUTS.md"},
       "crux: my.toml: line 2: unknown key walls.sigma (it is now wall.sigma)",
       "plan --wall-seed 3 --config my.toml",
       {{"my.toml", "[walls]\nsigma = 0.1\n"}}},
      {{"docs/OUTPUTS.md"},
       "crux: my.toml: line 2: learning.alpha must be a finite number",
       train,
       {{"my.toml", "[learning]\nalpha = nan\n"}}},
      {{"docs/OUTPUTS.md"},
       "crux: my.toml: line 5: learning.epsilon must be one value; only crux sweep takes lists",
       "paper --config my.toml -o out",
       {{"my.toml", "[experiment]\nwalls = 2\n\n[learning]\nepsilon = [0.1, 0.2]\n"}}},
      {{"docs/OUTPUTS.md"},
       "crux: walls/mine.json: holds[3].radius must be positive, got -0.01",
       "wall show --wall-file walls/mine.json",
       {{"walls/mine.json",
         testing::replaced(kFourHoldWall, "0.85, 1.7], \"radius\": 0.04", "0.85, 1.7], \"radius\": -0.01")}}},
      {{"docs/OUTPUTS.md"},
       "crux: walls/mine.json: unknown key \"finsh_height\" at the top level (allowed: format, version, name, "
       "finish_height, start, holds)",
       "wall show --wall-file walls/mine.json",
       {{"walls/mine.json", testing::replaced(kFourHoldWall, "\"finish_height\"", "\"finsh_height\"")}}},
      {{"docs/OUTPUTS.md"},
       "crux: walls/mine.json: JSON syntax error at line 3, column 16: unexpected ','; expected string literal",
       "wall show --wall-file walls/mine.json",
       {{"walls/mine.json", testing::replaced(kFourHoldWall, "\"version\": 1,", "\"version\": 1,,")}}},
      {{"docs/OUTPUTS.md"},
       "crux: walls/mine.json: start.right_hand and start.left_foot both name hold 3; each limb needs its own hold",
       "wall show --wall-file walls/mine.json",
       {{"walls/mine.json", testing::replaced(kFourHoldWall, "\"left_foot\": 2", "\"left_foot\": 3")}}},
  };
  const std::filesystem::path four_holds = testing::temporary_path("cli-docs-four-holds");
  std::filesystem::create_directories(four_holds);
  std::ofstream(four_holds / "wall.json") << kFourHoldWall;
  ASSERT_EQ(testing::run_crux_in(four_holds, "wall show --wall-file wall.json").exit_code, 0)
      << "the docs' four-hold wall loads as it is";
  for (std::size_t i = 0; i < quoted.size(); ++i) {
    const QuotedError& q = quoted[i];
    for (const std::string& doc : q.docs) {
      EXPECT_TRUE(testing::quotes(testing::repository_file(doc), q.line)) << doc << " does not quote " << q.line;
    }
    const std::filesystem::path folder = testing::temporary_path("cli-docs-error-" + std::to_string(i));
    std::filesystem::create_directories(folder / "walls");
    for (const auto& [name, contents] : q.files) std::ofstream(folder / name) << contents;
    const testing::Outcome run = testing::run_crux_in(folder, q.command);
    EXPECT_EQ(run.exit_code, 2) << q.command;
    EXPECT_EQ(run.err, q.line + "\n") << q.command;
    EXPECT_FALSE(std::filesystem::exists(folder / "out")) << q.command << ": nothing written";
  }
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

// output.progress: the display changes stderr only. Under ctest stderr is a pipe, so
// bar shows nothing there (as before the key), lines a line per 10 %, none nothing.
TEST(Cli, OutputProgressChangesStderrOnly) {
  const std::string command = "filter-stats --wall-count 10 --wall-seed 2";
  const testing::Outcome bar = testing::run_crux(command);
  const testing::Outcome lines = testing::run_crux(command + " --output-progress lines");
  const testing::Outcome none = testing::run_crux(command + " --output-progress none");
  ASSERT_EQ(bar.exit_code, 0) << bar.err;
  EXPECT_EQ(bar.err, "");
  EXPECT_EQ(none.err, "");
  EXPECT_NE(lines.err.find("filter-stats ["), std::string::npos) << lines.err;
  EXPECT_NE(lines.err.find("100% (10/10)\n"), std::string::npos) << lines.err;
  EXPECT_LE(std::count(lines.err.begin(), lines.err.end(), '\n'), 11) << "a line per 10 %";
  EXPECT_EQ(lines.out, bar.out);
  EXPECT_EQ(none.out, bar.out);
  const testing::Outcome refused = testing::run_crux(command + " --output-progress quiet");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err, "crux: --output-progress: unknown progress 'quiet' (expected bar, lines or none)\n");
  EXPECT_NE(testing::run_crux("filter-stats --help").out.find("--output-progress"), std::string::npos);
}

}  // namespace
}  // namespace crux

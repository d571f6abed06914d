// crux ik and crux ik-compare: one reaching query, and the agreement of the two solvers.

#include <iostream>
#include <memory>
#include <string>

#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/run_inputs.hpp"
#include "ik/reach_queries.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/posture_csv.hpp"
#include "reports/ik_description.hpp"

namespace crux::cli {

namespace {

// The IK parameters; ik-compare runs both solvers, so it takes no ik.solver.
const ParameterSet kIkCommandKeys{{"experiment.urdf", "ik"}, {"ik.cache_unreachable", "ik.guess"}};
const ParameterSet kIkCompareKeys{{"experiment.urdf", "experiment.seed", "ik", "compare", "output.progress"},
                                  {"ik.solver", "ik.cache_unreachable", "ik.guess"}};

struct IkCommand {
  ParameterBinding binding{"ik", kIkCommandKeys};
  std::array<std::string, kLimbCount> holds;
  int path_every = 10;
  std::string path_output;
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const IkParameters& settings = config.settings.learning.climbing.reachability.ik;
    if (path_every <= 0) throw InputError("--path-every", "must be positive");
    if (!path_output.empty()) check_output_file(path_output, {configured_urdf_path(config), binding.config_path()});
    const BodyModel model = load_configured_body(config);
    static const char* const flags[kLimbCount] = {"--rh", "--lh", "--rf", "--lf"};
    ReachTarget target;
    for (int limb = 0; limb < kLimbCount; ++limb)
      target.hold_centres[limb] = parse_wall_point(holds[limb], flags[limb]);
    target.root = root_target(model, target.hold_centres, config.settings.learning.climbing.reachability.root);
    BodyData data(model);
    std::vector<Posture> path;
    const PathRecorder recorder{path_output.empty() ? nullptr : &path, path_every};
    const IkResult result = solve_ik(model, data, standing_posture(target.root), target, settings, recorder);
    if (!path_output.empty()) write_file_atomically(path_output, posture_csv(model, path, "sample"));
    std::cout << (json ? ik_result_json(model, settings.solver, target, result).dump(2) + "\n"
                       : ik_result_text(model, settings.solver, target, result));
  }
};

// ik-compare's own keys: its climbing-like queries, and the solver whose reached
// postures start the walk's next queries.
struct CompareOptions {
  int queries = 2000;
  IkSolverKind walk_solver = IkSolverKind::Paper;
};

std::vector<ConfigField> compare_fields(CompareOptions& options) {
  return {{"compare.queries", "Climbing-like queries that ik-compare gives both solvers", &options.queries, "",
           work_size(1, 10000000)},
          {"compare.walk_solver", "Solver whose reached postures start the next queries of ik-compare's climbing walk",
           choice_of(&options.walk_solver)}};
}

struct IkCompareCommand {
  CompareOptions options;
  ParameterBinding binding{"ik-compare", kIkCompareKeys};
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const IkParameters& settings = config.settings.learning.climbing.reachability.ik;
    const BodyModel model = load_configured_body(config);
    IkParameters walk = settings;
    walk.solver = options.walk_solver;
    // The queries are the same whatever the wall rule, so that rules compare on one set.
    walk.wall = WallRule::Ignore;
    ReachQueryParameters query_settings;
    query_settings.root = config.settings.learning.climbing.reachability.root;
    const auto batch = climbing_reach_queries(model, walk, options.queries, config.settings.seed, query_settings);
    ProgressBar progress("ik-compare", options.queries, config.progress);
    const SolverAgreement a = compare_solvers(model, batch, settings, [&](int done) { progress.update(done); });
    progress.finish();
    std::cout << (json ? solver_agreement_json(a, config.settings.seed).dump(2) + "\n"
                       : solver_agreement_text(a, config.settings.seed));
  }
};

}  // namespace

void add_ik_commands(CLI::App& app) {
  auto ik = std::make_shared<IkCommand>();
  auto* command = app.add_subcommand(
      "ik", "Solve one reaching query: four hold centres on the wall plane, root target H(C4), from standing");
  static const char* const limb_help[kLimbCount] = {"Right hand hold centre Y,Z (m)", "Left hand hold centre Y,Z (m)",
                                                    "Right foot hold centre Y,Z (m)", "Left foot hold centre Y,Z (m)"};
  static const char* const flags[kLimbCount] = {"--rh", "--lh", "--rf", "--lf"};
  for (int limb = 0; limb < kLimbCount; ++limb)
    command->add_option(flags[limb], ik->holds[limb], limb_help[limb])->required();
  ik->binding.bind(command);
  command->add_flag("--json", ik->json, "Print JSON instead of text");
  command->add_option("-o,--output", ik->path_output, "Write the posture path (CSV, one sample per row) to this file");
  command->add_option("--path-every", ik->path_every, "Sample the path every k iterations")->capture_default_str();
  command->callback([ik] { ik->run(); });

  auto compare = std::make_shared<IkCompareCommand>();
  auto* compare_command = app.add_subcommand(
      "ik-compare", "Run both solvers on climbing-like queries and measure how often their verdicts agree");
  compare->binding.add_command_options(compare->options, compare_fields);
  compare->binding.bind(compare_command);
  compare_command->add_flag("--json", compare->json, "Print JSON instead of text");
  compare_command->callback([compare] { compare->run(); });
}

}  // namespace crux::cli

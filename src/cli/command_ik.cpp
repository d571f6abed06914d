// crux ik and crux ik-compare: one reaching query, and the agreement of the two solvers.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "body/kinematics.hpp"
#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "ik/ik_solver.hpp"
#include "ik/reach_queries.hpp"
#include "ik/solver_agreement.hpp"
#include "ik/root_target.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/posture_csv.hpp"

namespace crux::cli {

namespace {

// The IK parameters; ik-compare runs both solvers, so it takes no ik.solver.
const ParameterSet kIkParameters{{"experiment.urdf", "ik"}, {"ik.cache_unreachable"}};
const ParameterSet kIkCompareParameters{{"experiment.urdf", "experiment.seed", "ik"},
                                        {"ik.solver", "ik.cache_unreachable"}};

nlohmann::ordered_json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

struct IkCommand {
  ParameterBinding binding{"ik", kIkParameters};
  std::array<std::string, kLimbCount> holds;
  int path_every = 10;
  std::string path_out;
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const IkSettings& settings = config.settings.learning.climbing.reachability.ik;
    if (path_every <= 0) throw InputError("--path-every", "must be positive");
    const BodyModel model = load_configured_body(config);
    static const char* const flags[kLimbCount] = {"--rh", "--lh", "--rf", "--lf"};
    ReachTarget target;
    for (int limb = 0; limb < kLimbCount; ++limb) target.hold_centres[limb] = parse_wall_point(holds[limb], flags[limb]);
    target.root = root_target(model, target.hold_centres, config.settings.learning.climbing.reachability.root);
    BodyData data(model);
    std::vector<Posture> path;
    const PathRecorder recorder{path_out.empty() ? nullptr : &path, path_every};
    const IkResult result = solve_ik(model, data, standing_posture(target.root), target, settings, recorder);
    if (!path_out.empty()) write_file_atomically(path_out, posture_csv(model, path, "sample"));
    forward_kinematics(model, data, result.posture);
    if (json) {
      nlohmann::ordered_json out;
      out["solver"] = ik_solver_name(settings.solver);
      out["reached"] = result.reached;
      out["iterations"] = result.iterations;
      out["simulated_time_s"] = result.simulated_time_s;
      out["residual_m"] = result.residual_m;
      out["root_target"] = vector_json(target.root);
      out["root"] = vector_json(data.points[0]);
      out["grasp_points"] = nlohmann::json::array();
      for (int limb = 0; limb < kLimbCount; ++limb) out["grasp_points"].push_back(vector_json(data.points[operational_point(limb)]));
      out["centre_of_mass"] = vector_json(centre_of_mass(model, data));
      out["posture"] = std::vector<double>(result.posture.data(), result.posture.data() + kConfigurationDof);
      std::cout << out.dump(2) << '\n';
      return;
    }
    std::cout << fmt::format("solver {}: {} after {} iterations ({:.2f} s simulated), residual {:.4f} m\n",
                             ik_solver_name(settings.solver), result.reached ? "reached" : "NOT reached",
                             result.iterations, result.simulated_time_s, result.residual_m)
              << fmt::format("root target H(C4) = ({:.3f}, {:.3f}, {:.3f}); root at ({:.3f}, {:.3f}, {:.3f})\n",
                             target.root.x(), target.root.y(), target.root.z(), data.points[0].x(),
                             data.points[0].y(), data.points[0].z());
    if (!result.reached) std::cout << "returned the initial posture G_init, as Algorithm 1 does on time-out\n";
  }
};

struct IkCompareCommand {
  ParameterBinding binding{"ik-compare", kIkCompareParameters};
  int queries = 2000;
  std::string walk_solver = "paper";
  bool json = false;

  void run() {
    const ExperimentConfig config = binding.resolve();
    const IkSettings& settings = config.settings.learning.climbing.reachability.ik;
    const std::uint64_t seed = config.settings.seed;
    if (queries <= 0) throw InputError("--queries", "must be positive");
    const BodyModel model = load_configured_body(config);
    IkSettings walk = settings;
    walk.solver = require_ik_solver(walk_solver, "--walk-solver");
    ReachQuerySettings query_settings;
    query_settings.root = config.settings.learning.climbing.reachability.root;
    const auto batch = climbing_reach_queries(model, walk, queries, seed, query_settings);
    ProgressBar progress("ik-compare", queries);
    const SolverAgreement a = compare_solvers(model, batch, settings, [&](int done) { progress.update(done); });
    progress.finish();
    if (json) {
      nlohmann::ordered_json out;
      out["queries"] = a.queries;
      out["seed"] = seed;
      out["agreement"] = a.agreement();
      out["paper_reached"] = a.paper_reached;
      out["fast_reached"] = a.fast_reached;
      out["only_paper_reached"] = a.only_paper_reached;
      out["only_fast_reached"] = a.only_fast_reached;
      out["far_queries"] = a.far_queries;
      out["paper_mean_iterations"] = static_cast<double>(a.paper_iterations) / a.queries;
      out["fast_mean_iterations"] = static_cast<double>(a.fast_iterations) / a.queries;
      out["paper_mean_us"] = 1e6 * a.paper_seconds / a.queries;
      out["fast_mean_us"] = 1e6 * a.fast_seconds / a.queries;
      std::cout << out.dump(2) << '\n';
      return;
    }
    std::cout << fmt::format("{} climbing-like queries (seed {}, {} of them clearly unreachable)\n", a.queries, seed,
                             a.far_queries)
              << fmt::format("paper solver reached {} ({:.1f} %), fast solver reached {} ({:.1f} %)\n", a.paper_reached,
                             100.0 * a.paper_reached / a.queries, a.fast_reached, 100.0 * a.fast_reached / a.queries)
              << fmt::format("verdicts agree on {} queries: {:.2f} % (only paper reached {}, only fast reached {})\n",
                             a.agree, 100.0 * a.agreement(), a.only_paper_reached, a.only_fast_reached)
              << fmt::format("mean per query: paper {:.1f} iterations, {:.1f} us; fast {:.1f} iterations, {:.1f} us\n",
                             static_cast<double>(a.paper_iterations) / a.queries, 1e6 * a.paper_seconds / a.queries,
                             static_cast<double>(a.fast_iterations) / a.queries, 1e6 * a.fast_seconds / a.queries);
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
  for (int limb = 0; limb < kLimbCount; ++limb) command->add_option(flags[limb], ik->holds[limb], limb_help[limb])->required();
  ik->binding.bind(command);
  command->add_flag("--json", ik->json, "Print JSON instead of text");
  command->add_option("--path-out", ik->path_out, "Write the posture path (CSV, one sample per row) to this file");
  command->add_option("--path-every", ik->path_every, "Sample the path every k iterations")->capture_default_str();
  command->callback([ik] { ik->run(); });

  auto compare = std::make_shared<IkCompareCommand>();
  auto* compare_command = app.add_subcommand(
      "ik-compare", "Run both solvers on climbing-like queries and measure how often their verdicts agree");
  compare_command->add_option("--queries", compare->queries, "Number of queries")->capture_default_str();
  compare_command->add_option("--walk-solver", compare->walk_solver,
                              "Solver whose reached postures start the next queries of the climbing walk")
      ->capture_default_str();
  compare->binding.bind(compare_command);
  compare_command->add_flag("--json", compare->json, "Print JSON instead of text");
  compare_command->callback([compare] { compare->run(); });
}

}  // namespace crux::cli

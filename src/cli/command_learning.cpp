// crux paper | train | transfer | plan: learning to climb and transfer (section IV).

#include <chrono>
#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "experiments/learning_parameters.hpp"
#include "experiments/run_checkpoint.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/output_folder.hpp"
#include "reports/plan_description.hpp"
#include "reports/summary.hpp"
#include "reports/text_report.hpp"

namespace crux::cli {

namespace {

const ParameterSet kPlanParameters{{"experiment.urdf", "experiment.plan_max_solves", "ik", "filter", "wall"}, {"wall.name", "wall.count"}};

// The replayed config's recorded digests must match the inputs used now.
Provenance checked_provenance(const ExperimentConfig& config, const ParameterBinding& binding) {
  Provenance provenance = record_provenance(config);
  if (!binding.config_path().empty()) check_recorded_provenance(config, provenance, binding.config_path());
  return provenance;
}

void require_wall(const ExperimentConfig& config) {
  if (config.wall_file.empty() && !config.wall_seed) {
    throw InputError("--wall-file", "give a wall: a file (--wall-file FILE) or a seed (--wall-seed N)");
  }
}

// The files a command reads: none may lie in its output folder.
std::vector<std::string> inputs_of(const ExperimentConfig& config, const ParameterBinding& binding) {
  return {config.urdf, config.wall_file, config.q_grid, binding.config_path()};
}

struct PaperCommand {
  ParameterBinding binding{"paper", kPaperParameters};
  std::string output = "out/paper";
  bool json = false;
  bool overwrite = false;

  void run() {
    ExperimentConfig config = binding.resolve();
    const Provenance provenance = checked_provenance(config, binding);
    const BodyModel model = load_configured_body(config);
    const ExperimentSettings& settings = config.settings;
    const std::string config_toml = config_file_text(config, binding.accepted(), provenance);
    check_output_folder(output, inputs_of(config, binding), overwrite);
    ProgressBar progress(fmt::format("paper: {} x {} x 3 conditions", counted(settings.wall_pairs, "wall"),
                                     counted(settings.seeds_per_wall, "seed")),
                         3L * settings.runs());
    const ExperimentResult result = run_paper_experiment(model, settings, [&](int done) { progress.update(done); });
    progress.finish();
    const ExperimentAnalysis analysis = analyse_experiment(result, settings);
    const nlohmann::ordered_json summary = summary_json(result, &analysis, settings, provenance);
    write_experiment_folder(output, result, settings, model, config_toml, summary);
    if (json) {
      std::cout << summary.dump(2) << '\n';
      return;
    }
    std::cout << experiment_text(result, analysis, settings)
              << fmt::format("\nwrote {} ({:.1f} s)\n", output, result.seconds);
  }
};

struct SingleRunCommand {
  ParameterBinding binding;
  Condition condition;
  std::string output;
  bool json = false;
  bool overwrite = false;

  void run() {
    ExperimentConfig config = binding.resolve();
    require_wall(config);
    if (condition == Condition::Transfer && config.q_grid.empty()) {
      throw InputError("--q-grid", "give the Q_grid to transfer (q_grid.bin of a training run)");
    }
    const Provenance provenance = checked_provenance(config, binding);
    const BodyModel model = load_configured_body(config);
    const Wall wall = load_configured_wall(config);
    std::optional<QTable> initial;
    if (condition == Condition::Transfer) initial = load_q_grid(config.q_grid, config.settings.learning.climbing.grid);
    const std::string config_toml = config_file_text(config, binding.accepted(), provenance);
    // A checkpoint resumes the run whose parameters and inputs it records, whatever
    // its checkpoint interval.
    ParameterSet identity_keys = binding.accepted();
    identity_keys.exclude.push_back("experiment.checkpoint_every");
    const std::string identity = config_file_text(config, identity_keys, provenance);
    const std::filesystem::path checkpoint_file = std::filesystem::path(output) / kCheckpointFile;
    RunCheckpoints checkpoints{config.checkpoint_every, {}, {}, checkpoint_file.string()};
    // What a SIGKILL left half-written is no output: a folder killed while it wrote its
    // first checkpoint starts again.
    remove_crux_temporaries(output);
    if (!overwrite) checkpoints.resume = read_checkpoint(checkpoint_file, identity).value_or("");
    check_output_folder(output, inputs_of(config, binding), overwrite || !checkpoints.resume.empty());
    checkpoints.save = [&](std::string state, int) {
      write_checkpoint(output, checkpoint_file_bytes(identity, state));
    };
    ProgressBar progress(condition_name(condition), config.settings.learning.iterations);
    const auto start = std::chrono::steady_clock::now();
    RunResult run = run_learning(model, wall, config.settings.learning, config.settings.seed,
                                 initial ? &*initial : nullptr, [&](int done) { progress.update(done); }, &checkpoints);
    progress.finish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const ExperimentResult result =
        single_run_result(std::move(run), wall, config.wall_seed, config.settings.seed, condition, seconds);
    const nlohmann::ordered_json summary = summary_json(result, nullptr, config.settings, provenance);
    write_run_folder(output, result, model, config.settings.learning.climbing.grid, config_toml, summary);
    std::cout << (json ? summary.dump(2) + "\n" : run_text(result, config.settings.learning.iterations, output));
  }
};

struct PlanCommand {
  ParameterBinding binding{"plan", kPlanParameters};
  bool json = false;

  void run() {
    ExperimentConfig config = binding.resolve();
    require_wall(config);
    const BodyModel model = load_configured_body(config);
    const Wall wall = load_configured_wall(config);
    const Plan plan = shortest_plan(model, wall, config.settings.learning.climbing, config.settings.plan_search);
    std::cout << (json ? plan_json(wall, plan).dump(2) + "\n" : plan_text(wall, plan));
  }
};

void add_single_run_command(CLI::App& app, const char* name, const char* description, Condition condition,
                            const ParameterSet& parameters) {
  auto command = std::make_shared<SingleRunCommand>(
      SingleRunCommand{ParameterBinding(name, parameters), condition, fmt::format("out/{}", name)});
  auto* c = app.add_subcommand(name, description);
  c->add_option("-o,--output", command->output, "Output folder")->capture_default_str();
  c->add_flag("--json", command->json, "Print summary.json's contents instead of text");
  c->add_flag("--overwrite", command->overwrite, "Replace crux's outputs in an output folder that holds some");
  command->binding.bind(c);
  c->callback([command] { command->run(); });
}

}  // namespace

void add_learning_commands(CLI::App& app) {
  auto paper = std::make_shared<PaperCommand>();
  auto* p = app.add_subcommand("paper", "Run the paper's experiment (training, transfer, control) and print Table I");
  p->add_option("-o,--output", paper->output, "Output folder")->capture_default_str();
  p->add_flag("--json", paper->json, "Print summary.json's contents instead of text");
  p->add_flag("--overwrite", paper->overwrite, "Replace crux's outputs in an output folder that holds some");
  paper->binding.bind(p);
  paper->binding.option("experiment.runs")
      ->excludes(paper->binding.option("experiment.walls"))
      ->excludes(paper->binding.option("experiment.seeds_per_wall"));
  p->callback([paper] { paper->run(); });

  add_single_run_command(app, "train", "Learn to climb one wall from empty tables", Condition::Training,
                         kTrainParameters);
  add_single_run_command(app, "transfer", "Learn to climb one wall starting from a Q_grid learnt elsewhere",
                         Condition::Transfer, kTransferParameters);

  auto plan = std::make_shared<PlanCommand>();
  auto* l = app.add_subcommand("plan", "Exact shortest climb of a wall under the learning's rules");
  l->add_flag("--json", plan->json, "Print JSON instead of text");
  plan->binding.bind(l);
  l->callback([plan] { plan->run(); });
}

}  // namespace crux::cli

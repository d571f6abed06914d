// crux paper | train | transfer | plan | perform: learning to climb and transfer (section
// IV), the exact plan, and a plan performed in MuJoCo.

#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/progress_bar.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "experiments/run_checkpoint.hpp"
#include "experiments/run_inputs.hpp"
#include "jobs/command_keys.hpp"
#include "jobs/learning_job.hpp"
#include "jobs/paper_job.hpp"
#include "jobs/perform_job.hpp"
#include "reports/perform_description.hpp"
#include "reports/plan_description.hpp"
#include "reports/text_report.hpp"

namespace crux::cli {

namespace {

void require_wall(const ExperimentConfig& config) {
  if (config.wall_file.empty() && !config.wall_seed) {
    throw InputError("--wall-file", "give a wall: a file (--wall-file FILE) or a seed (--wall-seed N)");
  }
}

// The job's errors name config keys; the command's name the flag or the config file's line.
template <typename Call>
auto run_with_flags(const ParameterBinding& binding, Call call) {
  try {
    return call();
  } catch (const InputError& e) {
    throw InputError(binding.where(e.source()), e.problem());
  }
}

// A job without a folder writes nothing: the command always writes one.
void require_output(const std::string& output) {
  if (output.empty()) throw InputError("--output", "the output folder name is empty");
}

struct PaperCommand {
  ParameterBinding binding{"paper", with_progress(kPaperKeys)};
  std::string output = "out/paper";
  bool json = false;
  bool overwrite = false;

  void run() {
    require_output(output);
    PaperJob job{binding.resolve(), binding.config_path(), output, overwrite};
    const ExperimentParameters settings = job.config.settings;  // the job takes the config
    ProgressBar progress(fmt::format("paper: {} x {} x 3 conditions", counted(settings.wall_pairs, "wall"),
                                     counted(settings.seeds_per_wall, "seed")),
                         settings.learning_runs(), job.config.progress);
    const PaperJobOutcome outcome = run_with_flags(binding, [&] {
      return run_paper_job(std::move(job), {"crux paper", [&](int done) { progress.update(done); }, {}, {}});
    });
    progress.finish();
    if (json) {
      std::cout << outcome.summary.dump(2) << '\n';
      return;
    }
    std::cout << experiment_text(outcome.result, outcome.analysis, settings)
              << fmt::format("\nwrote {} ({:.1f} s)\n", output, outcome.result.seconds);
  }
};

struct SingleRunCommand {
  ParameterBinding binding;
  Condition condition;
  std::string output;
  bool json = false;
  bool overwrite = false;

  void run() {
    require_output(output);
    LearningJob job;
    job.config = binding.resolve();
    require_wall(job.config);
    job.condition = condition;
    job.config_path = binding.config_path();
    job.output = output;
    job.overwrite = overwrite;
    const int iterations = job.config.settings.learning.iterations;
    ProgressBar progress(enum_name(condition), iterations, job.config.progress);
    const std::string caller = condition == Condition::Transfer ? "crux transfer" : "crux train";
    const JobHooks hooks{caller,
                         [&](int done) { progress.update(done); },
                         {},
                         [&](int iteration) {
                           progress.start_at(iteration);
                           std::cerr << fmt::format("{}: resumed at iteration {} of {} from {}\n", caller, iteration,
                                                    iterations,
                                                    (std::filesystem::path(output) / kCheckpointFile).string());
                         }};
    const LearningJobOutcome outcome = run_with_flags(binding, [&] { return run_learning_job(std::move(job), hooks); });
    progress.finish();
    std::cout << (json ? outcome.summary.dump(2) + "\n" : run_text(outcome.result, iterations, output));
  }
};

// The plan's answer with the climb performed in MuJoCo, and its wall-clock time.
void print_performed(const PerformJobOutcome& outcome, bool json) {
  if (json) {
    nlohmann::ordered_json out = outcome.record;
    out["wall_s"] = outcome.wall_s;
    std::cout << out.dump(2) << '\n';
    return;
  }
  std::cout << performed_plan_text(outcome.wall, outcome.performed)
            << fmt::format("({:.1f} s of wall-clock time)\n", outcome.wall_s);
}

struct PlanCommand {
  ParameterBinding binding{"plan", kPlanKeys};
  bool json = false;

  void run() {
    ExperimentConfig config = binding.resolve();
    require_wall(config);
    run_with_flags(binding, [&] { require_perform_keys_used(config, "crux plan"); });
    if (config.settings.learning.climbing.physics.model == PhysicsModel::Dynamic) {
      PerformJob job{config, binding.config_path(), {}, false, {}};
      print_performed(run_with_flags(binding,
                                     [&] {
                                       return run_perform_job(std::move(job), {"crux plan", {}, {}, {}});
                                     }),
                      json);
      return;
    }
    const BodyModel model = load_configured_body(config);
    const Wall wall = load_configured_wall(config);
    const Plan plan = shortest_plan(model, wall, config.settings.learning.climbing, config.settings.plan_search);
    std::cout << (json ? plan_json(wall, plan).dump(2) + "\n" : plan_text(wall, plan));
  }
};

struct PerformCommand {
  ParameterBinding binding{"perform", kPerformKeys, perform_defaults()};
  std::string output = "out/perform";
  bool json = false;
  bool overwrite = false;

  void run() {
    require_output(output);
    ExperimentConfig config = binding.resolve();
    if (config.run.empty()) require_wall(config);
    PerformJob job{std::move(config), binding.config_path(), output, overwrite, {}};
    const PerformJobOutcome outcome = run_with_flags(binding, [&] {
      return run_perform_job(std::move(job), {"crux perform", {}, {}, {}});
    });
    print_performed(outcome, json);
    if (!json) std::cout << fmt::format("wrote {}\n", output);
  }
};

void add_single_run_command(CLI::App& app, const char* name, const char* description, Condition condition,
                            const ParameterSet& keys) {
  auto command = std::make_shared<SingleRunCommand>(
      SingleRunCommand{ParameterBinding(name, keys), condition, fmt::format("out/{}", name)});
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
                         with_progress(kTrainKeys));
  add_single_run_command(app, "transfer", "Learn to climb one wall starting from a Q_grid learnt elsewhere",
                         Condition::Transfer, with_progress(kTransferKeys));

  auto perform = std::make_shared<PerformCommand>();
  auto* f =
      app.add_subcommand("perform",
                         "Perform a wall's exact plan in MuJoCo from its start (physics.model static, the default "
                         "here, performs it as planned; dynamic repairs it by planning again around the moves "
                         "that fail) and write the climb's folder");
  f->add_option("-o,--output", perform->output, "Output folder")->capture_default_str();
  f->add_flag("--json", perform->json, "Print perform.json's contents and the wall-clock time instead of text");
  f->add_flag("--overwrite", perform->overwrite, "Replace crux's outputs in an output folder that holds some");
  perform->binding.bind(f);
  f->callback([perform] { perform->run(); });

  auto plan = std::make_shared<PlanCommand>();
  auto* l = app.add_subcommand("plan", "Exact shortest climb of a wall under the learning's rules");
  l->add_flag("--json", plan->json, "Print JSON instead of text");
  plan->binding.bind(l);
  l->callback([plan] { plan->run(); });
}

}  // namespace crux::cli

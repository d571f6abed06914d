// crux paper | train | transfer | plan: learning to climb and transfer (section IV).

#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "body/urdf_loader.hpp"
#include "cli/commands.hpp"
#include "agent_space/agent_descriptor.hpp"
#include "cli/progress_bar.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/experiment_config.hpp"
#include "experiments/experiment_output.hpp"
#include "experiments/table_one.hpp"
#include "experiments/transfer_comparison.hpp"
#include "learning/q_table_file.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

// Binds every config field to a flag, plus --config FILE; flags given on the command
// line override the file, which overrides the defaults.
struct ConfigBinding {
  ExperimentConfig from_flags;
  std::string config_path;
  std::vector<CLI::Option*> options;

  void bind(CLI::App* command) {
    command->add_option("--config", config_path, "TOML config file (flags given here override it)");
    for (const ConfigField& field : config_fields(from_flags)) {
      std::visit([&](auto* target) { options.push_back(command->add_option(field.flag, *target, field.help)->capture_default_str()); },
                 field.target);
    }
  }

  CLI::Option* option(const std::string& flag) const {
    ExperimentConfig scratch;
    const auto fields = config_fields(scratch);
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (fields[i].flag == flag) return options[i];
    }
    return nullptr;
  }

  ExperimentConfig resolve() {
    ExperimentConfig config;
    if (!config_path.empty()) apply_config_file(config_path, config);
    const auto flags = config_fields(from_flags);
    const auto fields = config_fields(config);
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (options[i]->count() == 0) continue;
      std::visit(
          [&](auto* destination) {
            *destination = *std::get<std::remove_cvref_t<decltype(destination)>>(flags[i].target);
          },
          fields[i].target);
    }
    finalize_config(config);
    return config;
  }
};

struct WallChoice {
  std::string file;
  std::uint64_t seed = 0;
  CLI::Option* seed_option = nullptr;

  void bind(CLI::App* command) {
    auto* f = command->add_option("--wall", file, "Wall file (JSON)");
    seed_option = command->add_option("--wall-seed", seed, "Generate a random wall from this seed")->excludes(f);
  }

  Wall load(const ExperimentConfig& config) const {
    if (!file.empty()) return load_wall(file);
    if (seed_option->count() == 0) throw InputError("--wall", "give a wall file (--wall FILE) or a seed (--wall-seed N)");
    return generate_random_wall(seed, config.settings.walls);
  }
};

std::string cell(double ours, double paper) { return fmt::format("{:6.1f} ({:4.1f})", ours, paper); }

void print_table_one(const ExperimentResult& result, const ExperimentConfig& config) {
  const PaperTableOne& paper = paper_table_one();
  std::array<std::array<std::array<RegimeStats, kRegimeCount>, 2>, 3> ours;
  for (const Condition c : kConditions) {
    ours[static_cast<int>(c)] = table_one(result.conditions[static_cast<int>(c)].runs, config.settings.analysis.beginning);
  }
  std::cout << fmt::format(
      "\nTable I: ours (paper's in brackets), over {} runs per condition; beginning = first {} iterations\n",
      config.settings.runs(), config.settings.analysis.beginning);
  for (const Window w : {Window::Beginning, Window::Overall}) {
    std::cout << fmt::format("\n{:<26}{:>16}{:>16}{:>10}\n", window_name(w), "training", "transfer", "control");
    for (int metric = 0; metric < 3; ++metric) {
      static const char* const names[3] = {"vertical e0 (cm)", "success rate (%)", "actions per run"};
      std::cout << "  " << names[metric] << '\n';
      for (int r = 0; r < kRegimeCount; ++r) {
        std::cout << fmt::format("    {:<22}", regime_name(static_cast<Regime>(r)));
        for (int c = 0; c < 3; ++c) {
          const RegimeStats& s = ours[c][static_cast<int>(w)][r];
          if (metric == 2) {
            std::cout << fmt::format("{:>16.0f}", s.actions_per_run);
          } else if (c < 2) {
            const double paper_value = metric == 0 ? paper.vertical_cm[c][static_cast<int>(w)][r]
                                                   : 100 * paper.success_rate[c][static_cast<int>(w)][r];
            std::cout << fmt::format("{:>16}", cell(metric == 0 ? s.vertical_cm : 100 * s.success_rate, paper_value));
          } else {
            std::cout << fmt::format("{:>10.1f}", metric == 0 ? s.vertical_cm : 100 * s.success_rate);
          }
        }
        std::cout << '\n';
      }
    }
  }
}

void print_transfer_analysis(const ExperimentAnalysis& analysis, const ExperimentSettings& settings) {
  std::cout << fmt::format(
      "\nTransfer against control, paired by wall and seed ({} walls x {} seeds); means over walls with 95 % "
      "intervals:\n",
      settings.wall_pairs, settings.seeds_per_wall);
  for (const MetricComparison& m : analysis.metrics) {
    const auto& tr = m.per_condition[static_cast<int>(Condition::Transfer)];
    const auto& co = m.per_condition[static_cast<int>(Condition::Control)];
    const ClusteredDifference& d = m.transfer_minus_control;
    std::cout << fmt::format("  {} ({} is better)\n", m.metric.description, m.metric.higher_is_better ? "higher" : "lower");
    std::cout << fmt::format(
        "    transfer {:.4g} +- {:.3g}, control {:.4g} +- {:.3g}; difference {:+.4g} ({:+.0f} %), t-interval over walls "
        "[{:.4g}, {:.4g}], cluster bootstrap [{:.4g}, {:.4g}], p = {:.3g}; paired r = {:.2f}; walls for 80 % power: "
        "{}\n",
        tr.mean, tr.half_width, co.mean, co.half_width, d.mean, 100 * m.relative_difference, d.t_low, d.t_high,
        d.bootstrap_low, d.bootstrap_high, d.p_value, m.paired_correlation,
        m.walls_for_power > 0 ? std::to_string(m.walls_for_power) : "-");
  }
  std::cout << fmt::format("\nTake-off (first episode of at most {} iterations, at least half w-greedy):\n",
                           settings.analysis.threshold_length);
  for (const Condition c : kConditions) {
    const ExperimentAnalysis::TakeOff& t = analysis.take_off[static_cast<int>(c)];
    std::cout << fmt::format("  {:<9} {} of {} runs take off; median iteration {}\n", condition_name(c), t.taken_off,
                             t.runs, t.taken_off > 0 ? fmt::format("{:.0f}", t.median_iteration) : "-");
  }
  std::cout << fmt::format("Transfer and control runs first differ at iteration {:.1f} (median over pairs)\n",
                           analysis.median_first_divergence);
  std::cout << fmt::format("\nTransfer's choices in its first {} iterations (evidence: earlier tries of the same "
                           "agent-space pair; far: more than {:.0f} cm from them in the tile):\n",
                           settings.analysis.beginning, 100 * kFarFromEvidence);
  const auto share = [](int part, int whole) { return whole > 0 ? fmt::format("{:.0f} %", 100.0 * part / whole) : std::string("-"); };
  for (int r = 0; r < kRegimeCount; ++r) {
    const ChoiceProfile& p = analysis.transfer_choices[r];
    std::cout << fmt::format(
        "  {:<9} {:6d} actions, {} reachable; back to the hold just left {} (reachable {}); the hold that failed "
        "just before {} (reachable {}); of the others, with evidence {} "
        "(which succeeded {}); far {} (reachable {}), near {} (reachable {}); median distance {:.1f} cm\n",
        regime_name(static_cast<Regime>(r)), p.actions, share(p.successes, p.actions),
        share(p.back_to_left_hold, p.actions), share(p.back_to_left_hold_successes, p.back_to_left_hold),
        share(p.repeats_of_failure, p.actions), share(p.repeats_of_failure_successes, p.repeats_of_failure),
        share(p.with_evidence, p.actions - p.repeats_of_failure), fmt::format("{:.0f} %", 100 * p.evidence_success_rate),
        share(p.far, p.with_evidence), share(p.far_successes, p.far), share(p.near, p.with_evidence),
        share(p.near_successes, p.near),
        p.median_distance_cm);
  }
}

struct PaperCommand {
  ConfigBinding config_binding;
  std::string output = "out/paper";
  std::string urdf = default_body_model_path();

  void run() {
    ExperimentConfig config = config_binding.resolve();
    const BodyModel model = load_body_model(urdf);
    const ExperimentSettings& settings = config.settings;
    const int total = settings.runs();
    std::cerr << fmt::format("crux paper: {} walls x {} seeds x 3 conditions x {} iterations ({} solver), seed {}\n",
                             settings.wall_pairs, settings.seeds_per_wall, settings.learning.iterations, config.solver,
                             settings.seed);
    ProgressBar progress("runs", 3L * total);
    const ExperimentResult result = run_paper_experiment(model, settings, [&](int done) { progress.update(done); });
    progress.finish();
    const ExperimentAnalysis analysis = analyse_experiment(result, settings);
    write_experiment(output, result, analysis, settings, model, config_to_toml(config));
    print_table_one(result, config);
    std::cout << "\nEpisode lengths (mean over runs):\n";
    for (const Condition c : kConditions) {
      const auto& cr = result.conditions[static_cast<int>(c)];
      double episodes = 0, greedy = 0;
      int greedy_ok = 0;
      for (const RunResult& r : cr.runs) {
        episodes += static_cast<double>(r.episode_lengths.size()) / total;
        if (r.greedy_length > 0) greedy += r.greedy_length, ++greedy_ok;
      }
      std::cout << fmt::format("  {:<9} {:6.1f} episodes per run; greedy climb {} ({} of {} runs finish)\n",
                               condition_name(c), episodes,
                               greedy_ok ? fmt::format("{:.1f}", greedy / greedy_ok) : std::string("-"), greedy_ok,
                               total);
    }
    if (settings.plan) {
      double plan = 0;
      int found = 0;
      for (const ExperimentWall& w : result.walls) {
        if (w.plan.found) plan += w.plan.length, ++found;
      }
      std::cout << fmt::format("  exact shortest climb: {:.1f} actions on average ({} of {} walls; the paper: about 10)\n",
                               found ? plan / found : 0.0, found, result.walls.size());
    }
    print_transfer_analysis(analysis, settings);
    std::cout << fmt::format("\nwrote {} ({:.1f} s)\n", output, result.seconds);
  }
};

struct SingleRunCommand {
  ConfigBinding config_binding;
  WallChoice wall_choice;
  std::string output;
  std::string q_grid_path;  // transfer only
  std::string urdf = default_body_model_path();

  void run() {
    ExperimentConfig config = config_binding.resolve();
    const BodyModel model = load_body_model(urdf);
    const Wall wall = wall_choice.load(config);
    std::optional<QTable> initial;
    if (!q_grid_path.empty()) {
      const GridParameters& grid = config.settings.learning.climbing.grid;
      initial = load_q_table(q_grid_path, grid.tile_count());
      // Codes beyond this grid's would be read as states of another shape.
      initial->for_each_row([&](StateCode state, auto, auto) {
        if (state >= agent_state_count(grid)) {
          throw InputError(q_grid_path, fmt::format("state code {} does not exist on a {} x {} grid", state,
                                                    grid.columns, grid.rows));
        }
      });
    }
    ProgressBar progress(initial ? "transfer" : "train", config.settings.learning.iterations);
    const std::uint64_t seed = config.settings.seed;
    const RunResult result = run_learning(model, wall, config.settings.learning, seed, initial ? &*initial : nullptr,
                                          [&](int done) { progress.update(done); });
    progress.finish();
    write_run_files(output, result, model);
    write_file_atomically(std::filesystem::path(output) / "config.toml", config_to_toml(config));
    save_wall((std::filesystem::path(output) / "wall.json").string(), wall);
    nlohmann::ordered_json summary;
    summary["format"] = "crux-run-summary";
    summary["version"] = 1;
    summary["wall"] = wall.name;
    summary["seed"] = seed;
    summary["transferred_q_grid"] = q_grid_path.empty() ? nlohmann::json(nullptr) : nlohmann::json(q_grid_path);
    summary["episodes"] = result.episode_lengths.size();
    summary["episode_lengths"] = result.episode_lengths;
    summary["greedy_length"] = result.greedy_length;
    summary["ik_solves"] = result.ik_solves;
    const auto cells = table_one(std::span(&result, 1), config.settings.analysis.beginning);
    for (const Window w : {Window::Beginning, Window::Overall}) {
      for (int r = 0; r < kRegimeCount; ++r) {
        const RegimeStats& s = cells[static_cast<int>(w)][r];
        summary["table1"][window_name(w)][regime_name(static_cast<Regime>(r))] = {
            {"actions", s.actions_per_run}, {"success_rate", s.success_rate}, {"vertical_cm", s.vertical_cm}};
      }
    }
    write_file_atomically(std::filesystem::path(output) / "summary.json", summary.dump(2) + "\n");
    std::cout << fmt::format("{} on '{}': {} episodes in {} iterations; greedy climb: {}; wrote {}\n",
                             initial ? "transfer" : "training", wall.name, result.episode_lengths.size(),
                             config.settings.learning.iterations,
                             result.greedy_length > 0 ? fmt::format("{} actions", result.greedy_length) : "does not finish",
                             output);
  }
};

struct PlanCommand {
  ConfigBinding config_binding;
  WallChoice wall_choice;
  bool json = false;
  std::string urdf = default_body_model_path();

  void run() {
    ExperimentConfig config = config_binding.resolve();
    const BodyModel model = load_body_model(urdf);
    const Wall wall = wall_choice.load(config);
    const Plan plan = shortest_plan(model, wall, config.settings.learning.climbing);
    if (json) {
      nlohmann::ordered_json out;
      out["wall"] = wall.name;
      out["found"] = plan.found;
      out["length"] = plan.found ? plan.length : -1;
      out["holds"] = plan.hold_ids;
      std::vector<std::string> limbs;
      for (const Limb l : plan.limbs) limbs.push_back(limb_name(l));
      out["limbs"] = limbs;
      out["expanded_states"] = plan.expanded_states;
      out["ik_solves"] = plan.ik_solves;
      std::cout << out.dump(2) << '\n';
      return;
    }
    if (!plan.found) {
      std::cout << fmt::format("no climb found on '{}' ({} states explored)\n", wall.name, plan.expanded_states);
      return;
    }
    std::cout << fmt::format("shortest climb on '{}': {} actions ({} states explored, {} IK solves)\n", wall.name,
                             plan.length, plan.expanded_states, plan.ik_solves);
    for (int i = 0; i < plan.length; ++i) {
      std::cout << fmt::format("  {:2d}. {:<10} -> hold {}\n", i + 1, limb_name(plan.limbs[i]), plan.hold_ids[i]);
    }
  }
};

}  // namespace

void add_learning_commands(CLI::App& app) {
  auto paper = std::make_shared<PaperCommand>();
  auto* p = app.add_subcommand("paper", "Run the paper's experiment (training, transfer, control) and print Table I");
  p->add_option("-o,--output", paper->output, "Output folder")->capture_default_str();
  p->add_option("--urdf", paper->urdf, "URDF file of the body")->capture_default_str();
  paper->config_binding.bind(p);
  paper->config_binding.option("--runs")
      ->excludes(paper->config_binding.option("--walls"))
      ->excludes(paper->config_binding.option("--seeds-per-wall"));
  p->callback([paper] { paper->run(); });

  auto train = std::make_shared<SingleRunCommand>();
  train->output = "out/train";
  auto* t = app.add_subcommand("train", "Learn to climb one wall from empty tables");
  train->wall_choice.bind(t);
  t->add_option("-o,--output", train->output, "Output folder")->capture_default_str();
  t->add_option("--urdf", train->urdf, "URDF file of the body")->capture_default_str();
  train->config_binding.bind(t);
  t->callback([train] { train->run(); });

  auto transfer = std::make_shared<SingleRunCommand>();
  transfer->output = "out/transfer";
  auto* x = app.add_subcommand("transfer", "Learn to climb one wall starting from a Q_grid learnt elsewhere");
  x->add_option("--qgrid", transfer->q_grid_path, "Q_grid file (q_grid.bin of a training run)")->required();
  transfer->wall_choice.bind(x);
  x->add_option("-o,--output", transfer->output, "Output folder")->capture_default_str();
  x->add_option("--urdf", transfer->urdf, "URDF file of the body")->capture_default_str();
  transfer->config_binding.bind(x);
  x->callback([transfer] { transfer->run(); });

  auto plan = std::make_shared<PlanCommand>();
  auto* l = app.add_subcommand("plan", "Exact shortest climb of a wall under the learning's rules");
  plan->wall_choice.bind(l);
  l->add_flag("--json", plan->json, "Print JSON instead of text");
  l->add_option("--urdf", plan->urdf, "URDF file of the body")->capture_default_str();
  plan->config_binding.bind(l);
  l->callback([plan] { plan->run(); });
}

}  // namespace crux::cli

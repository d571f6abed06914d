// crux report and crux figures: one self-contained HTML page for an output folder, with
// the figures, the statistics and a 3D replay of a climb; the SVG figures of a paper folder.

#include <chrono>
#include <iostream>
#include <memory>

#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "experiments/run_inputs.hpp"
#include "jobs/report_job.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/perform_folder.hpp"
#include "outputs/run_config_file.hpp"
#include "reports/report_figures.hpp"
#include "reports/web_assets.hpp"
#include "reports/written_report.hpp"

namespace crux::cli {

namespace {

// A folder is reported with its own config.toml; only the body may be named again.
const ParameterSet kReportKeys{{"experiment.urdf"}, {}};

struct ReportCommand {
  ParameterBinding binding{"report", kReportKeys};
  std::string folder;
  std::string output;
  std::string run_name = "training_0";
  std::string climb_choice = "greedy";
  int replay_moves = kDefaultReplayMoves;
  std::string performed;  // a crux perform folder shown beside the run's replay
  bool json = false;
  CLI::App* command = nullptr;

  void run() {
    const auto started = std::chrono::steady_clock::now();
    if (replay_moves < 1 || replay_moves > kMaxReplayMoves) {
      throw InputError("--replay-moves", fmt::format("must be from 1 to {} (a move is about 4 KB of the page), got {}",
                                                     kMaxReplayMoves, replay_moves));
    }
    ExperimentConfig config = binding.resolve();
    if (is_perform_folder(folder)) {
      for (const char* flag : {"--run", "--climb", "--replay-moves", "--performed"}) {
        if (command->count(flag) > 0) {
          throw InputError(flag,
                           fmt::format("{} is a crux perform folder, which holds one climb: drop {}", folder, flag));
        }
      }
      write(perform_page(config), folder_name(folder), started);
      return;
    }
    const ReportedRun reported = locate_reported_run(folder, run_name, "--run");
    RunFolder run = locate_run_folder(reported.run_directory);
    const ExperimentConfig recorded = read_run_config(run.config_file);
    if (config.urdf.empty()) config.urdf = run.urdf;
    check_output_file(output, {folder, performed, binding.config_path(), configured_urdf_path(config)});
    const BodyModel model = load_configured_body(config);
    std::optional<PerformedSection> section;
    if (!performed.empty()) section = performed_beside(model, config);
    read_run_climb(run, model);
    ReportPage page = report_page(folder, reported, run, model, recorded, climb_choice, replay_moves);
    page.performed = std::move(section);
    write(std::move(page), run.name, started);
  }

  // The page of a crux perform folder, read with its own config.toml and body.
  ReportPage perform_page(ExperimentConfig& config) const {
    const ExperimentConfig recorded = read_perform_config(std::filesystem::path(folder) / "config.toml");
    if (config.urdf.empty()) config.urdf = recorded.urdf;
    check_output_file(output, {folder, binding.config_path(), configured_urdf_path(config)});
    const BodyModel model = load_configured_body(config);
    return perform_report_page(read_perform_folder(folder, model), model, grasp_radius(recorded));
  }

  // --performed: a crux perform folder on the same body, shown after the run's replay.
  PerformedSection performed_beside(const BodyModel& model, const ExperimentConfig& config) const {
    if (!is_perform_folder(performed)) {
      throw InputError("--performed",
                       fmt::format("{} is not a crux perform folder (it has no perform.json)", performed));
    }
    const ExperimentConfig recorded = read_perform_config(std::filesystem::path(performed) / "config.toml");
    namespace fs = std::filesystem;
    if (fs::absolute(configured_urdf_path(recorded)) != fs::absolute(configured_urdf_path(config))) {
      throw InputError("--performed", fmt::format("{} was performed with the body {}, not the report's {}", performed,
                                                  configured_urdf_path(recorded), configured_urdf_path(config)));
    }
    return performed_section(read_perform_folder(performed, model), model, grasp_radius(recorded));
  }

  static double grasp_radius(const ExperimentConfig& recorded) {
    return recorded.settings.learning.climbing.reachability.ik.tolerances.grasp_radius;
  }

  void write(ReportPage page, const std::string& name, std::chrono::steady_clock::time_point started) const {
    page.style = report_style();
    page.script = replay_script();
    const std::string html = html_report(page);
    write_file_atomically(output, html);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::cout << (json ? written_report_json(page, name, output, html.size(), seconds).dump(2) + "\n"
                       : written_report_text(page, name, output, html.size(), seconds));
  }
};

struct FiguresCommand {
  std::string folder;
  bool json = false;

  void run() const {
    const std::vector<std::filesystem::path> written = write_paper_figure_files(folder);
    std::cout << (json ? figure_files_json(written).dump(2) + "\n" : figure_files_text(written));
  }
};

}  // namespace

void add_report_commands(CLI::App& app) {
  auto figures = std::make_shared<FiguresCommand>();
  auto* f = app.add_subcommand(
      "figures",
      "Redraw the SVG figures of a crux paper folder into its figures/ from its files: Figs. 2b, 3, 4\n"
      "and the transfer-minus-control plot (crux paper writes them too)");
  f->add_option("folder", figures->folder, "The crux paper output folder")->required();
  f->add_flag("--json", figures->json, "Print JSON instead of text");
  f->callback([figures] { figures->run(); });

  auto report = std::make_shared<ReportCommand>();
  auto* r = app.add_subcommand(
      "report",
      "Write one self-contained HTML page for an output folder of crux paper, train or transfer: Table I\n"
      "beside the paper's, the statistics, the figures and a 3D replay of a climb (works offline); or for a\n"
      "crux perform folder: the climb performed in MuJoCo, replayed as simulated. The folder is read with its\n"
      "own config.toml");
  r->add_option("folder", report->folder, "The output folder")->required();
  r->add_option("-o,--output", report->output, "The HTML file to write")->required();
  r->add_option("--run", report->run_name, "For a crux paper folder: the run whose climb is replayed, <condition>_<i>")
      ->capture_default_str();
  add_climb_option(r, report->climb_choice);
  r->add_option("--replay-moves", report->replay_moves,
                fmt::format("The replay shows the climb's first N moves, from 1 to {} (a move is about 4 KB of the "
                            "page); the page says when the climb has more",
                            kMaxReplayMoves))
      ->capture_default_str();
  r->add_option("--performed", report->performed,
                "A crux perform folder (on the same body) whose climb performed in MuJoCo the page shows after the "
                "run's replay");
  r->add_flag("--json", report->json, "Print JSON instead of text");
  report->command = r;
  report->binding.bind(r);
  r->callback([report] { report->run(); });
}

}  // namespace crux::cli

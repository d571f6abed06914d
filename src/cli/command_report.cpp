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
  bool json = false;

  void run() {
    const auto started = std::chrono::steady_clock::now();
    if (replay_moves < 1 || replay_moves > kMaxReplayMoves) {
      throw InputError("--replay-moves", fmt::format("must be from 1 to {} (a move is about 4 KB of the page), got {}",
                                                     kMaxReplayMoves, replay_moves));
    }
    ExperimentConfig config = binding.resolve();
    const ReportedRun reported = locate_reported_run(folder, run_name, "--run");
    RunFolder run = locate_run_folder(reported.run_directory);
    const ExperimentConfig recorded = read_run_config(run.config_file);
    if (config.urdf.empty()) config.urdf = run.urdf;
    check_output_file(output, {folder, binding.config_path(), configured_urdf_path(config)});
    const BodyModel model = load_configured_body(config);
    read_run_climb(run, model);
    ReportPage page = report_page(folder, reported, run, model, recorded, climb_choice, replay_moves);
    page.style = report_style();
    page.script = replay_script();
    const std::string html = html_report(page);
    write_file_atomically(output, html);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::cout << (json ? written_report_json(page, run.name, output, html.size(), seconds).dump(2) + "\n"
                       : written_report_text(page, run.name, output, html.size(), seconds));
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
      "beside the paper's, the statistics, the figures and a 3D replay of a climb (works offline); the\n"
      "folder is read with its own config.toml");
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
  r->add_flag("--json", report->json, "Print JSON instead of text");
  report->binding.bind(r);
  r->callback([report] { report->run(); });
}

}  // namespace crux::cli

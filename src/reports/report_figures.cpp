#include "reports/report_figures.hpp"

#include <map>

#include <fmt/format.h>

#include "body/body_data.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "outputs/run_folder.hpp"
#include "outputs/summary_file.hpp"
#include "views/body_svg.hpp"
#include "views/paper_figures.hpp"

namespace crux {

namespace {

struct FigureText {
  const char* title;
  const char* caption;
};

const std::map<std::string, FigureText>& figure_texts() {
  static const std::map<std::string, FigureText> texts{
      {"fig2b_qgrid_maps.svg",
       {"Fig. 2b: Q_grid per free limb",
        "The sum of Q_grid over the agent-space states of each free limb, per tile of the moving grid, averaged over "
        "runs; the dot is the limb's anchor point P_i."}},
      {"fig3_regimes.svg",
       {"Fig. 3: actions per regime",
        "Cumulative actions of each regime against iterations; the band is a 95 % interval over walls."}},
      {"fig4_episode_lengths.svg",
       {"Fig. 4: episode lengths",
        "Iterations per episode, mean over runs with a 95 % band over walls; dashed: the walls' shortest climb."}},
      {"transfer_minus_control.svg",
       {"Transfer minus control",
        "Each metric's mean paired difference relative to control's mean, with its 95 % interval over walls."}},
  };
  return texts;
}

}  // namespace

std::vector<std::filesystem::path> write_paper_figure_files(const std::filesystem::path& experiment_folder) {
  if (summary_kind(read_summary(experiment_folder), (experiment_folder / "summary.json").string()) != "experiment") {
    throw InputError(experiment_folder.string(), "not a crux paper folder (its summary.json is of kind \"run\")");
  }
  // Drawn before anything is written, so that bad input leaves the folder as it was.
  const auto figures = paper_figures(read_paper_figure_data(experiment_folder));
  std::vector<std::filesystem::path> written;
  make_output_directory(experiment_folder / "figures");
  for (const auto& [name, svg] : figures) {
    written.push_back(experiment_folder / "figures" / name);
    write_file_atomically(written.back(), svg);
  }
  return written;
}

nlohmann::ordered_json figure_files_json(const std::vector<std::filesystem::path>& written) {
  nlohmann::ordered_json out;
  out["figures"] = nlohmann::ordered_json::array();
  for (const auto& file : written) out["figures"].push_back(file.string());
  return out;
}

std::string figure_files_text(const std::vector<std::filesystem::path>& written) {
  std::string out;
  for (const auto& file : written) out += "wrote " + file.string() + "\n";
  return out;
}

std::vector<ReportFigure> report_figures(const std::filesystem::path& experiment_folder, const BodyModel& model,
                                         const RunFolder& run, const ReachabilityParameters& reach) {
  std::vector<ReportFigure> figures;
  if (!experiment_folder.empty()) {
    for (auto& [name, svg] : paper_figures(read_paper_figure_data(experiment_folder))) {
      const auto text = figure_texts().find(name);
      figures.push_back({text != figure_texts().end() ? text->second.title : name,
                         text != figure_texts().end() ? text->second.caption : "", std::move(svg)});
    }
  }
  BodyData data(model);
  const Posture posture = solve_start(model, data, run.wall, reach).posture;
  BodySvgOptions options;
  options.title = fmt::format("{} on '{}'", run.name, run.wall.name);
  options.subtitle = "the start posture";
  options.grasp_radius = reach.ik.tolerances.grasp_radius;
  figures.push_back({"Fig. 1: the climber on the wall",
                     "Front and side views at the start posture, the body drawn from the URDF's visual primitives; "
                     "the coloured discs are the grasp spheres.",
                     render_body_svg(model, posture, run.wall, options)});
  return figures;
}

}  // namespace crux

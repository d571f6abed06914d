// crux view: the virtual human on the wall at one posture (the paper's Fig. 1), as SVG.

#include <iostream>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"
#include "cli/cli_parsing.hpp"
#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "configurations/reachability.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/run_folder.hpp"
#include "views/body_svg.hpp"
#include "wall/wall_file.hpp"

namespace crux::cli {

namespace {

const ParameterSet kViewParameters{{"experiment.urdf", "wall.file", "ik"}, {"ik.cache_unreachable"}};

struct ViewCommand {
  ParameterBinding binding{"view", kViewParameters};
  std::string run;
  int step = 0;
  std::string climb_kind = "greedy";
  std::string svg;
  bool json = false;

  void run_command() {
    ExperimentConfig config = binding.resolve();
    if (run.empty() && config.wall_file.empty()) {
      throw InputError("--run", "give a run folder (--run DIR) or a wall file (--wall-file FILE)");
    }
    if (!run.empty() && !config.wall_file.empty()) {
      throw InputError("--run", "give a run folder (--run DIR) or a wall file (--wall-file FILE), not both");
    }
    if (svg.empty()) throw InputError("--svg", "give the SVG file to write");
    Wall wall;
    Posture posture;
    std::string title, subtitle;
    const ReachabilityParameters& reach = config.settings.learning.climbing.reachability;
    if (!run.empty()) {
      RunFolder folder = locate_run_folder(run);
      if (config.urdf.empty()) config.urdf = folder.urdf;
      const BodyModel model = load_configured_body(config);
      read_run_climb(folder, model);
      const RecordedClimb& climb = chosen_climb(folder, climb_kind);
      if (climb.postures.empty()) throw InputError(run, "the run completed no climb, so it has no posture to show");
      if (step < 0 || step >= static_cast<int>(climb.postures.size())) {
        throw InputError("--step", fmt::format("must be from 0 to {}, the postures of the climb, got {}",
                                               climb.postures.size() - 1, step));
      }
      wall = folder.wall;
      posture = climb.postures[step];
      title = fmt::format("{} on '{}'", folder.name, wall.name);
      subtitle = fmt::format("step {} of {} ({} postures, the start is step 0)", step,
                             climb.kind == "greedy" ? std::string("the greedy policy's climb after learning")
                                                    : fmt::format("the climb of episode {}", climb.episode),
                             climb.postures.size());
      write(model, posture, wall, title, subtitle, reach);
      return;
    }
    const BodyModel model = load_configured_body(config);
    wall = load_wall(config.wall_file);
    BodyData data(model);
    const IkResult start = solve_start(model, data, wall, reach);
    if (!start.reached) throw InputError(config.wall_file, "the start configuration is not reachable");
    title = fmt::format("'{}'", wall.name);
    subtitle = "the start posture, solved by IK from standing";
    write(model, start.posture, wall, title, subtitle, reach);
  }

  void write(const BodyModel& model, const Posture& posture, const Wall& wall, const std::string& title,
             const std::string& subtitle, const ReachabilityParameters& reach) const {
    BodySvgOptions options;
    options.title = title;
    options.subtitle = subtitle;
    options.grasp_radius = reach.ik.tolerances.grasp_radius;
    write_file_atomically(svg, render_body_svg(model, posture, wall, options));
    BodyData data(model);
    forward_kinematics(model, data, posture);
    const Eigen::Vector3d& com = centre_of_mass(model, data);
    if (!json) {
      std::cout << fmt::format("wrote {}: {}, {}\n", svg, title, subtitle);
      return;
    }
    nlohmann::ordered_json out;
    out["svg"] = svg;
    out["title"] = title;
    out["subtitle"] = subtitle;
    out["root"] = {posture[0], posture[1], posture[2]};
    out["centre_of_mass"] = {com.x(), com.y(), com.z()};
    nlohmann::ordered_json grasp;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const Eigen::Vector3d& p = data.points[operational_point(static_cast<Limb>(limb))];
      grasp[limb_name(static_cast<Limb>(limb))] = {p.x(), p.y(), p.z()};
    }
    out["grasp_points"] = grasp;
    std::cout << out.dump(2) << '\n';
  }
};

}  // namespace

void add_view_command(CLI::App& app) {
  auto view = std::make_shared<ViewCommand>();
  auto* v = app.add_subcommand(
      "view", "Draw the climber on the wall at one posture, front and side (paper Fig. 1), as SVG: step K of a run's\n"
              "climb (--run DIR --step K), or the start posture of a wall file (--wall-file FILE)");
  v->add_option("--run", view->run,
                "A run folder: that of crux train or transfer, or runs/<condition>_<i> of a crux paper folder");
  v->add_option("--step", view->step, "The posture of the climb to draw: 0 is the start")->capture_default_str();
  add_climb_option(v, view->climb_kind);
  v->add_option("--svg", view->svg, "The SVG file to write");
  v->add_flag("--json", view->json, "Print JSON instead of text");
  view->binding.bind(v);
  v->callback([view] { view->run_command(); });
}

}  // namespace crux::cli

// crux demo: load the body and solve a few reaching queries with both solvers.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/ik_description.hpp"

namespace crux::cli {

void add_demo_command(CLI::App& app) {
  auto* command = app.add_subcommand("demo", "Load the body and solve a few reaching queries with both IK solvers");
  auto binding = std::make_shared<ParameterBinding>("demo", ParameterSet{{"experiment.urdf"}, {}});
  auto json = std::make_shared<bool>(false);
  binding->bind(command);
  command->add_flag("--json", *json, "Print JSON instead of text");
  command->callback([binding, json] {
    const BodyModel model = load_configured_body(binding->resolve());
    const std::vector<IkDemoSolve> solves = run_ik_demo(model);
    std::cout << (*json ? ik_demo_json(solves).dump(2) + "\n" : ik_demo_text(model, solves));
  });
}

}  // namespace crux::cli

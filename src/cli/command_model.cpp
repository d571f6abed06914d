// crux model: what the body is.

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "experiments/run_inputs.hpp"
#include "reports/model_description.hpp"

namespace crux::cli {

void add_model_command(CLI::App& app) {
  auto* command = app.add_subcommand("model", "Describe the virtual human: degrees of freedom, size, mass, joints");
  auto binding = std::make_shared<ParameterBinding>("model", ParameterSet{{"experiment.urdf"}, {}});
  auto json = std::make_shared<bool>(false);
  binding->bind(command);
  command->add_flag("--json", *json, "Print JSON instead of text");
  command->callback([binding, json] {
    const BodyModel model = load_configured_body(binding->resolve());
    std::cout << (*json ? model_json(model).dump(2) + "\n" : model_text(model));
  });
}

}  // namespace crux::cli

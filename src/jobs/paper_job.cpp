#include "jobs/paper_job.hpp"

#include "experiments/run_inputs.hpp"
#include "jobs/command_keys.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/summary.hpp"
#include "reports/report_figures.hpp"

namespace crux {

PaperJobOutcome run_paper_job(PaperJob job, const JobHooks& hooks) {
  ExperimentConfig& config = job.config;
  Provenance provenance = record_provenance(config);
  provenance.produced_by = hooks.caller;
  if (!job.config_path.empty()) check_recorded_provenance(config, provenance, job.config_path);
  const BodyModel model = load_configured_body(config);
  const bool writes_folder = job.output.has_value();
  std::string config_toml;
  if (writes_folder) {
    config_toml = config_file_text(config, kPaperKeys, provenance);
    check_output_folder(*job.output, {config.urdf, job.config_path}, job.overwrite);
  }
  PaperJobOutcome outcome;
  outcome.result = run_paper_experiment(model, config.settings, hooks.progress, hooks.interruption_point);
  outcome.analysis = analyse_experiment(outcome.result, config.settings);
  outcome.summary = summary_json(outcome.result, &outcome.analysis, config.settings, provenance);
  if (writes_folder) {
    write_experiment_folder(*job.output, outcome.result, config.settings, model, config_toml, outcome.summary,
                            [](const std::filesystem::path& folder) { write_paper_figure_files(folder); });
  }
  return outcome;
}

}  // namespace crux

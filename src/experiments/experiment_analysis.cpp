#include "experiments/experiment_analysis.hpp"

#include <algorithm>

#include "common/random_stream.hpp"

namespace crux {

std::uint64_t bootstrap_seed(const ExperimentParameters& parameters) {
  return RandomStream(parameters.seed, "bootstrap").bits(0, 0);
}

RandomStream stratified_bootstrap_stream(const ExperimentParameters& parameters) {
  return RandomStream(parameters.seed, "stratified_bootstrap");
}

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return -1.0;
  std::sort(values.begin(), values.end());
  return percentile(values, 0.5);
}

}  // namespace

MetricWindows metric_windows(const ExperimentParameters& parameters) {
  return {parameters.learning.iterations, parameters.analysis.beginning, parameters.analysis.threshold_length};
}

ExperimentAnalysis analyse_experiment(const ExperimentResult& result, const ExperimentParameters& parameters) {
  ExperimentAnalysis out;
  out.metrics = compare_transfer(result, metric_windows(parameters), bootstrap_seed(parameters),
                                 parameters.analysis.bootstrap_resamples, stratified_bootstrap_stream(parameters));
  for (const Condition condition : kConditions) {
    ExperimentAnalysis::TakeOff& t = out.take_off[static_cast<int>(condition)];
    std::vector<double> iterations;
    for (const RunResult& run : result.conditions[static_cast<int>(condition)].runs) {
      ++t.runs;
      t.iterations.push_back(take_off_iteration(run, parameters.analysis.threshold_length));
      if (t.iterations.back() > 0) iterations.push_back(t.iterations.back());
    }
    t.taken_off = static_cast<int>(iterations.size());
    t.median_iteration = median(iterations);
  }
  const auto& transfer = result.conditions[static_cast<int>(Condition::Transfer)].runs;
  const auto& control = result.conditions[static_cast<int>(Condition::Control)].runs;
  std::vector<double> divergence;
  for (std::size_t i = 0; i < transfer.size(); ++i) {
    out.first_divergence.push_back(first_divergence(transfer[i], control[i]));
    divergence.push_back(out.first_divergence.back() > 0 ? out.first_divergence.back()
                                                         : parameters.learning.iterations + 1);
  }
  out.median_first_divergence = median(divergence);
  out.transfer_choices = diagnose_transfer(result, parameters.analysis.beginning);
  return out;
}

}  // namespace crux

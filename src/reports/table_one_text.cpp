#include "reports/table_one_text.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "experiments/table_one.hpp"
#include "reports/paper_reference.hpp"

namespace crux {

std::string table_one_text(const ExperimentResult& result, const ExperimentParameters& parameters) {
  const PaperTableOne& paper = paper_table_one();
  std::array<std::array<std::array<RegimeStats, kRegimeCount>, 2>, 3> ours;
  for (const Condition c : kConditions) {
    ours[static_cast<int>(c)] = table_one(result.conditions[static_cast<int>(c)].runs, parameters.analysis.beginning);
  }
  std::string text =
      fmt::format("\nTable I: ours (paper's in brackets), over {} per condition; beginning = first {}\n",
                  counted(parameters.runs(), "run"), counted(parameters.analysis.beginning, "iteration"));
  for (const Window w : {Window::Beginning, Window::Overall}) {
    text += fmt::format("\n{:<26}{:>16}{:>16}{:>10}\n", enum_name(w), enum_name(Condition::Training),
                        enum_name(Condition::Transfer), enum_name(Condition::Control));
    for (int metric = 0; metric < 3; ++metric) {
      static const char* const names[3] = {"vertical e0 (cm)", "success rate (%)", "actions per run"};
      text += fmt::format("  {}\n", names[metric]);
      for (int r = 0; r < kRegimeCount; ++r) {
        text += fmt::format("    {:<22}", enum_name(static_cast<Regime>(r)));
        for (int c = 0; c < 3; ++c) {
          const RegimeStats& s = ours[c][static_cast<int>(w)][r];
          // No rate without actions, no displacement without successes.
          const bool defined = metric == 0 ? s.successes > 0 : s.actions > 0;
          const std::string value =
              defined ? fmt::format("{:6.1f}", metric == 0 ? s.vertical_cm : 100 * s.success_rate) : "     -";
          if (metric == 2) {
            text += fmt::format("{:>{}.0f}", s.actions_per_run, c < 2 ? 16 : 10);
          } else if (c < 2) {
            const double paper_value = metric == 0 ? paper.vertical_cm[c][static_cast<int>(w)][r]
                                                   : 100 * paper.success_rate[c][static_cast<int>(w)][r];
            text += fmt::format("{:>16}", fmt::format("{} ({:4.1f})", value, paper_value));
          } else {
            text += fmt::format("{:>10}", value);
          }
        }
        text += '\n';
      }
    }
  }
  return text;
}

}  // namespace crux

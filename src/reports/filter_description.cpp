#include "reports/filter_description.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "reports/paper_reference.hpp"

namespace crux {

namespace {

std::size_t selected_reading(const FilterReport& report) {
  for (std::size_t r = 0; r < kFeetAboveHandsReadings.size(); ++r) {
    if (kFeetAboveHandsReadings[r] == report.parameters.feet_above_hands) return r;
  }
  return 0;
}

}  // namespace

nlohmann::ordered_json filter_json(const FilterReport& report) {
  const FilterCounts& c = report.counts[selected_reading(report)];
  nlohmann::ordered_json out;
  out["wall_count"] = report.wall_count;
  out["wall_seed"] = report.wall_seed;
  out["reading"] = enum_name(report.parameters.feet_above_hands);
  out["max_span_m"] = report.parameters.max_span_m;
  out["pass3"] = c.share3();
  out["pass4"] = c.share4();
  out["passing3"] = c.pass3;
  out["configurations3"] = c.configurations3;
  out["passing4"] = c.pass4;
  out["configurations4"] = c.configurations4;
  out["paper_pass3"] = kPaperFilterPass3;
  out["paper_pass4"] = kPaperFilterPass4;
  out["readings"] = nlohmann::json::array();
  for (std::size_t r = 0; r < report.counts.size(); ++r) {
    out["readings"].push_back({{"reading", enum_name(kFeetAboveHandsReadings[r])},
                               {"pass3", report.counts[r].share3()},
                               {"pass4", report.counts[r].share4()}});
  }
  return out;
}

std::string filter_text(const FilterReport& report) {
  const std::size_t chosen = selected_reading(report);
  const FilterCounts& c = report.counts[chosen];
  std::string out =
      fmt::format("{} (seed {}), span <= {} m, crossed arms and legs rejected\n",
                  counted(report.wall_count, "random wall"), report.wall_seed, report.parameters.max_span_m) +
      fmt::format("{:<34} {:>14} {:>14}\n", "reading of 'both feet above the hands'", "3-configs", "4-configs");
  for (std::size_t r = 0; r < report.counts.size(); ++r) {
    out += fmt::format("{:<34} {:>13.2f}% {:>13.2f}%{}\n", enum_name(kFeetAboveHandsReadings[r]),
                       100 * report.counts[r].share3(), 100 * report.counts[r].share4(),
                       r == chosen ? "  <- selected" : "");
  }
  out += fmt::format("{:<34} {:>13.1f}% {:>13.1f}%\n", "paper (section III-C)", 100 * kPaperFilterPass3,
                     100 * kPaperFilterPass4) +
         fmt::format("selected: {} of {} 3-configurations and {} of {} 4-configurations pass\n", c.pass3,
                     c.configurations3, c.pass4, c.configurations4);
  return out;
}

}  // namespace crux

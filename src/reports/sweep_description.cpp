#include "reports/sweep_description.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"

namespace crux {

std::string sweep_text(const nlohmann::json& summary, const std::string& folder, std::size_t tasks, std::size_t kept,
                       double seconds) {
  std::string out;
  const auto& cells = summary.at("cells");
  out += "crux sweep: " + counted(cells.size(), "cell");
  const auto& keys = summary.at("listed_keys");
  if (!keys.empty()) {
    std::string names;
    for (const auto& key : keys) names += (names.empty() ? "" : " x ") + key.get<std::string>();
    out += " (" + names + ")";
  }
  out += "\ntransfer minus control per metric: mean over walls [95 % t-interval], p (Holm over cells)\n";
  for (const auto& cell : cells) {
    std::string parameters;
    for (const auto& [key, value] : cell.at("parameters").items()) {
      parameters += fmt::format("{}{} = {}", parameters.empty() ? "" : ", ", key, value.get<std::string>());
    }
    out += fmt::format(
        "\ncell {}{}: {} x {}\n", cell.at("cell").get<int>(), parameters.empty() ? "" : " (" + parameters + ")",
        counted(cell.at("wall_pairs").get<int>(), "wall"), counted(cell.at("seeds_per_wall").get<int>(), "seed"));
    for (const auto& [name, metric] : cell.at("transfer_vs_control").items()) {
      const auto& d = metric.at("transfer_minus_control");
      const auto& interval = d.at("ci95_t_over_walls");
      const auto number = [](const nlohmann::json& v) {
        return v.is_number() ? fmt::format("{:.4g}", v.get<double>()) : std::string("-");
      };
      out += fmt::format("  {:<34} {:>10} [{}, {}]  p = {} ({})\n", name, number(d.at("mean")), number(interval.at(0)),
                         number(interval.at(1)), number(d.at("p_value")), number(d.at("p_value_holm_over_cells")));
    }
  }
  out += fmt::format("\nwrote {} ({:.1f} s; {} of {} kept from an earlier start)\n", folder, seconds, kept,
                     counted(tasks, "task"));
  return out;
}

}  // namespace crux

#include "reports/sweep_report.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "views/svg_document.hpp"

namespace crux {

std::string sweep_cell_title(const nlohmann::ordered_json& cell) {
  std::string title = fmt::format("cell {}", cell.at("cell").get<int>());
  const char* separator = ": ";
  for (const auto& [key, value] : cell.at("parameters").items()) {
    title += fmt::format("{}{} = {}", separator, key, value.get<std::string>());
    separator = ", ";
  }
  return title;
}

namespace {

// "-110 [-264, +43], p = 0.15 (Holm 0.15)"
std::string difference_cell(const nlohmann::ordered_json& comparison) {
  const auto& d = comparison.at("transfer_minus_control");
  std::string text = fmt::format("{:+.4g}", d.at("mean").get<double>());
  if (d.at("ci95_t_over_walls").is_array()) {
    text += fmt::format(" [{:+.4g}, {:+.4g}]", d.at("ci95_t_over_walls")[0].get<double>(),
                        d.at("ci95_t_over_walls")[1].get<double>());
  }
  return text + fmt::format("<br>p = {:.3g} (Holm {:.3g})", d.at("p_value").get<double>(),
                            d.at("p_value_holm_over_cells").get<double>());
}

// rliable's view: "-95 [-180, -20]<br>P 0.62 [0.51, 0.72]", blank for a summary.json
// written before these fields.
std::string stratified_cell(const nlohmann::ordered_json& comparison) {
  if (!comparison.contains("iqm") || !comparison.contains("probability_of_improvement")) return {};
  const auto number = [](const nlohmann::ordered_json& v, const char* format) {
    return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : std::string("-");
  };
  // An interval only where the bootstrap had seeds to resample (summary.json's null).
  const auto estimate = [&](const nlohmann::ordered_json& e, const char* format) {
    if (e.at("low").is_null()) return number(e.at("value"), format) + " (no interval)";
    return fmt::format("{} [{}, {}]", number(e.at("value"), format), number(e.at("low"), format),
                       number(e.at("high"), format));
  };
  return estimate(comparison.at("iqm").at("difference"), "{:+.4g}") + "<br>P " +
         estimate(comparison.at("probability_of_improvement"), "{:.2f}");
}

// One row per cell, one column per metric, each table cell written by `cell_text` (empty
// where the cell lacks the metric).
template <typename CellText>
std::string metric_rows(const nlohmann::ordered_json& cells, const std::vector<std::string>& metrics,
                        const CellText& cell_text) {
  std::string rows;
  for (const auto& cell : cells) {
    rows += fmt::format("<tr><td>{}</td>", xml_escaped(sweep_cell_title(cell)));
    const auto& comparisons = cell.at("transfer_vs_control");
    for (const std::string& metric : metrics) {
      rows += "<td>" + (comparisons.contains(metric) ? cell_text(comparisons.at(metric)) : std::string()) + "</td>";
    }
    rows += "</tr>\n";
  }
  return rows;
}

}  // namespace

std::string sweep_report_html(const nlohmann::ordered_json& summary, const std::vector<std::string>& cell_figures) {
  const auto& cells = summary.at("cells");
  std::vector<std::string> metrics;
  for (const auto& [name, comparison] : cells.at(0).at("transfer_vs_control").items()) metrics.push_back(name);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>crux sweep</title>\n<style>\n"
      "body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse;font-size:13px}"
      "td,th{border:1px solid #ccc;padding:4px 6px;vertical-align:top}th{background:#f4f4f4}"
      ".figures{display:flex;flex-wrap:wrap;gap:12px}.figures figure{margin:0;flex:1 1 480px;max-width:760px}"
      ".figures svg{width:100%;height:auto}\n</style>\n</head>\n<body>\n<h1>crux sweep</h1>\n";
  std::string keys;
  for (const auto& key : summary.at("listed_keys")) keys += (keys.empty() ? "" : ", ") + key.get<std::string>();
  html += fmt::format(
      "<p>{} over {}. Transfer minus control per metric: mean over walls, Student-t 95 % "
      "interval over walls, p-value, and the p-value Holm-adjusted over the cells.</p>\n",
      counted(cells.size(), "cell"), xml_escaped(keys.empty() ? std::string("no listed key") : keys));
  html += "<table>\n<tr><th>cell</th>";
  for (const std::string& metric : metrics) {
    html +=
        fmt::format("<th title=\"{}\">{}</th>",
                    xml_escaped(cells.at(0).at("transfer_vs_control").at(metric).at("description").get<std::string>()),
                    xml_escaped(metric));
  }
  html += "</tr>\n";
  html += metric_rows(cells, metrics, difference_cell);
  html +=
      "</table>\n<p>rliable's view (Agarwal et al., NeurIPS 2021): the interquartile mean of the pair differences "
      "(transfer minus control, same wall and seed) and the probability that transfer beats control on a wall (P), "
      "each with a 95 % stratified bootstrap interval: the walls are kept and their seeds resampled, so these "
      "intervals leave out wall-to-wall variation, which the t-intervals above "
      "include.</p>\n<table>\n<tr><th>cell</th>";
  for (const std::string& metric : metrics) html += fmt::format("<th>{}</th>", xml_escaped(metric));
  html += "</tr>\n";
  html += metric_rows(cells, metrics, stratified_cell);
  html += "</table>\n<h2>Episode lengths per cell</h2>\n<div class=\"figures\">\n";
  for (std::string_view svg : cell_figures) {
    if (svg.starts_with("<?xml")) svg.remove_prefix(svg.find("?>") + 2);  // a declaration has no place in HTML
    html += fmt::format("<figure>{}</figure>\n", svg);
  }
  return html + "</div>\n</body>\n</html>\n";
}

}  // namespace crux

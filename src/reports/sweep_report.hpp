#pragma once
// The report of a finished sweep (docs/OUTPUTS.md): each cell's Fig. 4 (episode lengths
// of transfer and control, bands over walls) and report.html, one self-contained page
// with a table of each cell's transfer-minus-control analysis and the cells' figures
// side by side, so that, for example, transfer modes compare at a glance.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "views/paper_figures.hpp"

namespace crux {

// Cell `cell` of the sweep's summary.json, as a title: "cell 2: experiment.transfer = seeded".
std::string sweep_cell_title(const nlohmann::ordered_json& cell);

// The page, from the sweep's summary.json contents and each cell's figure (SVG), in cell order.
std::string sweep_report_html(const nlohmann::ordered_json& summary, const std::vector<std::string>& cell_figures);

}  // namespace crux

#pragma once
// What crux sweep prints: its cells, and per cell each transfer metric's transfer minus
// control over walls with its p-value, raw and Holm-adjusted over the cells, read from
// the sweep's summary.json.

#include <string>

#include <nlohmann/json.hpp>

namespace crux {

// `summary`: the sweep's summary.json; `tasks`, `kept`: tasks in the sweep and those
// an earlier start had finished.
std::string sweep_text(const nlohmann::json& summary, const std::string& folder, std::size_t tasks, std::size_t kept,
                       double seconds);

}  // namespace crux

#pragma once
// What crux report says once its page is written: the file, its size, its figures and
// the replay it holds, as JSON or text.

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "reports/html_report.hpp"

namespace crux {

// What crux report says once `page` is written to `file`: its size, figures and replay.
nlohmann::ordered_json written_report_json(const ReportPage& page, const std::string& run_name, const std::string& file,
                                           std::size_t bytes, double seconds);
std::string written_report_text(const ReportPage& page, const std::string& run_name, const std::string& file,
                                std::size_t bytes, double seconds);

}  // namespace crux

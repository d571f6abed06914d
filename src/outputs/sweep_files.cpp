#include "outputs/sweep_files.hpp"

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"

namespace crux {

namespace fs = std::filesystem;

void write_sweep_wall_facts(const fs::path& folder, const nlohmann::ordered_json& facts) {
  nlohmann::ordered_json document;
  document["format"] = "crux-sweep-wall";
  document["version"] = 1;
  document.update(facts);
  write_file_atomically(folder / kWallFactsFile, document.dump(2) + "\n");
}

nlohmann::json read_sweep_wall_facts(const fs::path& folder) {
  const std::string file = (folder / kWallFactsFile).string();
  const std::string text = read_input_file(file, "JSON file");
  nlohmann::json facts;
  try {
    facts = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, std::string("not valid JSON: ") + e.what());
  }
  // Compared as JSON, so that a format or version of another type is refused, not thrown on.
  const bool crux_facts = facts.is_object() && facts.contains("format") && facts["format"] == "crux-sweep-wall" &&
                          facts.contains("version") && facts["version"] == 1;
  if (!crux_facts) {
    throw InputError(file, "not a crux sweep's wall facts (format crux-sweep-wall, version 1)");
  }
  return facts;
}

nlohmann::ordered_json write_sweep_results_files(const fs::path& folder, const std::string& csv,
                                                 const nlohmann::ordered_json& provenance,
                                                 const std::vector<std::string>& listed_keys,
                                                 const nlohmann::ordered_json& cells) {
  nlohmann::ordered_json summary;
  summary["format"] = "crux-sweep-summary";
  summary["version"] = 1;
  summary["provenance"] = provenance;
  summary["listed_keys"] = listed_keys;
  summary["cells"] = cells;
  write_file_atomically(folder / "results.csv", csv);
  write_file_atomically(folder / "summary.json", summary.dump(2) + "\n");
  return summary;
}

std::vector<fs::path> write_sweep_report_files(const fs::path& folder, const std::vector<std::string>& cell_figures,
                                               const std::string& report_html) {
  std::vector<fs::path> written;
  fs::create_directories(folder / "figures");
  for (std::size_t c = 0; c < cell_figures.size(); ++c) {
    written.push_back(folder / "figures" / fmt::format("c{}_episode_lengths.svg", c));
    write_file_atomically(written.back(), cell_figures[c]);
  }
  written.push_back(folder / "report.html");
  write_file_atomically(written.back(), report_html);
  return written;
}

}  // namespace crux

#include "support/repository_docs.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace crux::testing {

namespace {

std::string single_spaced(const std::string& text) {
  std::istringstream words(text);
  std::string out, word;
  while (words >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

int heading_level(const std::string& line) {
  const std::size_t hashes = line.find_first_not_of('#');
  return hashes != 0 && hashes != std::string::npos && line[hashes] == ' ' ? static_cast<int>(hashes) : 0;
}

}  // namespace

std::string repository_file(const std::string& relative_path) {
  std::ifstream in(std::string(CRUX_SOURCE_DIR) + "/" + relative_path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + relative_path + " of the repository");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool quotes(const std::string& markdown, const std::string& text) {
  return single_spaced(markdown).find(single_spaced(text)) != std::string::npos;
}

std::vector<std::string> documented_keys(const std::string& markdown, const std::string& heading) {
  std::istringstream lines(markdown);
  std::string line;
  int level = 0;
  std::vector<std::string> keys;
  while (std::getline(lines, line)) {
    if (level == 0) {
      if (line == heading) level = heading_level(line);
      continue;
    }
    const int this_level = heading_level(line);
    if (this_level != 0 && this_level <= level) break;
    if (line.rfind("| ", 0) != 0) continue;
    const std::string cell = line.substr(2, line.find(" |", 1) - 2);
    for (std::size_t open = cell.find('`'); open != std::string::npos; open = cell.find('`', open)) {
      const std::size_t close = cell.find('`', open + 1);
      if (close == std::string::npos) break;
      keys.push_back(cell.substr(open + 1, close - open - 1));
      open = close + 1;
    }
  }
  return keys;
}

}  // namespace crux::testing

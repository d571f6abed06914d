#include "support/xml_check.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

#include <fmt/format.h>

namespace crux {
namespace {

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; }
bool is_name_char(char c) {
  return is_name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

// Every '&' in character data must start one of XML's predefined or numeric references.
std::string check_references(const std::string& text) {
  for (std::size_t at = text.find('&'); at != std::string::npos; at = text.find('&', at + 1)) {
    const std::size_t end = text.find(';', at);
    if (end == std::string::npos) return "unterminated reference";
    const std::string name = text.substr(at + 1, end - at - 1);
    const bool numeric = name.size() > 1 && name[0] == '#' &&
                         std::all_of(name.begin() + 1, name.end(), [](char c) { return std::isxdigit(c) || c == 'x'; });
    if (!numeric && name != "amp" && name != "lt" && name != "gt" && name != "quot" && name != "apos") {
      return "unknown reference &" + name + ";";
    }
  }
  return "";
}

}  // namespace

std::string check_well_formed(const std::string& xml) {
  std::vector<std::string> open;
  int roots = 0;
  std::size_t at = 0;
  if (xml.starts_with("<?xml")) at = xml.find("?>") + 2;
  while (true) {
    const std::size_t tag = xml.find('<', at);
    const std::string text = xml.substr(at, tag == std::string::npos ? std::string::npos : tag - at);
    if (open.empty() && text.find_first_not_of(" \t\r\n") != std::string::npos) return "text outside the root";
    if (text.find('>') != std::string::npos) return "raw '>' in text";
    if (const std::string problem = check_references(text); !problem.empty()) return problem;
    if (tag == std::string::npos) break;
    if (xml.compare(tag, 4, "<!--") == 0) {
      at = xml.find("-->", tag);
      if (at == std::string::npos) return "unterminated comment";
      at += 3;
      continue;
    }
    std::size_t p = tag + 1;
    const bool closing = xml[p] == '/';
    if (closing) ++p;
    if (p >= xml.size() || !is_name_start(xml[p])) return fmt::format("bad tag name at {}", tag);
    const std::size_t name_start = p;
    while (p < xml.size() && is_name_char(xml[p])) ++p;
    const std::string name = xml.substr(name_start, p - name_start);
    bool self_closing = false;
    std::set<std::string> attributes;
    while (true) {
      while (p < xml.size() && std::isspace(static_cast<unsigned char>(xml[p]))) ++p;
      if (p >= xml.size()) return "unterminated tag <" + name;
      if (xml[p] == '>') break;
      if (!closing && xml.compare(p, 2, "/>") == 0) {
        self_closing = true;
        ++p;
        break;
      }
      if (closing || !is_name_start(xml[p])) return fmt::format("bad attribute in <{}> at {}", name, p);
      const std::size_t attribute_start = p;
      while (p < xml.size() && is_name_char(xml[p])) ++p;
      const std::string attribute = xml.substr(attribute_start, p - attribute_start);
      if (!attributes.insert(attribute).second) return "repeated attribute " + attribute + " in <" + name;
      if (xml.compare(p, 2, "=\"") != 0) return "unquoted attribute " + attribute + " in <" + name;
      const std::size_t value_end = xml.find('"', p + 2);
      if (value_end == std::string::npos) return "unterminated attribute " + attribute;
      const std::string value = xml.substr(p + 2, value_end - p - 2);
      if (value.find('<') != std::string::npos) return "'<' in attribute " + attribute;
      if (const std::string problem = check_references(value); !problem.empty()) return problem;
      p = value_end + 1;
    }
    at = p + 1;
    if (closing) {
      if (open.empty() || open.back() != name) return "</" + name + "> closes nothing open";
      open.pop_back();
    } else {
      if (open.empty() && ++roots > 1) return "more than one root";
      if (open.empty() && name != "svg") return "root is <" + name + ">, not <svg>";
      if (open.empty() && attributes.count("xmlns") == 0) return "<svg> without xmlns";
      if (!self_closing) open.push_back(name);
    }
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  if (roots != 1) return "no root element";
  return "";
}

}  // namespace crux

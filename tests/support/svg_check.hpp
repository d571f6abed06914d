#pragma once
// Checks of the SVG documents crux writes, shared by the view tests.

#include <string>
#include <vector>

namespace crux::testing {

// A small well-formedness check, enough for what crux's renderers write: an optional XML
// declaration, balanced and properly nested tags with quoted attributes, valid
// references and a single <svg> root. Returns the first problem, or "" when none.
std::string check_well_formed(const std::string& xml);

// The contents of every <text> in the group of this class, tags (tspans) stripped.
std::vector<std::string> group_texts(const std::string& svg, const std::string& group_class);

int count_of(const std::string& text, const std::string& what);

// The start tag of the element whose opening contains `marker` (e.g. id="hold-3").
std::string element_with(const std::string& svg, const std::string& marker);

std::string attribute(const std::string& element, const std::string& name);
double number_attribute(const std::string& svg, const std::string& marker, const std::string& name);

}  // namespace crux::testing

#pragma once
// A small XML well-formedness check for the SVG that src/views/ writes by hand, so that
// tests can tell a broken document without an XML library.

#include <string>

namespace crux {

// Checks an optional XML declaration, balanced and properly nested tags with quoted,
// unrepeated attributes, valid references, and a single <svg> root with xmlns. Returns
// the first problem, or "" when none.
std::string check_well_formed(const std::string& xml);

}  // namespace crux

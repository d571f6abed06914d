#pragma once
// Text for XML and HTML documents: the SVG figures, the report, the MuJoCo model.

#include <string>
#include <string_view>

namespace crux {

// `text` with XML's special characters escaped, and the control characters XML 1.0
// forbids replaced by U+FFFD.
std::string xml_escaped(std::string_view text);

}  // namespace crux

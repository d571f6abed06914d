#pragma once
// Text in hand-written SVG: escaping for XML, and an estimate of its width, which SVG
// cannot measure before it is drawn. Shared by every figure of src/views/.

#include <string>
#include <string_view>

namespace crux {

// The text with XML's five special characters escaped; control characters that XML 1.0
// forbids even as references become U+FFFD.
std::string xml_escaped(std::string_view text);

// Width in pixels of the text in a sans-serif font of this size, from a generous average
// character width, so that a page sized with it does not clip its labels.
double estimated_text_width(std::string_view text, double font_size);

}  // namespace crux

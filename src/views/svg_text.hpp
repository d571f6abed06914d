#pragma once
// What every SVG view of crux shares: text made safe for XML, a width estimate for
// laying out text (SVG cannot measure it), the spacing of metre lines, and the colours of
// the limbs and of the grid's anchor.

#include <array>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "body/limb.hpp"

namespace crux {

// `text` with XML's special characters escaped, and the control characters XML 1.0
// forbids replaced by U+FFFD.
std::string xml_escaped(std::string_view text);

// Appends the formatted text to `out`: how the SVG and HTML writers build their documents.
template <typename... Args>
void append_format(std::string& out, fmt::format_string<Args...> format, Args&&... args) {
  fmt::format_to(std::back_inserter(out), format, std::forward<Args>(args)...);
}

// Width of `text` in a sans-serif font of `font_size` pixels, from a generous average.
double estimated_text_width(std::string_view text, double font_size);

// Metres between the lines of a wall's metre grid drawn at `pixels_per_metre`: 0.5 m,
// doubled while neighbouring lines would be closer than 30 pixels.
double metre_tick_spacing(double pixels_per_metre);

// The anchor P_i of the moving grid (Fig. 2a), in the wall view and in Fig. 2b alike.
inline constexpr const char* kAnchorColour = "#1a9641";

struct LimbStyle {
  const char* code;
  const char* name;
  const char* colour;
};
// In limb order. Okabe-Ito colours, told apart by colour-blind readers.
inline constexpr std::array<LimbStyle, kLimbCount> kLimbStyles{{
    {"RH", "right hand", "#d55e00"},
    {"LH", "left hand", "#0072b2"},
    {"RF", "right foot", "#e69f00"},
    {"LF", "left foot", "#cc79a7"},
}};

}  // namespace crux

#include "views/svg_text.hpp"

#include <algorithm>

namespace crux {

std::string xml_escaped(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          escaped += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
        } else {
          escaped += c;
        }
    }
  }
  return escaped;
}

double estimated_text_width(std::string_view text, double font_size) {
  const auto code_points = std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // not a UTF-8 continuation byte
  });
  return 0.6 * font_size * static_cast<double>(code_points);
}

double metre_tick_spacing(double pixels_per_metre) {
  constexpr double kFinestSpacing = 0.5;  // metres
  constexpr double kMinimumGap = 30;      // pixels
  double spacing = kFinestSpacing;
  while (spacing * pixels_per_metre < kMinimumGap) spacing *= 2;
  return spacing;
}

}  // namespace crux

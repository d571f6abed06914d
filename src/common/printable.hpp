#pragma once
// Text from input files (a wall's name) as it may be printed on a terminal: control
// characters and DEL escaped as \xNN, so that a name cannot break a line or send
// terminal escape codes.

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace crux {

inline std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte < 0x20 || byte == 0x7f || ch == '\\') {
      out += ch == '\\' ? std::string("\\\\") : fmt::format("\\x{:02x}", byte);
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace crux

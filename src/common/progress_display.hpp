#pragma once
// How a long command shows its progress on stderr (output.progress): stdout and every
// file stay the same whichever is chosen.

#include "common/enum_names.hpp"

namespace crux {

enum class ProgressDisplay {
  Bar,    // a bar redrawn in place on a terminal (and a timed job's line every ten seconds elsewhere)
  Lines,  // a plain line at each step, for logs and pipes
  None,   // nothing
};
template <>
struct EnumNames<ProgressDisplay> {
  static constexpr std::array<EnumName<ProgressDisplay>, 3> entries{
      {{ProgressDisplay::Bar, "bar"}, {ProgressDisplay::Lines, "lines"}, {ProgressDisplay::None, "none"}}};
};

}  // namespace crux

#pragma once
// Parsing of command-line values shared by several commands.

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include "body/body_model.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace crux::cli {

// "Y,Z" in metres, a point on the wall plane x = 0; InputError naming `flag` otherwise.
inline Eigen::Vector3d parse_wall_point(const std::string& text, const char* flag) {
  std::istringstream in(text);
  double y = 0, z = 0;
  char comma = 0;
  if (!(in >> y >> comma >> z) || comma != ',' || !(in >> std::ws).eof() || !std::isfinite(y) || !std::isfinite(z)) {
    throw InputError(flag, fmt::format("expected Y,Z in metres, got '{}'", printable(text)));
  }
  return {0.0, y, z};
}

// --climb of view and report: which climb of a run (climb_to_show).
inline void add_climb_option(CLI::App* command, std::string& choice) {
  command
      ->add_option("--climb", choice,
                   "The run's climb: greedy (the learnt policy's, after learning; the last episode's when it does "
                   "not finish), last (the last completed episode, with its exploration) or an episode number N "
                   "(from 1, as in Fig. 4; replayed from the run's actions)")
      ->capture_default_str();
}

}  // namespace crux::cli

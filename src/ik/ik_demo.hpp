#pragma once
// crux demo: a few reaching queries around the start layout (one from standing, three
// reachable moves, one no body can make), each solved by both IK solvers and timed
// (reports/ik_description prints them).

#include <string>
#include <vector>

#include "ik/ik_solver.hpp"

namespace crux {

struct IkDemoSolve {
  std::string query;
  IkSolverKind solver;
  IkResult result;
  double wall_clock_us = 0;  // informative only
};

// Every query with the paper's solver, then the fast one.
std::vector<IkDemoSolve> run_ik_demo(const BodyModel& model);

}  // namespace crux

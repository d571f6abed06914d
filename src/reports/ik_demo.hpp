#pragma once
// crux demo: a few reaching queries around the start layout (one from standing, three
// reachable moves, one no body can make), each solved by both IK solvers and timed.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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

nlohmann::ordered_json ik_demo_json(const std::vector<IkDemoSolve>& solves);
std::string ik_demo_text(const BodyModel& model, const std::vector<IkDemoSolve>& solves);

}  // namespace crux

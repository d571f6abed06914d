#pragma once
// How often the paper's solver and the fast solver agree on what is reachable.

#include <functional>
#include <vector>

#include "ik/reach_queries.hpp"

namespace crux {

struct SolverAgreement {
  int queries = 0;
  int agree = 0;
  int paper_reached = 0, fast_reached = 0;
  int only_paper_reached = 0, only_fast_reached = 0;
  int far_queries = 0;
  long paper_iterations = 0, fast_iterations = 0;
  double paper_seconds = 0, fast_seconds = 0;  // wall clock, informative only
  double agreement() const { return queries > 0 ? static_cast<double>(agree) / queries : 0.0; }
};

// Runs both solvers on every query from its start posture. `parameters` gives the shared
// tolerances and each solver's parameters; its `solver` field is ignored.
SolverAgreement compare_solvers(const BodyModel& model, const std::vector<ReachQuery>& queries,
                                const IkParameters& parameters, const std::function<void(int done)>& progress = {});

}  // namespace crux

#include "ik/solver_agreement.hpp"

#include <chrono>

namespace crux {

SolverAgreement compare_solvers(const BodyModel& model, const std::vector<ReachQuery>& queries,
                                const IkParameters& parameters, const std::function<void(int done)>& progress) {
  IkParameters paper = parameters, fast = parameters;
  paper.solver = IkSolverKind::Paper;
  fast.solver = IkSolverKind::Fast;
  BodyData data(model);
  SolverAgreement out;
  using Clock = std::chrono::steady_clock;
  for (const ReachQuery& q : queries) {
    const auto t0 = Clock::now();
    const IkResult by_paper = solve_ik(model, data, q.start, q.target, paper);
    const auto t1 = Clock::now();
    const IkResult by_fast = solve_ik(model, data, q.start, q.target, fast);
    const auto t2 = Clock::now();
    out.paper_seconds += std::chrono::duration<double>(t1 - t0).count();
    out.fast_seconds += std::chrono::duration<double>(t2 - t1).count();
    out.paper_iterations += by_paper.iterations;
    out.fast_iterations += by_fast.iterations;
    ++out.queries;
    out.agree += by_paper.reached == by_fast.reached;
    out.paper_reached += by_paper.reached;
    out.fast_reached += by_fast.reached;
    out.only_paper_reached += by_paper.reached && !by_fast.reached;
    out.only_fast_reached += by_fast.reached && !by_paper.reached;
    out.far_queries += q.far_move;
    if (progress) progress(out.queries);
  }
  return out;
}

}  // namespace crux

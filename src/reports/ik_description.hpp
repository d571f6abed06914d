#pragma once
// crux ik's, crux ik-compare's and crux demo's outputs: one solved query, how often the
// two solvers agree, and the demo's queries, as JSON or text.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "ik/ik_demo.hpp"
#include "ik/ik_solver.hpp"
#include "ik/solver_agreement.hpp"

namespace crux {

// The query's result with the body placed at the returned posture (root, grasp points,
// centre of mass).
nlohmann::ordered_json ik_result_json(const BodyModel& model, IkSolverKind solver, const ReachTarget& target,
                                      const IkResult& result);
std::string ik_result_text(const BodyModel& model, IkSolverKind solver, const ReachTarget& target,
                           const IkResult& result);

nlohmann::ordered_json solver_agreement_json(const SolverAgreement& agreement, std::uint64_t seed);
std::string solver_agreement_text(const SolverAgreement& agreement, std::uint64_t seed);

nlohmann::ordered_json ik_demo_json(const std::vector<IkDemoSolve>& solves);
std::string ik_demo_text(const BodyModel& model, const std::vector<IkDemoSolve>& solves);

}  // namespace crux

#pragma once
// crux ik's and crux ik-compare's outputs: one solved query, and how often the two
// solvers agree, as JSON or text.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

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

}  // namespace crux

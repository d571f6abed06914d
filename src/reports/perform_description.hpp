#pragma once
// A climb performed in MuJoCo, as JSON or text: crux perform's record (its folder's
// perform.json) and crux plan's answer under physics.model = dynamic (docs/OUTPUTS.md).

#include <string>

#include <nlohmann/json.hpp>

#include "experiments/performed_plan.hpp"

namespace crux {

// The plan (plan_json), the climb performed and its moves, and the replans that led to it.
nlohmann::ordered_json performed_plan_json(const Wall& wall, const PerformedPlan& performed);
std::string performed_plan_text(const Wall& wall, const PerformedPlan& performed);

// Why a move failed, in words ("the body hit the wall"); "" for none.
std::string failure_words(MoveFailure failure);

}  // namespace crux

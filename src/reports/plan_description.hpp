#pragma once
// crux plan's output: a wall's exact shortest climb, or why there is none, as JSON or text.

#include <string>

#include <nlohmann/json.hpp>

#include "experiments/shortest_plan.hpp"

namespace crux {

nlohmann::ordered_json plan_json(const Wall& wall, const Plan& plan);
std::string plan_text(const Wall& wall, const Plan& plan);

}  // namespace crux

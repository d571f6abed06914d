#include "reports/plan_description.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/printable.hpp"

namespace crux {

nlohmann::ordered_json plan_json(const Wall& wall, const Plan& plan) {
  nlohmann::ordered_json out;
  out["wall"] = wall.name;
  out["physics_model"] = enum_name(plan.physics_model);
  out["found"] = plan.found;
  out["stopped_at_limit"] = plan.stopped_at_limit;
  out["length"] = plan.found ? plan.length : -1;
  out["holds"] = plan.hold_ids;
  std::vector<std::string> limbs;
  for (const Limb l : plan.limbs) limbs.push_back(enum_name(l));
  out["limbs"] = limbs;
  out["expanded_states"] = plan.expanded_states;
  out["ik_solves"] = plan.ik_solves;
  if (plan.checked_moves) out["moves_refused_on_the_way"] = plan.moves_refused_on_the_way;
  return out;
}

std::string plan_text(const Wall& wall, const Plan& plan) {
  const std::string model = fmt::format("under the {} model", enum_name(plan.physics_model));
  if (plan.stopped_at_limit) {
    return fmt::format(
        "no climb found on '{}' {} within {} ({} explored); the search stopped at its limit, "
        "--plan-max-solves raises it\n",
        printable(wall.name), model, counted(plan.ik_solves, "IK solve"), counted(plan.expanded_states, "state"));
  }
  if (!plan.found) {
    return fmt::format("no climb exists on '{}' {} ({} explored, {})\n", printable(wall.name), model,
                       counted(plan.expanded_states, "state"), counted(plan.ik_solves, "IK solve"));
  }
  std::string out = fmt::format("shortest climb on '{}' {}: {} ({} explored, {})\n", printable(wall.name), model,
                                counted(plan.length, "action"), counted(plan.expanded_states, "state"),
                                counted(plan.ik_solves, "IK solve"));
  for (int i = 0; i < plan.length; ++i) {
    out += fmt::format("  {:2d}. {:<10} -> hold {}\n", i + 1, enum_name(plan.limbs[i]), plan.hold_ids[i]);
  }
  return out;
}

}  // namespace crux

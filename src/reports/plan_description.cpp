#include "reports/plan_description.hpp"

#include <fmt/format.h>

#include "common/printable.hpp"

namespace crux {

nlohmann::ordered_json plan_json(const Wall& wall, const Plan& plan) {
  nlohmann::ordered_json out;
  out["wall"] = wall.name;
  out["found"] = plan.found;
  out["stopped_at_limit"] = plan.stopped_at_limit;
  out["length"] = plan.found ? plan.length : -1;
  out["holds"] = plan.hold_ids;
  std::vector<std::string> limbs;
  for (const Limb l : plan.limbs) limbs.push_back(limb_name(l));
  out["limbs"] = limbs;
  out["expanded_states"] = plan.expanded_states;
  out["ik_solves"] = plan.ik_solves;
  return out;
}

std::string plan_text(const Wall& wall, const Plan& plan) {
  if (plan.stopped_at_limit) {
    return fmt::format(
        "no climb found on '{}' within {} IK solves ({} states explored); the search stopped at its limit, "
        "--plan-max-solves raises it\n",
        printable(wall.name), plan.ik_solves, plan.expanded_states);
  }
  if (!plan.found) {
    return fmt::format("no climb exists on '{}' ({} states explored, {} IK solves)\n", printable(wall.name),
                       plan.expanded_states, plan.ik_solves);
  }
  std::string out = fmt::format("shortest climb on '{}': {} actions ({} states explored, {} IK solves)\n",
                                printable(wall.name), plan.length, plan.expanded_states, plan.ik_solves);
  for (int i = 0; i < plan.length; ++i) {
    out += fmt::format("  {:2d}. {:<10} -> hold {}\n", i + 1, limb_name(plan.limbs[i]), plan.hold_ids[i]);
  }
  return out;
}

}  // namespace crux

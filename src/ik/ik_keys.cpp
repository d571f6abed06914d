#include "ik/ik_keys.hpp"

namespace crux {

namespace {

template <typename Parameters>
void declare_ik_keys(FieldsFor<Parameters>& keys, Parameters& ik) {
  keys.insert(
      keys.end(),
      {
          {"ik.solver", "IK solver: fast, or paper (Algorithm 1)", choice_of(&ik.solver)},
          {"ik.alpha",
           "Step size of the paper's gradient descent",
           &ik.paper.step_size,
           "",
           {.min = 0, .max = 1000, .min_open = true}},
          // The paper's solver iterates timeout / time_step times (at most kMaxIkIterations,
          // checked with both keys).
          {"ik.time_step",
           "Simulated seconds per IK iteration (both solvers)",
           &ik.time_step_s,
           "s",
           {.min = 0, .max = 1, .min_open = true}},
          {"ik.timeout",
           "Delta_t: simulated seconds before the paper's solver gives up",
           &ik.paper.timeout_s,
           "s",
           {.min = 0, .max = 3600, .min_open = true, .sizes_work = true}},
          {"ik.paper_stall_iterations",
           "Steps over which the paper's solver looks for a stall (0: it never gives up before Delta_t, as Algorithm "
           "1)",
           &ik.paper.stall_iterations, "", closed_range(0, 64)},
          {"ik.paper_stall_decrease", "It has stalled when f fell by less than this share of f over those steps...",
           &ik.paper.stall_decrease, "", kShareOfOne},
          {"ik.paper_stall_margin", "...while a point is more than this outside its sphere; it then gives up",
           &ik.paper.stall_margin_m, "m", closed_range(0, kMaxLengthM)},
          {"ik.rule_out_beyond_reach",
           "Both solvers give up before iterating when a hold lies beyond its limb's reach (the verdict cannot change)",
           &ik.rule_out_beyond_reach},
          {"ik.fast_max_iterations", "Iteration cap of the fast solver", &ik.fast.max_iterations, "",
           work_size(1, kMaxIkIterations)},
          {"ik.fast_stall_decrease", "The fast solver gives up when f drops by less than this share per step...",
           &ik.fast.stall_relative_decrease, "", kShareOfOne},
          {"ik.fast_stall_iterations", "...this many steps in a row", &ik.fast.stall_iterations, "",
           closed_range(1, kMaxIkIterations)},
          {"ik.fast_aim", "The fast solver aims at this share of each tolerance radius", &ik.fast.aim_fraction, "",
           kZeroToBelowOne},
          {"ik.grasp_radius", "Radius of the grasp spheres", &ik.tolerances.grasp_radius, "m", kLength},
          {"ik.root_tolerance", "Radius of the root tolerance sphere", &ik.tolerances.root_radius, "m", kLength},
          {"ik.wall",
           "The body and the wall: ignore it (the paper's kinematic model), reject a solved posture that passes "
           "through "
           "it, or avoid it (keep the body out while solving; the static model's, and its default)",
           choice_of(&ik.wall)},
      });
}

}  // namespace

void ik_keys(std::vector<ConfigField>& keys, IkParameters& ik) { declare_ik_keys(keys, ik); }
void ik_keys(std::vector<ConstConfigField>& keys, const IkParameters& ik) { declare_ik_keys(keys, ik); }

}  // namespace crux

#include "reports/ik_description.hpp"

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "common/counted.hpp"
#include "common/json_field.hpp"

namespace crux {

nlohmann::ordered_json ik_result_json(const BodyModel& model, IkSolverKind solver, const ReachTarget& target,
                                      const IkResult& result) {
  BodyData data(model);
  forward_kinematics(model, data, result.posture);
  nlohmann::ordered_json out;
  out["solver"] = enum_name(solver);
  out["reached"] = result.reached;
  out["iterations"] = result.iterations;
  out["simulated_time_s"] = result.simulated_time_s;
  out["residual_m"] = result.residual_m;
  out["root_target"] = vector_json(target.root);
  out["root"] = vector_json(data.points[0]);
  out["grasp_points"] = nlohmann::json::array();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    out["grasp_points"].push_back(vector_json(data.points[operational_point(limb)]));
  }
  out["centre_of_mass"] = vector_json(centre_of_mass(model, data));
  out["posture"] = std::vector<double>(result.posture.data(), result.posture.data() + kConfigurationDof);
  return out;
}

std::string ik_result_text(const BodyModel& model, IkSolverKind solver, const ReachTarget& target,
                           const IkResult& result) {
  BodyData data(model);
  forward_kinematics(model, data, result.posture);
  std::string out =
      fmt::format("solver {}: {} after {} ({:.2f} s simulated), residual {:.4f} m\n", enum_name(solver),
                  result.reached ? "reached" : "NOT reached", counted(result.iterations, "iteration"),
                  result.simulated_time_s, result.residual_m) +
      fmt::format("root target H(C4) = ({:.3f}, {:.3f}, {:.3f}); root at ({:.3f}, {:.3f}, {:.3f})\n", target.root.x(),
                  target.root.y(), target.root.z(), data.points[0].x(), data.points[0].y(), data.points[0].z());
  if (!result.reached) out += "returned the initial posture G_init, as Algorithm 1 does when it does not reach\n";
  return out;
}

nlohmann::ordered_json solver_agreement_json(const SolverAgreement& a, std::uint64_t seed) {
  nlohmann::ordered_json out;
  out["queries"] = a.queries;
  out["seed"] = seed;
  out["agreement"] = a.agreement();
  out["paper_reached"] = a.paper_reached;
  out["fast_reached"] = a.fast_reached;
  out["only_paper_reached"] = a.only_paper_reached;
  out["only_fast_reached"] = a.only_fast_reached;
  out["far_queries"] = a.far_queries;
  out["paper_mean_iterations"] = static_cast<double>(a.paper_iterations) / a.queries;
  out["fast_mean_iterations"] = static_cast<double>(a.fast_iterations) / a.queries;
  out["paper_mean_us"] = 1e6 * a.paper_seconds / a.queries;
  out["fast_mean_us"] = 1e6 * a.fast_seconds / a.queries;
  return out;
}

std::string solver_agreement_text(const SolverAgreement& a, std::uint64_t seed) {
  return fmt::format("{} (seed {}, {} of them clearly unreachable)\n",
                     counted(a.queries, "climbing-like query", "climbing-like queries"), seed, a.far_queries) +
         fmt::format("paper solver reached {} ({:.1f} %), fast solver reached {} ({:.1f} %)\n", a.paper_reached,
                     100.0 * a.paper_reached / a.queries, a.fast_reached, 100.0 * a.fast_reached / a.queries) +
         fmt::format("verdicts agree on {}: {:.2f} % (only paper reached {}, only fast reached {})\n",
                     counted(a.agree, "query", "queries"), 100.0 * a.agreement(), a.only_paper_reached,
                     a.only_fast_reached) +
         fmt::format("mean per query: paper {:.1f} iterations, {:.1f} us; fast {:.1f} iterations, {:.1f} us\n",
                     static_cast<double>(a.paper_iterations) / a.queries, 1e6 * a.paper_seconds / a.queries,
                     static_cast<double>(a.fast_iterations) / a.queries, 1e6 * a.fast_seconds / a.queries);
}

nlohmann::ordered_json ik_demo_json(const std::vector<IkDemoSolve>& solves) {
  nlohmann::ordered_json out = nlohmann::json::array();
  for (const IkDemoSolve& s : solves) {
    out.push_back({{"query", s.query},
                   {"solver", enum_name(s.solver)},
                   {"reached", s.result.reached},
                   {"iterations", s.result.iterations},
                   {"simulated_time_s", s.result.simulated_time_s},
                   {"residual_m", s.result.residual_m},
                   {"wall_clock_us", s.wall_clock_us}});
  }
  return out;
}

std::string ik_demo_text(const BodyModel& model, const std::vector<IkDemoSolve>& solves) {
  std::string out = fmt::format("body '{}': {} root + {} revolute degrees of freedom, {:.2f} m, {:.1f} kg\n",
                                model.name, kRootDof, kRevoluteDof, model.stature, model.total_mass);
  for (std::size_t i = 0; i < solves.size(); ++i) {
    const IkDemoSolve& s = solves[i];
    if (i == 0 || solves[i - 1].query != s.query) out += fmt::format("\n{}:\n", s.query);
    out += fmt::format("  {:<5} {:<11} {:5d} {}, {:5.2f} s simulated, residual {:.3f} m, {:8.1f} us\n",
                       enum_name(s.solver), s.result.reached ? "reached" : "NOT reached", s.result.iterations,
                       counted_noun(s.result.iterations, "iteration"), s.result.simulated_time_s, s.result.residual_m,
                       s.wall_clock_us);
  }
  return out;
}

}  // namespace crux

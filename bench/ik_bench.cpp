// Climbing-like IK queries for the paper's solver, crux's fast solver and KDL's
// multi-endpoint tree solver (TreeIkSolverPos_NR_JL), all judged by the same
// termination test. One benchmark iteration solves the whole fixed batch, so every
// solver's solve_rate covers the same queries; `per_query` is the time of one query.

#include <benchmark/benchmark.h>

#include <kdl/treeiksolverpos_nr_jl.hpp>
#include <kdl/treeiksolvervel_wdls.hpp>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "ik/ik_solver.hpp"
#include "ik/reach_queries.hpp"
#include "support/kdl_reference.hpp"

namespace crux {
namespace {

constexpr int kBatch = 200;

IkParameters paper_walk() {
  IkParameters walk;
  walk.solver = IkSolverKind::Paper;  // the walk of crux ik-compare
  return walk;
}

struct Fixture {
  BodyModel model = load_body_model(default_body_model_path());
  IkParameters settings;
  std::vector<ReachQuery> queries = climbing_reach_queries(model, paper_walk(), kBatch, 2026);
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void report(benchmark::State& state, long reached) {
  const double attempted = static_cast<double>(state.iterations()) * kBatch;
  state.counters["solve_rate"] = reached / attempted;
  state.counters["per_query"] =
      benchmark::Counter(attempted, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void run_crux_solver(benchmark::State& state, IkSolverKind kind, WallRule wall = WallRule::Ignore) {
  const Fixture& f = fixture();
  IkParameters settings = f.settings;
  settings.solver = kind;
  settings.wall = wall;
  BodyData data(f.model);
  long reached = 0;
  for (auto _ : state) {
    for (const ReachQuery& q : f.queries) {
      const IkResult result = solve_ik(f.model, data, q.start, q.target, settings);
      reached += result.reached;
      benchmark::DoNotOptimize(result.posture);
    }
  }
  report(state, reached);
}

void BM_IkPaper(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Paper); }
void BM_IkFast(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Fast); }
BENCHMARK(BM_IkPaper)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IkFast)->Unit(benchmark::kMillisecond);

// The body kept out of the wall (ik.wall): rejected after the solve, or avoided inside it.
void BM_IkPaperWallReject(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Paper, WallRule::Reject); }
void BM_IkPaperWallAvoid(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Paper, WallRule::Avoid); }
void BM_IkFastWallReject(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Fast, WallRule::Reject); }
void BM_IkFastWallAvoid(benchmark::State& state) { run_crux_solver(state, IkSolverKind::Fast, WallRule::Avoid); }
BENCHMARK(BM_IkPaperWallReject)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IkPaperWallAvoid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IkFastWallReject)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IkFastWallAvoid)->Unit(benchmark::kMillisecond);

// KDL as a robotics user would set it up: Newton-Raphson with joint limits over the
// five endpoints (root and grasp frames), velocity IK by weighted damped least squares
// with the orientation rows weighted zero (crux asks for positions only), KDL's default
// iteration cap and tolerance. The damping lambda = 0.3 is the best of a scan over
// 0 (KDL's default; it diverges to NaN here), 0.01, 0.03, 0.1, 0.3 and 1
// (docs/PERFORMANCE.md).
void BM_IkKdl(benchmark::State& state) {
  const Fixture& f = fixture();
  testing::KdlReference kdl(default_body_model_path(), f.model);
  const std::vector<std::string> endpoints(kdl.segments().begin(), kdl.segments().end());
  // KDL needs finite bounds; the root keeps +-100 m, effectively free.
  Posture lower = f.model.lower_limits, upper = f.model.upper_limits;
  lower.head<kRootDof>().setConstant(-100.0);
  upper.head<kRootDof>().setConstant(100.0);
  const KDL::JntArray q_min = kdl.to_kdl(lower), q_max = kdl.to_kdl(upper);
  KDL::TreeFkSolverPos_recursive fk(kdl.tree());
  KDL::TreeIkSolverVel_wdls velocity_ik(kdl.tree(), endpoints);
  Eigen::MatrixXd task_weight = Eigen::MatrixXd::Zero(6 * endpoints.size(), 6 * endpoints.size());
  for (std::size_t e = 0; e < endpoints.size(); ++e) task_weight.block<3, 3>(6 * e, 6 * e).setIdentity();
  velocity_ik.setWeightTS(task_weight);
  velocity_ik.setLambda(0.3);
  KDL::TreeIkSolverPos_NR_JL position_ik(kdl.tree(), endpoints, q_min, q_max, fk, velocity_ik);
  BodyData data(f.model);
  KDL::JntArray q_out(kConfigurationDof);
  long reached = 0;
  for (auto _ : state) {
    for (const ReachQuery& q : f.queries) {
      KDL::Frames targets;
      for (std::size_t e = 0; e < endpoints.size(); ++e) {
        const Eigen::Vector3d& p = e == 0 ? q.target.root : q.target.hold_centres[e - 1];
        targets[endpoints[e]] = KDL::Frame(KDL::Vector(p.x(), p.y(), p.z()));
      }
      position_ik.CartToJnt(kdl.to_kdl(q.start), targets, q_out);
      const Posture g = kdl.from_kdl(q_out);
      forward_kinematics(f.model, data, g);
      reached += target_reached(data.points, q.target, f.settings.tolerances) && within_limits(f.model, g);
    }
  }
  report(state, reached);
}
BENCHMARK(BM_IkKdl)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace crux

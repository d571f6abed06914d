// One static-equilibrium solve of the human on four holds, on the postures crux's fast IK
// reaches (kept out of the wall) for the climbing-like queries of ik_bench.cpp. The reused,
// warm-started program and a fresh program per stance, and the same stances on three holds
// with and without the balance precheck; median and 99th percentile of the
// single solves are counters (Google Benchmark reports means only).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "body/urdf_loader.hpp"
#include "ik/ik_solver.hpp"
#include "ik/reach_queries.hpp"
#include "physics/static_equilibrium.hpp"

namespace crux {
namespace {

struct EquilibriumFixture {
  BodyModel model = load_body_model(default_body_model_path());
  StrengthProfile strength = published_strength_profile(model, 68.0, 1.70);
  std::vector<Posture> stances;
  std::vector<PointContact> contacts;

  EquilibriumFixture() {
    IkParameters walk;
    walk.solver = IkSolverKind::Paper;  // the queries of ik_bench.cpp
    IkParameters avoid;
    avoid.wall = WallRule::Avoid;
    BodyData data(model);
    for (const ReachQuery& query : climbing_reach_queries(model, walk, 200, 2026)) {
      const IkResult result = solve_ik(model, data, query.start, query.target, avoid);
      if (result.reached) stances.push_back(result.posture);
    }
    // Incut jugs for the hands, ledges for the feet, as in the tests: inputs, not data.
    for (int limb = 0; limb < kLimbCount; ++limb) {
      PointContact contact;
      contact.limb = static_cast<Limb>(limb);
      contact.support_direction = Eigen::Vector3d(limb < 2 ? 1.0 : -1.0, 0.0, 1.0).normalized();
      contact.friction = 1.0;
      contact.normal_force_limit = limb < 2 ? 500.0 : 1000.0;
      contacts.push_back(contact);
    }
  }
};

const EquilibriumFixture& equilibrium_fixture() {
  static const EquilibriumFixture f;
  return f;
}

void report_percentiles(benchmark::State& state, std::vector<double>& seconds, long balanced, long solves) {
  std::sort(seconds.begin(), seconds.end());
  state.counters["median_us"] = 1e6 * seconds[seconds.size() / 2];
  state.counters["p99_us"] = 1e6 * seconds[seconds.size() * 99 / 100];
  state.counters["balanced"] = static_cast<double>(balanced) / solves;
  state.counters["stances"] = static_cast<double>(equilibrium_fixture().stances.size());
}

template <bool kReused>
void run_equilibrium(benchmark::State& state) {
  const EquilibriumFixture& f = equilibrium_fixture();
  BodyData data(f.model);
  StaticEquilibrium reused(f.model, f.strength);
  std::vector<double> seconds;
  long balanced = 0, solves = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const Posture& g = f.stances[next++ % f.stances.size()];
    const auto start = std::chrono::steady_clock::now();
    if constexpr (kReused) {
      balanced += reused.solve(data, g, f.contacts).balanced;
    } else {
      StaticEquilibrium fresh(f.model, f.strength);
      balanced += fresh.solve(data, g, f.contacts).balanced;
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    ++solves;
  }
  report_percentiles(state, seconds, balanced, solves);
}

// The same stances on three holds (each limb in turn lets go): here some do not balance,
// and the balance precheck refuses most of those without the program. Against the
// program alone, and against the program that asks only whether the stance holds (the
// exact planner's: StaticEquilibrium::holds_within_strength; its counter counts held).
enum class Question { Effort, HoldsOnly };
template <EquilibriumPrecheck kPrecheck, Question kQuestion = Question::Effort>
void run_three_holds(benchmark::State& state) {
  const EquilibriumFixture& f = equilibrium_fixture();
  BodyData data(f.model);
  StaticEquilibrium equilibrium(f.model, f.strength, kPrecheck);
  std::vector<double> seconds;
  long balanced = 0, solves = 0;
  std::size_t next = 0;
  for (auto _ : state) {
    const std::size_t case_index = next++ % (f.stances.size() * kLimbCount);
    const int free_limb = static_cast<int>(case_index % kLimbCount);
    std::vector<PointContact> held;
    for (const PointContact& contact : f.contacts) {
      if (static_cast<int>(contact.limb) != free_limb) held.push_back(contact);
    }
    const auto start = std::chrono::steady_clock::now();
    const Posture& g = f.stances[case_index / kLimbCount];
    if constexpr (kQuestion == Question::Effort) {
      balanced += equilibrium.solve(data, g, held).balanced;
    } else {
      balanced += equilibrium.holds_within_strength(data, g, held);
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    ++solves;
  }
  report_percentiles(state, seconds, balanced, solves);
}

void BM_StaticEquilibrium(benchmark::State& state) { run_equilibrium<true>(state); }
void BM_StaticEquilibriumCold(benchmark::State& state) { run_equilibrium<false>(state); }
BENCHMARK(BM_StaticEquilibrium)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticEquilibriumCold)->Unit(benchmark::kMicrosecond);
void BM_StaticEquilibriumThreeHolds(benchmark::State& state) { run_three_holds<EquilibriumPrecheck::On>(state); }
void BM_StaticEquilibriumThreeHoldsProgramAlone(benchmark::State& state) {
  run_three_holds<EquilibriumPrecheck::Off>(state);
}
void BM_StaticEquilibriumThreeHoldsHoldsOnly(benchmark::State& state) {
  run_three_holds<EquilibriumPrecheck::On, Question::HoldsOnly>(state);
}
BENCHMARK(BM_StaticEquilibriumThreeHolds)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticEquilibriumThreeHoldsProgramAlone)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticEquilibriumThreeHoldsHoldsOnly)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crux

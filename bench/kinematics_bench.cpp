// Forward kinematics plus the five operational Jacobians, crux against KDL.

#include <benchmark/benchmark.h>

#include <vector>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "common/random.hpp"
#include "support/kdl_reference.hpp"

namespace crux {
namespace {

std::vector<Posture> random_postures(const BodyModel& model, int count) {
  Random random(7);
  std::vector<Posture> out(count);
  for (Posture& g : out) {
    for (int i = 0; i < kRootDof; ++i) g[i] = random.uniform(-0.5, 0.5);
    for (int i = kRootDof; i < kConfigurationDof; ++i)
      g[i] = random.uniform(model.lower_limits[i], model.upper_limits[i]);
  }
  return out;
}

void BM_FkJacobians(benchmark::State& state) {
  const BodyModel model = load_body_model(default_body_model_path());
  BodyData data(model);
  const auto postures = random_postures(model, 256);
  std::size_t n = 0;
  for (auto _ : state) {
    forward_kinematics(model, data, postures[n++ & 255]);
    operational_jacobians(model, data);
    benchmark::DoNotOptimize(data.jacobians);
  }
}
BENCHMARK(BM_FkJacobians);

// The same work with KDL: the five frames and the five Jacobians.
void BM_FkJacobiansKdl(benchmark::State& state) {
  const BodyModel model = load_body_model(default_body_model_path());
  testing::KdlReference kdl(default_body_model_path(), model);
  KDL::TreeFkSolverPos_recursive fk(kdl.tree());
  KDL::TreeJntToJacSolver jacobian_solver(kdl.tree());
  KDL::Jacobian jacobian(kConfigurationDof);
  KDL::Frame frame;
  std::vector<KDL::JntArray> postures;
  for (const Posture& g : random_postures(model, 256)) postures.push_back(kdl.to_kdl(g));
  std::size_t n = 0;
  for (auto _ : state) {
    const KDL::JntArray& q = postures[n++ & 255];
    for (const std::string& segment : kdl.segments()) {
      fk.JntToCart(q, frame, segment);
      jacobian_solver.JntToJac(q, jacobian, segment);
      benchmark::DoNotOptimize(frame);
      benchmark::DoNotOptimize(jacobian.data.data());
    }
  }
}
BENCHMARK(BM_FkJacobiansKdl);

}  // namespace
}  // namespace crux

#include "ik/task_jacobian.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <span>
#include <string>
#include <vector>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "support/sample_count.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kSeed = 20261124;

using TaskJacobian = Eigen::Matrix<double, kTaskSize, kConfigurationDof>;

// The dense J the solver used to stack, with the frozen coordinates' columns zeroed.
TaskJacobian dense_jacobian(const BodyData& data, CoordinateSet frozen) {
  TaskJacobian jacobian;
  for (int k = 0; k < kOperationalPointCount; ++k) jacobian.middleRows<3>(3 * k) = data.jacobians[k];
  for (int i = 0; i < kConfigurationDof; ++i) {
    if ((frozen >> i) & 1) jacobian.col(i).setZero();
  }
  return jacobian;
}

void expect_same_bits(double expected, double actual, const std::string& where) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(expected), std::bit_cast<std::uint64_t>(actual))
      << where << ": Eigen " << expected << ", block-sparse " << actual;
}

// A random set of frozen joints (never the root's coordinates, as in the solver).
CoordinateSet random_frozen(Random& random) {
  CoordinateSet frozen = 0;
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    if (random.uniform() < 0.2) frozen |= CoordinateSet{1} << i;
  }
  return frozen;
}

// Both products, entry by entry, against Eigen's: J J^T (`rows` square) and J^T v.
template <typename Normal>
void expect_products_bits(const Normal& expected_normal, const Normal& normal, const Posture& expected_product,
                          const Posture& product, int rows, const std::string& where) {
  ASSERT_EQ(normal.rows(), rows) << where;
  ASSERT_EQ(normal.cols(), rows) << where;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < rows; ++c) {
      expect_same_bits(expected_normal(r, c), normal(r, c),
                       where + ", J J^T (" + std::to_string(r) + ", " + std::to_string(c) + ")");
    }
  }
  for (int i = 0; i < kConfigurationDof; ++i) {
    expect_same_bits(expected_product[i], product[i], where + ", J^T v [" + std::to_string(i) + "]");
  }
}

// Both products against Eigen's dense ones at `postures` random postures, each with a
// random set of frozen joints.
void expect_eigens_bits(const BodyModel& model, std::uint64_t seed, int postures, const std::string& body) {
  Random random(seed);
  BodyData data(model);
  const ChainCoordinates chains = chain_coordinates(model);
  for (int n = 0; n < postures; ++n) {
    const Posture g = n == 0 ? Posture(standing_posture({0.3, 0.6, 1.0})) : testing::random_posture(model, random);
    operational_forward_kinematics(model, data, g);
    operational_jacobians(model, data);
    const CoordinateSet frozen = random_frozen(random);
    TaskVector v;
    for (int r = 0; r < kTaskSize; ++r) v[r] = random.uniform(-1.0, 1.0);
    const TaskJacobian jacobian = dense_jacobian(data, frozen);

    TaskMatrix expected_normal, normal;
    expected_normal.noalias() = jacobian * jacobian.transpose();
    task_normal_matrix(data, chains, frozen, normal);
    Posture expected_product, product;
    expected_product.noalias() = jacobian.transpose() * v;
    task_transpose_product(data, chains, frozen, v, product);

    expect_products_bits(expected_normal, normal, expected_product, product, kTaskSize,
                         body + ", seed " + std::to_string(seed) + ", posture " + std::to_string(n));
    if (::testing::Test::HasFailure()) return;  // one posture's report is enough
  }
}

// The stacked task as the solver stacked it before the stacked products: J row-major, of
// 15 + w rows at most 15 + kMaxExtraTaskRows, the frozen columns zeroed.
using StackedJacobian =
    Eigen::Matrix<double, Eigen::Dynamic, kConfigurationDof, Eigen::RowMajor, kMaxStackedTaskRows, kConfigurationDof>;

// Both stacked products against Eigen's dense ones for every count of extra rows (so every
// shape of GEBP's blocks), at `postures` random postures each: random extra rows that, like
// a primitive's gradient, move only a random chain of coordinates, and random frozen joints.
void expect_eigens_stacked_bits(const BodyModel& model, std::uint64_t seed, int postures, const std::string& body) {
  Random random(seed);
  BodyData data(model);
  const ChainCoordinates chains = chain_coordinates(model);
  std::vector<Posture> extra_rows(kMaxExtraTaskRows);
  for (int extra = 0; extra <= kMaxExtraTaskRows; ++extra) {
    for (int n = 0; n < postures; ++n) {
      operational_forward_kinematics(model, data, testing::random_posture(model, random));
      operational_jacobians(model, data);
      const CoordinateSet frozen = random_frozen(random);
      const int rows = kTaskSize + extra;
      StackedJacobian jacobian(rows, kConfigurationDof);
      for (int k = 0; k < kOperationalPointCount; ++k) jacobian.middleRows<3>(3 * k) = data.jacobians[k];
      for (int r = 0; r < extra; ++r) {
        const double moving = random.uniform();
        for (int i = 0; i < kConfigurationDof; ++i) {
          extra_rows[r][i] = random.uniform() < moving ? random.uniform(-1.0, 1.0) : 0.0;
        }
        jacobian.row(kTaskSize + r) = extra_rows[r].transpose();
      }
      for (int i = 0; i < kConfigurationDof; ++i) {
        if ((frozen >> i) & 1) jacobian.col(i).setZero();
      }
      StackedTaskVector v(rows);
      for (int r = 0; r < rows; ++r) v[r] = random.uniform(-1.0, 1.0);
      const std::span<const Posture> extra_span(extra_rows.data(), static_cast<std::size_t>(extra));

      StackedTaskMatrix expected_normal, normal;
      expected_normal.noalias() = jacobian * jacobian.transpose();
      const StackedTask task(data, chains, extra_span, frozen);
      task.normal_matrix(normal);
      Posture expected_product, product;
      expected_product.noalias() = jacobian.transpose() * v;
      task.transpose_product(v, product);

      expect_products_bits(expected_normal, normal, expected_product, product, rows,
                           body + ", seed " + std::to_string(seed) + ", " + std::to_string(extra) +
                               " extra rows, posture " + std::to_string(n));
      if (::testing::Test::HasFailure()) return;  // one posture's report is enough
    }
  }
}

TEST(TaskJacobian, ChainCoordinatesAreTheChains) {
  const BodyModel& model = testing::human_model();
  const ChainCoordinates chains = chain_coordinates(model);
  for (int k = 0; k < kOperationalPointCount; ++k) {
    EXPECT_EQ(std::popcount(chains[k]), static_cast<int>(model.chains[k].size())) << "point " << k;
    for (const int i : model.chains[k]) EXPECT_TRUE((chains[k] >> i) & 1) << "point " << k << " coordinate " << i;
  }
  EXPECT_EQ(chains[0], CoordinateSet{0b111}) << "the root point moves with the root's translation only";
}

TEST(TaskJacobian, ProductsEqualEigensBitForBit) {
  expect_eigens_bits(testing::human_model(), kSeed, testing::sample_count(500), "human");
  for (std::uint64_t tree = 1; tree <= 3; ++tree) {
    const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(tree));
    expect_eigens_bits(load_body_model(path.string()), kSeed + tree, testing::sample_count(200),
                       "synthetic tree " + std::to_string(tree));
  }
}

TEST(TaskJacobian, StackedProductsEqualEigensBitForBit) {
  expect_eigens_stacked_bits(testing::human_model(), kSeed, testing::sample_count(40), "human");
  const auto path = testing::write_temporary("synthetic.urdf", testing::synthetic_tree_urdf(2));
  expect_eigens_stacked_bits(load_body_model(path.string()), kSeed + 2, testing::sample_count(10), "synthetic tree 2");
}

}  // namespace
}  // namespace crux

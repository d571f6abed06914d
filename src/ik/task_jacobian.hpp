#pragma once
// The stacked Jacobian J of the five operational points (the root, then the grasp points)
// and the two products the fast solver needs, J J^T and J^T v, computed over J's block
// sparsity: point k moves only with the coordinates of its chain (model.chains[k]), so a
// block of J J^T sums over the few coordinates two chains share, not all 35. When the
// solver keeps the body out of the wall, J has more rows below the points' (one per
// primitive past the margin, ik/wall_clearance.hpp), and the stacked products take them.
//
// Every entry is summed in the order Eigen 3.4's dense kernels use for these sizes (GEBP
// for J J^T; for J^T v the row-major GEMV of the fixed-size task, the column-major one of
// the stacked task, whose J the solver kept row-major); terms that are exactly zero are
// skipped, which leaves a sum that starts at +0 unchanged when every factor is finite. So
// the solver's postures, and every result built on them, are bit for bit those of the
// dense products. The tests TaskJacobian.ProductsEqualEigensBitForBit and
// TaskJacobian.StackedProductsEqualEigensBitForBit (every row count) fail if a compiler or
// Eigen version sums in another order.

#include <array>
#include <cstdint>
#include <span>

#include <Eigen/Core>

#include "body/body_data.hpp"

namespace crux {

inline constexpr int kTaskSize = 3 * kOperationalPointCount;
using TaskVector = Eigen::Matrix<double, kTaskSize, 1>;
using TaskMatrix = Eigen::Matrix<double, kTaskSize, kTaskSize>;

// At most this many rows below the points' in a stacked task (the human has 12 primitives
// that the wall counts).
inline constexpr int kMaxExtraTaskRows = 32;
inline constexpr int kMaxStackedTaskRows = kTaskSize + kMaxExtraTaskRows;
using StackedTaskVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStackedTaskRows, 1>;
using StackedTaskMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStackedTaskRows, kMaxStackedTaskRows>;

// A set of coordinates, bit i for coordinate i.
using CoordinateSet = std::uint64_t;
static_assert(kConfigurationDof <= 64, "a CoordinateSet holds one bit per coordinate");

// chain_coordinates(model)[k]: the coordinates that move operational point k.
using ChainCoordinates = std::array<CoordinateSet, kOperationalPointCount>;
ChainCoordinates chain_coordinates(const BodyModel& model);

// J J^T, with J stacked from data.jacobians and the `frozen` coordinates' columns taken as 0.
void task_normal_matrix(const BodyData& data, const ChainCoordinates& chains, CoordinateSet frozen, TaskMatrix& normal);

// J^T v, with the `frozen` coordinates' columns taken as 0.
void task_transpose_product(const BodyData& data, const ChainCoordinates& chains, CoordinateSet frozen,
                            const TaskVector& v, Posture& out);

// The points' rows of J stacked over `extra_rows` (each a row of J over all coordinates),
// with the `frozen` coordinates' columns taken as 0: 15 + extra rows. Made once per IK
// iteration (it records which coordinates each row moves), then asked for J J^T and for
// the J^T v of every trial step. It refers to `data`, `chains` and `extra_rows`.
class StackedTask {
 public:
  StackedTask(const BodyData& data, const ChainCoordinates& chains, std::span<const Posture> extra_rows,
              CoordinateSet frozen);

  int rows() const { return rows_; }
  void normal_matrix(StackedTaskMatrix& normal) const;                     // J J^T, rows() square
  void transpose_product(const StackedTaskVector& v, Posture& out) const;  // J^T v, v of rows() entries

  // One row of J: its entries (`stride` apart) and the coordinates it moves.
  struct Row {
    const double* first;
    int stride;
    CoordinateSet support;
    double operator[](int i) const { return first[i * stride]; }
  };
  const Row& row(int row) const { return row_views_[row]; }
  const BodyData& data() const { return data_; }
  const ChainCoordinates& chains() const { return chains_; }
  CoordinateSet frozen() const { return frozen_; }

 private:
  const BodyData& data_;
  const ChainCoordinates& chains_;
  CoordinateSet frozen_;
  int rows_;
  std::array<Row, kMaxStackedTaskRows> row_views_;
};

}  // namespace crux

#include "ik/task_jacobian.hpp"

#include <bit>

namespace crux {

namespace {

// The shape of Eigen 3.4's SSE2 kernels for a 15 x 35 by 35 x 15 product: GEBP takes the
// rows in blocks of 4, then one packet of 2 rows, then single rows, and the columns in
// blocks of 4; it unrolls the depth by 8. On the 2-row packet against a 4-column block,
// it sums even and odd depth steps of the unrolled part in two accumulators, adds them,
// then adds the rest in order. Every other entry is one sum in depth order. The
// row-major GEMV behind J^T v sums each 2-wide packet of a row in two lanes, adds the
// lanes, then adds the last (odd) entry.
constexpr int kRowBlock = 4, kColumnBlock = 4, kPacket = 2, kDepthUnroll = 8;
constexpr int kPacketRowsBegin = kTaskSize / kRowBlock * kRowBlock;
constexpr int kPacketRowsEnd = kPacketRowsBegin + kPacket;
constexpr int kColumnBlocksEnd = kTaskSize / kColumnBlock * kColumnBlock;
constexpr int kPeeledDepth = kConfigurationDof / kDepthUnroll * kDepthUnroll;
constexpr int kLaneRowsEnd = kTaskSize / kPacket * kPacket;
static_assert(kTaskSize - kLaneRowsEnd == 1, "J^T v ends each sum with a single last row");

// Block (k, l) of J J^T summed over `shared` in ascending coordinate order.
Eigen::Matrix3d sequential_block(const BodyData& data, int k, int l, CoordinateSet shared) {
  const OperationalJacobian& jk = data.jacobians[k];
  const OperationalJacobian& jl = data.jacobians[l];
  Eigen::Matrix3d block = Eigen::Matrix3d::Zero();
  for (; shared != 0; shared &= shared - 1) {
    const int i = std::countr_zero(shared);
    for (int b = 0; b < 3; ++b) {
      for (int a = 0; a < 3; ++a) block(a, b) += jk(a, i) * jl(b, i);
    }
  }
  return block;
}

// Entry (row a of point k, row b of point l) of J J^T with GEBP's two accumulators.
double two_accumulator_entry(const BodyData& data, int k, int a, int l, int b, CoordinateSet shared) {
  constexpr CoordinateSet kPeeled = (CoordinateSet{1} << kPeeledDepth) - 1;
  const OperationalJacobian& jk = data.jacobians[k];
  const OperationalJacobian& jl = data.jacobians[l];
  double even = 0.0, odd = 0.0;
  for (CoordinateSet peeled = shared & kPeeled; peeled != 0; peeled &= peeled - 1) {
    const int i = std::countr_zero(peeled);
    (i % 2 == 0 ? even : odd) += jk(a, i) * jl(b, i);
  }
  double sum = even + odd;
  for (CoordinateSet rest = shared & ~kPeeled; rest != 0; rest &= rest - 1) {
    const int i = std::countr_zero(rest);
    sum += jk(a, i) * jl(b, i);
  }
  return sum;
}

}  // namespace

ChainCoordinates chain_coordinates(const BodyModel& model) {
  ChainCoordinates chains{};
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (const int i : model.chains[k]) chains[k] |= CoordinateSet{1} << i;
  }
  return chains;
}

void task_normal_matrix(const BodyData& data, const ChainCoordinates& chains, CoordinateSet frozen,
                        TaskMatrix& normal) {
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (int l = 0; l <= k; ++l) {
      // A product commutes exactly, so a block summed in order equals its mirror's transpose.
      const Eigen::Matrix3d block = sequential_block(data, k, l, chains[k] & chains[l] & ~frozen);
      normal.block<3, 3>(3 * k, 3 * l) = block;
      normal.block<3, 3>(3 * l, 3 * k) = block.transpose();
    }
  }
  for (int row = kPacketRowsBegin; row < kPacketRowsEnd; ++row) {
    for (int column = 0; column < kColumnBlocksEnd; ++column) {
      const int k = row / 3, l = column / 3;
      normal(row, column) = two_accumulator_entry(data, k, row % 3, l, column % 3, chains[k] & chains[l] & ~frozen);
    }
  }
}

void task_transpose_product(const BodyData& data, const ChainCoordinates& chains, CoordinateSet frozen,
                            const TaskVector& v, Posture& out) {
  // Every sum starts at +0 and so never becomes -0: adding a last row of +0 changes nothing.
  std::array<double, kConfigurationDof> even{}, odd{}, last{};
  for (int row = 0; row < kTaskSize; ++row) {
    for (CoordinateSet moving = chains[row / 3] & ~frozen; moving != 0; moving &= moving - 1) {
      const int i = std::countr_zero(moving);
      const double term = data.jacobians[row / 3](row % 3, i) * v[row];
      if (row == kLaneRowsEnd) {
        last[i] = term;
      } else if (row % 2 == 0) {
        even[i] += term;
      } else {
        odd[i] += term;
      }
    }
  }
  for (int i = 0; i < kConfigurationDof; ++i) {
    out[i] = (even[i] + odd[i]) + last[i];
  }
}

}  // namespace crux

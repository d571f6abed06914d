#include "ik/task_jacobian.hpp"

#include <bit>

namespace crux {

namespace {

// The shape of Eigen 3.4's SSE2 kernels. GEBP, for an R x 35 by 35 x R product (R <= 47,
// too small to be split in blocks): rows in blocks of 4, then one packet of 2 rows if two
// are left, then single rows, and columns in blocks of 4, then single columns; it unrolls
// the depth by 8. On the 2-row packet against a 4-column block, it sums even and odd depth
// steps of the unrolled part in two accumulators, adds them, then adds the rest in order.
// Every other entry is one sum in depth order. The row-major GEMV behind the task's J^T v
// sums each 2-wide packet of a row in two lanes, adds the lanes, then adds the last (odd)
// entry; the column-major GEMV behind the stacked J^T v sums each entry in row order.
constexpr int kRowBlock = 4, kColumnBlock = 4, kPacket = 2, kDepthUnroll = 8;
constexpr int kPeeledDepth = kConfigurationDof / kDepthUnroll * kDepthUnroll;
constexpr int kLaneRowsEnd = kTaskSize / kPacket * kPacket;
static_assert(kTaskSize - kLaneRowsEnd == 1, "J^T v ends each sum with a single last row");

using Row = StackedTask::Row;

// Block (k, l) of J J^T for points k and l, summed over `shared` in ascending coordinate order.
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

// An entry of J J^T, rows a and b of J, summed in ascending coordinate order.
double sequential_entry(const Row& a, const Row& b) {
  double sum = 0.0;
  for (CoordinateSet shared = a.support & b.support; shared != 0; shared &= shared - 1) {
    const int i = std::countr_zero(shared);
    sum += a[i] * b[i];
  }
  return sum;
}

// The same entry with GEBP's two accumulators.
double two_accumulator_entry(const Row& a, const Row& b) {
  constexpr CoordinateSet kPeeled = (CoordinateSet{1} << kPeeledDepth) - 1;
  const CoordinateSet shared = a.support & b.support;
  double even = 0.0, odd = 0.0;
  for (CoordinateSet peeled = shared & kPeeled; peeled != 0; peeled &= peeled - 1) {
    const int i = std::countr_zero(peeled);
    (i % 2 == 0 ? even : odd) += a[i] * b[i];
  }
  double sum = even + odd;
  for (CoordinateSet rest = shared & ~kPeeled; rest != 0; rest &= rest - 1) {
    const int i = std::countr_zero(rest);
    sum += a[i] * b[i];
  }
  return sum;
}

// J J^T in GEBP's order into `normal`, already rows.rows() square.
template <typename Matrix>
void fill_normal_matrix(const StackedTask& rows, Matrix& normal) {
  const ChainCoordinates& chains = rows.chains();
  const CoordinateSet frozen = rows.frozen();
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (int l = 0; l <= k; ++l) {
      // A product commutes exactly, so a block summed in order equals its mirror's transpose.
      const Eigen::Matrix3d block = sequential_block(rows.data(), k, l, chains[k] & chains[l] & ~frozen);
      normal.template block<3, 3>(3 * k, 3 * l) = block;
      normal.template block<3, 3>(3 * l, 3 * k) = block.transpose();
    }
  }
  const int count = rows.rows();
  for (int row = kTaskSize; row < count; ++row) {
    for (int column = 0; column <= row; ++column) {
      normal(row, column) = normal(column, row) = sequential_entry(rows.row(row), rows.row(column));
    }
  }
  const int packet_rows_begin = count / kRowBlock * kRowBlock;
  const int packet_rows_end = count - packet_rows_begin >= kPacket ? packet_rows_begin + kPacket : packet_rows_begin;
  const int column_blocks_end = count / kColumnBlock * kColumnBlock;
  for (int row = packet_rows_begin; row < packet_rows_end; ++row) {
    for (int column = 0; column < column_blocks_end; ++column) {
      normal(row, column) = two_accumulator_entry(rows.row(row), rows.row(column));
    }
  }
}

}  // namespace

ChainCoordinates chain_coordinates(const BodyModel& model) {
  ChainCoordinates chains{};
  for (int k = 0; k < kOperationalPointCount; ++k) {
    for (const int i : model.chains[k]) chains[k] |= CoordinateSet{1} << i;
  }
  return chains;
}

StackedTask::StackedTask(const BodyData& data, const ChainCoordinates& chains, std::span<const Posture> extra_rows,
                         CoordinateSet frozen)
    : data_(data), chains_(chains), frozen_(frozen), rows_(kTaskSize + static_cast<int>(extra_rows.size())) {
  for (int row = 0; row < kTaskSize; ++row) {
    // A point's Jacobian is column-major, 3 rows.
    row_views_[row] = {data.jacobians[row / 3].data() + row % 3, 3, chains[row / 3] & ~frozen};
  }
  for (std::size_t r = 0; r < extra_rows.size(); ++r) {
    CoordinateSet moving = 0;
    for (int i = 0; i < kConfigurationDof; ++i) {
      if (extra_rows[r][i] != 0.0) moving |= CoordinateSet{1} << i;
    }
    row_views_[kTaskSize + r] = {extra_rows[r].data(), 1, moving & ~frozen};
  }
}

void StackedTask::normal_matrix(StackedTaskMatrix& normal) const {
  normal.resize(rows_, rows_);
  fill_normal_matrix(*this, normal);
}

void StackedTask::transpose_product(const StackedTaskVector& v, Posture& out) const {
  out.setZero();
  for (int r = 0; r < rows_; ++r) {
    const Row& row = row_views_[r];
    for (CoordinateSet moving = row.support; moving != 0; moving &= moving - 1) {
      const int i = std::countr_zero(moving);
      out[i] += row[i] * v[r];
    }
  }
}

void task_normal_matrix(const BodyData& data, const ChainCoordinates& chains, CoordinateSet frozen,
                        TaskMatrix& normal) {
  fill_normal_matrix(StackedTask(data, chains, {}, frozen), normal);
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

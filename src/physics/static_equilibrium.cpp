#include "physics/static_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <malloc.h>
#include <ClpSimplex.hpp>
#include <Eigen/Geometry>

#include "body/kinematics.hpp"
#include "common/checkpoint_stream.hpp"
#include "physics/balance_precheck.hpp"

namespace crux {
namespace {

// Columns: the weights of each limb's kFrictionConeFaces generators, limb after limb, then
// the effort t. Rows: force balance (3), moment balance about the root (3), each limb's
// normal force (kLimbCount), then one row per bounded joint and direction.
constexpr int kEffortColumn = kLimbCount * kFrictionConeFaces;
constexpr int kEquilibriumColumns = kEffortColumn + 1;
constexpr int kBalanceRows = 6;
constexpr int kFirstNormalRow = kBalanceRows;
constexpr int kFirstJointRow = kFirstNormalRow + kLimbCount;
const double kUnboundedRow = COIN_DBL_MAX;  // CLP's infinity

bool moves_limb(const BodyModel& model, int limb, int joint) {
  const std::vector<int>& chain = model.chains[operational_point(limb)];
  return std::find(chain.begin(), chain.end(), joint) != chain.end();
}

// CLP allocates and frees work areas of 164 and 328 kB in every solve, which glibc serves
// by default with mmap and munmap: a tenth of a static run's time went to the kernel
// (docs/PERFORMANCE.md, "Static equilibrium"). From the heap, and kept there, they cost
// nothing. Process-wide, and only a matter of speed.
void keep_clp_work_areas_on_the_heap() {
  [[maybe_unused]] static const bool kept =
      mallopt(M_MMAP_THRESHOLD, 4 << 20) == 1 && mallopt(M_TRIM_THRESHOLD, 16 << 20) == 1;
}

// The balance precheck on the held limbs' contacts, their levers about the root: true when
// no forces within their cones and normal limits balance the weight and its moment.
bool precheck_proves_unbalanced(const BodyData& data, const Eigen::Vector3d& root,
                                const std::array<const PointContact*, kLimbCount>& held,
                                const std::array<FrictionConeGenerators, kLimbCount>& cones,
                                const Eigen::Vector3d& weight, const Eigen::Vector3d& weight_moment) {
  std::array<HeldContact, kLimbCount> held_contacts;
  std::size_t held_count = 0;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (held[limb] == nullptr) continue;
    held_contacts[held_count++] = {data.points[operational_point(limb)] - root, cones[limb],
                                   held[limb]->normal_force_limit};
  }
  return proven_unbalanced(std::span<const HeldContact>(held_contacts.data(), held_count), -weight, -weight_moment);
}

}  // namespace

StaticEquilibrium::StaticEquilibrium(const BodyModel& model, const StrengthProfile& strength,
                                     EquilibriumPrecheck precheck)
    : model_(model), precheck_(precheck) {
  keep_clp_work_areas_on_the_heap();
  for (int j = kRootDof; j < static_cast<int>(model.joints.size()); ++j) {
    const JointStrength& limits = strength.joints[j];
    if (!(limits.positive > 0.0) || !(limits.negative > 0.0)) {
      throw std::invalid_argument("the torque limits of " + model.joints[j].name + " must be > 0");
    }
    if (std::isfinite(limits.positive)) joint_rows_.push_back({j, 1.0, limits.positive});
    if (std::isfinite(limits.negative)) joint_rows_.push_back({j, -1.0, limits.negative});
  }
  const int row_count = kFirstJointRow + static_cast<int>(joint_rows_.size());
  // The sparsity never changes: a limb's forces reach the joints of its own chain only.
  starts_.push_back(0);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    for (int face = 0; face < kFrictionConeFaces; ++face) {
      for (int row = 0; row < kBalanceRows; ++row) rows_.push_back(row);
      rows_.push_back(kFirstNormalRow + limb);
      for (int r = 0; r < static_cast<int>(joint_rows_.size()); ++r) {
        if (moves_limb(model, limb, joint_rows_[r].joint)) rows_.push_back(kFirstJointRow + r);
      }
      starts_.push_back(static_cast<int>(rows_.size()));
    }
  }
  for (int r = 0; r < static_cast<int>(joint_rows_.size()); ++r) rows_.push_back(kFirstJointRow + r);
  starts_.push_back(static_cast<int>(rows_.size()));
  values_.assign(rows_.size(), 0.0);
  column_lower_.assign(kEquilibriumColumns, 0.0);
  column_upper_.assign(kEquilibriumColumns, kUnboundedRow);
  objective_.assign(kEquilibriumColumns, 0.0);
  objective_[kEffortColumn] = 1.0;  // minimise t
  row_lower_.assign(row_count, -kUnboundedRow);
  row_upper_.assign(row_count, kUnboundedRow);
  basis_.assign(row_count + kEquilibriumColumns, 0);
  pristine_solver_ = std::make_unique<ClpSimplex>();
  pristine_solver_->setLogLevel(0);
  // Unscaled: reloaded into one object, CLP's scaled programs gave different optima warm and
  // cold (by up to 0.26 in effort on random postures); unscaled they agree
  // (StaticEquilibrium.WarmStartsGiveTheColdSolvesEffort).
  pristine_solver_->scaling(0);
}

StaticEquilibrium::~StaticEquilibrium() = default;

bool StaticEquilibrium::load_stance(BodyData& data, const Posture& g, std::span<const PointContact> contacts,
                                    const Eigen::Vector3d& gravity) {
  tau_g_ = gravity_forces(model_, data, g, gravity);
  const Eigen::Vector3d& com = centre_of_mass(model_, data);
  const Eigen::Vector3d& root = data.points[0];

  held_.fill(nullptr);
  for (const PointContact& contact : contacts) {
    const int limb = static_cast<int>(contact.limb);
    if (held_[limb] != nullptr) throw std::invalid_argument("two contacts for one limb");
    held_[limb] = &contact;
  }
  // Each held limb's cone edges, once: the precheck, the program and its forces read them.
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (held_[limb] != nullptr) cones_[limb] = friction_cone_generators(*held_[limb]);
  }

  // Force balance: sum of f_c = -(the weight) = -tau_g's root part. Moment balance about
  // the root: sum of (p_c - root) x f_c = -M (com - root) x gravity.
  const Eigen::Vector3d weight = tau_g_.head<kRootDof>();
  const Eigen::Vector3d weight_moment = model_.total_mass * (com - root).cross(gravity);
  for (int row = 0; row < 3; ++row) {
    row_lower_[row] = row_upper_[row] = -weight[row];
    row_lower_[3 + row] = row_upper_[3 + row] = -weight_moment[row];
  }
  for (int limb = 0; limb < kLimbCount; ++limb) {
    row_upper_[kFirstNormalRow + limb] = held_[limb] != nullptr && std::isfinite(held_[limb]->normal_force_limit)
                                             ? held_[limb]->normal_force_limit
                                             : kUnboundedRow;
  }
  // Most stances that cannot balance are refused here, without the program (40 % of all
  // stances on random vertical walls, 86 % of those unbalanced): see docs/PHYSICS.md,
  // "Proven unbalanced without a program". The basis stays the last program's.
  if (precheck_ == EquilibriumPrecheck::On &&
      precheck_proves_unbalanced(data, root, held_, cones_, weight, weight_moment)) {
    return false;
  }
  operational_jacobians(model_, data);
  // tau_j = -(tau_g_j + r_j) with r_j = sum of J_c(:, j) . f_c; sign * tau_j <= t * limit
  // reads sign * r_j + limit * t >= -sign * tau_g_j.
  for (int r = 0; r < static_cast<int>(joint_rows_.size()); ++r) {
    row_lower_[kFirstJointRow + r] = -joint_rows_[r].sign * tau_g_[joint_rows_[r].joint];
  }

  for (int limb = 0; limb < kLimbCount; ++limb) {
    const bool is_held = held_[limb] != nullptr;
    const FrictionConeGenerators& generators = cones_[limb];
    const Eigen::Vector3d lever = data.points[operational_point(limb)] - root;
    const OperationalJacobian& jacobian = data.jacobians[operational_point(limb)];
    for (int face = 0; face < kFrictionConeFaces; ++face) {
      const int column = limb * kFrictionConeFaces + face;
      column_upper_[column] = is_held ? kUnboundedRow : 0.0;
      const Eigen::Vector3d edge = is_held ? generators[face] : Eigen::Vector3d::Zero();
      const Eigen::Vector3d moment = lever.cross(edge);
      for (int e = starts_[column]; e < starts_[column + 1]; ++e) {
        const int row = rows_[e];
        if (row < 3) {
          values_[e] = edge[row];
        } else if (row < kBalanceRows) {
          values_[e] = moment[row - 3];
        } else if (row < kFirstJointRow) {
          values_[e] = 1.0;  // each edge has normal component 1
        } else {
          const JointRow& joint_row = joint_rows_[row - kFirstJointRow];
          values_[e] = joint_row.sign * jacobian.col(joint_row.joint).dot(edge);
        }
      }
    }
  }
  for (int e = starts_[kEffortColumn]; e < starts_[kEffortColumn + 1]; ++e) {
    values_[e] = joint_rows_[rows_[e] - kFirstJointRow].limit;
  }
  return true;
}

bool StaticEquilibrium::run_program(ClpSimplex& solver, ProgramGoal goal) {
  // The least effort: minimise t. Holding or not: t at most 1 and nothing to minimise, so
  // the simplex stops at the first equilibrium it finds (no second phase).
  objective_[kEffortColumn] = goal == ProgramGoal::LeastEffort ? 1.0 : 0.0;
  column_upper_[kEffortColumn] = goal == ProgramGoal::LeastEffort ? kUnboundedRow : 1.0;
  const int row_count = static_cast<int>(row_lower_.size());
  // The last basis has the same rows and columns, so the primal simplex starts from it
  // (docs/PERFORMANCE.md, "Static equilibrium").
  solver.loadProblem(kEquilibriumColumns, row_count, starts_.data(), rows_.data(), values_.data(), column_lower_.data(),
                     column_upper_.data(), objective_.data(), row_lower_.data(), row_upper_.data());
  if (has_basis_) solver.copyinStatus(basis_.data());
  solver.primal(0, 0);
  if (!solver.isProvenOptimal() && !solver.isProvenPrimalInfeasible()) {
    solver.allSlackBasis(true);
    solver.primal();
  }
  if (!solver.isProvenOptimal() && !solver.isProvenPrimalInfeasible()) {
    throw std::runtime_error("CLP neither solved the static equilibrium nor proved it infeasible");
  }
  std::copy_n(solver.statusArray(), basis_.size(), basis_.begin());
  has_basis_ = true;
  return solver.isProvenOptimal();
}

bool StaticEquilibrium::holds_within_strength(BodyData& data, const Posture& g, std::span<const PointContact> contacts,
                                              const Eigen::Vector3d& gravity) {
  if (!load_stance(data, g, contacts, gravity)) return false;
  ClpSimplex solver(*pristine_solver_);
  return run_program(solver, ProgramGoal::HoldsWithinStrength);
}

const StaticEquilibriumResult& StaticEquilibrium::solve(BodyData& data, const Posture& g,
                                                        std::span<const PointContact> contacts,
                                                        const Eigen::Vector3d& gravity) {
  if (!load_stance(data, g, contacts, gravity)) return unbalanced_result();
  // A fresh solver object each time (a copy of one never solved), given the program and the
  // last basis: CLP adjusts its own parameters during a solve (its infeasibility cost,
  // perturbation), so a reused object's result would depend on every earlier solve, and a
  // run resumed from a checkpoint, which restores the basis alone, would drift in the
  // efforts' last bits.
  ClpSimplex solver(*pristine_solver_);
  if (!run_program(solver, ProgramGoal::LeastEffort)) return unbalanced_result();
  StaticEquilibriumResult& result = result_;
  result.contact_forces.fill(Eigen::Vector3d::Zero());
  result.joint_torques.setZero();
  result.at_force_limit.fill(false);
  result.binding_joint = -1;
  const double* weights = solver.primalColumnSolution();
  GeneralisedForce contact_forces = GeneralisedForce::Zero();
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (held_[limb] == nullptr) continue;
    const FrictionConeGenerators& generators = cones_[limb];
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    double normal = 0.0;
    for (int face = 0; face < kFrictionConeFaces; ++face) {
      const double weight_k = std::max(0.0, weights[limb * kFrictionConeFaces + face]);
      force += weight_k * generators[face];
      normal += weight_k;
    }
    result.contact_forces[limb] = force;
    result.at_force_limit[limb] = normal >= held_[limb]->normal_force_limit - 1e-6;
    contact_forces.noalias() += data.jacobians[operational_point(limb)].transpose() * force;
  }
  result.joint_torques = -(tau_g_ + contact_forces);
  result.joint_torques.head<kRootDof>().setZero();
  // The effort is t, the largest ratio: reported from the torques, with its joint.
  result.effort = 0.0;
  result.binding = EquilibriumBinding::None;
  for (const JointRow& joint_row : joint_rows_) {
    const double ratio = joint_row.sign * result.joint_torques[joint_row.joint] / joint_row.limit;
    if (ratio > result.effort) {
      result.effort = ratio;
      result.binding_joint = joint_row.joint;
      result.binding = joint_row.sign > 0 ? EquilibriumBinding::JointPositive : EquilibriumBinding::JointNegative;
    }
  }
  result.balanced = true;
  result.feasible = result.effort <= 1.0;
  return result;
}

const StaticEquilibriumResult& StaticEquilibrium::unbalanced_result() {
  StaticEquilibriumResult& result = result_;
  result.contact_forces.fill(Eigen::Vector3d::Zero());
  result.joint_torques.setZero();
  result.at_force_limit.fill(false);
  result.binding_joint = -1;
  result.feasible = result.balanced = false;
  result.effort = std::numeric_limits<double>::infinity();
  result.binding = EquilibriumBinding::Contacts;
  return result;
}

void StaticEquilibrium::save_basis(CheckpointWriter& out) const {
  out.value<std::uint8_t>(has_basis_ ? 1 : 0);
  out.vector(basis_);
}

void StaticEquilibrium::load_basis(CheckpointReader& in) {
  has_basis_ = in.flag();
  const std::vector<unsigned char> basis = in.vector<unsigned char>();
  if (basis.size() != basis_.size()) in.fail();
  basis_ = basis;
}

}  // namespace crux

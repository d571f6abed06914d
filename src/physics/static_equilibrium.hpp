#pragma once
// Whether a posture can be held still on its holds, and at what effort (docs/PHYSICS.md,
// "Static equilibrium"): a linear program over the contact forces, solved with COIN-OR CLP.

#include <array>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "body/body_data.hpp"
#include "body/body_model.hpp"
#include "body/gravity_forces.hpp"
#include "physics/contact_model.hpp"
#include "physics/strength_profile.hpp"

class ClpSimplex;

namespace crux {

class CheckpointReader;
class CheckpointWriter;

// What limits the stance: the joint whose torque-to-limit ratio is the effort, or, when
// no equilibrium exists, the contacts (no forces in their cones and under their normal
// force limits balance gravity; joint limits alone never make the program infeasible).
enum class EquilibriumBinding { None, JointPositive, JointNegative, Contacts };

struct StaticEquilibriumResult {
  bool feasible = false;  // an equilibrium exists and effort <= 1
  bool balanced = false;  // an equilibrium exists, within the contacts' limits, at any effort
  // The largest torque-to-limit ratio, minimised over the equilibria; +infinity unbalanced.
  double effort = 0.0;
  // The force each hold exerts on its limb, newtons, limb order; zero for free limbs.
  std::array<Eigen::Vector3d, kLimbCount> contact_forces;
  // The torque each joint exerts, tau = -(tau_g + sum J_c^T f_c), newton-metres; zero on
  // the three unactuated root translations.
  GeneralisedForce joint_torques = GeneralisedForce::Zero();
  EquilibriumBinding binding = EquilibriumBinding::None;
  int binding_joint = -1;                         // coordinate of G for the Joint* bindings
  std::array<bool, kLimbCount> at_force_limit{};  // normal force at its limit, within 1e-6
};

// Whether a stance goes through proven_unbalanced (physics/balance_precheck) before the
// program: Off lets the program decide every stance, the reference the check is tested
// against.
enum class EquilibriumPrecheck { On, Off };

// One linear program, built once for a model and strength profile and refilled for every
// stance, each solve warm started from the last one's basis: one per thread, like BodyData.
class StaticEquilibrium {
 public:
  StaticEquilibrium(const BodyModel& model, const StrengthProfile& strength,
                    EquilibriumPrecheck precheck = EquilibriumPrecheck::On);
  ~StaticEquilibrium();
  StaticEquilibrium(const StaticEquilibrium&) = delete;
  StaticEquilibrium& operator=(const StaticEquilibrium&) = delete;

  // The posture g held by `contacts` (at most one per limb, at the limb's grasp point).
  // Places the body in `data`. A contact checked by check_contact is a precondition;
  // two contacts of one limb are std::invalid_argument. The result stays valid until the
  // next solve.
  const StaticEquilibriumResult& solve(BodyData& data, const Posture& g, std::span<const PointContact> contacts,
                                       const Eigen::Vector3d& gravity = kStandardGravity);

  // solve(...).feasible, without the least effort: the same program with the effort
  // bounded by 1 and nothing to minimise, which the simplex answers with its first
  // equilibrium (one phase instead of two). The two agree but for efforts within CLP's
  // tolerance of 1 (StaticEquilibrium.HoldingWithinStrengthIsAnEffortOfAtMostOne). Its
  // bases join the same warm-start chain, so an object whose efforts must repeat bit for
  // bit (a learning run's) asks only solve.
  bool holds_within_strength(BodyData& data, const Posture& g, std::span<const PointContact> contacts,
                             const Eigen::Vector3d& gravity = kStandardGravity);

  // The basis the next solve starts from, for a run's checkpoint: a warm start from
  // another basis may end on another optimal vertex, with an effort that differs in its
  // last bits, so a resumed run restores it to continue bit for bit.
  void save_basis(CheckpointWriter& out) const;
  void load_basis(CheckpointReader& in);
  // The next solve starts cold, as the first one did: a degenerate program's optimal
  // vertex, and so its torques, then do not depend on the solves before.
  void forget_basis() { has_basis_ = false; }

 private:
  struct JointRow {
    int joint;
    double sign;   // +1 bounds the torque from above by t * limit, -1 from below
    double limit;  // newton-metres
  };
  enum class ProgramGoal { LeastEffort, HoldsWithinStrength };
  // Fills the program for the stance; false when the precheck proves it unbalanced.
  bool load_stance(BodyData& data, const Posture& g, std::span<const PointContact> contacts,
                   const Eigen::Vector3d& gravity);
  // Solves the loaded program from the last basis: true when an equilibrium exists
  // (`solver`, a copy of the pristine one, then holds it), false when none does.
  bool run_program(ClpSimplex& solver, ProgramGoal goal);
  const StaticEquilibriumResult& unbalanced_result();

  const BodyModel& model_;
  EquilibriumPrecheck precheck_;
  std::vector<JointRow> joint_rows_;
  std::vector<int> starts_, rows_;
  std::vector<double> values_, column_lower_, column_upper_, objective_, row_lower_, row_upper_;
  std::vector<unsigned char> basis_;
  bool has_basis_ = false;
  // Never solved: each solve copies it, cheaper than a new object, which builds CLP's
  // message tables anew.
  std::unique_ptr<ClpSimplex> pristine_solver_;
  // The stance being solved: gravity's generalised force, each limb's contact (the
  // caller's, during a call only) and friction cone.
  GeneralisedForce tau_g_ = GeneralisedForce::Zero();
  std::array<const PointContact*, kLimbCount> held_{};
  std::array<FrictionConeGenerators, kLimbCount> cones_{};
  StaticEquilibriumResult result_;
};

}  // namespace crux

#include "simulation/performed_move.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <mujoco/mujoco.h>

#include "configurations/held_contacts.hpp"

namespace crux {

namespace {

// 0 to 1 with zero slope at both ends: a reference, or a load, that starts and ends at rest.
double smoothstep(double tau) { return tau * tau * (3.0 - 2.0 * tau); }

// The servos' references along a path of postures, in time.
struct ReferencePoint {
  Posture angle;
  Posture rate;
  GeneralisedForce feed_forward;
};

class PathReference {
 public:
  PathReference(std::vector<Posture> path, std::vector<GeneralisedForce> feed_forward, double speed,
                double min_duration)
      : path_(std::move(path)), feed_forward_(std::move(feed_forward)) {
    double excursion = 0.0;
    for (std::size_t k = 0; k + 1 < path_.size(); ++k) {
      excursion += (path_[k + 1] - path_[k]).tail<kConfigurationDof - kRootDof>().cwiseAbs().maxCoeff();
    }
    duration_ = path_.size() < 2 ? 0.0 : std::max(min_duration, excursion / speed);
  }

  double duration() const { return duration_; }

  void at(double t, ReferencePoint& point) const {
    if (t >= duration_) {
      point.angle = path_.back();
      point.rate.setZero();
      point.feed_forward = feed_forward_.back();
      return;
    }
    // A smoothstep in time: the reference starts and ends at rest.
    const double tau = t / duration_;
    const double s = smoothstep(tau);
    const double ds = 6.0 * tau * (1.0 - tau) / duration_;
    const double segments = static_cast<double>(path_.size() - 1);
    const double u = s * segments;
    const std::size_t k = std::min(static_cast<std::size_t>(u), path_.size() - 2);
    const double a = u - static_cast<double>(k);
    point.angle = path_[k] + a * (path_[k + 1] - path_[k]);
    point.rate = (path_[k + 1] - path_[k]) * segments * ds;
    point.feed_forward = feed_forward_[k] + a * (feed_forward_[k + 1] - feed_forward_[k]);
  }

 private:
  std::vector<Posture> path_;
  std::vector<GeneralisedForce> feed_forward_;
  double duration_ = 0.0;
};

class MoveSimulation {
 public:
  MoveSimulation(SimulatedClimber& climber, const MoveParameters& parameters, TrajectoryRecorder* recorder)
      : climber_(climber),
        parameters_(parameters),
        recorder_(recorder),
        wall_push_limit_(parameters.wall_push_share * climber.body().total_mass * kStandardGravity.norm()) {}

  // `moving`: the free limb goes to reference.hold; otherwise the body holds still on
  // `reference.kept`, which then names all its holds. `allowance`: the time after the
  // path's end before the move fails.
  MoveOutcome run(const MoveReference& reference, bool moving, double allowance) {
    mjData* data = climber_.data();
    const MujocoLayout& layout = climber_.layout();
    MoveOutcome outcome;
    const double start = data->time;
    if (moving && reference.left_hold != kFree && !unweight(reference, start, outcome)) {
      return finish(reference, moving, start, outcome);
    }
    ReferencePoint point;
    std::vector<Posture> path{simulated_posture(layout, data)};
    path.insert(path.end(), reference.samples.begin(), reference.samples.end());
    std::vector<GeneralisedForce> feed_forward{moving ? reference.unloaded_feed_forward
                                                      : reference.feed_forward.front()};
    feed_forward.insert(feed_forward.end(), reference.feed_forward.begin(), reference.feed_forward.end());
    const PathReference path_reference(std::move(path), std::move(feed_forward), parameters_.joint_speed,
                                       parameters_.min_duration_s);
    hold_on(reference.kept);
    leaving_ = std::nullopt;
    if (moving) climber_.release(reference.limb);
    bool arrived = !moving;
    const double path_start = data->time;
    const double end_of_path = moving ? path_reference.duration() : 0.0;
    const double time_limit = end_of_path + allowance;
    double still = 0.0;
    double arrival = 0.0;
    Eigen::Vector3d last_limb_point =
        moving ? simulated_grasp_point(layout, data, reference.limb) : Eigen::Vector3d::Zero();
    while (true) {
      const double elapsed = data->time - path_start;
      path_reference.at(elapsed, point);
      if (arrived && moving) {
        // Weighting the new hold, as the old one was unweighted.
        const double s = smoothstep(std::min(1.0, (elapsed - arrival) / parameters_.unweight_time_s));
        point.feed_forward = (1.0 - s) * point.feed_forward + s * reference.arrived_feed_forward;
      }
      outcome.failure = advance(point, outcome);
      if (outcome.failure != MoveFailure::None) break;
      // The limb takes its hold at the path's end (a hold near the one it left is met on the
      // way out), once it has come to rest there: a hand grasping while it still moves is
      // jerked to a stop by its grasp.
      const Eigen::Vector3d limb_point =
          moving ? simulated_grasp_point(layout, data, reference.limb) : Eigen::Vector3d::Zero();
      const double limb_speed = (limb_point - last_limb_point).norm() / climber_.model()->opt.timestep;
      last_limb_point = limb_point;
      if (!arrived && elapsed >= end_of_path && limb_speed < parameters_.still_speed &&
          on_hold(reference.limb, reference.hold)) {
        arrived = true;
        arrival = elapsed;
        hold_on(held_.with(reference.limb, reference.hold));
        climber_.take(reference.limb, reference.hold);
      }
      if (arrived && elapsed >= end_of_path) {
        still = fastest_speed() < parameters_.still_speed ? still + climber_.model()->opt.timestep : 0.0;
        if (still >= parameters_.still_time_s - 1e-12 && elapsed - arrival >= parameters_.unweight_time_s) break;
      }
      if (elapsed >= time_limit) {
        outcome.failure = !arrived && saturated_steps_ >= parameters_.saturated_share * outcome.steps
                              ? MoveFailure::TorqueSaturated
                              : MoveFailure::TimedOut;
        break;
      }
    }
    return finish(reference, moving, start, outcome);
  }

 private:
  SimulatedClimber& climber_;
  const MoveParameters& parameters_;
  TrajectoryRecorder* recorder_;
  double wall_push_limit_;
  HoldConfiguration held_;
  std::array<PointContact, kLimbCount> contacts_;  // of held_'s hands, judged each step
  int saturated_steps_ = 0;
  std::optional<Limb> leaving_;                 // the limb being unweighted
  std::array<double, kLimbCount> outside_s_{};  // how long each hand's force has been outside its limits

  void hold_on(const HoldConfiguration& held) {
    held_ = held;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      if (held.holds[limb] != kFree) {
        contacts_[limb] = held_contact(climber_.wall(), held.holds[limb], static_cast<Limb>(limb), climber_.physics());
      }
    }
  }

  // As the IK's termination test: the limb's grasp sphere meets the hold's sphere.
  bool on_hold(Limb limb, int hold) const {
    const Hold& on = climber_.wall().holds[hold];
    return (simulated_grasp_point(climber_.layout(), climber_.data(), limb) - on.position).norm() <=
           parameters_.grasp_radius + on.radius;
  }

  // The feed-forward passes from the stance's on its four holds to its own on the three
  // kept, so that the hold about to be let go carries nothing when it is: until it carries
  // no more than the grasp's tolerance, for at most twice unweight_time_s. False when the
  // move failed meanwhile.
  bool unweight(const MoveReference& reference, double start, MoveOutcome& outcome) {
    const mjData* data = climber_.data();
    hold_on(reference.kept.with(reference.limb, reference.left_hold));
    leaving_ = reference.limb;
    ReferencePoint point;
    point.angle = simulated_posture(climber_.layout(), data);
    point.rate.setZero();
    for (double t = 0.0; outcome.failure == MoveFailure::None && t < 2.0 * parameters_.unweight_time_s &&
                         (t < parameters_.unweight_time_s ||
                          climber_.hold_force(reference.limb).norm() > parameters_.grasp_tolerance_n);
         t = data->time - start) {
      const double s = smoothstep(std::min(1.0, t / parameters_.unweight_time_s));
      point.feed_forward = (1.0 - s) * reference.loaded_feed_forward + s * reference.unloaded_feed_forward;
      outcome.failure = advance(point, outcome);
    }
    return outcome.failure == MoveFailure::None;
  }

  // One step of the servos towards `point`, measured; the failure it shows, if any.
  MoveFailure advance(const ReferencePoint& point, MoveOutcome& outcome) {
    mjData* data = climber_.data();
    const MujocoLayout& layout = climber_.layout();
    for (int i = kRootDof; i < kConfigurationDof; ++i) {
      const int actuator = layout.actuator[i];
      if (actuator >= 0) {
        data->ctrl[actuator] = servo_control(climber_.gain(i), point.angle[i], point.rate[i], point.feed_forward[i]);
      }
    }
    const int bad_accelerations = data->warning[mjWARN_BADQACC].number;
    mj_step(climber_.model(), data);
    ++outcome.steps;
    if (recorder_ != nullptr) recorder_->record(climber_);
    if (data->warning[mjWARN_BADQACC].number != bad_accelerations) return MoveFailure::Unstable;
    if (measure(outcome)) ++saturated_steps_;
    const MoveFailure failure = failure_on_holds();
    const double push = wall_push();
    outcome.peak_wall_push_n = std::max(outcome.peak_wall_push_n, push);
    if (failure == MoveFailure::None && push > wall_push_limit_) return MoveFailure::HitWall;
    return failure;
  }

  MoveOutcome& finish(const MoveReference& reference, bool moving, double start, MoveOutcome& outcome) const {
    const mjData* data = climber_.data();
    const MujocoLayout& layout = climber_.layout();
    outcome.seconds = data->time - start;
    const Posture reached = simulated_posture(layout, data);
    outcome.joint_error_rad =
        (reached - reference.samples.back()).tail<kConfigurationDof - kRootDof>().cwiseAbs().maxCoeff();
    if (moving) {
      outcome.grasp_error_m =
          (simulated_grasp_point(layout, data, reference.limb) - climber_.wall().holds[reference.hold].position).norm();
    }
    return outcome;
  }

  // Records the step's torque ratios, range-limit torques and turn; true when a servo
  // was at its limit.
  bool measure(MoveOutcome& outcome) const {
    const mjData* data = climber_.data();
    const MujocoLayout& layout = climber_.layout();
    bool saturated = false;
    for (int i = kRootDof; i < kConfigurationDof; ++i) {
      if (layout.actuator[i] < 0) continue;
      const double torque = data->actuator_force[layout.actuator[i]];
      const JointStrength& limit = climber_.limits().joints[i];
      const double ratio = std::abs(torque) / (torque >= 0.0 ? limit.positive : limit.negative);
      outcome.max_torque_ratio = std::max(outcome.max_torque_ratio, ratio);
      saturated = saturated || ratio >= 1.0 - 1e-9;
    }
    for (int row = 0; row < data->nefc; ++row) {
      if (data->efc_type[row] == mjCNSTR_LIMIT_JOINT) {
        outcome.peak_range_torque = std::max(outcome.peak_range_torque, std::abs(data->efc_force[row]));
      }
    }
    outcome.max_root_turn_rad = std::max(outcome.max_root_turn_rad, root_turn(layout, data));
    return saturated;
  }

  // A held hand whose force left its limits lets go; a held foot that left its hold slipped.
  MoveFailure failure_on_holds() {
    mjModel* model = climber_.model();
    const mjData* data = climber_.data();
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const int hold = held_.holds[limb];
      if (hold == kFree) continue;
      const Limb held_limb = static_cast<Limb>(limb);
      if (is_hand(held_limb)) {
        const Grasp& grasp = climber_.grasp(held_limb);
        if (!grasp.taken(model)) continue;
        const Eigen::Vector3d force = climber_.layout().to_world.transpose() * grasp.force(model, data);
        const GraspVerdict verdict = grasp_verdict(contacts_[limb], force, parameters_.grasp_tolerance_n);
        double& outside = outside_s_[limb];
        outside = verdict == GraspVerdict::Held ? 0.0 : outside + model->opt.timestep;
        if (outside < parameters_.slip_time_s - 1e-12) continue;
        if (held_limb == leaving_) {
          // A hand being unweighted that cannot hold what is left lets go a little early.
          hold_on(held_.with(held_limb, kFree));
          climber_.release(held_limb);
          continue;
        }
        grasp.release(model);
        return verdict == GraspVerdict::GripExceeded ? MoveFailure::GripExceeded : MoveFailure::HandSlipped;
      }
      if (!on_hold(held_limb, hold)) return MoveFailure::FootSlipped;
    }
    return MoveFailure::None;
  }

  // The wall's push on the body's segments, N: the plane stands the skin's margin behind
  // the wall (simulation/mjcf_model), so any push comes from a segment deeper than crux
  // lets a posture go.
  double wall_push() const {
    const mjModel* model = climber_.model();
    const mjData* data = climber_.data();
    const int root = climber_.layout().root_body;
    double push = 0.0;
    for (int c = 0; c < data->ncon; ++c) {
      const mjContact& contact = data->contact[c];
      const int other = contact.geom1 == climber_.wall_geom()   ? contact.geom2
                        : contact.geom2 == climber_.wall_geom() ? contact.geom1
                                                                : -1;
      if (other < 0 || model->geom_bodyid[other] < root) continue;
      mjtNum force[6];
      mj_contactForce(model, data, c, force);
      push += force[0];
    }
    return push;
  }

  double fastest_speed() const {
    const mjData* data = climber_.data();
    double fastest = 0.0;
    for (int v = 0; v < climber_.model()->nv; ++v) fastest = std::max(fastest, std::abs(data->qvel[v]));
    return fastest;
  }
};

}  // namespace

MoveOutcome perform_move(SimulatedClimber& climber, const MoveReference& reference, const MoveParameters& parameters,
                         TrajectoryRecorder* recorder) {
  MoveSimulation simulation(climber, parameters, recorder);
  return simulation.run(reference, true, parameters.settle_time_s);
}

MoveOutcome hold_still(SimulatedClimber& climber, const Posture& posture, const HoldConfiguration& holds,
                       const GeneralisedForce& feed_forward, double seconds, const MoveParameters& parameters,
                       TrajectoryRecorder* recorder) {
  MoveSimulation simulation(climber, parameters, recorder);
  MoveReference reference;
  reference.kept = holds;
  reference.samples = {posture};
  reference.feed_forward = {feed_forward};
  reference.arrived_feed_forward = feed_forward;
  return simulation.run(reference, false, seconds);
}

}  // namespace crux

#include "simulation/perform_keys.hpp"

namespace crux {

namespace {

// Each time's bound keeps a move's simulation within minutes of wall-clock time at the
// measured 8 to 10 times real time.
constexpr Bounds kSimulatedTime = closed_range(0, 60, "a minute of simulated time, seconds of wall-clock time");

template <typename Parameters>
void declare_perform_keys(FieldsFor<Parameters>& keys, Parameters& perform) {
  keys.insert(
      keys.end(),
      {
          {"perform.joint_speed",
           "A move's pace: its duration is its path's largest joint excursion over this speed (docs/PHYSICS.md)",
           &perform.move.joint_speed, "rad/s",
           closed_range(0.05, 20, "at least a minute for the longest path's excursion")},
          {"perform.min_duration", "A move's shortest duration", &perform.move.min_duration_s, "s", kSimulatedTime},
          {"perform.settle_time", "Time allowed after a move's path to arrive and hold still",
           &perform.move.settle_time_s, "s", kSimulatedTime},
          {"perform.start_time", "Time allowed to the start stance to hold still before the first move",
           &perform.start_time_s, "s", kSimulatedTime},
          {"perform.unweight_time",
           "Time over which a limb's hold is unweighted before it lets go, and the next weighted",
           &perform.move.unweight_time_s, "s", closed_range(0.002, 10, "from one simulation step")},
          {"perform.slip_time", "A hand lets go when its force stays beyond the grip or the friction pyramid this long",
           &perform.move.slip_time_s, "s", closed_range(0.002, 10, "from one simulation step")},
          {"perform.grasp_tolerance", "A hand's force within this of its limits is held",
           &perform.move.grasp_tolerance_n, "N", closed_range(0, 1000, "the body's weight")},
          {"perform.still_speed",
           "Held still: every velocity below this (rad/s, m/s for the root)",
           &perform.move.still_speed,
           "",
           {.min = 0, .max = 10, .min_open = true}},
          {"perform.still_time", "Held still: for this long", &perform.move.still_time_s, "s", kSimulatedTime},
          {"perform.wall_push_share",
           "The body hit the wall when the wall pushes it with more than this share of its weight",
           &perform.move.wall_push_share,
           "",
           {.min = 0, .max = 100, .min_open = true}},
          {"perform.saturated_share",
           "A move that timed out failed for its torques when a motor was at its limit in this share of its steps",
           &perform.move.saturated_share, "", kShareOfOne},
          {"perform.path_samples", "IK postures along a move's path", &perform.path_samples, "",
           work_size(2, 1000, "one IK solve each")},
          {"perform.force_margin",
           "The share of friction and grip the feed-forward leaves unused where it can",
           &perform.force_margin,
           "",
           {.min = 0, .max = 1, .max_open = true}},
          {"perform.lift", "How far a free limb's path bows away from the wall", &perform.lift, "m",
           closed_range(0, 1)},
          {"perform.servo_saturation_angle",
           "A servo's angle error at which its feedback alone reaches the torque limit",
           &perform.servo.saturation_angle, "rad", closed_range(0.001, 3.14159)},
          {"perform.servo_damping_time", "A servo's damping over its stiffness", &perform.servo.damping_time, "s",
           closed_range(0, 1)},
          {"perform.record_interval", "The trajectory's sampling interval", &perform.record_interval_s, "s",
           closed_range(0.002, 10, "from one simulation step")},
      });
}

}  // namespace

void perform_keys(std::vector<ConfigField>& keys, PerformParameters& perform) { declare_perform_keys(keys, perform); }
void perform_keys(std::vector<ConstConfigField>& keys, const PerformParameters& perform) {
  declare_perform_keys(keys, perform);
}

}  // namespace crux

// libFuzzer harness for the static model (climbing/stance_check, physics/): each input is
// a [physics] config and a stance, and runs one stance check, the stance's effort. The
// config goes through the declared keys (apply_config_text, finalize_config), so their
// bounds alone decide which values reach the check: a value beyond them is an InputError.
// A value within them must give a finite effort or +infinity (cannot hold); NaN, any
// other exception (CLP failing to decide), a sanitizer report or a hang is a failure.
//
// Input layout, front to back; bytes past the end read as zero, so every input decodes:
//   physics.friction, physics.grip, physics.support_angle, wall.incline: 9 bytes each,
//     a mode byte (mod 3: the key absent; a value from 4 bytes in a span a little past
//     the realistic values at both ends; any double, from 8 raw bytes: NaN, infinities,
//     1e308) then 8 value bytes;
//   physics.strength: 1 byte (absent, each climbing level, the empty name, an unknown one);
//   the posture: the root's 3 coordinates in [-2, 4] m, then each of the 32 joints within
//     its limits, 2 bytes each;
//   each limb's hold: a mode byte (even: no support direction, the contact model's
//     default; odd: the direction of the next 2 + 2 bytes, azimuth and polar angle);
//   the limb that moves next: 1 byte (mod 4).
// The seeds (fuzz/corpus/stance_check) hold stances 0, 5 and 10 of the StanceCheck tests'
// random walk on random wall 2: the default physics, and friction 0 (cannot hold); an
// overhang of 20 degrees, friction 0.8 and the intermediate level's grip; a slab of -15
// degrees, grip 400 N, support angle 60 and every hold's support direction given.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "climbing/stance_check.hpp"
#include "common/input_error.hpp"
#include "experiments/experiment_config.hpp"
#include "physics/strength_profile.hpp"

namespace {

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() {
    const std::uint8_t value = offset_ < size_ ? data_[offset_] : 0;
    ++offset_;
    return value;
  }
  // `count` bytes, little-endian.
  std::uint64_t bytes(int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value |= static_cast<std::uint64_t>(byte()) << (8 * i);
    return value;
  }
  // A value from `lo` to `hi`, both included, from 2 bytes.
  double within(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(bytes(2)) / 65535.0; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t offset_ = 0;
};

// A number key's line of the config's TOML, or nothing (the key keeps its default). The
// span only makes realistic values common; the raw mode reaches every double.
std::string number_line(ByteReader& in, const char* name, double lo, double hi) {
  const std::uint8_t mode = in.byte();
  const std::uint64_t bits = in.bytes(8);
  switch (mode % 3) {
    case 0:
      return {};
    case 1:
      return fmt::format("{} = {}\n", name, lo + (hi - lo) * static_cast<double>(bits & 0xffffffffu) / 4294967295.0);
    default:
      // fmt writes nan, -nan, inf and -inf as TOML spells them.
      return fmt::format("{} = {}\n", name, std::bit_cast<double>(bits));
  }
}

std::string strength_line(ByteReader& in) {
  const auto levels = crux::climbing_levels();
  const std::size_t choice = in.byte() % (levels.size() + 3);
  if (choice == 0) return {};
  const std::string name = choice <= levels.size()       ? std::string(levels[choice - 1].name)
                           : choice == levels.size() + 1 ? std::string()
                                                         : std::string("novice");
  return "strength = " + crux::toml_quoted(name) + "\n";
}

// The static model's physics as a config file of the keys would give it.
crux::ExperimentConfig decoded_config(ByteReader& in) {
  std::string physics = "[physics]\nmodel = \"static\"\n";
  physics += number_line(in, "friction", -0.5, 12.0);
  physics += number_line(in, "grip", -100.0, 12000.0);
  physics += number_line(in, "support_angle", -100.0, 100.0);
  const std::string incline = number_line(in, "incline", -100.0, 100.0);
  physics += strength_line(in);
  crux::ExperimentConfig config;
  crux::apply_config_text(physics + "[wall]\n" + incline, "fuzz.toml", config,
                          crux::ParameterSet{{"physics", "wall.incline"}, {}}, "fuzz");
  crux::finalize_config(config);
  return config;
}

crux::Posture decoded_posture(ByteReader& in, const crux::BodyModel& body) {
  crux::Posture posture;
  for (int i = 0; i < crux::kRootDof; ++i) posture[i] = in.within(-2.0, 4.0);
  for (int i = crux::kRootDof; i < crux::kConfigurationDof; ++i) {
    posture[i] = in.within(body.lower_limits[i], body.upper_limits[i]);
  }
  return posture;
}

// Each limb's hold at its grasp point, as on a reached stance (the check reads only the
// support directions, but a hold away from its limb is no stance a climb gives).
crux::Wall decoded_wall(ByteReader& in, const crux::BodyModel& body, const crux::Posture& posture, double incline) {
  crux::BodyData data(body);
  crux::forward_kinematics(body, data, posture);
  crux::Wall wall;
  wall.incline_deg = incline;
  for (int limb = 0; limb < crux::kLimbCount; ++limb) {
    crux::Hold hold;
    hold.id = limb + 1;
    hold.position = data.points[crux::operational_point(limb)];
    const bool has_support = in.byte() % 2 == 1;
    const double azimuth = in.within(0.0, 2.0 * std::numbers::pi);
    const double polar = in.within(0.0, std::numbers::pi);
    if (has_support) {
      hold.support =
          Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
    }
    wall.holds.push_back(hold);
    wall.start[limb] = limb;
  }
  return wall;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const crux::BodyModel body = crux::load_body_model(crux::default_body_model_path());
  ByteReader in(data, size);
  try {
    const crux::ExperimentConfig config = decoded_config(in);
    const crux::Posture posture = decoded_posture(in, body);
    const crux::Wall wall = decoded_wall(in, body, posture, config.settings.walls.incline_deg);
    const auto next = static_cast<crux::Limb>(in.byte() % crux::kLimbCount);
    // A check of its own: one warm started from the last input's basis would make an
    // input's outcome depend on the inputs before it, which no reproducer replays.
    crux::StanceCheck check(body, wall, config.settings.learning.climbing.physics);
    const crux::HoldConfiguration complete{{0, 1, 2, 3}};
    const double effort = check.effort(posture, complete, next);
    // NaN and negative efforts fail here; +infinity is "cannot hold".
    if (!(effort >= 0.0)) __builtin_trap();
  } catch (const crux::InputError&) {
  }
  return 0;
}

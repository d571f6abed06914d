#include "simulation/mjcf_model.hpp"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>
#include <Eigen/Geometry>
#include <algorithm>

#include "body/gravity_forces.hpp"
#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"
#include "body/wall_penetration.hpp"
#include "configurations/reachability.hpp"
#include "simulation/mujoco_layout.hpp"
#include "simulation/mujoco_model.hpp"
#include "support/mujoco_reference.hpp"
#include "support/sample_count.hpp"
#include "support/test_models.hpp"
#include "wall/incline.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

constexpr std::uint64_t kMjcfSeed = 20261129;

StrengthProfile human_motor_limits() {
  const BodyModel& model = testing::human_model();
  return motor_limits(model, published_strength_profile(model, model.total_mass, model.stature));
}

Posture start_posture(const Wall& wall) {
  const BodyModel& model = testing::human_model();
  BodyData data(model);
  const IkResult start = solve_start(model, data, wall, ReachabilityParameters{});
  EXPECT_TRUE(start.reached) << wall.name;
  return start.posture;
}

// MuJoCo's model of the human on `wall`, with crux's coordinates found in it by name.
class MujocoClimber {
 public:
  MujocoClimber(const Wall& wall, const Posture& start, const BodyModel& model = testing::human_model(),
                const StrengthProfile& limits = human_motor_limits())
      : mujoco_(mjcf_text(model, wall, PhysicsParameters{}, limits, start), "test"),
        data_(mj_makeData(mujoco_.get())),
        layout_(mujoco_layout(model, mujoco_.get(), wall.incline_deg)) {}
  ~MujocoClimber() { mj_deleteData(data_); }

  const mjModel* model() const { return mujoco_.get(); }
  mjData* data() { return data_; }

  // crux's posture in wall coordinates, the root unturned, at rest.
  void set_posture(const Posture& g) { place_at_rest(layout_, mujoco_.get(), data_, g); }

  // In wall coordinates, as crux's.
  Eigen::Vector3d centre_of_mass() const {
    return layout_.to_world.transpose() * Eigen::Vector3d(data_->subtree_com + 3 * layout_.root_body);
  }
  // The generalised force that holds the body still against gravity, on crux's
  // coordinates: the root's translations in wall coordinates, then the revolute joints.
  GeneralisedForce holding_forces() const {
    GeneralisedForce out;
    out.head<kRootDof>() = layout_.to_world.transpose() * Eigen::Vector3d(data_->qfrc_bias + layout_.root_dof);
    for (int i = kRootDof; i < kConfigurationDof; ++i) out[i] = data_->qfrc_bias[layout_.dof[i]];
    return out;
  }
  Eigen::MatrixXd revolute_inertia() const { return testing::revolute_inertia(mujoco_.get(), data_, layout_.dof); }
  Eigen::Vector3d site(const std::string& name) const {
    const int id = mj_name2id(mujoco_.get(), mjOBJ_SITE, name.c_str());
    EXPECT_GE(id, 0) << name;
    return layout_.to_world.transpose() * Eigen::Vector3d(data_->site_xpos + 3 * id);
  }

 private:
  MujocoModel mujoco_;
  mjData* data_;
  MujocoLayout layout_;
};

// Issue 40: mass, centre of mass and gravity's torques as crux computes them, at the
// start posture the IK solves and at random postures, on a vertical and an inclined wall.
void expect_dynamics_as_crux(const Wall& wall) {
  const BodyModel& model = testing::human_model();
  const Posture start = start_posture(wall);
  MujocoClimber mujoco(wall, start);
  EXPECT_NEAR(mj_getTotalmass(mujoco.model()), model.total_mass, 1e-6 * model.total_mass)
      << "25 massless links weigh a nanogram each in MuJoCo";
  const Eigen::Vector3d gravity = wall_to_world(wall.incline_deg).transpose() * kStandardGravity;
  BodyData data(model);
  Random random(kMjcfSeed);
  for (int sample = 0; sample <= testing::sample_count(100); ++sample) {
    const Posture g = sample == 0 ? start : testing::random_posture(model, random);
    mujoco.set_posture(g);
    const GeneralisedForce tau = gravity_forces(model, data, g, gravity);
    const GeneralisedForce holding = mujoco.holding_forces();
    const double scale = tau.cwiseAbs().maxCoeff();
    for (int i = 0; i < kConfigurationDof; ++i) {
      ASSERT_NEAR(tau[i], -holding[i], 1e-6 * scale)
          << wall.name << " seed " << kMjcfSeed << " sample " << sample << " " << model.joints[i].name;
    }
    const Eigen::Vector3d com = centre_of_mass(model, data);
    ASSERT_LT((mujoco.centre_of_mass() - com).norm(), 1e-6 * com.norm()) << wall.name << " sample " << sample;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      ASSERT_LT((mujoco.site(model.grasp_frame_names[limb]) - data.points[operational_point(limb)]).norm(), 1e-9)
          << wall.name << " sample " << sample << " " << model.grasp_frame_names[limb];
    }
  }
}

TEST(MjcfModel, MassCentreOfMassAndGravityTorquesAreCruxsOnAVerticalWall) {
  expect_dynamics_as_crux(generate_random_wall(1));
}

TEST(MjcfModel, MassCentreOfMassAndGravityTorquesAreCruxsOnAnOverhang) {
  Wall wall = generate_random_wall(2);
  wall.incline_deg = 20.0;
  expect_dynamics_as_crux(wall);
}

// The inertias: the joint-space inertia matrix between the revolute joints (which a free
// root leaves as it is) equals that of MuJoCo's own reading of the URDF, whose
// <inertial> elements crux merged per joint (parallel axes), at random postures.
void expect_inertia_as_mujocos_urdf(const std::string& urdf_path, const BodyModel& model, const Posture& start,
                                    const StrengthProfile& limits) {
  const Wall wall = generate_random_wall(1);
  MujocoClimber exported(wall, start, model, limits);
  testing::MujocoReference urdf(urdf_path, model);
  Random random(kMjcfSeed + 1);
  for (int sample = 0; sample < testing::sample_count(50); ++sample) {
    const Posture g = testing::random_posture(model, random);
    exported.set_posture(g);
    urdf.set_posture(g);
    const Eigen::MatrixXd expected = urdf.revolute_inertia();
    const double scale = expected.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 1.0) << "kg m^2: the arms and legs about the lumbar joint";
    ASSERT_LT((exported.revolute_inertia() - expected).cwiseAbs().maxCoeff(), 1e-9 * scale)
        << urdf_path << " seed " << kMjcfSeed + 1 << " sample " << sample;
  }
}

TEST(MjcfModel, TheRevoluteJointsInertiaMatrixIsThatOfMujocosOwnReadingOfTheUrdf) {
  const Wall wall = generate_random_wall(1);
  expect_inertia_as_mujocos_urdf(default_body_model_path(), testing::human_model(), start_posture(wall),
                                 human_motor_limits());
}

// A synthetic tree: random joint frames and axes, each link's centre of mass off every
// axis of its joint. No source measures its joints: its motors are unbounded.
TEST(MjcfModel, ASyntheticTreesInertiasAreMujocosOwnReadingOfItsUrdf) {
  const auto path = testing::write_temporary("synthetic_mjcf.urdf", testing::synthetic_tree_urdf_for_mujoco(kMjcfSeed));
  const BodyModel model = load_body_model(path.string());
  const StrengthProfile limits = motor_limits(model, StrengthProfile{});
  EXPECT_FALSE(std::isfinite(limits.joints[kRootDof].positive));
  expect_inertia_as_mujocos_urdf(path.string(), model, standing_posture({-0.5, 0.0, 1.0}), limits);
}

TEST(MjcfModel, TheRootIsFreeAndEveryRevoluteJointHasOneMotorWithinItsLimits) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  const StrengthProfile limits = human_motor_limits();
  const MujocoModel mujoco(mjcf_text(model, wall, PhysicsParameters{}, limits, start_posture(wall)), "test");
  const mjModel* m = mujoco.get();
  EXPECT_EQ(m->nq, 7 + kRevoluteDof);
  EXPECT_EQ(m->nv, 6 + kRevoluteDof);
  ASSERT_EQ(m->nu, kRevoluteDof);
  EXPECT_EQ(m->nbody, 1 + 1 + wall.hold_count() + 2 + 1 + kRevoluteDof)
      << "world, wall, holds, the feet's footings, root, one per joint";
  for (int a = 0; a < m->nu; ++a) {
    const int joint = m->actuator_trnid[2 * a];
    ASSERT_EQ(m->actuator_trntype[a], mjTRN_JOINT);
    EXPECT_NE(m->jnt_type[joint], mjJNT_FREE) << "nothing drives the root";
    const std::string name = mj_id2name(m, mjOBJ_JOINT, joint);
    int i = kRootDof;
    while (model.joints[i].name != name) ++i;
    EXPECT_EQ(m->actuator_gear[6 * a], 1.0);
    EXPECT_EQ(m->actuator_forcerange[2 * a], -limits.joints[i].negative) << name;
    EXPECT_EQ(m->actuator_forcerange[2 * a + 1], limits.joints[i].positive) << name;
    const ServoGain gain = servo_gain(limits.joints[i], ServoParameters{});
    EXPECT_EQ(m->actuator_ctrllimited[a], 0) << "the control is a target angle: " << name;
    EXPECT_EQ(m->actuator_gainprm[mjNGAIN * a], gain.kp) << name;
    EXPECT_EQ(m->actuator_biasprm[mjNBIAS * a], 0.0) << name;
    EXPECT_EQ(m->actuator_biasprm[mjNBIAS * a + 1], -gain.kp) << name;
    EXPECT_EQ(m->actuator_biasprm[mjNBIAS * a + 2], -gain.kv) << name;
    EXPECT_EQ(m->jnt_range[2 * joint], model.joints[i].lower) << name;
    EXPECT_EQ(m->jnt_range[2 * joint + 1], model.joints[i].upper) << name;
    EXPECT_EQ(Eigen::Vector3d(m->jnt_axis + 3 * joint), model.joints[i].axis) << name;
  }
  EXPECT_EQ(m->neq, 2) << "one grasp per hand";
  for (const Limb hand : {Limb::RightHand, Limb::LeftHand}) {
    const int grasp = mj_name2id(m, mjOBJ_EQUALITY, mjcf_grasp_name(hand).c_str());
    ASSERT_GE(grasp, 0);
    EXPECT_EQ(m->eq_type[grasp], mjEQ_CONNECT);
    EXPECT_EQ(m->eq_active[grasp], 0) << "off until the hand takes a hold";
    EXPECT_EQ(m->eq_obj2id[grasp], 0) << "to the world";
  }
}

// The keyframe "start" is the posture given; a foot's hold pushes along its support
// direction, turned with the wall.
TEST(MjcfModel, TheStartKeyframeIsThePostureAndEachHoldIsAtItsPlace) {
  const BodyModel& model = testing::human_model();
  Wall wall = generate_random_wall(3);
  wall.incline_deg = -15.0;
  const Posture start = start_posture(wall);
  MujocoClimber mujoco(wall, start);
  mj_resetDataKeyframe(mujoco.model(), mujoco.data(), mj_name2id(mujoco.model(), mjOBJ_KEY, "start"));
  mj_forward(mujoco.model(), mujoco.data());
  BodyData data(model);
  forward_kinematics(model, data, start);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    EXPECT_LT((mujoco.site(model.grasp_frame_names[limb]) - data.points[operational_point(limb)]).norm(), 1e-9);
  }
  const Eigen::Matrix3d to_world = wall_to_world(wall.incline_deg);
  for (const Hold& hold : wall.holds) {
    const int body = mj_name2id(mujoco.model(), mjOBJ_BODY, mjcf_hold_name(hold.id).c_str());
    ASSERT_GE(body, 0);
    EXPECT_LT((Eigen::Vector3d(mujoco.data()->xpos + 3 * body) - to_world * hold.position).norm(), 1e-12) << hold.id;
  }
}

// What touches what: the segments crux keeps out of the wall touch its plane, which stands
// kMjcfWallDepth behind x = 0; the hands and feet touch nothing but a foot's contact sphere,
// which touches only the footings.
TEST(MjcfModel, SegmentsTouchTheWallAndOnlyTheFeetsSpheresTouchTheFootings) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(1);
  MujocoClimber mujoco(wall, start_posture(wall));
  const mjModel* m = mujoco.model();
  mujoco.set_posture(standing_posture({-0.5, 0.0, 1.0}));
  const int wall_geom = mj_name2id(m, mjOBJ_GEOM, "wall");
  ASSERT_GE(wall_geom, 0);
  const Eigen::Vector3d plane(mujoco.data()->geom_xpos + 3 * wall_geom);
  EXPECT_NEAR(plane.x(), kMjcfWallDepth, 1e-12);
  EXPECT_EQ(m->geom_conaffinity[wall_geom], 1);
  int spheres = 0, segments = 0;
  for (int g = 0; g < m->ngeom; ++g) {
    const char* name = mj_id2name(m, mjOBJ_GEOM, g);
    const std::string geom = name == nullptr ? "" : name;
    if (m->geom_bodyid[g] < mj_name2id(m, mjOBJ_BODY, kMjcfRoot)) continue;
    EXPECT_EQ(m->geom_conaffinity[g], 0) << geom << ": the body's geoms never touch each other";
    if (geom.ends_with("_contact")) {
      ++spheres;
      EXPECT_EQ(m->geom_contype[g], 4) << geom;
      EXPECT_EQ(m->geom_size[3 * g], kFootContactRadius) << geom;
      continue;
    }
    const auto visual = std::find_if(model.visuals.begin(), model.visuals.end(),
                                     [&](const BodyVisual& v) { return geom.substr(0, geom.rfind('_')) == v.link; });
    ASSERT_NE(visual, model.visuals.end()) << geom;
    EXPECT_EQ(m->geom_contype[g], counts_for_the_wall(model, *visual) ? 1 : 0) << geom;
    segments += m->geom_contype[g];
  }
  EXPECT_EQ(spheres, 2);
  EXPECT_GT(segments, 8);
  for (const Limb foot : {Limb::RightFoot, Limb::LeftFoot}) {
    const int footing = mj_name2id(m, mjOBJ_BODY, mjcf_footing_name(foot).c_str());
    ASSERT_GE(footing, 0);
    EXPECT_GE(m->body_mocapid[footing], 0);
    EXPECT_EQ(m->geom_conaffinity[m->body_geomadr[footing]], 4);
  }
}

// Hand-computed: measured joints keep their published limits; lumbar bending and twisting
// take lumbar flexion's smaller limit, hip abduction and rotation the hip flexion's, ankle
// inversion the ankle flexion's, and the neck, whose site no source measures, the
// smallest limit measured (forearm pronation's, 12.976 N m in the Gymnast set, scaled).
TEST(MjcfModel, AJointNoSourceMeasuresTakesItsSitesSmallerLimitOrTheWeakest) {
  const BodyModel& model = testing::human_model();
  const StrengthProfile published = published_strength_profile(model, model.total_mass, model.stature);
  const StrengthProfile limits = motor_limits(model, published);
  const auto index = [&](const std::string& name) {
    for (int i = 0; i < kConfigurationDof; ++i) {
      if (model.joints[i].name == name) return i;
    }
    ADD_FAILURE() << name;
    return 0;
  };
  const auto smaller = [&](const std::string& name) {
    return std::min(published.joints[index(name)].positive, published.joints[index(name)].negative);
  };
  for (int i = kRootDof; i < kConfigurationDof; ++i) {
    EXPECT_TRUE(std::isfinite(limits.joints[i].positive) && std::isfinite(limits.joints[i].negative))
        << model.joints[i].name;
    if (std::isfinite(published.joints[i].positive)) {
      EXPECT_EQ(limits.joints[i].positive, published.joints[i].positive);
      EXPECT_EQ(limits.joints[i].negative, published.joints[i].negative);
    }
  }
  for (const auto& [joint, site] :
       std::vector<std::pair<std::string, std::string>>{{"lumbar_lateral", "lumbar_flexion"},
                                                        {"lumbar_rotation", "lumbar_flexion"},
                                                        {"right_hip_abduction", "right_hip_flexion"},
                                                        {"left_hip_rotation", "left_hip_flexion"},
                                                        {"left_ankle_inversion", "left_ankle_flexion"}}) {
    EXPECT_EQ(limits.joints[index(joint)].positive, smaller(site)) << joint;
    EXPECT_EQ(limits.joints[index(joint)].negative, smaller(site)) << joint;
  }
  const double weakest = smaller("right_forearm_pronation");
  EXPECT_NEAR(weakest, 12.976 * model.total_mass * model.stature / (69.6 * 1.732), 1e-9);
  for (const char* neck : {"neck_flexion", "neck_lateral", "neck_rotation"}) {
    EXPECT_EQ(limits.joints[index(neck)].positive, weakest) << neck;
  }
}

TEST(MjcfModel, TheSameInputsGiveTheSameText) {
  const BodyModel& model = testing::human_model();
  const Wall wall = generate_random_wall(4);
  const Posture start = start_posture(wall);
  EXPECT_EQ(mjcf_text(model, wall, PhysicsParameters{}, human_motor_limits(), start),
            mjcf_text(model, wall, PhysicsParameters{}, human_motor_limits(), start));
}

}  // namespace
}  // namespace crux

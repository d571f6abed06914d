"""The body from Python: the same model and kinematics as the C++ library's."""

import numpy as np
import pytest

import crux


def test_default_body_has_a_translating_root_and_32_revolute_joints():
    model = crux.BodyModel.load()
    assert len(model.joint_names) == crux.CONFIGURATION_DOF == 35
    assert np.all(np.isinf(model.lower_limits[:3])) and np.all(np.isfinite(model.lower_limits[3:]))
    assert np.all(model.lower_limits[3:] < model.upper_limits[3:])
    assert model.grasp_frame_names == ["right_palm", "left_palm", "right_foot_ball", "left_foot_ball"]
    assert crux.BodyModel.load(model.source).total_mass == model.total_mass


def test_kinematics_equal_the_cli_at_the_posture_it_solved(cli_json):
    # crux ik prints the posture it reached and, at it, the C++ library's points and centre of mass.
    out = cli_json("ik", "--rh", "0.3,1.6", "--lh", "0.7,1.6", "--rf", "0.35,0.2", "--lf", "0.65,0.2")
    kinematics = crux.forward_kinematics(None, np.array(out["posture"]))
    assert np.array_equal(kinematics["points"][0], out["root"])
    assert np.array_equal(kinematics["points"][1:], out["grasp_points"])
    assert np.array_equal(kinematics["centre_of_mass"], out["centre_of_mass"])


def test_batch_equals_one_posture_at_a_time():
    model = crux.BodyModel.load()
    rng = np.random.default_rng(3)
    low, high = model.lower_limits.copy(), model.upper_limits.copy()
    low[:3], high[:3] = -1.0, 1.0
    postures = rng.uniform(low, high, size=(20, 35))
    batch = crux.forward_kinematics(model, postures, jacobians=True)
    assert batch["points"].shape == (20, 5, 3) and batch["jacobians"].shape == (20, 5, 3, 35)
    for i, g in enumerate(postures):
        one = crux.forward_kinematics(model, g, jacobians=True)
        for key in ("points", "centre_of_mass", "jacobians"):
            assert np.array_equal(one[key], batch[key][i]), key


def test_joint_origins_draw_a_rigid_skeleton():
    model = crux.BodyModel.load()
    parents = model.joint_parents
    assert parents.shape == (35,) and parents[0] == -1 and all(parents[j] < j for j in range(35))
    rng = np.random.default_rng(3)
    postures = np.stack([model.standing_posture([-0.3, 0.6, 0.9])] * 5)
    postures[:, 3:] = rng.uniform(model.lower_limits[3:], model.upper_limits[3:], size=(5, 32))
    k = crux.forward_kinematics(model, postures, joints=True)
    origins = k["joint_origins"]
    assert origins.shape == (5, 35, 3)
    # A joint sits at a fixed offset from its parent whatever the angles: the links are rigid.
    children = np.arange(1, 35)
    lengths = np.linalg.norm(origins[:, children] - origins[:, parents[children]], axis=2)
    assert np.allclose(lengths, lengths[0], atol=1e-9) and lengths.max() > 0.2
    assert np.array_equal(crux.forward_kinematics(model, postures[2], joints=True)["joint_origins"], origins[2])
    assert "joint_origins" not in crux.forward_kinematics(model, postures[2])


def test_jacobians_match_central_finite_differences():
    model = crux.BodyModel.load()
    rng = np.random.default_rng(11)
    g = model.standing_posture([0.3, 0.5, 1.0])
    g[3:] = rng.uniform(model.lower_limits[3:], model.upper_limits[3:]) * 0.5
    jacobians = crux.forward_kinematics(model, g, jacobians=True)["jacobians"]
    h = 1e-6
    for j in range(35):
        step = np.zeros(35)
        step[j] = h
        plus = crux.forward_kinematics(model, g + step)["points"]
        minus = crux.forward_kinematics(model, g - step)["points"]
        np.testing.assert_allclose(jacobians[:, :, j], (plus - minus) / (2 * h), atol=1e-7, err_msg=f"column {j}")


def test_bad_posture_shape_is_a_value_error():
    with pytest.raises(ValueError, match=r"postures: must be an array of shape \(35,\) or \(N, 35\)"):
        crux.forward_kinematics(None, np.zeros(34))


def test_bad_urdf_is_the_cli_message(run_cli, tmp_path):
    bad = tmp_path / "body.urdf"
    bad.write_text("<robot name='x'></robot>")
    code, _, err = run_cli("model", "--urdf", bad)
    assert code == 2
    with pytest.raises(ValueError) as error:
        crux.BodyModel.load(bad)
    assert err.strip() == "crux: " + str(error.value)

"""crux.ClimbMdp's invariants: Gymnasium's conventions over the climbing MDP."""

import numpy as np
import pytest

import crux

REWARDS = {"unreachable": -1000.0, "step": -1.0, "finish": 200000.0}


def random_policy_steps(env, seed, count):
    """(action, step result) pairs of a seeded random policy over the mask."""
    rng = np.random.default_rng(seed)
    env.reset()
    out = []
    for _ in range(count):
        action = int(rng.choice(np.flatnonzero(env.action_mask())))
        result = env.step(action)
        out.append((action, result))
        if result[2] or result[3]:
            env.reset()
    return out


def same_observation(a, b):
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k], equal_nan=True) for k in a)


def test_reset_takes_none_or_an_integer_seed(wall7):
    env = crux.ClimbMdp(wall7)
    for seed in (None, 0, np.int64(7), 2**64 - 1):
        env.reset(seed=seed)
    for seed in ("x", 1.5, True, -1, 2**64):
        with pytest.raises(ValueError, match="^seed: "):
            env.reset(seed=seed)


def test_reset_is_the_start_with_the_right_hand_free(wall7):
    env = crux.ClimbMdp(wall7)
    obs, info = env.reset(seed=5)
    expected = wall7.start.copy()
    expected[0] = -1
    assert np.array_equal(obs["configuration"], expected)
    assert obs["free_limb"] == 0 and np.all(np.isnan(obs["holds"][0]))
    assert np.array_equal(obs["holds"][1:], wall7.positions[wall7.start[1:]])
    assert obs["wall_state"] == crux.wall_state(wall7, expected)
    placement = crux.place_grid(0, crux.forward_kinematics(env.model, obs["posture"])["points"][1])
    assert obs["grid_state"] == crux.agent_state(wall7, expected, placement)
    assert np.array_equal(info["centre_of_mass"], crux.forward_kinematics(None, obs["posture"])["centre_of_mass"])
    assert env.action_count == wall7.hold_count and env.grid_action_count == 35


def test_the_mask_is_the_possible_actions_of_every_state(wall7):
    env = crux.ClimbMdp(wall7)
    obs, _ = env.reset()
    rng = np.random.default_rng(1)
    for _ in range(300):
        mask = env.action_mask()
        assert np.array_equal(np.flatnonzero(mask), crux.possible_actions(wall7, obs["configuration"]))
        obs, _, terminated, truncated, _ = env.step(int(rng.choice(np.flatnonzero(mask))))
        if terminated or truncated:
            obs, _ = env.reset()


def test_rewards_and_what_each_kind_of_step_does(wall7):
    env = crux.ClimbMdp(wall7, max_steps=10**6)
    kinds = set()
    before, _ = env.reset()
    rng = np.random.default_rng(2)
    for _ in range(3000):
        action = int(rng.choice(np.flatnonzero(env.action_mask())))
        after, reward, terminated, truncated, info = env.step(action)
        assert not truncated
        assert info["hold_id"] == wall7.hold_ids[action] and wall7.index_of(info["hold_id"]) == action
        if not info["reached"]:
            kinds.add("unreachable")
            assert reward == REWARDS["unreachable"] and not terminated and info["root_rise"] == 0.0
            assert same_observation(before, after)
        elif terminated:
            kinds.add("finish")
            assert reward == REWARDS["finish"]
            # The observation is where the finishing move left the climber, the next limb free.
            assert after["free_limb"] == (before["free_limb"] + 1) % 4
            assert after["configuration"][before["free_limb"]] == action
            assert after["configuration"][after["free_limb"]] == -1
            com = crux.forward_kinematics(None, after["posture"])["centre_of_mass"]
            assert np.array_equal(info["centre_of_mass"], com) and com[2] >= wall7.finish_height
            assert after["wall_state"] == crux.wall_state(wall7, after["configuration"])
            placement = crux.place_grid(after["free_limb"],
                                        crux.forward_kinematics(None, after["posture"])["points"][1 + after["free_limb"]])
            assert after["grid_state"] == crux.agent_state(wall7, after["configuration"], placement)
            assert np.array_equal(np.flatnonzero(env.action_mask()),
                                  crux.possible_actions(wall7, after["configuration"]))
            after, _ = env.reset()
        else:
            kinds.add("step")
            assert reward == REWARDS["step"]
            assert after["configuration"][after["free_limb"]] == -1
            assert after["free_limb"] == (before["free_limb"] + 1) % 4
            assert info["root_rise"] == pytest.approx(after["posture"][2] - before["posture"][2])
            com = crux.forward_kinematics(None, after["posture"])["centre_of_mass"]
            assert np.array_equal(info["centre_of_mass"], com) and com[2] < wall7.finish_height
        before = after
    assert kinds == {"unreachable", "finish", "step"}


def test_truncation_after_max_steps_and_no_step_after_the_end(wall7):
    env = crux.ClimbMdp(wall7, max_steps=3)
    env.reset()
    ends = []
    for _ in range(3):
        _, _, terminated, truncated, _ = env.step(int(np.flatnonzero(env.action_mask())[0]))
        ends.append((terminated, truncated))
    assert ends == [(False, False), (False, False), (False, True)]
    with pytest.raises(RuntimeError, match="call reset"):
        env.step(int(np.flatnonzero(env.action_mask())[0]))
    env.reset()
    assert env.steps == 0


def test_no_truncation_without_max_steps(wall7):
    env = crux.ClimbMdp(wall7, max_steps=None)
    assert env.max_steps is None
    env.reset()
    for _ in range(1500):
        _, _, terminated, truncated, _ = env.step(int(np.flatnonzero(env.action_mask())[0]))
        assert not truncated
        if terminated:
            env.reset()


def test_same_actions_same_observations(wall7):
    first = random_policy_steps(crux.ClimbMdp(wall7), 9, 400)
    second = random_policy_steps(crux.ClimbMdp(crux.Wall.random(7)), 9, 400)
    for (a1, r1), (a2, r2) in zip(first, second):
        assert a1 == a2 and same_observation(r1[0], r2[0]) and r1[1:4] == r2[1:4]


def test_replay_in_cpp_gives_the_rewards_of_step(wall7):
    env = crux.ClimbMdp(wall7, max_steps=10**6)
    steps = random_policy_steps(env, 4, 500)
    total = sum(result[1] for _, result in steps)
    env.reset()
    assert env.replay_actions(np.array([a for a, _ in steps])) == total


def test_bad_actions_are_value_errors(wall7):
    env = crux.ClimbMdp(wall7)
    env.reset()
    impossible = int(np.flatnonzero(~env.action_mask())[0])
    with pytest.raises(ValueError, match=f"^action: hold {impossible} is not a possible action"):
        env.step(impossible)
    for not_a_hold in (wall7.hold_count, -1, 2**70, 1.5, True, "3"):
        with pytest.raises(ValueError, match="^action: must be an integer from 0 to 44$"):
            env.step(not_a_hold)
    possible = np.flatnonzero(env.action_mask())
    assert env.step(possible[0])[4]["reached"] in (True, False)  # numpy integers are actions
    with pytest.raises(ValueError, match="^config: crux.ClimbMdp does not take wall.seed$"):
        crux.ClimbMdp(wall7, config={"wall.seed": 3})
    with pytest.raises(ValueError, match="^config: reward.step must be a finite number$"):
        crux.ClimbMdp(wall7, config={"reward": {"step": "minus one"}})
    with pytest.raises(ValueError, match="^max_steps: must be an integer from 1 to"):
        crux.ClimbMdp(wall7, max_steps=0)
    with pytest.raises(ValueError, match="^model: must be a crux.BodyModel or None$"):
        crux.ClimbMdp(wall7, model="body.urdf")


def test_config_changes_the_rewards(wall7):
    env = crux.ClimbMdp(wall7, config={"reward": {"step": -2.0}})
    env.reset()
    rewards = {result[1] for _, result in random_policy_steps(env, 3, 200) if result[4]["reached"]}
    assert -2.0 in rewards and -1.0 not in rewards


def test_numeric_observation_is_relative_to_the_free_limbs_grasp_point(wall7):
    env = crux.ClimbMdp(wall7)
    raw, info = env.reset()
    obs = env.numeric_observation(32)
    shapes = {"free_limb": (4,), "held": (4, 3), "candidates": (32, 3), "candidate_mask": (32,),
              "posture": (35,), "centre_of_mass": (3,), "to_finish": (1,)}
    assert {key: value.shape for key, value in obs.items()} == shapes
    assert all(value.dtype == np.float32 for value in obs.values())
    grasp = crux.forward_kinematics(None, raw["posture"])["points"][1]  # the right hand is free
    holds = np.flatnonzero(env.action_mask())
    assert np.array_equal(obs["candidates"][: len(holds)], (wall7.positions[holds] - grasp).astype(np.float32))
    assert np.array_equal(obs["candidate_mask"], (np.arange(32) < len(holds)).astype(np.float32))
    assert np.array_equal(obs["centre_of_mass"], (info["centre_of_mass"] - grasp).astype(np.float32))
    assert env.max_span == 2.8
    with pytest.raises(ValueError, match=f"^max_candidates: the wall '{wall7.name}' offers {len(holds)} candidates"):
        env.numeric_observation(len(holds) - 1)


def test_the_old_name_of_the_raw_mdp_still_works_and_says_it_is_deprecated(wall7):
    with pytest.warns(DeprecationWarning, match=r"crux.ClimbEnv is now crux.ClimbMdp"):
        old = crux.ClimbEnv
    assert old is crux.ClimbMdp
    assert "ClimbEnv" not in crux.__all__
    with pytest.raises(AttributeError):
        crux.ClimbEnvironment  # noqa: B018


def test_height_shaping_uses_the_learners_discount_learning_gamma():
    # reward.height's shaping gamma phi(s') - phi(s) is potential-based only under the
    # learner's own discount: the same reached move differs by (0.99 - 0.9) phi(s'), phi
    # being 100 per metre of the held holds' mean height after it.
    wall = crux.Wall.random(7)
    rewards = {}
    for gamma in (0.9, 0.99):
        mdp = crux.ClimbMdp(wall, config={"reward.height": 100.0, "learning.gamma": gamma})
        for hold in np.flatnonzero(mdp.action_mask()):
            mdp.reset()
            obs, reward, _, _, info = mdp.step(int(hold))
            if info["reached"]:
                rewards[gamma] = (int(hold), reward, obs["configuration"])
                break
    assert rewards[0.9][0] == rewards[0.99][0]
    held = [h for h in rewards[0.99][2] if h >= 0]
    potential = 100.0 * np.mean(wall.positions[held][:, 2])
    assert rewards[0.99][1] - rewards[0.9][1] == pytest.approx(0.09 * potential, rel=1e-9)
    assert crux.ClimbMdp(wall).step(rewards[0.9][0])[1] == -1.0  # the paper's step reward, unshaped

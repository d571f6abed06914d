"""crux.gym.VectorClimbEnv: the same numbers as single ClimbEnvs under Gymnasium's
SyncVectorEnv, Gymnasium's vector API (make_vec, its vector wrappers' autoreset checks),
the batched masks, and bad input."""

import warnings

import numpy as np
import pytest

import crux

from needed import GYMNASIUM, need

(gymnasium,) = need(["gymnasium"], GYMNASIUM)
from gymnasium.vector import AutoresetMode, SyncVectorEnv  # noqa: E402 (after Gymnasium is known to be there)

import crux.gym  # noqa: E402
from gym_extremes import (  # noqa: E402
    check_every_operation_refused_once_closed,
    integer_arguments,
    integer_walk,
    refusal,
    start_holds_alone,
)

# Walls whose finish is low enough that random climbs finish often: episodes end both ways.
LOW_FINISH = {"wall": {"finish_height": 1.3}}


def assert_same(a, b, where):
    if isinstance(a, dict):
        assert a.keys() == b.keys(), f"{where}: keys {sorted(a)} != {sorted(b)}"
        for key in a:
            assert_same(a[key], b[key], f"{where}/{key}")
        return
    a, b = np.asarray(a), np.asarray(b)
    assert (a.dtype, a.shape) == (b.dtype, b.shape), f"{where}: {a.dtype}{a.shape} != {b.dtype}{b.shape}"
    assert np.array_equal(a, b), f"{where}: {a} != {b}"


def random_masked_actions(rng, masks):
    return np.array([rng.choice(np.flatnonzero(mask)) for mask in masks])


CASES = {
    "random walls, numeric": dict(wall=None, wall_config=LOW_FINISH),
    "random walls, paper": dict(wall=None, observation="paper", wall_config=LOW_FINISH),
    "random walls, reach": dict(wall=None, observation="reach", wall_config=LOW_FINISH),
    "wall list, cycle": dict(wall=[crux.Wall.random(seed, LOW_FINISH) for seed in (1, 2, 3)]),
    "wall list, sample": dict(wall=[crux.Wall.random(seed, LOW_FINISH) for seed in (4, 5)], wall_order="sample"),
}


@pytest.mark.parametrize("case", CASES)
def test_matches_single_environments_under_sync_vector_env(case):
    arguments, envs, limit = CASES[case], 4, 12
    vector = crux.gym.VectorClimbEnv(envs, max_episode_steps=limit, **arguments)
    singles = SyncVectorEnv(
        [lambda: gymnasium.make(crux.gym.ENV_ID, max_episode_steps=limit, **arguments) for _ in range(envs)]
    )
    assert vector.single_observation_space == singles.single_observation_space
    assert vector.observation_space == singles.observation_space
    assert vector.action_space == singles.action_space
    rng = np.random.default_rng(0)
    ends = {"terminated": 0, "truncated": 0, "mixed steps": 0}
    # Seeded, going on with each np_random, seeded per environment, and a named wall for one episode.
    for reset in ({"seed": 5}, {}, {"seed": [9, 8, 7, 6]}, {"options": {"wall": 11}}):
        got, expected = vector.reset(**reset), singles.reset(**reset)
        assert_same(got[0], expected[0], f"reset {reset}: obs")
        assert_same(got[1], expected[1], f"reset {reset}: info")
        info = got[1]
        for step in range(50):
            actions = random_masked_actions(rng, info["action_mask"])
            got, expected = vector.step(actions), singles.step(actions)
            for name, a, b in zip(("obs", "reward", "terminated", "truncated", "info"), got, expected):
                assert_same(a, b, f"reset {reset}, step {step}: {name}")
            info = got[4]
            ends["terminated"] += int(got[2].sum())
            ends["truncated"] += int(got[3].sum())
            ends["mixed steps"] += int(0 < info.get("_hold_id", np.zeros(envs)).sum() < envs)
    assert all(count > 0 for count in ends.values()), ends  # episodes ended both ways, and autoreset
    vector.close()
    singles.close()


def test_make_vec_and_gymnasiums_vector_wrappers_accept_it():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # make_vec warns of a missing or malformed autoreset mode
        envs = gymnasium.make_vec(
            crux.gym.ENV_ID, 3, vectorization_mode="vector_entry_point", wall=crux.Wall.random(7)
        )
    assert isinstance(envs, crux.gym.VectorClimbEnv)
    assert envs.metadata["autoreset_mode"] == AutoresetMode.NEXT_STEP
    assert envs.max_episode_steps == crux.gym.MAX_EPISODE_STEPS  # the registered limit
    short = crux.gym.VectorClimbEnv(3, crux.Wall.random(7), max_episode_steps=8)
    # Both check the autoreset mode; FlattenObservation refuses any but next-step and disabled.
    wrapped = gymnasium.wrappers.vector.FlattenObservation(gymnasium.wrappers.vector.RecordEpisodeStatistics(short))
    obs, info = wrapped.reset(seed=0)
    rng = np.random.default_rng(1)
    episodes = 0
    for _ in range(20):
        assert obs.shape == wrapped.observation_space.shape and wrapped.observation_space.contains(obs)
        obs, _, terminated, truncated, info = wrapped.step(random_masked_actions(rng, info["action_mask"]))
        if "episode" in info:
            episodes += int(info["_episode"].sum())
            assert (info["episode"]["l"][info["_episode"]] <= 8).all()
    assert episodes >= 6


def test_masks_are_batched_in_info_and_action_masks():
    envs = crux.gym.VectorClimbEnv(3, crux.Wall.random(7))
    obs, info = envs.reset(seed=1)
    envs.action_space.seed(2)
    for _ in range(5):
        assert info["action_mask"].shape == (3, crux.gym.DEFAULT_MAX_CANDIDATES)
        assert info["action_mask"].dtype == np.int8
        assert np.array_equal(envs.action_masks(), info["action_mask"].astype(bool))
        assert np.array_equal(obs["candidate_mask"], info["action_mask"])
        assert envs.observation_space.contains(obs)
        actions = envs.action_space.sample(mask=tuple(info["action_mask"]))
        assert all(info["action_mask"][env, action] for env, action in enumerate(actions))
        obs, _, _, _, info = envs.step(actions)


def test_an_environment_that_resets_ignores_its_action():
    envs = crux.gym.VectorClimbEnv(2, crux.Wall.random(7), max_episode_steps=1)
    start, info = envs.reset(seed=0)
    actions = random_masked_actions(np.random.default_rng(0), info["action_mask"])
    _, rewards, terminated, truncated, info = envs.step(actions)
    assert truncated.all() and not terminated.any() and (rewards != 0).all()
    obs, rewards, terminated, truncated, info = envs.step([-5, 999])  # both reset: any action
    assert not (rewards.any() or terminated.any() or truncated.any()) and "hold_id" not in info
    assert_same(obs, start, "the start again")


def test_bad_input_is_a_value_error_naming_the_argument():
    wall = crux.Wall.random(7)
    for count in (0, -1, 1.5, True, "2"):
        with pytest.raises(ValueError, match=rf"^num_envs: must be an integer from 1 to 65536, got {count!r}$"):
            crux.gym.VectorClimbEnv(count, wall)
    with pytest.raises(ValueError, match="^max_episode_steps: must be None or an integer from 1 to 2147483647, got 0$"):
        crux.gym.VectorClimbEnv(2, wall, max_episode_steps=0)
    with pytest.raises(ValueError, match="^observation: unknown form 'pixels'"):
        crux.gym.VectorClimbEnv(2, wall, "pixels")
    with pytest.raises(ValueError, match="^config: reward.step must be a finite number$"):
        crux.gym.VectorClimbEnv(2, wall, config={"reward": {"step": "x"}})
    envs = crux.gym.VectorClimbEnv(3, wall)
    with pytest.raises(gymnasium.error.ResetNeeded):
        envs.step([0, 0, 0])
    with pytest.raises(ValueError, match="^seed: 2 seeds for 3 environments"):
        envs.reset(seed=[1, 2])
    with pytest.raises(ValueError, match="^options: reset_mask is not supported"):
        envs.reset(options={"reset_mask": np.array([True, False, True])})
    with pytest.raises(ValueError, match=r"^options: unknown option 'wal' \(wall\)$"):
        envs.reset(options={"wal": 3})
    _, info = envs.reset(seed=0)
    actions = random_masked_actions(np.random.default_rng(0), info["action_mask"])
    outside = int(np.flatnonzero(info["action_mask"][1] == 0)[0])
    for action in (outside, -1, crux.gym.DEFAULT_MAX_CANDIDATES):
        bad = actions.copy()
        bad[1] = action
        with pytest.raises(ValueError, match=rf"^actions: env 1: {action} is not a possible action"):
            envs.step(bad)
    with pytest.raises(ValueError, match="^actions: must be 3 integers, one per environment"):
        envs.step(actions[:2])
    with pytest.raises(ValueError, match="^actions:"):
        envs.step(actions.astype(float))
    envs.step(actions)  # a refused step changed nothing


# Arguments that size the work: run up to this value, checked beyond it through the
# validation alone (accepted, not run).
RUN_AT_MOST = {"num_envs": 4}


def climbs(envs):
    """envs reset and take a possible action each, their observations in their space."""
    obs, info = envs.reset(seed=0)
    assert envs.observation_space.contains(obs)
    obs = envs.step([int(np.flatnonzero(mask)[0]) for mask in info["action_mask"]])[0]
    assert envs.observation_space.contains(obs)
    envs.close()


@pytest.mark.parametrize("name", integer_arguments(crux.gym.VectorClimbEnv))
def test_integer_arguments_at_their_extremes_work_or_are_refused_naming_them(name):
    arguments = {"num_envs": 2}
    if name != "wall":
        arguments["wall"] = start_holds_alone()
    for value, accepted in integer_walk(name):
        arguments[name] = value
        if accepted and value > RUN_AT_MOST.get(name, value):
            assert crux.gym._integer(value, name) == value
        elif accepted:
            climbs(crux.gym.VectorClimbEnv(**arguments))
        else:
            with pytest.raises(ValueError, match=refusal(name, value)):
                crux.gym.VectorClimbEnv(**arguments)
    for value in (True, 3.0, 3.5):  # not integers, even if whole
        arguments[name] = value
        with pytest.raises(ValueError, match=rf"^{name}: "):
            crux.gym.VectorClimbEnv(**arguments)


def test_num_envs_times_max_candidates_is_bounded():
    wall = start_holds_alone()
    most = crux.gym._INTEGER_ARGUMENTS["max_candidates"][1]
    envs = crux.gym._MAX_BATCH_SLOTS // most
    assert crux.gym.VectorClimbEnv(envs, wall, max_candidates=most).num_envs == envs
    refused = rf"^num_envs: must be an integer from 1 to {envs} with max_candidates={most} .*, got {envs + 1}$"
    with pytest.raises(ValueError, match=refused):
        crux.gym.VectorClimbEnv(envs + 1, wall, max_candidates=most)
    # The paper's form has no candidate slots.
    assert crux.gym.VectorClimbEnv(envs + 1, wall, "paper", max_candidates=most).num_envs == envs + 1


def test_a_closed_environment_refuses_every_operation_and_closes_again():
    operations = check_every_operation_refused_once_closed(
        crux.gym.VectorClimbEnv, lambda: crux.gym.VectorClimbEnv(2, crux.Wall.random(7))
    )
    assert {"reset", "step", "action_masks", "render"} <= set(operations)

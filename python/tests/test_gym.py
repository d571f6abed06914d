"""crux.gym against the real Gymnasium 1.4.0: its checker, make, wrappers and vector env,
masks, seeds, the finishing observation, walls per episode and the held-out split."""

import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import crux

from needed import GYMNASIUM, need

(gymnasium,) = need(["gymnasium"], GYMNASIUM)
from gymnasium.utils.env_checker import check_env  # noqa: E402 (after Gymnasium is known to be there)

import crux.gym  # noqa: E402
from gym_extremes import (  # noqa: E402
    check_every_operation_refused_once_closed,
    integer_arguments,
    integer_walk,
    refusal,
    start_holds_alone,
)

FORMS = ("numeric", "reach", "paper")
REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def masked_random_steps(env, seed, count, reset_seed=None):
    """(action, step result) of a seeded random policy over info["action_mask"], through episode ends."""
    env.action_space.seed(seed)
    _, info = env.reset(seed=reset_seed)
    out = []
    for _ in range(count):
        action = int(env.action_space.sample(mask=info["action_mask"]))
        result = env.step(action)
        out.append((action, result))
        info = result[4]
        if result[2] or result[3]:
            _, info = env.reset()
    return out


def same(a, b):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return np.array_equal(a, b)


@pytest.mark.parametrize("form", FORMS)
@pytest.mark.parametrize("wall", ["fixed", "per_episode"])
def test_gymnasiums_checker_passes(form, wall):
    env = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7) if wall == "fixed" else None, observation=form)
    # The checker steps an action it drew before its reset(seed=123); sample() draws among
    # the current state's possible actions, and with this seed that one is possible after too.
    env.unwrapped.action_space.seed(0)
    check_env(env.unwrapped)


def test_import_crux_needs_no_gymnasium():
    code = "import sys, crux; crux.ClimbMdp(crux.Wall.random(7)); assert 'gymnasium' not in sys.modules"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_make_truncates_with_time_limit():
    env = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7))
    assert env.spec.max_episode_steps == crux.gym.MAX_EPISODE_STEPS
    assert gymnasium.spec(crux.gym.ENV_ID).to_json()  # a spec that serialises: the entry point by name
    short = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7), max_episode_steps=4)
    ends = [result[2:4] for _, result in masked_random_steps(short, 1, 4, reset_seed=0)]
    assert ends == [(False, False)] * 3 + [(False, True)]
    # The environment itself never truncates: only TimeLimit does.
    raw = crux.gym.ClimbEnv(crux.Wall.random(7))
    assert not any(result[3] for _, result in masked_random_steps(raw, 1, 1500, reset_seed=0))


def test_record_statistics_and_flatten_observation():
    env = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7), max_episode_steps=50)
    env = gymnasium.wrappers.FlattenObservation(gymnasium.wrappers.RecordEpisodeStatistics(env))
    assert isinstance(env.observation_space, gymnasium.spaces.Box)
    episodes = []
    for _, (obs, _, terminated, truncated, info) in masked_random_steps(env, 2, 120, reset_seed=3):
        assert obs.shape == env.observation_space.shape and env.observation_space.contains(obs)
        if terminated or truncated:
            episodes.append(info["episode"])
    assert len(episodes) >= 2 and all(e["l"] <= 50 for e in episodes)


def test_sync_vector_env_batches_the_masks():
    envs = gymnasium.vector.SyncVectorEnv(
        [lambda: gymnasium.make(crux.gym.ENV_ID, max_episode_steps=30) for _ in range(3)]
    )
    _, infos = envs.reset(seed=[1, 2, 3])
    names = set(infos["wall_name"])
    rng = np.random.default_rng(0)
    finished = 0
    for _ in range(80):
        masks = infos["action_mask"]
        assert masks.shape == (3, crux.gym.DEFAULT_MAX_CANDIDATES)
        actions = np.array([rng.choice(np.flatnonzero(m)) for m in masks])
        obs, _, terminated, truncated, infos = envs.step(actions)
        assert envs.observation_space.contains(obs)
        finished += int(np.sum(terminated | truncated))
        names |= set(infos["wall_name"])
    # Gymnasium's next-step autoreset starts each environment on a new random wall.
    assert finished >= 6 and len(names) > 3
    envs.close()


@pytest.mark.parametrize("form", FORMS)
def test_same_seed_same_episodes(form):
    first, second = (masked_random_steps(crux.gym.ClimbEnv(None, form), 5, 300, reset_seed=11) for _ in range(2))
    assert all(a1 == a2 and same(r1, r2) for (a1, r1), (a2, r2) in zip(first, second))
    other = masked_random_steps(crux.gym.ClimbEnv(None, form), 5, 300, reset_seed=12)
    assert [r[4]["wall_name"] for _, r in first] != [r[4]["wall_name"] for _, r in other]


@pytest.mark.parametrize("form", FORMS)
def test_every_masked_in_action_is_taken_and_no_other(form):
    env = crux.gym.ClimbEnv(crux.Wall.random(7), form)
    for seed in range(3):  # three states along a random climb
        steps = masked_random_steps(env, seed, 5 * seed, reset_seed=0)
        history = [a for a, _ in steps]
        _, info = env.reset(seed=0)
        for a in history:
            info = env.step(a)[4]
        mask = info["action_mask"]
        assert mask.dtype == np.int8 and np.array_equal(env.action_masks(), mask.astype(bool))
        for action in range(env.action_space.n):
            env.reset(seed=0)
            for a in history:
                env.step(a)
            if mask[action]:
                assert "hold_id" in env.step(action)[4]
            else:
                with pytest.raises(ValueError, match=f"^action: {action} is not a possible action"):
                    env.step(action)


def test_numeric_slots_name_the_candidate_holds():
    wall = crux.Wall.random(7)
    env = crux.gym.ClimbEnv(wall, "numeric")
    obs, info = env.reset(seed=0)
    holds = info["candidate_holds"][info["candidate_holds"] >= 0]
    assert np.array_equal(holds, np.flatnonzero(crux.ClimbMdp(wall).action_mask()))
    assert np.array_equal(np.flatnonzero(info["action_mask"]), np.arange(len(holds)))
    assert np.array_equal(obs["candidate_mask"], info["action_mask"])
    grasp = crux.forward_kinematics(None, crux.ClimbMdp(wall).observation()["posture"])["points"][1]
    assert np.allclose(obs["candidates"][: len(holds)], wall.positions[holds] - grasp, atol=1e-6)
    assert not obs["candidates"][len(holds):].any()
    slot = len(holds) - 1
    assert env.step(slot)[4]["hold_id"] == wall.hold_ids[holds[slot]]


def test_reach_features_measure_from_the_free_limbs_shoulder_and_the_held_holds():
    wall = crux.Wall.random(7)
    env = crux.gym.ClimbEnv(wall, "reach")
    obs, info = env.reset(seed=0)
    mdp = crux.ClimbMdp(wall)
    raw = mdp.observation()
    joints = list(mdp.model.joint_names)
    origins = crux.forward_kinematics(None, raw["posture"], joints=True)["joint_origins"]
    shoulder = origins[joints.index("right_shoulder_flexion")]  # the start frees the right hand
    holds = info["candidate_holds"][info["candidate_holds"] >= 0]
    candidates = wall.positions[holds]
    reach = obs["candidate_reach"]
    assert np.allclose(reach[: len(holds), :3], candidates - shoulder, atol=1e-5)
    assert np.allclose(reach[: len(holds), 3], np.linalg.norm(candidates - shoulder, axis=1), atol=1e-5)
    held = [wall.positions[h] for h in raw["configuration"] if h >= 0]
    assert len(held) == 3
    for column, position in enumerate(held):
        assert np.allclose(reach[: len(holds), 4 + column], np.linalg.norm(candidates - position, axis=1), atol=1e-5)
    assert not reach[len(holds):].any() and not obs["candidate_failed"].any()


def test_reach_marks_the_moves_that_failed_until_the_climber_moves():
    env = crux.gym.ClimbEnv(crux.Wall.random(7), "reach")
    obs, info = env.reset(seed=0)
    failed, reached = [], None
    for slot in range(int(obs["candidate_mask"].sum())):
        env.reset(seed=0)
        for earlier in failed:
            env.step(earlier)
        obs, _, _, _, step_info = env.step(slot)
        if step_info["reached"]:
            reached = slot
            break
        failed.append(slot)
        expected = np.zeros(env.max_candidates, dtype=np.float32)
        expected[failed] = 1.0
        assert np.array_equal(obs["candidate_failed"], expected)  # every failed move, and no other
    assert len(failed) >= 1 and reached is not None
    assert not obs["candidate_failed"].any()  # a new state: nothing has failed from it yet
    assert not env.reset(seed=0)[0]["candidate_failed"].any()


@pytest.mark.parametrize("form", FORMS)
def test_termination_returns_the_finishing_state(form):
    env = crux.gym.ClimbEnv(crux.Wall.random(7), form)
    finishes = 0
    for _, (obs, reward, terminated, _, info) in masked_random_steps(env, 4, 3000, reset_seed=0):
        assert env.observation_space.contains(obs)
        if terminated:
            finishes += 1
            assert reward == 200000.0 and info["centre_of_mass"][2] >= env.wall.finish_height
            if form != "paper":
                assert obs["to_finish"][0] <= 0.0
            start, _ = crux.gym.ClimbEnv(crux.Wall.random(7), form).reset()
            assert not same(obs, start)
    assert finishes >= 2


@pytest.mark.parametrize("form", FORMS)
def test_observations_stay_within_their_bounds_on_many_walls(form):
    env = crux.gym.ClimbEnv(None, form, wall_config={"wall": {"sigma": 0.12}})
    steps = masked_random_steps(env, 6, 2000, reset_seed=1)
    assert all(env.observation_space.contains(result[0]) for _, result in steps)


def test_walls_drawn_per_episode_differ_and_follow_the_seed():
    def walls(env, seed, count):
        names = [env.reset(seed=seed)[1]["wall_seed"]]
        names += [env.reset()[1]["wall_seed"] for _ in range(count - 1)]
        return names

    env = crux.gym.ClimbEnv(None, wall_config={"wall": {"rows": 9}})
    drawn = walls(env, 21, 4)
    assert len(set(drawn)) == 4 and walls(env, 21, 4) == drawn
    assert env.wall.hold_count == 5 * 10
    assert np.array_equal(env.wall.positions, crux.Wall.random(drawn[-1], {"wall": {"rows": 9}}).positions)
    _, info = env.reset(options={"wall": crux.Wall.random(3, {"wall": {"rows": 9}})})
    assert info["wall_name"] == "random wall, seed 3"
    fixed = crux.gym.ClimbEnv(crux.Wall.random(7))
    assert fixed.reset(options={"wall": 3})[1]["wall_name"] == "random wall, seed 3"
    assert fixed.reset()[1]["wall_name"] == "random wall, seed 7"  # the option named one episode's wall


def test_a_random_wall_whose_start_cannot_be_taken_is_skipped():
    # At 40 degrees the static model holds few starts (docs/PHYSICS.md): reset(seed=3)'s
    # first draw is one it cannot take, and the episode climbs the next draw that it can.
    steep, static = {"wall": {"incline": 40}}, {"physics.model": "static"}
    env = crux.gym.ClimbEnv(None, wall_config=steep, config=static)
    _, info = env.reset(seed=3)
    draws = np.random.default_rng(3)
    seeds = [int(draws.integers(2**63)) for _ in range(50)]
    assert info["wall_seed"] in seeds
    taken = seeds.index(info["wall_seed"])
    assert taken >= 1
    for skipped in seeds[:taken]:
        with pytest.raises(ValueError, match="the start configuration"):
            crux.ClimbMdp(crux.Wall.random(skipped, steep), config=static)
    crux.ClimbMdp(crux.Wall.random(info["wall_seed"], steep), config=static)
    with pytest.raises(ValueError, match="^wall_config: 1000 random walls in a row have a start the climber cannot"):
        crux.gym.ClimbEnv(None, config={"filter.max_span": 0.5})


def test_wall_lists_cycle_or_sample():
    cycle = crux.gym.ClimbEnv([1, 2, 3])
    names = [cycle.reset(seed=0)[1]["wall_name"]] + [cycle.reset()[1]["wall_name"] for _ in range(3)]
    assert names == [f"random wall, seed {s}" for s in (1, 2, 3, 1)]
    assert cycle.reset(seed=0)[1]["wall_name"] == names[0]  # a seeded reset starts the cycle again
    sample = crux.gym.ClimbEnv([1, 2, 3], wall_order="sample")
    drawn = [sample.reset(seed=s)[1]["wall_name"] for s in range(12)]
    assert len(set(drawn)) == 3 and drawn == [sample.reset(seed=s)[1]["wall_name"] for s in range(12)]


def test_wall_files_are_walls(tmp_path):
    crux.Wall.random(4).save(tmp_path / "a.json")
    env = crux.gym.ClimbEnv([str(tmp_path / "a.json"), crux.Wall.random(5)], "paper")
    assert env.reset(seed=0)[1]["wall_name"] != env.reset()[1]["wall_name"]


def test_held_out_split():
    split = {"train": range(0, 20), "evaluation": range(100, 105)}
    train = crux.gym.ClimbEnv(wall_split=split, wall_order="sample")
    held_out = crux.gym.ClimbEnv(wall_split=split, evaluation=True)
    seen = {train.reset(seed=s)[1]["wall_name"] for s in range(40)}
    evaluated = [held_out.reset()[1]["wall_name"] for _ in range(5)]
    assert evaluated == [f"random wall, seed {s}" for s in range(100, 105)]
    assert len(seen) > 10 and seen <= {f"random wall, seed {s}" for s in range(20)}
    same_wall_renamed = crux.Wall.random(4)
    same_wall_renamed.name = "renamed"
    with pytest.raises(ValueError, match="^wall_split: the training wall 'renamed' is also an evaluation wall"):
        crux.gym.ClimbEnv(wall_split={"train": [same_wall_renamed, 5], "evaluation": [4]})


def test_bad_input_is_a_value_error_naming_the_argument():
    wall = crux.Wall.random(7)
    with pytest.raises(ValueError, match="^observation: unknown form 'pixels'"):
        crux.gym.ClimbEnv(wall, "pixels")
    with pytest.raises(ValueError, match="^wall: is an empty list of walls"):
        crux.gym.ClimbEnv([])
    with pytest.raises(ValueError, match="^wall: must be a wall, a wall file, a seed or a list of them, got 2.5$"):
        crux.gym.ClimbEnv(2.5)
    with pytest.raises(ValueError, match="^wall: holds 2.5, which is not a crux.Wall"):
        crux.gym.ClimbEnv([1, 2.5])
    assert crux.gym.ClimbEnv(7).reset(seed=0)[1]["wall_name"] == "random wall, seed 7"
    with pytest.raises(ValueError, match="^wall_split: is an empty list of walls"):
        crux.gym.ClimbEnv(wall_split={"train": [1], "evaluation": []})
    with pytest.raises(ValueError, match="^wall_split: must be a dict"):
        crux.gym.ClimbEnv(wall_split=[[1], [2]])
    with pytest.raises(ValueError, match="^evaluation: takes the evaluation walls of a wall_split"):
        crux.gym.ClimbEnv(evaluation=True)
    with pytest.raises(ValueError, match="^wall: walls of different hold counts"):
        crux.gym.ClimbEnv([wall, crux.Wall.random(7, {"wall": {"rows": 9}})], "paper")
    with pytest.raises(ValueError, match="^config: reward.step must be a finite number$"):
        crux.gym.ClimbEnv(wall, config={"reward": {"step": "x"}})
    env = crux.gym.ClimbEnv(wall)
    env.reset(seed=0)
    for action in (crux.gym.DEFAULT_MAX_CANDIDATES, -1):
        with pytest.raises(ValueError, match=f"^action: {action} is not a possible action"):
            env.step(action)
    for action in (1.5, True, "3", None):
        with pytest.raises(ValueError, match="^action: must be an integer"):
            env.step(action)


def test_every_bounded_integer_is_an_argument_of_an_environment():
    arguments = integer_arguments(crux.gym.ClimbEnv) + integer_arguments(crux.gym.VectorClimbEnv)
    assert set(arguments) == set(crux.gym._INTEGER_ARGUMENTS)


def climbs(env):
    """env resets and takes a possible action, its observations in its space."""
    obs, info = env.reset(seed=0)
    assert env.observation_space.contains(obs)
    obs = env.step(int(np.flatnonzero(info["action_mask"])[0]))[0]
    assert env.observation_space.contains(obs)


@pytest.mark.parametrize("name", integer_arguments(crux.gym.ClimbEnv))
def test_integer_arguments_at_their_extremes_work_or_are_refused_naming_them(name):
    arguments = {} if name == "wall" else {"wall": start_holds_alone()}
    for value, accepted in integer_walk(name):
        if accepted:
            climbs(crux.gym.ClimbEnv(**arguments, **{name: value}))
        else:
            with pytest.raises(ValueError, match=refusal(name, value)):
                crux.gym.ClimbEnv(**arguments, **{name: value})
            with pytest.raises(ValueError, match=refusal(name, value)):
                gymnasium.make(crux.gym.ENV_ID, **arguments, **{name: value})
    for value in (True, 3.0, 3.5):  # not integers, even if whole
        with pytest.raises(ValueError, match=rf"^{name}: "):
            crux.gym.ClimbEnv(**arguments, **{name: value})


def test_a_random_walls_seed_is_checked_wherever_it_is_given():
    low, high = crux.gym._INTEGER_ARGUMENTS["wall"]
    for seed in (high, 2**63, 2**31):
        climbs(crux.gym.ClimbEnv([1, seed]))
        climbs(crux.gym.ClimbEnv(wall_split={"train": [seed], "evaluation": [1]}))
        assert crux.gym.ClimbEnv(7).reset(options={"wall": seed})[1]["wall_name"] == f"random wall, seed {seed}"
    for seed in (low - 1, high + 1):
        refused = rf"a random wall's seed must be an integer from {low} to {high}, got {seed}$"
        with pytest.raises(ValueError, match=f"^wall: {refused}"):
            crux.gym.ClimbEnv([1, seed])
        with pytest.raises(ValueError, match=f"^wall_split: {refused}"):
            crux.gym.ClimbEnv(wall_split={"train": [1], "evaluation": [seed]})
        with pytest.raises(ValueError, match=f"^options: {refused}"):
            crux.gym.ClimbEnv(7).reset(options={"wall": seed})


def test_max_candidates_reaches_the_most_holds_a_wall_may_have():
    header = (REPOSITORY / "src" / "wall" / "wall.hpp").read_text()
    assert re.search(r"constexpr int kMaxHoldCount = (\d+);", header).group(1) == str(crux.gym._MAX_HOLDS)
    assert crux.gym._INTEGER_ARGUMENTS["max_candidates"][1] == crux.gym._MAX_HOLDS


def test_unknown_reset_options_are_refused():
    env = crux.gym.ClimbEnv(7)
    for options in ({"wal": 3}, {"wall": 3, "seed": 1}):
        with pytest.raises(ValueError, match=r"^options: unknown option '(wal|seed)' \(wall\)$"):
            env.reset(options=options)
    with pytest.raises(ValueError, match="^options: must be a dict or None$"):
        env.reset(options=["wall"])
    assert env.reset(options={"wall": 3})[1]["wall_name"] == "random wall, seed 3"


def test_a_closed_environment_refuses_every_operation_and_closes_again():
    operations = check_every_operation_refused_once_closed(
        crux.gym.ClimbEnv, lambda: crux.gym.ClimbEnv(7, render_mode="ansi")
    )
    assert {"reset", "step", "action_masks", "render", "wall", "model"} <= set(operations)
    closed = r"^crux.gym.ClimbEnv is closed \(close\(\) was called\): make a new one$"
    # Through gymnasium.make's wrappers too.
    env = gymnasium.make(crux.gym.ENV_ID, wall=7, render_mode="ansi")
    env.reset(seed=0)
    env.close()
    env.close()
    for operation in (env.reset, lambda: env.step(0), env.render):
        with pytest.raises(gymnasium.error.ClosedEnvironmentError, match=closed):
            operation()


def test_render_modes():
    env = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7), render_mode="rgb_array")
    env.reset(seed=0)
    image = env.render()
    assert image.dtype == np.uint8 and image.shape == (480, 480, 3)
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 3  # holds, body and wall, not a blank frame
    text = gymnasium.make(crux.gym.ENV_ID, wall=crux.Wall.random(7), render_mode="ansi")
    text.reset(seed=0)
    out = text.render()
    assert out.startswith("random wall, seed 7: right_hand free") and "possible holds:" in out


def test_rgb_array_tells_left_from_right_and_says_which_is_which():
    env = crux.gym.ClimbEnv(crux.Wall.random(7), render_mode="rgb_array")
    env.reset(seed=0)
    image = env.render()
    figure = env._rgb_figure()
    figure.canvas.draw()
    assert np.array_equal(image, np.asarray(figure.canvas.buffer_rgba())[:, :, :3])
    (legend,) = figure.legends
    assert [text.get_text() for text in legend.get_texts()] == [
        "right hand", "left hand", "right foot", "left foot", "trunk, head",
        "held hold", "possible hold", "other hold", "centre of mass", "finish, 3.00 m",
    ]
    # The limbs' colours are those of the SVG views, in limb order.
    palette = (REPOSITORY / "src" / "views" / "palette.hpp").read_text()
    named = dict(re.findall(r'(kOkabeIto\w+) = "(#[0-9a-f]{6})"', palette))
    styles = re.findall(r'\{"[RL][HF]", "([a-z ]+)", (kOkabeIto\w+)\}', palette)
    assert [(name, named[colour]) for name, colour in styles] == [
        (name.replace("_", " "), colour) for name, colour in zip(crux.LIMB_NAMES, crux.gym._LIMB_COLOURS)]
    # Each limb's colour is drawn on the wall itself, not only in the legend beside it.
    on_the_wall = image[:, : int(legend.get_window_extent().x0)]
    for name, colour in zip(crux.LIMB_NAMES, crux.gym._LIMB_COLOURS):
        rgb = np.array([int(colour[i : i + 2], 16) for i in (1, 3, 5)], dtype=np.uint8)
        assert np.all(on_the_wall == rgb, axis=2).sum() > 20, name


def test_a_fall_under_the_static_model_terminates_on_the_dead_end():
    """Random wall 7 under the static model (docs/PHYSICS.md): after the right hand takes
    hold 14 and the left hand hold 20, no stance of the right foot holds on the three holds
    left, so every candidate fails; the last failure is a fall (docs/MODEL.md, choice C27),
    which terminates the episode on the dead end, not on the start it falls back to."""
    wall = crux.Wall.random(7)
    env = crux.gym.ClimbEnv(wall, "paper", config={"physics": {"model": "static"}})
    env.reset(seed=0)
    for hold_id in (14, 20):
        _, _, terminated, _, info = env.step(wall.index_of(hold_id))
        assert info["reached"] and not info["fell"] and not terminated
    candidates = list(np.flatnonzero(info["action_mask"]))
    assert len(candidates) > 3
    for k, hold in enumerate(candidates):
        obs, reward, terminated, truncated, info = env.step(int(hold))
        assert not info["reached"] and reward == -1000.0
        assert terminated == info["fell"] == (k == len(candidates) - 1)
    assert obs["free_limb"] == 2, "the dead end, with the right foot free, not the start"
    kinematic = crux.gym.ClimbEnv(wall, "paper")
    kinematic.reset(seed=0)
    assert kinematic.step(wall.index_of(14))[4]["fell"] is False

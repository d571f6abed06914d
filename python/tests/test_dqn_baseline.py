"""The deep-RL baseline of examples/python/dqn_baseline.py, in a short version: a few hundred
steps on 2 training walls (docs/BASELINES.md has the real runs)."""

import argparse
import importlib.util
import json
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import crux

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"], "the baseline needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and Debian's python3-torch"
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = REPOSITORY / "examples" / "python" / "dqn_baseline.py"
BASELINES = REPOSITORY / "docs" / "BASELINES.md"
SHORT = ["--steps", "300", "--train-walls", "2", "--validation-walls", "2"]


@pytest.fixture(scope="module")
def baseline():
    spec = importlib.util.spec_from_file_location("dqn_baseline", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run_script(*args):
    # The example's interpreter finds crux and Gymnasium where this one did (not where a
    # symlinked package file points, which may lack the extension).
    path = [str(pathlib.Path(crux.__file__).absolute().parents[1]), str(pathlib.Path(gymnasium.__file__).parents[1])]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(path))
    return subprocess.run([sys.executable, str(SCRIPT), *args], capture_output=True, text=True, env=env)


def short_run(*extra):
    done = run_script("train", *SHORT, *extra)
    assert done.returncode == 0, done.stderr
    record = json.loads(done.stdout)
    record.pop("wall_clock_s")  # the only field the seed does not fix
    return record


def short_args(**changes):
    values = dict(steps=300, seed=1, lr=1e-3, epsilon_decay=0.2, hidden=64, train_walls=2, envs=1,
                  batch=32, replay=None, checkpoints=2, reward_height=None)
    return argparse.Namespace(**dict(values, **changes))


def random_transitions(baseline, count=200):
    """A replay of a masked random policy's n-step transitions on 2 training walls."""
    env = baseline.make_env(baseline.split(2, [baseline.HELD_OUT_FIRST_SEED]), max_episode_steps=1000)
    span = env.unwrapped._span
    rng = np.random.default_rng(0)
    replay = baseline.Replay(count, baseline.STATE_SIZE, env.unwrapped.max_candidates)
    obs, info = env.reset(seed=0)
    for _ in range(count):
        state, candidates, mask = baseline.features(obs, span)
        action = baseline.random_policy(state, candidates, mask, rng)
        obs, reward, terminated, truncated, info = env.step(action)
        replay.add([(state, candidates, mask, action, reward * baseline.REWARD_SCALE)],
                   baseline.features(obs, span), terminated)
        if terminated or truncated:
            obs, info = env.reset()
    return replay


def test_the_loss_falls_on_a_fixed_batch(baseline):
    baseline.deterministic(0)
    batch = random_transitions(baseline).batch(np.arange(64))
    net, target = baseline.SlotQNetwork(baseline.STATE_SIZE, 32), baseline.SlotQNetwork(baseline.STATE_SIZE, 32)
    optimiser = torch.optim.Adam(net.parameters(), lr=1e-3)
    losses = []
    for _ in range(60):
        loss = baseline.td_loss(net, target, batch)
        optimiser.zero_grad()
        loss.backward()
        optimiser.step()
        losses.append(float(loss))
    assert losses[-1] < 0.5 * losses[0], losses


def test_masked_actions_are_never_chosen_nor_bootstrapped_from(baseline):
    baseline.deterministic(0)
    net = baseline.SlotQNetwork(baseline.STATE_SIZE, 16)
    state = torch.zeros(1, baseline.STATE_SIZE)
    candidates = torch.randn(1, 8, 3)
    unmasked = net(state, candidates, torch.ones(1, 8, dtype=torch.bool))[0]
    best = int(torch.argmax(unmasked))
    mask = torch.ones(1, 8, dtype=torch.bool)
    mask[0, best] = False  # the action the network prefers is not possible
    masked = net(state, candidates, mask)[0]
    assert torch.isinf(masked[best]) and masked[best] < 0
    chosen = baseline.greedy_action(net, state[0].numpy(), candidates[0].numpy(), mask[0].numpy())
    assert chosen != best and mask[0, chosen]
    # The target's max is over the next state's possible actions: with the same network as
    # target, a 1-step transition's target is reward + gamma * (best possible value).
    batch = (state, candidates, torch.ones(1, 8, dtype=torch.bool), torch.tensor([best]), torch.tensor([0.0]),
             torch.tensor([baseline.GAMMA]), state, candidates, mask)
    expected = baseline.GAMMA * float(masked.max())
    q = float(unmasked[best])
    with torch.no_grad():
        loss = float(baseline.td_loss(net, net, batch))
    huber = 0.5 * (q - expected) ** 2 if abs(q - expected) < 1 else abs(q - expected) - 0.5
    assert loss == pytest.approx(huber, rel=1e-5)


def test_the_same_seed_gives_the_same_bytes_and_the_record_its_fields(baseline):
    first, again = short_run("--seed", "4"), short_run("--seed", "4")
    assert json.dumps(first, sort_keys=True) == json.dumps(again, sort_keys=True)
    other, _, _ = baseline.train(short_args(seed=5), validation_walls=2)
    assert first["network_sha256"] != other["network_sha256"]
    assert first["masked_choices"] == 0  # neither exploration nor the greedy choice took a masked action
    assert first["setting"] == {"lr": 1e-3, "epsilon_decay": 0.2, "hidden": 64}
    assert first["steps"] == 300 and first["train_walls"] == 2 and first["seed"] == 4
    assert sum(episode["length"] for episode in first["episodes"]) <= 300
    assert all(episode["end_step"] <= 300 and episode["finished"] in (True, False) for episode in first["episodes"])
    assert [point["step"] for point in first["curve"]] == [150, 300]
    for point in first["curve"]:
        assert [climb["wall"] for climb in point["validation"]] == ["random wall, seed 10000", "random wall, seed 10001"]
        for climb in point["validation"]:
            assert climb["finished"] == (climb["length"] is not None)
            assert climb["finished_no_retry"] == (climb["length_no_retry"] is not None)
            assert climb["length"] is None or 1 <= climb["length"] <= baseline.GREEDY_CAP
            # A greedy climb finishes only without a failed move, and is then its own climb without retries.
            assert not climb["finished"] or (climb["failed_moves"] == 0 and climb["length_no_retry"] == climb["length"])
    assert first["mean_loss_per_tenth"] and all(np.isfinite(first["mean_loss_per_tenth"]))


@pytest.mark.parametrize("argument, value", [("--steps", "0"), ("--hidden", "-3"), ("--lr", "0"),
                                             ("--epsilon-decay", "1.5"), ("--train-walls", "two"),
                                             ("--reward-height", "-1"), ("--envs", "0"),
                                             ("--replay", "8")])
def test_bad_input_is_one_line_naming_the_argument(baseline, capsys, argument, value):
    with pytest.raises(SystemExit) as exit:
        baseline.main(["train", argument, value])
    assert exit.value.code == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert len(err.splitlines()) == 1 and argument in err, err


def test_train_refuses_a_budget_below_one(baseline):
    with pytest.raises(ValueError, match="^steps: must be a positive integer"):
        baseline.train(short_args(steps=0))


def test_help_prints_the_whole_description(baseline, capsys):
    with pytest.raises(SystemExit) as exit:
        baseline.main(["--help"])
    assert exit.value.code == 0
    out = " ".join(capsys.readouterr().out.split())
    # The first paragraph was cut after its first line; the whole docstring is the description.
    assert " ".join(baseline.__doc__.split()) in out
    assert "beside the paper's Dyna-Q and the random policy on the same walls (docs/BASELINES.md)." in out


def test_the_docs_name_the_files_the_script_writes(baseline, tmp_path, monkeypatch):
    # One setting and one seed: the search's files for two short runs instead of 24.
    monkeypatch.setattr(baseline, "SEARCH_GRID", {"lr": [1e-3], "epsilon_decay": [0.2], "hidden": [16]})
    monkeypatch.setattr(baseline, "SEEDS_PER_SETTING", 1)
    for part, log in (("1/1", "search.jsonl"), ("1/2", "search-1of2.jsonl")):
        out = tmp_path / part.replace("/", "of")
        baseline.main(["search", "--out", str(out), "--steps", "20", "--train-walls", "2", "--validation-walls", "1",
                       "--part", part])
        assert sorted(path.name for path in out.iterdir()) == ["nets", log]
        assert baseline.search_log_name(*map(int, part.split("/"))) == log
    # What the docstring and BASELINES.md call them, their K/N included, and compare's file.
    written = {baseline.search_log_name(k, n) for k, n in ((1, 1), (1, 2), (2, 2), ("K", "N"))}
    written.add(baseline.COMPARISON_FILE)
    # BASELINES.md's section on the DQN; the learnt policy's sections name that script's files.
    text = BASELINES.read_text()
    docs = text[text.index("\n## The first baseline: a masked DQN\n"):text.index("\n## Not done\n")]
    for name, text in (("the docstring", baseline.__doc__), ("docs/BASELINES.md", docs)):
        # Records committed under models/ are quoted, not written by the script.
        committed = {path.name for path in (REPOSITORY / "models").rglob("*.json")}
        quoted = set(re.findall(r"[\w-]+\.jsonl?\b", text)) - committed
        assert {"search.jsonl", "search-KofN.jsonl", "comparison.json"} <= quoted <= written, name
        # plot writes the figure it is given: the docs' is the one they show.
        for figure in re.findall(r"dqn_baseline\.py plot --out \S+ (\S+)", text):
            assert figure.endswith(".png"), (name, figure)
            if figure.startswith("docs/"):
                assert (REPOSITORY / figure).is_file() and f"]({figure[len('docs/'):]})" in BASELINES.read_text()


def test_progress_is_a_timed_line_off_a_terminal_and_nothing_when_quiet(baseline):
    import io

    def written(**options):
        stream = io.StringIO()  # not a terminal
        progress = baseline.Progress("dqn train", 5, stream=stream, **options)
        for step in range(1, 6):
            progress.update(step)
        progress.close()
        return stream.getvalue()

    every_step = written(every_s=0.0)  # each step "ten seconds" after the last
    assert every_step.count("\n") == 5, every_step
    assert every_step.splitlines()[-1].startswith("dqn train [" + "#" * 40 + "] 100% (5/5, "), every_step
    assert "\r" not in every_step
    assert written(every_s=1e9) == "", "work done within the interval writes nothing"
    assert written(every_s=0.0, quiet=True) == ""


def test_train_keeps_stdout_to_its_record_and_takes_quiet():
    done = run_script("train", *SHORT, "--quiet")
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    json.loads(done.stdout)


def test_the_replay_keeps_the_last_transitions_of_its_capacity(baseline):
    replay = baseline.Replay(3, 2, 4)
    following = (np.zeros(2, np.float32), np.zeros((4, 3), np.float32), np.ones(4, bool))
    for action in range(5):
        replay.add([(np.full(2, action, np.float32), np.zeros((4, 3)), np.ones(4, bool), action, 1.0)], following,
                   terminated=action == 4)
    assert replay.size == 3 and sorted(replay.action.tolist()) == [2, 3, 4]
    assert replay.discount.tolist() == [pytest.approx(baseline.GAMMA), 0.0, pytest.approx(baseline.GAMMA)]


def test_vector_collection_repeats_itself_and_keeps_to_the_mask(baseline):
    args = short_args(steps=400, envs=4, batch=16, replay=100)
    first, net, _ = baseline.train(args, validation_walls=1)
    again, _, _ = baseline.train(args, validation_walls=1)
    assert json.dumps(first, sort_keys=True) == json.dumps(again, sort_keys=True)
    assert first["collection"] == {"envs": 4, "batch": 16, "replay": 100} and first["steps"] == 400
    assert first["masked_choices"] == 0
    assert [point["step"] for point in first["curve"]] == [200, 400]
    assert sum(episode["length"] for episode in first["episodes"]) <= 400
    one_env, _, _ = baseline.train(short_args(steps=400), validation_walls=1)
    assert one_env["network_sha256"] != first["network_sha256"]
    # Height shaping changes the rewards the DQN learns from, and the record says so.
    shaped, _, _ = baseline.train(short_args(steps=400, envs=4, batch=16, replay=100, reward_height=1e5))
    assert shaped["reward_height"] == 1e5 and first["reward_height"] is None
    assert shaped["network_sha256"] != first["network_sha256"]


def test_search_refuses_a_setting_outside_its_grid(baseline, capsys, tmp_path):
    with pytest.raises(SystemExit) as exit:
        baseline.main(["search", "--out", str(tmp_path), "--setting", "lr1-decay1-h1"])
    err = capsys.readouterr().err
    assert exit.value.code == 2 and len(err.splitlines()) == 1 and "--setting" in err and "lr0.001-decay0.2-h64" in err
    assert not any(tmp_path.iterdir())


def test_baselines_quotes_the_6m_record():
    record = json.loads((REPOSITORY / "models" / "policies" / "search" / "dqn_6m.json").read_text())
    text = BASELINES.read_text()
    for run in record["runs"]:
        assert run["steps"] == 6_000_000 and run["collection"] == {"envs": 64, "batch": 256, "replay": 1_000_000}
        per_million = ", ".join(map(str, run["finished_per_million_steps"]))
        last = run["validation"][-1]
        assert [point["finished"] for point in run["validation"]] == [0] * 6
        row = (f"| {run['seed']} | {run['training_episodes']} | {run['finished_episodes']} | {per_million} | 0 of 30 at "
               f"each")
        assert row in text and f"| {last['mean_moves_before_failure']:.0f} (the cap), {last['mean_rise_m']:.2f} m |" in text
    held_out = record["held_out"]["methods"]["DQN, greedy without retries (zero-shot)"]
    assert held_out["finished"]["mean"] == 0.0 and held_out["reached_share"]["mean"] == 1.0
    rise = held_out["rise_m"]
    assert f"rises {rise['mean']:.3f} m [{rise['low']:.3f}, {rise['high']:.3f}]" in text
    shaped = record["shaped_3m"]
    for run in shaped["runs"]:
        assert run["reward_height"] == 1e5 and run["steps"] == 3_000_000
        finished = ", ".join(str(point["finished_no_retry"]) for point in run["validation"])
        rises = ", ".join(f"{point['mean_rise_m']:.2f}" for point in run["validation"])
        per_half_million = ", ".join(map(str, run["finished_per_half_million_steps"]))
        row = f"| {run['seed']} | {per_half_million} | {finished} | {rises} |"
        assert row in text, row
    rise = shaped["held_out"]["methods"]["DQN, greedy without retries (zero-shot)"]["rise_m"]
    assert shaped["held_out"]["methods"]["DQN, greedy without retries (zero-shot)"]["finished"]["mean"] == 0.0
    assert f"(rise {rise['mean']:.3f} m [{rise['low']:.3f},\n  {rise['high']:.3f}]" in text

"""examples/python/plan_imitation.py: the demonstrations are the exact plans' moves as the
environment sees them, cloning them learns to choose the plan's slot and repeats itself,
and a bad demonstrations file is one line and exit code 2."""

import contextlib
import io
import json
import pathlib

import numpy as np
import pytest

import crux

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"], "plan imitation needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and python3-torch"
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
import plan_imitation as imitation  # noqa: E402 (conftest puts examples/python on the path; it needs torch)
baseline = imitation.baseline

WALLS = range(1000000, 1000008)  # 8 walls: 7 plans replay to the finish, 1 stops at a move it does not reach


@pytest.fixture(scope="module")
def demonstrations(tmp_path_factory):
    out = tmp_path_factory.mktemp("demonstrations") / "plans.npz"
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        imitation.main(["demonstrate", "--wall-seeds", f"{WALLS[0]}:{WALLS[-1]}", "--out", str(out)])
    return out, json.loads(printed.getvalue())


def test_the_demonstrations_are_the_plans_moves_as_the_environment_sees_them(demonstrations):
    path, printed = demonstrations
    data = imitation.load_demonstrations([path], "kinematic")
    assert printed["steps"] == len(data["action"]) and printed["replays"] == {"finished": 7, "replay failed": 1}
    span = baseline.configured_max_span()
    for seed in WALLS[:2]:
        steps = np.flatnonzero(data["wall"] == seed)
        plan = crux.plan(crux.Wall.random(seed))
        env = crux.gym.ClimbEnv(seed, "reach")
        obs, info = env.reset()
        assert len(steps) == plan["length"]  # both of these walls' plans replay to the finish
        for step, hold_id in zip(steps, plan["holds"]):
            state, slots, mask = baseline.single_features(obs, span)
            assert np.array_equal(state[0], data["state"][step]) and np.array_equal(slots[0], data["slots"][step])
            assert np.array_equal(mask[0], data["mask"][step])
            action = int(data["action"][step])
            assert env.wall.hold_ids[info["candidate_holds"][action]] == hold_id
            obs, _, terminated, _, info = env.step(action)
            assert info["reached"]
        assert terminated and not info.get("fell", False)


def test_failed_flags_never_mark_the_plans_slot_nor_an_empty_slot():
    rng = np.random.default_rng(3)
    slots = torch.zeros(64, baseline.MAX_CANDIDATES, baseline.SLOT_SIZE)
    mask = torch.zeros(64, baseline.MAX_CANDIDATES, dtype=torch.bool)
    mask[:, :10] = True
    action = torch.from_numpy(rng.integers(0, 10, 64))
    flagged = imitation.flag_failed(slots, mask, action, 0.5, rng)[:, :, imitation.FAILED_FLAG]
    assert not flagged[torch.arange(64), action].any() and not flagged[:, 10:].any()
    assert 0.4 < float(flagged[:, :10].sum()) / (64 * 9) < 0.6 and not slots.any()  # the input is left alone


def imitate(tmp_path, name, demonstrations, extra=()):
    out = tmp_path / name
    imitation.main(["imitate", "--demonstrations", str(demonstrations), "--out", str(out), "--epochs", "100",
                    "--lr", "0.01", "--hidden", "32", "--minibatch", "16", "--validation-walls", "0", *extra])
    return out


def test_cloning_learns_the_plans_slots_and_repeats_itself(tmp_path, demonstrations, capsys):
    first = imitate(tmp_path, "first.json", demonstrations[0])
    capsys.readouterr()
    record = json.loads(first.read_text())
    history = record["training"]["history"]
    # Measured: the plan's slot chosen on 13 % of the steps in the first epoch, 94 % in the last.
    assert history[0]["plan_slot_chosen"] < 0.5 and history[-1]["plan_slot_chosen"] >= 0.85, history[-1]
    policy, _ = baseline.load_policy(first)  # a policy file evaluate reads
    assert policy.hidden == 32 and record["training"]["imitated_steps"] > 50
    second = imitate(tmp_path, "second.json", demonstrations[0])
    assert json.loads(second.read_text())["slot_layers"] == record["slot_layers"]  # the same seed, the same weights


def bad_files(good, folder):
    """Demonstration files that must each be refused: (path, what the error names)."""
    data = dict(np.load(good))
    cases = {"missing": (folder / "missing.npz", "not a demonstrations file"),
             "not npz": (folder / "text.npz", "not a demonstrations file"),
             "truncated": (folder / "truncated.npz", "not a demonstrations file"),
             "an array": (folder / "array.npy", "not a demonstrations file"),
             "uneven": (folder / "uneven.npz", "different numbers of steps"),
             "narrow": (folder / "narrow.npz", "slots of shape"),
             "slot not offered": (folder / "offered.npz", "does not offer"),
             "empty": (folder / "empty.npz", "no step to imitate"),
             "static": (folder / "static.npz", "made under the static model")}
    cases["not npz"][0].write_bytes(b"not npz")
    cases["truncated"][0].write_bytes(good.read_bytes()[:300])
    np.save(cases["an array"][0], data["state"])
    np.savez(cases["uneven"][0], **{**data, "action": data["action"][:-1]})
    np.savez(cases["narrow"][0], **{**data, "slots": data["slots"][:, :, :5]})
    np.savez(cases["slot not offered"][0], **{**data, "action": np.full_like(data["action"], 31)})
    np.savez(cases["empty"][0], **{key: value[:0] if value.ndim else value for key, value in data.items()})
    np.savez(cases["static"][0], **{**data, "physics_model": np.array("static")})
    return cases


def test_bad_demonstrations_or_output_are_one_line_and_exit_code_2(tmp_path, demonstrations, capsys):
    assert str(np.load(demonstrations[0])["physics_model"]) == "kinematic"
    cases = bad_files(demonstrations[0], tmp_path)
    (tmp_path / "a file").write_text("")
    for name, (bad, problem) in cases.items():
        with pytest.raises(SystemExit) as exit_code:
            imitate(tmp_path, "x.json", bad)
        error = capsys.readouterr().err
        assert exit_code.value.code == 2 and error.count("\n") == 1 and problem in error, (name, error)
        assert error.startswith(f"plan_imitation.py: --demonstrations: {bad}: " if name != "empty" else
                                "plan_imitation.py: --demonstrations: ") and not (tmp_path / "x.json").exists()
    for command in (["demonstrate", "--wall-seeds", "1:1"], ["imitate", "--demonstrations", str(demonstrations[0])]):
        with pytest.raises(SystemExit) as exit_code:
            imitation.main([*command, "--out", str(tmp_path / "a file" / "x")])
        error = capsys.readouterr().err
        assert exit_code.value.code == 2 and error.count("\n") == 1 and "--out" in error, error


def test_baselines_cloning_table_quotes_its_record():
    record = json.loads((REPOSITORY / "models" / "policies" / "search" / "plan_imitation.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    steps = sum(part["steps"] for part in record["demonstrations"])
    stopped = sum(part["replays"].get("replay failed", 0) for part in record["demonstrations"])
    assert f"give {steps:,} pairs" in text and f"replays of {stopped} plans" in text

    def cells(held):
        done = round(held["finished"] * held["climbs"])
        return (f"| {held['finished']:.0%} ({done} of {held['climbs']}) | {held['mean_length_ratio']:.2f} "
                f"| {held['failed_moves_per_finished_climb']:.1f} |").replace("%", " %")

    parts = record["demonstrations"]
    walls = sum(sum(part["replays"].values()) - part["replays"].get("no start", 0) for part in parts)
    assert f"replays of {stopped} plans ({stopped / walls:.0%})".replace("%", " %") in text
    unflagged, flagged = (clone["held_out"] for clone in record["clones"])
    assert (f"({round(unflagged['finished'] * unflagged['climbs'])} walls, whose plans are shorter than most: "
            f"{unflagged['mean_plan_length']:.1f} moves on average), it climbs within\n  "
            f"{unflagged['mean_length_ratio']:.2f} times the plan") in text
    failed = flagged["failed_moves_per_finished_climb"]
    assert f"finishes {flagged['finished']:.0%}, but with {failed:.0f} failed moves a".replace("%", " %") \
        in text.replace("\n  ", " ")
    for clone in record["clones"]:
        assert f"| {clone['last_epoch']['plan_slot_chosen']:.0%} ".replace("%", " %") + cells(clone["held_out"]) in text
    assert "| " + cells(record["ppo_from_clone"]["held_out"]) in text
    policies = REPOSITORY / "models" / "policies"
    for label, path in (("the 6 M policy (PPO)", policies / "search" / "reach-ppo-6m.heldout.json"),
                        ("the shipped policy (PPO, 14 M steps)", policies / "reach-ppo.heldout.json")):
        held = json.loads(path.read_text())
        finished = [wall for wall in held["walls"] if wall["finished"]]
        held["failed_moves_per_finished_climb"] = np.mean([wall["failed_moves"] for wall in finished])
        assert f"| {label} | " + cells(held) in text, label


def test_baselines_static_cloning_table_quotes_its_record():
    record = json.loads((REPOSITORY / "models" / "policies" / "search" / "plan_imitation.json").read_text())["static"]
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    walls = {2: record["demonstrations"][:2], 4: record["demonstrations"]}
    for clone in record["clones"]:
        parts = walls[clone["demonstration_files"]]
        replayed = sum(part["replays"]["finished"] for part in parts)
        assert sum(part["steps"] for part in parts) == clone["imitated_steps"]
        held = clone["held_out"]
        validation = clone["validation_finished"]
        row = (f"| {clone['imitated_steps']:,} ({replayed}) | {clone['last_epoch']['plan_slot_chosen']:.0%} "
               f"| {max(validation):.0%}, {validation[-1]:.0%} "
               f"| {held['finished']:.0%} ({round(held['finished'] * held['climbs'])} of {held['climbs']}) "
               f"| {held['mean_length_ratio']:.2f} | {held['failed_moves_per_finished_climb']:.1f} |")
        row = row.replace("%", " %")
        assert row in text, row
    first = record["clones"][1]["held_out"]["walls"]  # the first flagged clone's climbs
    capped = sum(not wall["finished"] and wall["length"] == baseline.CLIMB_CAP for wall in first)
    fell = sum(not wall["finished"] and wall["length"] < baseline.CLIMB_CAP for wall in first)
    assert f"Of its 25 climbs, {fell} fall and {capped} reach the cap" in text
    shares = ", ".join(f"{row['finished']:.0%}".replace("%", " %") for row in record["ppo_from_clone"]["validation"])
    assert shares.replace(", 0 %", " and 0 %") in text


def test_static_plans_are_demonstrated_and_cloned_under_the_static_model(tmp_path, capsys):
    out = tmp_path / "static.npz"
    imitation.main(["demonstrate", "--physics-model", "static", "--wall-seeds", "1100000:1100000", "--out", str(out)])
    assert json.loads(capsys.readouterr().out)["replays"] == {"finished": 1}
    data = imitation.load_demonstrations([out], "static")
    plan = crux.plan(crux.Wall.random(1100000), config={"physics.model": "static"})
    assert np.sum(data["wall"] == 1100000) == plan["length"]  # the static plan, not the kinematic one
    assert plan["length"] != crux.plan(crux.Wall.random(1100000))["length"]
    policy = imitate(tmp_path, "static.json", out, ["--physics-model", "static", "--epochs", "1"])
    assert json.loads(policy.read_text())["training"]["settings"]["physics_model"] == "static"

"""examples/python/policy_baseline.py: masked PPO learns on a small wall set, the same seed
gives the same weights, the evaluator's numbers are those of a climb run by hand, and a
bad policy file is one line and exit code 2."""

import hashlib
import importlib.util
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import crux

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"], "the policy needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and Debian's python3-torch"
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = REPOSITORY / "examples" / "python" / "policy_baseline.py"
SEARCH = REPOSITORY / "models" / "policies" / "search"
VETOED = REPOSITORY / "models" / "policies" / "reach-ppo-vetoed.json"  # the policy trained under its veto


def climbs_under_the_veto():
    """The policy trained under its veto: its recorded climbs of the held-out walls 20000.., under the veto."""
    return json.loads((SEARCH / "reach_estimate.json").read_text())["trained_under_the_veto"]["held_out_walls"]


_spec = importlib.util.spec_from_file_location("policy_baseline", SCRIPT)
baseline = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(baseline)


def bracket(c, sign=""):
    """An interval as the docs print it: mean [low, high] to two decimals (sign="+" signs the mean)."""
    return f"{c['mean']:{sign}.2f} [{c['low']:.2f}, {c['high']:.2f}]"


def percent_bracket(c):
    """A share's interval as the docs print it: 98.6 % [97.5, 99.6]."""
    return f"{c['mean'] * 100:.1f} % [{c['low'] * 100:.1f}, {c['high'] * 100:.1f}]"


def negated(c):
    """The interval of minus the quantity: a change below zero told as a gain."""
    return {"mean": -c["mean"], "low": -c["high"], "high": -c["low"]}


def held_out_ratios(run):
    """A record's held-out climbs, each its length over its plan's (every climb finished)."""
    return [wall["length"] / wall["plan_length"] for wall in run["held_out"]["walls"]]


def evaluation_climbs(policy):
    """A record's evaluate climbs: each finished (0 or 1) and its length over its plan's (None unfinished)."""
    return [{"finished": float(w["finished"]), "ratio": w["length"] / w["plan_length"] if w["finished"] else None}
            for w in policy["evaluation"]["walls"]]

# The short run: 4 training walls, 8 environments, 96 updates of 8 x 32 steps (about 4 s).
SHORT = ["--steps", "24576", "--envs", "8", "--rollout", "32", "--minibatch", "256", "--hidden", "32",
         "--train-walls", "4", "--validation-walls", "0", "--validate-every", "0", "--episode-steps", "60",
         "--lr", "3e-3"]


def train(tmp_path, name, extra=()):
    out = tmp_path / name
    baseline.main(["train", "--out", str(out), *SHORT, *extra])
    return out


def reach_share(policy, walls):
    """The share of a greedy climb's moves that reach, over the walls' climbs."""
    reached = taken = 0
    for seed in walls:
        env = crux.gym.ClimbEnv(seed, "reach")
        obs, _ = env.reset()
        for _ in range(60):
            features = baseline.single_features(obs, policy.max_span)
            obs, _, terminated, _, info = env.step(baseline.greedy_slot(policy, *features))
            reached += info["reached"]
            taken += 1
            if terminated:
                break
    return reached / taken


def test_a_short_run_learns_to_choose_moves_that_reach_and_repeats_itself(tmp_path, capsys):
    first = train(tmp_path, "first.json")
    capsys.readouterr()
    trained, record = baseline.load_policy(first)
    baseline.deterministic(1)
    untrained = baseline.SlotPolicy(32, 2.8)
    before, after = reach_share(untrained, range(4)), reach_share(trained, range(4))
    print(f"share of greedy moves that reach on the training walls: {before:.3f} untrained, {after:.3f} trained")
    # Measured: 0.0 untrained (its greedy choice repeats a failed move), 0.996 trained.
    assert after >= 0.9 and before <= 0.5
    assert record["training"]["seed"] == 1 and record["training"]["steps"] == 24576
    assert "--train-walls 4" in record["training"]["command"]
    # The same seed gives the same weights to the bit, and another seed others: each over a
    # sixth of the steps (16 updates, each environment through several episodes).
    sixth = ["--steps", "4096"]
    one, again = train(tmp_path, "one.json", sixth), train(tmp_path, "again.json", sixth)
    assert without_command(again) == without_command(one)
    two = train(tmp_path, "two.json", [*sixth, "--seed", "2"])
    assert without_command(two)["slot_layers"] != without_command(one)["slot_layers"]


def without_command(path):
    """A policy file's record but the command, which names the file it wrote."""
    record = json.loads(path.read_text())
    del record["training"]["command"]
    return record


def hand_climb(policy, wall_seed):
    """A greedy climb through crux.ClimbMdp, without the gym environment: (finished, actions)."""
    mdp = crux.ClimbMdp(crux.Wall.random(wall_seed), max_steps=None)
    span = mdp.max_span
    mdp.reset()
    for taken in range(1, baseline.CLIMB_CAP + 1):
        observation = mdp.numeric_observation(32, reach=True)
        state, slots, mask = baseline.single_features(observation, span)
        scores = baseline.SlotPolicy.logits(policy, *(torch.from_numpy(a) for a in (state, slots, mask)))
        slot = int(np.argmax(scores.detach().numpy()[0]))
        hold = int(np.flatnonzero(mdp.action_mask())[slot])
        _, _, terminated, _, _ = mdp.step(hold)
        if terminated:
            return True, taken
    return False, baseline.CLIMB_CAP


def test_the_evaluators_numbers_are_those_of_climbs_run_by_hand(capsys):
    # The shipped policy, which finishes these walls: the lengths are compared, not only the cap.
    path = REPOSITORY / "models" / "policies" / "reach-ppo.json"
    loaded, _ = baseline.load_policy(path)
    baseline.main(["evaluate", "--policy", str(path), "--wall-seeds", "3:4", "--json"])
    result = json.loads(capsys.readouterr().out)
    climbs = [hand_climb(loaded, seed) for seed in (3, 4)]
    plans = [crux.plan(crux.Wall.random(seed))["length"] for seed in (3, 4)]
    lengths = [length for done, length in climbs if done]
    assert lengths and result["climbs"] == 2 and result["oracle"] == "none"
    assert result["finished"] == sum(done for done, _ in climbs) / 2
    assert result["mean_length"] == (np.mean(lengths) if lengths else None)
    finished_plans = [plan for plan, (done, _) in zip(plans, climbs) if done]
    assert result["mean_plan_length"] == (np.mean(finished_plans) if finished_plans else None)
    assert [wall["plan_length"] for wall in result["walls"]] == plans
    baseline.main(["evaluate", "--policy", str(path), "--wall-seeds", "3:4", "--json"])
    assert json.loads(capsys.readouterr().out) == result  # the same inputs, the same numbers


def run_evaluate(*arguments):
    # The example's interpreter finds crux and Gymnasium where this one did.
    path = [str(pathlib.Path(crux.__file__).absolute().parents[1]), str(pathlib.Path(gymnasium.__file__).parents[1])]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(path))
    return subprocess.run([sys.executable, str(SCRIPT), "evaluate", *arguments], capture_output=True, text=True,
                          env=env, timeout=120)


def test_the_verdict_oracle_foretells_each_move_of_a_climb_and_its_climbs_fail_none():
    seed = 20240  # the random climb's draws; printed by the assertion's message
    rng = np.random.default_rng(seed)
    config = baseline.climbing_config("kinematic")
    env = crux.gym.ClimbEnv(3, baseline.OBSERVATION, config=config)
    obs, _ = env.reset()
    history, verdicts = [], []
    for _ in range(40):  # a random climb meets moves that fail and moves that reach
        mask = obs["candidate_mask"][None] > 0.5
        foretold = baseline.verdict_mask(3, config, history, mask)
        action = int(rng.choice(np.flatnonzero(mask[0])))
        obs, _, terminated, _, info = env.step(action)
        history.append(action)
        verdicts.append((bool(foretold[0, action]), info["reached"]))
        if terminated:
            break
    assert all(told == reached for told, reached in verdicts), f"seed {seed}: {verdicts}"
    assert {reached for _, reached in verdicts} == {True, False}, f"seed {seed}: {verdicts}"
    policy, _ = baseline.load_policy(REPOSITORY / "models" / "policies" / "reach-ppo.json")
    plans = baseline.plan_lengths([20000])
    alone, told = (baseline.evaluate(policy, [20000], plans=plans, oracle=oracle)["walls"][0]
                   for oracle in (False, True))
    records = [json.loads((SEARCH / name).read_text())["policies"][0]["evaluation"]["walls"][0]
               for name in ("heldout_300.json", "oracle_verdict_300.json")]
    assert [alone, told] == records  # the shipped policy's first climb, alone (3 failed moves) and told
    assert (alone["failed_moves"], told["failed_moves"]) == (3, 0) and told["length"] < alone["length"]


def test_the_verdict_oracle_leaves_the_policy_its_own_choice_where_no_move_reaches(monkeypatch):
    policy, _ = baseline.load_policy(REPOSITORY / "models" / "policies" / "reach-ppo.json")
    plans = baseline.plan_lengths([20000])
    alone = baseline.evaluate(policy, [20000], plans=plans)
    monkeypatch.setattr(baseline, "verdict_mask", lambda wall_seed, config, history, mask: np.zeros_like(mask))
    assert baseline.evaluate(policy, [20000], plans=plans, oracle=True) == alone


@pytest.mark.parametrize("content, problem", [
    (None, "cannot read the policy file"),
    ("{not json", "not a policy file (not JSON"),
    ('{"format": "crux-policy", "version": 1, "observation": "numeric"}', "a policy for observation 'numeric'"),
    ('{"format": "crux-policy", "version": 1, "observation": "reach", "slot_layers": [{"weight": [[1]], '
     '"bias": [0]}], "value_layers": []}', "not a policy file"),
])
def test_a_bad_policy_file_is_one_line_and_exit_code_2(tmp_path, capsys, content, problem):
    path = tmp_path / "policy.json"
    if content is not None:
        path.write_text(content)
    with pytest.raises(SystemExit) as exit_:
        baseline.main(["evaluate", "--policy", str(path), "--wall-seeds", "1:2"])
    out = capsys.readouterr()
    assert exit_.value.code == 2 and out.out == ""
    assert out.err.count("\n") == 1 and problem in out.err, out.err
    assert out.err.startswith(f"policy_baseline.py: --policy: {path}: ")


def test_evaluate_climbs_under_the_veto_the_policy_file_names(tmp_path, monkeypatch, capsys):
    """The shipped policy trained under its veto: evaluate applies the reach head its record
    names, found from a folder above the policy file when the current folder has no such
    path, and climbs as its record says; under --no-veto it climbs alone."""
    monkeypatch.chdir(tmp_path)
    baseline.main(["evaluate", "--policy", str(VETOED), "--wall-seeds", "20000:20000", "--json"])
    under = json.loads(capsys.readouterr().out)
    assert under["veto"] == {"head": str(REPOSITORY / "models" / "policies" / "reach-ppo.reach-head.json"),
                             "threshold": 0.5}
    record = climbs_under_the_veto()
    assert [{key: wall[key] for key in record[0]} for wall in under["walls"]] == record[:1]
    baseline.main(["evaluate", "--policy", str(VETOED), "--wall-seeds", "20000:20000", "--json", "--no-veto"])
    alone = json.loads(capsys.readouterr().out)
    policy, _ = baseline.load_policy(VETOED)
    by_hand = baseline.evaluate(policy, [20000], plans=baseline.plan_lengths([20000]))
    assert alone["veto"] is None and alone["walls"] == by_hand["walls"] != under["walls"]


def policy_naming_a_veto(folder, veto):
    baseline.deterministic(5)
    path = folder / "policy.json"
    baseline.save_policy(baseline.SlotPolicy(8, baseline.configured_max_span()), path, {"seed": 5, "veto": veto})
    return path


@pytest.mark.parametrize("veto, problem", [
    ({"head": "missing-head.json", "threshold": 0.5}, "missing-head.json: cannot read the reach head"),
    ({"head": "head.json", "threshold": 1.5}, "veto threshold must be in [0, 1), got 1.5"),
    ("head.json", "its training record's veto is not a head and a threshold"),
    ({"head": "head.json", "threshold": 0.5}, "head.json: fitted with filter.max_span = 9.0 m"),
])
def test_a_veto_that_cannot_be_applied_is_one_line_and_exit_code_2(tmp_path, monkeypatch, capsys, veto, problem):
    import reach_estimate  # the module policy_baseline reads heads with

    head = reach_estimate.ReachHead(4, np.zeros(reach_estimate.ROW_SIZE), np.ones(reach_estimate.ROW_SIZE), 9.0)
    reach_estimate.save_head(head, tmp_path / "head.json", {})
    path = policy_naming_a_veto(tmp_path, veto)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as exit_:
        baseline.main(["evaluate", "--policy", str(path), "--wall-seeds", "20000:20001"])
    out = capsys.readouterr()
    assert exit_.value.code == 2 and out.out == "" and out.err.count("\n") == 1, out.err
    assert out.err.startswith(f"policy_baseline.py: --policy: {path}: ") and problem in out.err, out.err


def test_evaluate_refuses_a_veto_under_the_static_model_and_a_training_record_that_is_not_an_object(
        tmp_path, capsys):
    policy = policy_naming_a_veto(tmp_path, None)
    record = json.loads(policy.read_text())
    record["training"] = None
    policy.write_text(json.dumps(record))
    for arguments, option, problem in (
            (["--policy", str(VETOED), "--physics-model", "static"], "--physics-model",
             "learnt the kinematic model's verdicts, not the static model's; --no-veto climbs without it"),
            (["--policy", str(policy)], "--policy", f"{policy}: its training record is not an object")):
        with pytest.raises(SystemExit) as exit_:
            baseline.main(["evaluate", *arguments, "--wall-seeds", "20000:20000"])
        out = capsys.readouterr()
        assert exit_.value.code == 2 and out.out == "" and out.err.count("\n") == 1, out.err
        assert out.err.startswith(f"policy_baseline.py: {option}: ") and problem in out.err, out.err


def test_bad_arguments_are_one_line_and_exit_code_2(tmp_path):
    done = run_evaluate("--policy", str(tmp_path / "p.json"), "--wall-seeds", "5:2")
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "--wall-seeds" in done.stderr


def test_crux_trains_with_the_policy_as_its_network_prior_and_scores_as_torch_does(tmp_path):
    # Under --transfer network with epsilon 0 the first move of a run is the candidate the
    # C++ (Eigen) evaluation of the policy scores highest: on each wall it is torch's too.
    baseline.deterministic(3)
    policy = baseline.SlotPolicy(16, 2.8)
    path = tmp_path / "policy.json"
    baseline.save_policy(policy, path, {"seed": 3})
    loaded, _ = baseline.load_policy(path)
    config = {"experiment.transfer": "network", "experiment.policy": str(path), "experiment.iterations": 1,
              "learning.epsilon": 0.0}
    for seed in range(1, 6):
        wall = crux.Wall.random(seed)
        mdp = crux.ClimbMdp(wall)
        observation = mdp.numeric_observation(32, reach=True)
        state, slots, mask = baseline.single_features(observation, 2.8)
        scores = policy.logits(*(torch.from_numpy(a) for a in (state, slots, mask))).detach().numpy()[0]
        holds = np.flatnonzero(mdp.action_mask())
        assert np.sort(scores[: len(holds)])[-1] > np.sort(scores[: len(holds)])[-2] + 1e-4  # no near tie
        best = holds[int(np.argmax(scores[: len(holds)]))]
        run = crux.run_learning(wall, config, seed=seed)
        assert run.iterations["hold_id"][0] == wall.hold_ids[best], f"wall {seed}"
    with pytest.raises(ValueError, match="only experiment.transfer = network uses a policy file"):
        crux.run_learning(crux.Wall.random(1), {"experiment.policy": str(path), "experiment.iterations": 1})


def test_docs_python_block_loads_the_shipped_policy_and_climbs(monkeypatch, capsys):
    text = (REPOSITORY / "docs" / "PYTHON.md").read_text()
    start = text.index("shipped as `models/policies/reach-ppo.json`")
    block = text[text.index("```python\n", start) + len("```python\n"):text.index("```\n", text.index("```python\n", start))]
    monkeypatch.chdir(REPOSITORY)
    namespace = {}
    exec(block, namespace)  # the block as written
    assert namespace["done"] and namespace["actions"] >= 1
    assert capsys.readouterr().out.startswith("examples/python/policy_baseline.py train ")


def hand_random_climb(wall_seed, seed):
    """The random policy's episode through crux.ClimbMdp: a uniform draw among the offered slots."""
    mdp = crux.ClimbMdp(crux.Wall.random(wall_seed), max_steps=None)
    mdp.reset()
    rng = np.random.default_rng([seed, wall_seed])
    for taken in range(1, baseline.OTHERS_CAP + 1):
        holds = np.flatnonzero(mdp.action_mask())
        _, _, terminated, _, _ = mdp.step(int(holds[rng.choice(np.arange(holds.size))]))
        if terminated:
            return 1.0, taken
    return 0.0, None


def test_the_comparison_is_made_of_its_parts_and_draws(tmp_path, capsys):
    baseline.deterministic(4)
    paths = [tmp_path / "a.json", tmp_path / "b.json"]
    for path in paths:
        baseline.save_policy(baseline.SlotPolicy(16, 2.8), path, {"seed": 4})
    out = tmp_path / "comparison.json"
    baseline.main(["compare", "--policy", *map(str, paths), "--wall-seeds", "3:4", "--seeds", "1:2", "--out", str(out)])
    table = capsys.readouterr().out
    summary = json.loads(out.read_text())
    assert summary["vetoes"] == [None, None]
    policies = [baseline.load_policy(path)[0] for path in paths]
    for wall in summary["walls"]:
        seed = wall["wall_seed"]
        assert wall["plan_length"] == crux.plan(crux.Wall.random(seed))["length"]
        climbs = [hand_climb(policy, seed) for policy in policies]
        assert [(bool(r["finished"]), r["length"]) for r in wall["policy"]] == [
            (done, length if done else None) for done, length in climbs]
        for run, learning_seed in zip(wall["dyna_q"], (1, 2)):
            learnt = crux.run_learning(crux.Wall.random(seed), {"experiment.transfer": "paper"}, seed=learning_seed)
            assert run["length"] == (learnt.greedy_length if learnt.greedy_length >= 0 else None)
        assert [(r["finished"], r["length"]) for r in wall["random"]] == [hand_random_climb(seed, s) for s in (1, 2)]
        assert f"| {seed} | {wall['plan_length']} |" in table
    # Paired over walls: each wall's mean over its runs, policy minus random.
    differences = [np.mean([r["finished"] for r in w["policy"]]) - np.mean([r["finished"] for r in w["random"]])
                   for w in summary["walls"]]
    assert summary["paired"]["policy - random, finished"]["mean"] == pytest.approx(np.mean(differences))
    figure = tmp_path / "curves.png"
    baseline.main(["plot", "--search", str(SEARCH), "--comparison", str(out),
                   str(figure)])
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and not list(tmp_path.glob("*.partial*"))


def test_compare_climbs_each_policy_under_the_veto_its_file_names(tmp_path, monkeypatch, capsys):
    for method in ("dyna_q_climb", "random_climb"):  # their runs are checked above; here only the policy's
        monkeypatch.setattr(baseline, method, lambda wall_seed, seed: (True, 10))
    out = tmp_path / "comparison.json"
    under = climbs_under_the_veto()[0]
    alone = baseline.evaluate(baseline.load_policy(VETOED)[0], [20000], plans={})["walls"][0]
    for veto, climb in (([], under), (["--no-veto"], alone)):
        baseline.main(["compare", "--policy", str(VETOED), "--wall-seeds", "20000:20000", "--seeds", "1:1",
                       "--out", str(out), "--json", *veto])
        capsys.readouterr()
        summary = json.loads(out.read_text())
        assert [wall["policy"][0]["length"] for wall in summary["walls"]] == [climb["length"]]
        assert (summary["vetoes"][0] or {}).get("threshold") == (None if veto else 0.5)
    assert under["length"] != alone["length"]


def test_training_can_start_from_a_policy_and_refuses_a_bad_one(tmp_path, capsys):
    baseline.deterministic(6)
    start = tmp_path / "start.json"
    baseline.save_policy(baseline.SlotPolicy(32, 2.8), start, {"seed": 6})
    # One update at a rate of 1e-9: the weights stay the starting ones (Adam moves each by about the rate).
    tuned = train(tmp_path, "tuned.json", ["--init-policy", str(start), "--steps", "256", "--lr", "1e-9"])
    fresh = train(tmp_path, "fresh.json", ["--steps", "256", "--lr", "1e-9"])
    weights = {name: np.array(json.loads(path.read_text())["slot_layers"][0]["weight"])
               for name, path in (("start", start), ("tuned", tuned), ("fresh", fresh))}
    assert np.allclose(weights["tuned"], weights["start"], atol=1e-6)
    assert not np.allclose(weights["fresh"], weights["start"], atol=1e-2)
    capsys.readouterr()
    for bad, problem in ((tmp_path / "missing.json", "cannot read the policy file"), (start, "of width 32")):
        with pytest.raises(SystemExit) as exit_code:
            baseline.main(["train", "--out", str(tmp_path / "x.json"), *SHORT, "--hidden", "16", "--init-policy", str(bad)])
        error = capsys.readouterr().err
        assert exit_code.value.code == 2 and error.count("\n") == 1 and problem in error, error
        assert error.startswith("policy_baseline.py: --init-policy: ") and not (tmp_path / "x.json").exists()


def test_keep_best_writes_the_weights_of_the_best_validation(tmp_path, monkeypatch, capsys):
    # Scripted validations over a third of the short run (32 updates): the second is the
    # best (the fourth ties it on finished but climbs longer against the plans); the fifth
    # is the run without --keep-best.
    scores = iter([(0.2, 1.5), (0.6, 1.5), (0.4, 1.2), (0.6, 1.8), (0.1, 1.0)])
    weights_seen = []

    def scripted_evaluate(policy, wall_seeds, physics_model="kinematic", plans=None, veto=None):
        weights_seen.append(policy.slot_net[0].weight.detach()[:, :, 0].tolist())
        finished, ratio = next(scores)
        return {"finished": finished, "mean_length": 10.0, "mean_length_ratio": ratio, "within_1_5_plans": 0.0}

    monkeypatch.setattr(baseline, "evaluate", scripted_evaluate)
    monkeypatch.setattr(baseline, "plan_lengths", lambda walls, physics_model="kinematic": {})
    third = ["--steps", "8192", "--validation-walls", "1"]
    kept = train(tmp_path, "kept.json", [*third, "--validate-every", "8", "--keep-best"])
    last = train(tmp_path, "last.json", [*third, "--validate-every", "32"])
    capsys.readouterr()
    record = json.loads(kept.read_text())
    assert len(weights_seen) == 5 and record["training"]["kept_steps"] == record["training"]["history"][1]["steps"]
    assert record["slot_layers"][0]["weight"] == weights_seen[1] != weights_seen[3]
    # Without --keep-best the last weights are written, and the run is otherwise the same.
    assert json.loads(last.read_text())["slot_layers"][0]["weight"] == weights_seen[3] == weights_seen[4]
    assert "kept_steps" not in json.loads(last.read_text())["training"]


def test_baselines_keep_best_table_quotes_its_record():
    record = json.loads((SEARCH / "static_keep_best.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    for run in record["runs"]:
        rate = run["command"].split("--lr ")[1].split()[0]
        best = max(run["validation"], key=lambda p: (p["finished"], -(p["mean_length_ratio"] or np.inf)))
        held = run["held_out"]
        row = (f"| {float(rate):.0e} | {best['finished']:.0%} ({round(best['finished'] * 25)} of 25) "
               f"| {run['kept_steps']:,} | {run['validation'][-1]['finished']:.0%} "
               f"| {held['finished']:.0%} ({round(held['finished'] * held['climbs'])} of {held['climbs']})")
        row = row.replace("e-0", "e-").replace("%", " %")
        assert best["steps"] == run["kept_steps"] and row in text, row


def test_a_lower_finishing_height_reaches_the_training_walls_and_is_checked(tmp_path, capsys):
    # Below the start's centre of mass, the first move that reaches finishes the climb; at the
    # walls' own 3 m the short run's first updates finish almost nothing.
    counts = {}
    for height in ("0.5", None):
        extra = ["--steps", "2048", "--validate-every", "8"] + (["--finish-height", height] if height else [])
        record = json.loads(train(tmp_path, f"{height}.json", extra).read_text())
        last = record["training"]["history"][-1]
        counts[height] = last["finished_episodes"] / last["episodes"]
        assert record["training"]["settings"]["finish_height"] == (float(height) if height else None)
    capsys.readouterr()
    assert counts["0.5"] >= 0.9 and counts[None] <= 0.1, counts
    for bad, problem in (("nan", "must be a finite number"), ("2000", "wall.finish_height: must be in")):
        with pytest.raises(SystemExit) as exit_code:
            baseline.main(["train", "--out", str(tmp_path / "x.json"), *SHORT, "--finish-height", bad])
        error = capsys.readouterr().err
        assert exit_code.value.code == 2 and error.count("\n") == 1 and problem in error, error
        assert not (tmp_path / "x.json").exists()


def test_baselines_curriculum_table_quotes_its_record():
    record = json.loads((SEARCH / "static_curriculum.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    for run in record["runs"]:
        stages = run["stages"]
        assert [stage["finish_height"] for stage in stages] == [2.0, 2.5, 3.0]
        assert all(f"--finish-height {stage['finish_height']}" in stage["command"] for stage in stages)
        trained = ", ".join(f"{s['validation'][-1]['finished_episodes'] / s['validation'][-1]['episodes']:.0%}"
                            for s in stages)
        validated = ", ".join(f"{s['validation'][-1]['finished']:.0%}" for s in stages)
        best = max(v["finished"] for s in stages for v in s["validation"])
        held = run["held_out"]
        row = (f"| {run['lr']:.0e} | {trained} | {validated} | {best:.0%} "
               f"| {held['finished']:.0%} ({round(held['finished'] * held['climbs'])} of {held['climbs']}) |")
        row = row.replace("e-0", "e-").replace("%", " %")
        assert row in text, row


def test_baselines_long_training_table_quotes_its_record():
    record = json.loads((SEARCH / "long_training.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    stage3 = json.loads((SEARCH / "heldout_stage3.json").read_text())
    for run in record["runs"]:
        assert f"--steps 14000000 --seed {run['seed']} " in run["command"] and run["steps"] == 13_996_032
        # The 6 M-step column is the same seed's climbs in the comparison's record, recomputed here.
        six_climbs = [wall["policy"][run["seed"] - 1] for wall in stage3["walls"]]
        assert run["held_out_6m"]["mean_length_ratio"] == pytest.approx(
            np.mean([climb["ratio"] for climb in six_climbs if climb["finished"]]))
        held, static, change = run["held_out"], run["held_out_static"], run["paired_ratio_14m_minus_6m"]
        row = (f"| {run['seed']} | {run['seconds']:.0f} | {run['validation'][-1]['mean_length_ratio']:.2f} "
               f"| {held['finished']:.0%} | {run['held_out_6m']['mean_length_ratio']:.2f} "
               f"| {held['mean_length_ratio']:.2f} | {held['within_1_5_plans']:.0%} "
               f"| {bracket(change)}, p = {change['p']:.2g} "
               f"| {static['finished']:.0%} ({round(static['finished'] * static['climbs'])} of {static['climbs']}) |")
        assert row.replace("%", " %") in text, row
    # The pooled ratios are each wall's mean over the seeds, recomputed from the climbs.
    runs = record["runs"]

    def wall_means(ratios_per_seed):
        return [np.mean([r for r in wall if r is not None]) for wall in zip(*ratios_per_seed)]

    long = wall_means([[w["length"] / w["plan_length"] if w["finished"] else None for w in run["held_out"]["walls"]]
                       for run in runs])
    six = wall_means([[wall["policy"][seed]["ratio"] if wall["policy"][seed]["finished"] else None
                       for wall in stage3["walls"]] for seed in range(3)])
    assert record["ratio_14m"]["mean"] == pytest.approx(np.mean(long))
    assert record["ratio_6m"]["mean"] == pytest.approx(np.mean(six))
    change = record["paired_ratio_14m_minus_6m"]
    assert change["mean"] == pytest.approx(np.mean(np.subtract(long, six)))
    prose = text.replace("\n", " ")
    assert (f"{bracket(record['ratio_14m'])} times their plans, against {bracket(record['ratio_6m'])} "
            f"at 6 M steps") in prose
    assert f"{bracket(change)} (p = {change['p']:.1e})" in prose
    assert (f"and {bracket(record['ratio_14m'])} times the exact plan's: shorter than the same setting's at 6 M "
            f"steps ({bracket(record['ratio_6m'])}, paired {bracket(change)})") in prose
    python_doc = " ".join((REPOSITORY / "docs" / "PYTHON.md").read_text().split())
    [seed1] = [run for run in record["runs"] if run["seed"] == 1]
    assert (f"in {bracket(record['ratio_14m'])} times the exact plan's length over its setting's three seeds at 14 M "
            f"steps (the shipped policy, seed 1: {seed1['held_out']['mean_length_ratio']:.2f};") in python_doc
    diagnoses = json.loads((SEARCH / "climb_diagnosis.json").read_text())
    [six_m] = [d["moves"] for d in diagnoses["diagnoses"] if d["policy"] == "models/policies/search/reach-ppo-6m.json"
               and d["physics_model"] == "kinematic" and d["oracle"] == "none"]

    def spread(key):
        values = [key(run["diagnosis"]["moves"]) for run in runs]
        return min(values), max(values)

    actions, failed = spread(lambda m: sum(m.values())), spread(lambda m: m["failed"] + m["failed_graph_reaches"])
    detours, optimal = spread(lambda m: m["detour"]), spread(lambda m: m["optimal"])
    plans = sum(wall["plan_length"] for wall in runs[0]["held_out"]["walls"])
    assert (f"({actions[0]} to {actions[1]} actions against the plans' {plans}, where the 6 M policy "
            f"takes {sum(six_m.values())})") in prose
    assert (f"failed moves fell from {six_m['failed'] + six_m['failed_graph_reaches']} to {failed[0]}-{failed[1]}, "
            f"and detours from {six_m['detour']} to {detours[0]}-{detours[1]}, with {optimal[0]} to {optimal[1]} "
            f"optimal moves") in prose
    assert (f"is {round(1.5 * plans)} actions, so {actions[0] - round(1.5 * plans)} to "
            f"{actions[1] - round(1.5 * plans)} more actions") in prose


def test_baselines_quotes_the_comparison_of_the_policy_trained_under_its_veto():
    search = REPOSITORY / "models" / "policies" / "search"
    record = json.loads((search / "heldout_vetoed.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    start = text.index("the policy trained under its veto finishes every wall:")
    section = text[start:text.index("### The static model", start)]
    printed = baseline.comparison_markdown(record)
    for line in printed[:printed.index("| wall | plan |")].strip().splitlines():
        assert line in section, line  # the summary tables as compare prints them
    assert record["vetoes"] == [{"head": "models/policies/reach-ppo.reach-head.json", "threshold": 0.5}]
    # Its climbs are the first 30 of the 3000 evaluated under the veto; Dyna-Q's and random's
    # runs are those of the shipped policy's comparison.
    under = climbs_under_the_veto()
    assert [(w["wall_seed"], w["policy"][0]["length"], w["policy"][0]["failed_moves"]) for w in record["walls"]] == [
        (w["wall_seed"], w["length"], w["failed_moves"]) for w in under[:30]]
    others = json.loads((search / "heldout_14m.json").read_text())["walls"]
    assert [(w["dyna_q"], w["random"]) for w in record["walls"]] == [(w["dyna_q"], w["random"]) for w in others]
    failed = sum(w["policy"][0]["failed_moves"] for w in record["walls"])
    assert f"Its climbs fail {failed} moves in all" in " ".join(section.split())


def test_baselines_14m_comparison_quotes_its_record():
    policies = REPOSITORY / "models" / "policies"
    record = json.loads((policies / "search" / "heldout_14m.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    start = text.index("The shipped setting trained for 14 M steps, its three seeds")
    section = text[start:text.index("**At 6 M steps**", start)]
    for line in baseline.comparison_markdown(record).splitlines():
        assert line in section, line  # the tables as compare prints them
    # The first seed's climbs are the shipped policy's evaluation, climb for climb.
    shipped = json.loads((policies / "reach-ppo.heldout.json").read_text())["walls"]
    first_seed = [(wall["wall_seed"], wall["policy"][0]["length"], wall["policy"][0]["failed_moves"])
                  for wall in record["walls"]]
    assert first_seed == [(wall["wall_seed"], wall["length"], wall["failed_moves"]) for wall in shipped]
    climbs = [[wall["policy"][seed] for wall in record["walls"]] for seed in range(3)]
    assert all(climb["finished"] for seed in climbs for climb in seed)
    lengths = [np.mean([climb["length"] for climb in seed]) for seed in climbs]
    ratios = [np.mean([climb["ratio"] for climb in seed]) for seed in climbs]
    within = [np.mean([climb["ratio"] <= 1.5 for climb in seed]) for seed in climbs]
    prose = " ".join(section.split())
    assert (f"Per seed: {lengths[0]:.1f}, {lengths[1]:.1f} and {lengths[2]:.1f} actions (ratios {ratios[0]:.2f}, "
            f"{ratios[1]:.2f} and {ratios[2]:.2f}; within 1.5 times the plan on {within[0]:.0%}, {within[1]:.0%} and "
            f"{within[2]:.0%} of the walls)").replace("%", " %") in prose
    stage3 = json.loads((policies / "search" / "heldout_stage3.json").read_text())
    failed = [np.mean([climb["failed_moves"] for wall in comparison["walls"] for climb in wall["policy"]])
              for comparison in (stage3, record)]
    flat = " ".join(text.split())
    assert f"of which {failed[0]:.1f} a climb are failed moves; at 14 M steps," in flat
    assert f"more, of which {failed[1]:.1f} are failed moves." in flat


def test_the_shipped_policy_is_the_14m_run_the_docs_describe():
    policies = REPOSITORY / "models" / "policies"
    policy = json.loads((policies / "reach-ppo.json").read_text())
    record = policy["training"]
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    start = text.index("### The shipped policy")
    section = text[start:text.index("### The length target", start)]
    flat = " ".join(section.split())
    assert f"/usr/bin/python3 {record['command']}\n" in section and record["steps"] == 13_996_032
    last = record["history"][-1]
    assert f"This file's training took {last['seconds']:.0f} s on" in section
    assert (f"| validation, 10000-10029 (its last validation) | {last['finished']:.0%} | {last['mean_length']:.1f} | "
            f"| {last['mean_length_ratio']:.2f} | {last['within_1_5_plans']:.0%} |").replace("%", " %") in section
    assert f"(about {round(last['episodes'], -4):,} of them)" in " ".join(text.split())
    long_training = json.loads((policies / "search" / "long_training.json").read_text())
    runs = {run["seed"]: run for run in long_training["runs"]}
    # Its validations are those of the same command's first run, the wall-clock aside, and so are its weights.
    assert [{key: v[key] for key in runs[1]["validation"][0]} for v in record["history"]] == runs[1]["validation"]
    digest = hashlib.sha256(json.dumps([policy["slot_layers"], policy["value_layers"]]).encode()).hexdigest()
    assert runs[1]["weights_sha256"]["first_run"] == runs[1]["weights_sha256"]["rerun_shipped"] == digest
    # Chosen by the last validation's ratio, where the search's score would pick another seed.
    last_ratio = {seed: run["validation"][-1]["mean_length_ratio"] for seed, run in runs.items()}
    last_within = {seed: run["validation"][-1]["within_1_5_plans"] for seed, run in runs.items()}
    held = {seed: run["held_out"]["mean_length_ratio"] for seed, run in runs.items()}
    assert min(last_ratio, key=last_ratio.get) == 1 and max(last_within, key=last_within.get) == 3
    assert (f"{last_ratio[1]:.2f}, against seeds 2 and 3's {last_ratio[2]:.2f} and {last_ratio[3]:.2f}. By the "
            f"search's score, the share within 1.5 times the plan, seed 3 would lead ({last_within[3]:.0%} against "
            f"{last_within[1]:.0%})").replace("%", " %") in flat
    assert max(held, key=held.get) == 1
    assert f"({held[1]:.2f} against {held[2]:.2f} and {held[3]:.2f})" in flat
    six_m = json.loads((policies / "search" / "reach-ppo-6m.json").read_text())["training"]
    assert "--steps 6000000 --seed 3 " in six_m["command"] and six_m["steps"] == 5_996_544


def test_every_committed_policy_s_command_writes_its_own_file():
    # Rerunning a file's command must reproduce that file, never overwrite another policy.
    policies = sorted((REPOSITORY / "models" / "policies").rglob("*.json"))
    commands = {path: json.loads(path.read_text()).get("training", {}).get("command") for path in policies}
    commands = {path: command for path, command in commands.items() if command}
    # the policy, the 6 M policy, the policy's reach head and the policy trained under its veto
    assert len(commands) == 4
    for path, command in commands.items():
        assert command.split(" --out ")[1].split()[0] == str(path.relative_to(REPOSITORY)), path


def test_baselines_18m_runs_quote_their_record():
    from wall_statistics import paired
    record = json.loads((SEARCH / "long_training.json").read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    flat = " ".join(text.split())
    fourteen = {run["seed"]: run for run in record["runs"]}
    eighteen = {run["seed"]: run for run in record["eighteen_m"]}
    assert sorted(eighteen) == [1, 2]

    def row(label, run):
        last, held, static = run["validation"][-1], run["held_out"], run["held_out_static"]
        recent = np.mean([v["mean_length_ratio"] for v in run["validation"][-10:]])
        done = round(static["finished"] * static["climbs"])
        return (f"| {label} | {last['finished']:.0%}, {last['mean_length_ratio']:.2f} | {recent:.2f} "
                f"| {held['finished']:.0%} | {held['mean_length_ratio']:.2f} | {held['within_1_5_plans']:.0%} "
                f"| {static['finished']:.0%} ({done} of {static['climbs']}) |").replace("%", " %")

    def interval(change):
        return bracket(change, "+")

    assert row("1, 14 M (the shipped policy)", fourteen[1]) in text
    shipped = json.loads((REPOSITORY / "models" / "policies" / "reach-ppo.heldout.json").read_text())
    assert fourteen[1]["held_out"]["walls"] == shipped["walls"]
    for seed, run in eighteen.items():
        assert run["command"].replace("18000000", "14000000").replace("-18m", "-14m") == fourteen[seed]["command"]
        assert f"seed {seed} in {run['seconds']:.0f} s" in flat
        if seed != 1:
            assert row(f"{seed}, 14 M", fourteen[seed]) in text
        assert row(f"{seed}, 18 M", run) in text
        walls = [[wall["wall_seed"] for wall in r["held_out"]["walls"]] for r in (run, fourteen[seed])]
        assert walls[0] == walls[1]
        change = run["paired_ratio_18m_minus_14m"]
        assert change == pytest.approx(paired(held_out_ratios(run), held_out_ratios(fourteen[seed])))
        assert f"{interval(change)} {'times the plan for ' if seed == 1 else 'for '}seed {seed} " \
               f"(p = {change['p']:.2f})" in flat
    pooled = record["eighteen_m_pooled"]
    means = [np.mean([held_out_ratios(runs[seed]) for seed in pooled["seeds"]], axis=0)
             for runs in (eighteen, fourteen)]
    assert pooled["paired_ratio_18m_minus_14m"] == pytest.approx(paired(*means))
    assert [pooled["ratio_18m"], pooled["ratio_14m"]] == pytest.approx([float(np.mean(m)) for m in means])
    both = f"{pooled['ratio_18m']:.2f} against {pooled['ratio_14m']:.2f}"
    change = pooled["paired_ratio_18m_minus_14m"]
    assert f"{both} at 14 M: {interval(change)} (p = {change['p']:.2f})" in flat
    lead = " ".join(text[:text.index("## The learnt policy")].split())
    assert f"({both}, paired {interval(change)})" in lead
    lowest = min(eighteen[1]["validation"], key=lambda v: v["mean_length_ratio"])
    assert f"at its lowest, {lowest['mean_length_ratio']:.2f}, at {lowest['steps'] / 1e6:.1f} M steps" in flat
    last = eighteen[2]["validation"][-1]["mean_length_ratio"]
    assert f"2's last validation, {last:.2f}, is below 1.5 and its held-out climbs take " \
           f"{eighteen[2]['held_out']['mean_length_ratio']:.2f} times the plan" in flat


def test_baselines_keep_best_18m_quotes_its_record():
    from wall_statistics import paired
    record = json.loads((SEARCH / "long_training.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    eighteen = {run["seed"]: run for run in record["eighteen_m"]}
    kept = {run["seed"]: run for run in record["keep_best_18m"]}
    assert sorted(kept) == [1, 2]

    def interval(change):
        return f"{bracket(change, '+')} (p = {change['p']:.2f})"

    for seed, run in kept.items():
        last = eighteen[seed]
        command = last["command"].replace(" --out ", " --keep-best --out ").replace(".json", "-best.json")
        assert run["command"] == command
        # The rerun's validations are the first run's: the same trajectory, other weights written.
        assert run["validation_sha256"] == hashlib.sha256(json.dumps(last["validation"]).encode()).hexdigest()
        # --keep-best's rule: most finished, then the lowest ratio, over the run's validations.
        best = max(last["validation"], key=lambda v: (v["finished"], -v["mean_length_ratio"]))
        assert run["kept_validation"] == best and run["kept_steps"] == best["steps"]
        assert [wall["wall_seed"] for wall in run["held_out"]["walls"]] == \
               [wall["wall_seed"] for wall in last["held_out"]["walls"]]
        assert run["paired_ratio_kept_minus_last"] == pytest.approx(paired(held_out_ratios(run), held_out_ratios(last)))
    one, two = kept[1], kept[2]
    assert f"(the same commands, the two side by side: {one['seconds']:.0f} and {two['seconds']:.0f} s)" in flat
    assert (f"{one['kept_validation']['mean_length_ratio']:.2f} at {one['kept_steps'] / 1e6:.1f} M steps for seed 1 "
            f"and {two['kept_validation']['mean_length_ratio']:.2f} at {two['kept_steps'] / 1e6:.1f} M for seed 2, "
            f"where the last weights scored {eighteen[1]['validation'][-1]['mean_length_ratio']:.2f} and "
            f"{eighteen[2]['validation'][-1]['mean_length_ratio']:.2f}") in flat
    assert (f"they climb in {one['held_out']['mean_length_ratio']:.2f} and {two['held_out']['mean_length_ratio']:.2f} "
            f"times the plan, against the last weights' {eighteen[1]['held_out']['mean_length_ratio']:.2f} and "
            f"{eighteen[2]['held_out']['mean_length_ratio']:.2f}: paired "
            f"{interval(one['paired_ratio_kept_minus_last'])} and "
            f"{interval(two['paired_ratio_kept_minus_last'])}") in flat
    pooled = record["keep_best_18m_pooled"]
    means = [np.mean([held_out_ratios(runs[seed]) for seed in pooled["seeds"]], axis=0) for runs in (kept, eighteen)]
    assert pooled["ratio_kept"] == pytest.approx(float(np.mean(means[0])))
    assert pooled["paired_ratio_kept_minus_last"] == pytest.approx(paired(*means))
    assert (f"{np.mean(means[0]):.2f} against {np.mean(means[1]):.2f}, "
            f"{interval(pooled['paired_ratio_kept_minus_last'])}") in flat
    static = [f"{s['finished']:.0%} ({round(s['finished'] * s['climbs'])} of {s['climbs']})".replace("%", " %")
              for s in (one["held_out_static"], two["held_out_static"])]
    assert f"Under the static model they finish {static[0]} and {static[1]}." in flat
    differences = [np.subtract(held_out_ratios(run), held_out_ratios(eighteen[seed])) for seed, run in kept.items()]
    errors = [np.std(d, ddof=1) / np.sqrt(len(d)) for d in differences]
    assert f"standard error of {min(errors):.2f} to {max(errors):.2f} (kept against last" in flat
    gaps = [f"{run['kept_validation']['mean_length_ratio']:.2f} against "
            f"{eighteen[seed]['validation'][-1]['mean_length_ratio']:.2f}" for seed, run in kept.items()]
    assert f"(on validation, {gaps[0]} and {gaps[1]})" in flat
    for verb in ("do", "are"):  # the lead and "Not done"
        assert f"nor {verb} the weights of their best validations ({pooled['ratio_kept']:.2f})" in flat


def test_baselines_300_walls_quote_their_record():
    from wall_statistics import interval, paired, per_wall_mean
    root = REPOSITORY / "models" / "policies"
    record = json.loads((root / "search" / "heldout_300.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    shipped = record["policies"][0]
    assert shipped["policy"] == "models/policies/reach-ppo.json"
    assert [p["seed"] for p in record["policies"]] == [1, 2, 3]
    assert all("--wall-seeds 20000:20299" in p["command"] for p in record["policies"])
    walls = [[wall["wall_seed"] for wall in p["evaluation"]["walls"]] for p in record["policies"]]
    assert walls == [list(range(20000, 20300))] * 3
    # The first 30 of each seed's 300 climbs are its 30-wall climbs, climb for climb.
    thirty = {run["seed"]: run["held_out"]["walls"]
              for run in json.loads((root / "search" / "long_training.json").read_text())["runs"]}
    assert thirty[1] == json.loads((root / "reach-ppo.heldout.json").read_text())["walls"]
    assert all(p["evaluation"]["walls"][:30] == thirty[p["seed"]] for p in record["policies"])

    by_wall = [list(runs) for runs in zip(*[evaluation_climbs(p) for p in record["policies"]])]
    ratios = [c["ratio"] for c in evaluation_climbs(shipped)]
    setting = per_wall_mean(by_wall, "ratio")
    expected = {"shipped_ratio": interval(ratios), "shipped_ratio_minus_1_5": paired(ratios, [1.5] * 300),
                "setting_finished": interval(per_wall_mean(by_wall, "finished")), "setting_ratio": interval(setting),
                "setting_ratio_minus_1_5": paired(setting, [1.5] * 300),
                "setting_ratio_walls_20030_20299": interval(setting[30:]),
                "setting_ratio_walls_20030_20299_minus_1_5": paired(setting[30:], [1.5] * 270)}
    for key, value in expected.items():
        assert record[key] == pytest.approx(value), key

    share, ratio, above = record["setting_finished"], record["setting_ratio"], record["setting_ratio_minus_1_5"]
    alone = record["shipped_ratio_minus_1_5"]
    done = sum(w["finished"] for w in shipped["evaluation"]["walls"])
    finished = percent_bracket(share)
    assert (f"the three seeds finish {finished} of the climbs, in {bracket(ratio)} times the plan, "
            f"{bracket(above)} above 1.5 (p = {above['p']:.1e}); the shipped policy alone finishes {done} of 300, in "
            f"{bracket(record['shipped_ratio'])} times the plan (p = {alone['p']:.3f} against 1.5)") in flat
    new = record["setting_ratio_walls_20030_20299"], record["setting_ratio_walls_20030_20299_minus_1_5"]
    assert f"no earlier analysis used, the seeds take {bracket(new[0])} times the plan (p = {new[1]['p']:.1e})" in flat
    assert (f"the three seeds take {bracket(ratio)} times the plan, above 1.5 (p = {above['p']:.1e}), while "
            f"finishing {share['mean'] * 100:.1f} % of the climbs") in flat
    assert f"On 300 held-out walls the setting takes {bracket(ratio)} times the plan" in flat


def test_baselines_oracle_quotes_its_record():
    from wall_statistics import interval, paired, per_wall_mean
    record = json.loads((SEARCH / "oracle_verdict_300.json").read_text())
    alone = json.loads((SEARCH / "heldout_300.json").read_text())["policies"]
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    told = record["policies"]
    assert [(p["seed"], p["policy"]) for p in told] == [(p["seed"], p["policy"]) for p in alone]
    assert all(p["command"].endswith("--wall-seeds 20000:20299 --oracle verdict --json") for p in told)
    for mine, theirs in zip(told, alone):  # the same walls and plans as the zero-shot climbs
        assert [(w["wall_seed"], w["plan_length"]) for w in mine["evaluation"]["walls"]] == \
            [(w["wall_seed"], w["plan_length"]) for w in theirs["evaluation"]["walls"]]
        assert mine["evaluation"]["oracle"] == "verdict"
        assert sum(w["failed_moves"] for w in mine["evaluation"]["walls"]) == 0  # no move fails

    by_wall = [[list(runs) for runs in zip(*[evaluation_climbs(p) for p in policies])] for policies in (told, alone)]
    ratio_told, ratio_alone = (per_wall_mean(walls, "ratio") for walls in by_wall)
    expected = {"setting_finished": interval(per_wall_mean(by_wall[0], "finished")),
                "setting_ratio": interval(ratio_told),
                "setting_ratio_minus_1_5": paired(ratio_told, [1.5] * 300),
                "setting_ratio_oracle_minus_zero_shot": paired(ratio_told, ratio_alone)}
    for key, value in expected.items():
        assert record[key] == pytest.approx(value), key
    for mine, theirs in zip(told, alone):
        assert mine["ratio_oracle_minus_zero_shot"] == pytest.approx(
            paired([c["ratio"] for c in evaluation_climbs(mine)], [c["ratio"] for c in evaluation_climbs(theirs)]))

    share, ratio, below = record["setting_finished"], record["setting_ratio"], record["setting_ratio_minus_1_5"]
    shorter = record["setting_ratio_oracle_minus_zero_shot"]
    finished = percent_bracket(share)
    gain = negated(shorter)
    assert (f"three seeds then finish {finished} of the climbs, in {bracket(ratio)} times the plan: "
            f"{bracket(negated(below))} "
            f"below 1.5 (p = {below['p']:.2g}), and {bracket(gain)} shorter than their own zero-shot climbs of the "
            f"same walls (paired, p = {shorter['p']:.2g})") in flat
    seeds = [f"{np.mean([c['ratio'] for c in evaluation_climbs(p) if c['ratio'] is not None]):.2f}" for p in told]
    assert (f"Seed by seed: {seeds[0]}, {seeds[1]} and {seeds[2]} (the shipped policy "
            f"{bracket(told[0]['ratio_oracle_minus_zero_shot'])} against its own climbs)") in flat
    six_m, graph = record["six_m_policy_30_walls"]["evaluation"], record["shipped_graph_oracle_30_walls"]["diagnosis"]
    assert six_m["finished"] == 1.0 and six_m["climbs"] == 30
    six_m_alone = json.loads((SEARCH / "reach-ppo-6m.heldout.json").read_text())
    six_m_graph = next(d for d in json.loads((SEARCH / "climb_diagnosis.json").read_text())["diagnoses"]
                       if d["oracle"] == "reach" and d["physics_model"] == "kinematic")
    assert six_m_graph["policy"] == record["six_m_policy_30_walls"]["policy"]
    assert (f"with them the 6 M policy finishes {six_m_graph['finished']} of the {six_m_graph['climbs']} held-out "
            f"walls and fails {six_m_graph['moves']['failed_graph_reaches']} moves the graph reaches (the shipped "
            f"policy {graph['finished']} and {graph['moves']['failed_graph_reaches']}), while with the climb's own "
            f"verdicts the 6 M policy finishes all 30, in {six_m['mean_length_ratio']:.2f} times the plan "
            f"({six_m_alone['mean_length_ratio']:.2f} alone)") in flat
    assert f"climb the 300 walls in {bracket(ratio)} times the plan, {bracket(gain)} shorter than alone" in flat
    assert f"the 14 M setting climbs the 300 held-out walls in {bracket(ratio)} times the plan" in flat
    must_go = json.loads((SEARCH / "heldout_300.json").read_text())["setting_ratio_minus_1_5"]["mean"]
    assert (f"the 14 M setting's climbs are {gain['mean']:.2f} times the plan shorter, more than the "
            f"{must_go:.2f} that must go") in flat


def test_baselines_reach_pilots_quote_their_record():
    record = json.loads((SEARCH / "reach_pilots.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    labels, fitted, choice = record["labels"], record["classifier"], record["at_the_policy_choice"]
    assert (f"{labels['states']:,} states, {labels['moves']:,} moves, "
            f"{labels['reaching_moves'] / labels['moves']:.0%} of them reach").replace("%", " %") in flat
    assert (f"right on {fitted['accuracy']:.1%} of the moves of the last tenth of the walls "
            f"({fitted['accuracy_with_half_the_walls']:.1%} with half the walls").replace("%", " %") in flat
    assert choice["failing_passed"] + choice["reaching_rejected"] == pytest.approx(
        (1 - choice["classifier_right"]) * choice["states"], abs=0.5)
    assert (f"it is right on {choice['classifier_right']:.0%}: it passes {choice['failing_passed']} of the "
            f"{choice['failing_choices']} choices that fail and rejects {choice['reaching_rejected']} of the "
            f"{choice['states'] - choice['failing_choices']} that reach").replace("%", " %") in flat
    assert f"the policy's choice reaches {choice['choice_reaches']:.0%} of the time".replace("%", " %") in flat
    veto = {row["p"]: f"{row['mean_length_ratio']:.2f}" for row in record["veto_on_validation_walls_10000_10299"]}
    assert (f"the climbs take {veto[0.0]} times the plan with no veto, {veto[0.1]} at p = 0.1 and 0.2, {veto[0.3]} "
            f"at 0.3 and {veto[0.5]} at 0.5") in flat
    assert veto[0.1] == veto[0.2]
    distilled = {f"{row['validation_mean_length_ratio']:.2f}" for row in record["distillation"]}
    assert len(distilled) == 1 and f"take {distilled.pop()} times the plan on those validation walls" in flat
    standing = record["standing_guess"]
    assert (f"({standing['moves']:,}) is right on {standing['accuracy']:.1%}, against "
            f"{fitted['accuracy_with_half_the_walls']:.1%}; but {1 - standing['reaching_share']:.0%} of the moves fail "
            f"there, against {1 - fitted['half_the_walls_reaching_share']:.0%}").replace("%", " %") in flat
    assert (f"wall 20000's takes {standing['plan_length_wall_20000']} moves, against "
            f"{standing['default_plan_length_wall_20000']}") in flat
    focused = record["focused_on_the_policy_choice"]
    assert (f"right on {focused['right_at_the_choice']:.1%} of those choices (it passes {focused['failing_passed']} of "
            f"the {choice['failing_choices']} that fail and rejects {focused['reaching_rejected']} of those that "
            f"reach)").replace("%", " %") in flat
    vetoed = {row["p"]: row for row in focused["veto_on_validation_walls_10000_10299"]}
    plain = {row["p"]: row for row in record["veto_on_validation_walls_10000_10299"]}[0.0]
    assert (f"As a veto: {vetoed[0.1]['mean_length_ratio']:.2f} at p = 0.1, {vetoed[0.2]['mean_length_ratio']:.2f} "
            f"at 0.2, but with {vetoed[0.2]['finished']:.0%} of the climbs finished and more failed moves than without "
            f"it ({vetoed[0.2]['failed_moves']} against {plain['failed_moves']}), "
            f"{vetoed[0.3]['mean_length_ratio']:.2f} at 0.3").replace("%", " %") in flat
    soft = [row["mean_length_ratio"] for key in ("classifier", "focused")
            for row in record["soft_on_validation_walls_10000_10299"][key]]
    assert f"either classifier gives {min(soft):.2f} to {max(soft):.2f}" in flat
    fine = {row["reward_unreachable"]: row for row in record["failure_penalty_fine_tunes"]["runs"]}
    assert (f"the paper's -1000 give {fine[-1000]['mean_length_ratio']:.2f} on those validation walls "
            f"({fine[-1000]['failed_moves']} failed moves, unfinished climbs included), at -20000 "
            f"{fine[-20000]['mean_length_ratio']:.2f} ({fine[-20000]['failed_moves']}), at -5000 "
            f"{fine[-5000]['mean_length_ratio']:.2f} ({fine[-5000]['failed_moves']}) and at -1 "
            f"{fine[-1]['mean_length_ratio']:.2f} ({fine[-1]['failed_moves']})") in flat
    noisy = {row["q"]: row["mean_length_ratio"] for row in record["noisy_oracle"]["runs"]}
    middle = [noisy[q] for q in (0.95, 0.97, 0.98)]
    assert (f"where it climbs in {plain['mean_length_ratio']:.2f} times the plan alone and {noisy[1.0]:.2f} with the "
            f"oracle) gives {min(middle):.2f} to {max(middle):.2f} at q = 0.95 to 0.98, {noisy[0.9]:.2f} at 0.9 and "
            f"{noisy[0.85]:.2f} at 0.85") in flat
    assert f"the pilots' classifiers were right on {fitted['accuracy']:.0%}".replace("%", " %") in flat
    twice = fitted["twice_the_walls"]
    assert twice["moves"] > 1.9 * labels["moves"]
    accuracies = [fitted["accuracy_with_half_the_walls"], fitted["accuracy"], twice["accuracy"]]
    assert (f"{twice['moves']:,} moves) make it right on {twice['accuracy']:.1%}: about two points a doubling "
            f"({accuracies[0]:.1%}, {accuracies[1]:.1%}, {accuracies[2]:.1%})").replace("%", " %") in flat
    assert all(0.015 < b - a < 0.03 for a, b in zip(accuracies, accuracies[1:]))  # "about two points a doubling"
    later = {row["p"]: row for row in twice["veto_on_validation_walls_10000_10299"]}
    assert (f"As a veto it then gives {later[0.1]['mean_length_ratio']:.2f} at p = 0.1, "
            f"{later[0.2]['mean_length_ratio']:.2f} and {later[0.3]['mean_length_ratio']:.2f} at 0.2 and 0.3, "
            f"{later[0.5]['mean_length_ratio']:.2f} at 0.5, and fewer climbs finish the higher p is "
            f"({later[0.1]['finished']:.0%} to {later[0.5]['finished']:.0%})").replace("%", " %") in flat
    longer = fitted["longer_training"]
    at_choice = longer["at_the_policy_choice_6000_walls"]
    assert f"{longer['accuracy_24_epochs_6000_walls']:.3f}" == f"{longer['accuracy_64_epochs_3000_walls']:.3f}"
    assert (f"and 64 on the 3000 each make it right on {longer['accuracy_24_epochs_6000_walls']:.1%}, and on "
            f"{at_choice['classifier_right']:.1%} of the policy's own choices on the last tenth of the walls "
            f"(it passes "
            f"{at_choice['failing_passed']} of the {at_choice['failing_choices']} that fail and rejects "
            f"{at_choice['reaching_rejected']} of those that reach)").replace("%", " %") in flat
    vetoes = {row["p"]: row for row in longer["veto_on_validation_walls_10000_10299"]}
    assert (f"As a veto it gives {vetoes[0.1]['mean_length_ratio']:.2f} at p = 0.1, "
            f"{vetoes[0.2]['mean_length_ratio']:.2f} at 0.2 and 0.3 ({vetoes[0.2]['finished']:.0%} and "
            f"{vetoes[0.3]['finished']:.0%} of the climbs finished) and {vetoes[0.5]['mean_length_ratio']:.2f} at "
            f"0.5").replace("%", " %") in flat
    assert f"{vetoes[0.2]['mean_length_ratio']:.2f}" == f"{vetoes[0.3]['mean_length_ratio']:.2f}"

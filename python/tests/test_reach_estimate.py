"""examples/python/reach_estimate.py: its labels are the climb's own verdicts, its classifier
learns a rule it is shown and reads back what it wrote, its veto passes to the climbs the
moves it allows (and, allowing none, leaves the policy its own choice), and a bad head or
label file is one line and exit code 2."""

import importlib.util
import json
import pathlib
import sys

import numpy as np
import pytest

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"],
    "the estimate needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and Debian's python3-torch",
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = REPOSITORY / "examples" / "python"
SHIPPED = REPOSITORY / "models" / "policies" / "reach-ppo.json"
sys.path.insert(0, str(EXAMPLES))  # the script imports its neighbours, as when run from its folder
_spec = importlib.util.spec_from_file_location("reach_estimate", EXAMPLES / "reach_estimate.py")
estimate = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(estimate)
baseline = estimate.baseline


@pytest.fixture(scope="module")
def policy():
    return baseline.load_policy(SHIPPED)[0]


def test_the_labels_of_the_policy_choices_are_what_its_greedy_climb_met(policy):
    # With no random moves the labelled climb is the greedy climb: its chosen moves, in
    # order, are the climb's actions, and their labels its outcomes.
    config = baseline.climbing_config("kinematic")
    for wall_seed in (20000, 20001):
        rows, reached, chosen = estimate.label_wall(policy, wall_seed, config, 0.0, np.random.default_rng(1))
        finished, taken, failed = baseline.climb(policy, crux_env(wall_seed, config))
        assert taken <= estimate.LABEL_CAP, "the climb fits in the label cap"
        assert chosen.sum() == taken and (chosen & ~reached).sum() == failed, f"wall {wall_seed}"
        assert rows.shape == (len(reached), estimate.ROW_SIZE) and 0 < reached.mean() < 1


def test_the_labeller_verdicts_are_the_verdict_oracle_ones():
    seed = 20241  # the random climb's draws; printed by the assertion's message
    rng = np.random.default_rng(seed)
    config = baseline.climbing_config("kinematic")
    wall = baseline.crux.Wall.random(3)
    env = crux_env(3, config)
    obs, info = env.reset()
    history, holds_taken, both = [], [], []
    for _ in range(30):  # a random climb, to meet moves that fail and moves that reach
        mask = obs["candidate_mask"][None] > 0.5
        offered = np.flatnonzero(mask[0])
        both.append((baseline.verdict_mask(3, config, history, mask)[0, offered].tolist(),
                     estimate.verdicts(wall, config, holds_taken, info["candidate_holds"][offered]).tolist()))
        action = int(rng.choice(offered))
        history.append(action)
        holds_taken.append(int(info["candidate_holds"][action]))
        obs, _, terminated, _, info = env.step(action)
        if terminated:
            break
    assert all(oracle == labeller for oracle, labeller in both), f"seed {seed}"
    assert {verdict for oracle, _ in both for verdict in oracle} == {True, False}, f"seed {seed}"


def crux_env(wall_seed, config):
    return baseline.crux.gym.ClimbEnv(wall_seed, baseline.OBSERVATION, config=config)


def test_random_moves_change_the_climb_and_the_same_seed_the_same_labels(policy):
    config = baseline.climbing_config("kinematic")
    runs = [estimate.label_wall(policy, 20000, config, share, np.random.default_rng(seed))
            for share, seed in ((0.5, 7), (0.5, 7), (0.0, 7))]
    for a, b in zip(runs[0], runs[1]):
        np.testing.assert_array_equal(a, b)
    assert len(runs[0][1]) != len(runs[2][1]) or (runs[0][0] != runs[2][0]).any()


def synthetic_rows(count, seed):
    """Rows whose move reaches when the slot's first reach feature is below a bound: a rule to learn."""
    rng = np.random.default_rng(seed)
    rows = rng.normal(size=(count, estimate.ROW_SIZE)).astype(np.float32)
    return rows, rows[:, baseline.STATE_SIZE + 3] < 0.3


def test_the_head_learns_a_rule_deterministically_and_reads_back_what_it_wrote(tmp_path):
    rows, reached = synthetic_rows(6000, 11)
    heads = [estimate.fit_head(rows, reached, 16, 4, seed=3, max_span=2.8, batch=256, lr=1e-2) for _ in range(2)]
    test_rows, test_reached = synthetic_rows(2000, 12)
    accuracy = ((heads[0].logits(test_rows) > 0) == test_reached).mean()
    assert accuracy > 0.95, f"seed 11: accuracy {accuracy}"
    for a, b in zip(heads[0].net.parameters(), heads[1].net.parameters()):
        assert torch.equal(a, b)
    estimate.save_head(heads[0], tmp_path / "head.json", {"seed": 3})
    loaded, record = estimate.load_head(tmp_path / "head.json")
    np.testing.assert_array_equal(loaded.logits(test_rows), heads[0].logits(test_rows))
    assert record["max_span"] == 2.8 and record["training"] == {"seed": 3}


def test_the_report_counts_by_hand():
    head = estimate.ReachHead(4, np.zeros(estimate.ROW_SIZE), np.ones(estimate.ROW_SIZE), 2.8)
    head.logits = lambda rows: np.array([2.0, -1.0, 0.5, -3.0])
    reached = np.array([True, True, False, False])
    chosen = np.array([True, True, True, False])
    report = estimate.report(head, np.zeros((4, estimate.ROW_SIZE), np.float32), reached, chosen)
    assert report["accuracy"] == 0.5 and report["auc"] == 0.75 and report["reaching_share"] == 0.5
    assert report["at_the_policy_choice"] == {"moves": 3, "accuracy": 1 / 3, "choice_reaches": 2 / 3,
                                              "failing_passed": 1, "reaching_rejected": 1}


def test_the_veto_passes_the_moves_it_allows_and_allowing_none_leaves_the_policy_its_choice(policy):
    plans = baseline.plan_lengths([20000])
    alone = baseline.evaluate(policy, [20000], plans=plans)
    assert baseline.evaluate(policy, [20000], plans=plans, veto=lambda state, slots: np.zeros(slots.shape[:2], bool)) \
        == alone
    head = estimate.ReachHead(4, np.zeros(estimate.ROW_SIZE), np.ones(estimate.ROW_SIZE), 2.8)
    slots = np.zeros((1, 5, baseline.SLOT_SIZE), np.float32)
    head.logits = lambda rows: np.array([-2.0, -0.5, 0.0, 0.5, 2.0])  # p: 0.12, 0.38, 0.5, 0.62, 0.88
    state = np.zeros((1, baseline.STATE_SIZE), np.float32)
    assert head.veto(0.5)(state, slots).tolist() == [[False, False, True, True, True]]
    assert head.veto(0.0)(state, slots).all() and head.veto(0.8)(state, slots).sum() == 1
    # A veto that allows only the last offered slot: the climb takes it at every step.
    def last_only(state, slots):
        offered = np.flatnonzero(np.abs(slots[0]).sum(axis=1) > 0)  # padded slots are zeros
        return np.arange(slots.shape[1])[None] == offered[-1]

    env = Recording(crux_env(20000, baseline.climbing_config("kinematic")))
    baseline.climb(policy, env, cap=10, allowed=baseline.allowed_moves(20000, None, False, last_only))
    assert len(env.steps) == 10 and all(action == offered[-1] for action, offered in env.steps), env.steps


class Recording:
    """An environment that records each action and the slots offered when it was taken."""

    def __init__(self, env):
        self.env, self.steps = env, []

    def reset(self):
        self.obs, info = self.env.reset()
        return self.obs, info

    def step(self, action):
        self.steps.append((action, np.flatnonzero(self.obs["candidate_mask"] > 0.5)))
        self.obs, *rest = self.env.step(action)
        return (self.obs, *rest)


def run(*arguments, capsys):
    with pytest.raises(SystemExit) as exit_:
        estimate.main(list(arguments))
    return exit_.value.code, capsys.readouterr()


@pytest.mark.parametrize("content, problem", [
    (None, "cannot read the reach head"),
    ("{not json", "not a reach head (not JSON"),
    ('{"format": "crux-reach-head", "version": 1, "observation": "numeric"}', "a reach head for observation 'numeric'"),
    ('{"format": "crux-reach-head", "version": 1, "observation": "reach", "max_span": 2.8, "input_mean": [0], '
     '"input_scale": [1], "layers": [{"weight": [[1]], "bias": [0]}]}', "input_mean and input_scale must be 66"),
])
def test_a_bad_head_file_is_one_line_and_exit_code_2(tmp_path, capsys, content, problem):
    path = tmp_path / "head.json"
    if content is not None:
        path.write_text(content)
    code, out = run("evaluate", "--policy", str(SHIPPED), "--head", str(path), "--veto", "0.2", "--wall-seeds", "1:2",
                    capsys=capsys)
    assert code == 2 and out.out == "" and out.err.count("\n") == 1, out.err
    assert out.err.startswith(f"reach_estimate.py: --head: {path}: ") and problem in out.err


@pytest.mark.parametrize("arguments, named", [
    (["--veto", "1"], "--veto"), (["--veto", "-0.1"], "--veto"), (["--wall-seeds", "5:2"], "--wall-seeds")])
def test_bad_arguments_are_one_line_and_exit_code_2(tmp_path, capsys, arguments, named):
    given = {"--veto": "0.2", "--wall-seeds": "1:2", "--policy": str(SHIPPED), "--head": str(tmp_path / "h.json")}
    given.update(dict(zip(arguments[::2], arguments[1::2])))
    code, out = run("evaluate", *[part for item in given.items() for part in item], capsys=capsys)
    assert code == 2 and out.err.count("\n") == 1 and named in out.err, out.err


def test_a_file_that_is_not_labels_is_one_line_and_exit_code_2(tmp_path, capsys):
    bad = tmp_path / "labels.npz"
    bad.write_text("not a zip")
    code, out = run("fit", "--labels", str(bad), "--out", str(tmp_path / "head.json"), capsys=capsys)
    assert code == 2 and out.err.count("\n") == 1 and out.err.startswith(f"reach_estimate.py: --labels: {bad}: ")
    assert not (tmp_path / "head.json").exists()
    np.savez(tmp_path / "narrow.npz", rows=np.zeros((2, 3)), reached=np.zeros(2, bool), chosen=np.zeros(2, bool),
             wall=np.zeros(2, np.int64), policy="p.json")
    code, out = run("fit", "--labels", str(tmp_path / "narrow.npz"), "--out", str(tmp_path / "head.json"),
                    capsys=capsys)
    assert code == 2 and out.err.count("\n") == 1 and "rows of (3,) numbers, not 66" in out.err


def labels_file(path, walls, policy="p.json", rows=None):
    count = len(walls)
    np.savez(path, rows=np.zeros((count, estimate.ROW_SIZE), np.float32) if rows is None else rows,
             reached=np.arange(count) % 2 == 0, chosen=np.ones(count, bool), wall=np.asarray(walls, np.int64),
             policy=policy)
    return path


@pytest.mark.parametrize("make, argument, problem", [
    (lambda d: np.save(d / "l.npy", np.zeros(3)) or d / "l.npy", "--labels", "not a label file"),
    (lambda d: (d / "l.npz").write_bytes(b"PK\x03\x04 truncated") or d / "l.npz", "--labels", "not a label file"),
    (lambda d: labels_file(d / "l.npz", [1, 2], rows=np.zeros((3, 66), np.float32)), "--labels",
     "its arrays differ in length"),
    (lambda d: labels_file(d / "l.npz", [1]), "--held-out-share", "leaves no wall to train on"),
])
def test_labels_that_cannot_be_fitted_are_one_line_and_exit_code_2(tmp_path, capsys, make, argument, problem):
    path = make(tmp_path)
    code, out = run("fit", "--labels", str(path), "--out", str(tmp_path / "head.json"), capsys=capsys)
    assert code == 2 and out.err.count("\n") == 1 and out.err.startswith(f"reach_estimate.py: {argument}: ")
    assert problem in out.err, out.err
    assert not (tmp_path / "head.json").exists()


def test_label_files_of_two_policies_are_refused(tmp_path, capsys):
    files = [labels_file(tmp_path / f"{name}.npz", [1, 2], policy=name) for name in ("a.json", "b.json")]
    code, out = run("fit", "--labels", *map(str, files), "--out", str(tmp_path / "head.json"), capsys=capsys)
    assert code == 2 and "files of different policies (a.json, b.json)" in out.err


def test_evaluate_refuses_the_oracle_and_a_veto_together(policy):
    with pytest.raises(ValueError, match="not both"):
        baseline.evaluate(policy, [20000], oracle=True, veto=lambda state, slots: np.ones(slots.shape[:2], bool))


def test_label_and_fit_write_files_fit_and_evaluate_read(tmp_path, capsys):
    labels = tmp_path / "labels.npz"
    # Wall 3007399's start cannot be taken (the IK finds no posture on its four holds): skipped.
    estimate.main(["label", "--policy", str(SHIPPED), "--wall-seeds", "3007397:3007400", "--out", str(labels)])
    written = json.loads(capsys.readouterr().out)
    assert (written["walls"], written["skipped_walls"]) == (3, 1) and written["moves"] > 100
    assert not list(tmp_path.glob("*.partial*"))
    head = tmp_path / "head.json"
    estimate.main(["fit", "--labels", str(labels), "--out", str(head), "--epochs", "1", "--hidden", "8",
                   "--held-out-share", "0.3"])
    fitted = json.loads(capsys.readouterr().out)
    assert fitted["held_out_walls"] == [3007400, 3007400] and fitted["walls"] == 3
    assert fitted["held_out"]["moves"] + fitted["training_moves"] == written["moves"]
    training = estimate.load_head(head)[1]["training"]
    assert training["command"].startswith("examples/python/reach_estimate.py fit")
    assert training["labelled_by"] == str(SHIPPED)
    estimate.main(["evaluate", "--policy", str(SHIPPED), "--head", str(head), "--veto", "0.3", "0.6",
                   "--wall-seeds", "20000:20001", "--json"])
    results = json.loads(capsys.readouterr().out)
    assert [r["veto"] for r in results] == [0.3, 0.6] and all(r["climbs"] == 2 for r in results)
    assert all(r["failed_moves"] == sum(w["failed_moves"] for w in r["walls"]) for r in results)


SEARCH = REPOSITORY / "models" / "policies" / "search"
HEAD = REPOSITORY / "models" / "policies" / "reach-ppo.reach-head.json"
SHORT = ["--steps", "512", "--envs", "8", "--rollout", "32", "--minibatch", "256", "--train-walls", "4",
         "--validation-walls", "0", "--validate-every", "0", "--episode-steps", "60", "--lr", "3e-3"]


def short_training(tmp_path, veto):
    """Two updates of PPO from a small random policy, with the veto as train takes it: the
    starting and the trained policies."""
    baseline.deterministic(3)
    start = tmp_path / "start.json"
    baseline.save_policy(baseline.SlotPolicy(16, baseline.configured_max_span()), start, {"seed": 3})
    args = baseline.parser().parse_args(["train", "--out", str(tmp_path / "x.json"), "--init-policy", str(start),
                                         "--hidden", "16", *SHORT])
    baseline.training_walls(args, baseline.parser())
    args.command = "train"
    return baseline.load_policy(start)[0], baseline.train(args, veto=veto)[0]


def test_training_samples_and_learns_only_among_the_moves_the_veto_passes(tmp_path):
    seen = []

    def last_offered(state, slots, mask):  # a gap before it: the update must not pad it away
        seen.append(mask.shape)
        return mask & (np.cumsum(mask, axis=1) == mask.sum(axis=1, keepdims=True))

    start, tuned = short_training(tmp_path, last_offered)
    assert seen and all(shape == (8, baseline.MAX_CANDIDATES) for shape in seen)
    # One move to choose from has probability 1 whatever the weights: no gradient reaches
    # the slot network (rollouts sampled, or updates learnt, among all offered moves would
    # move it), while the value network learns.
    assert all(torch.equal(a, b) for a, b in zip(start.slot_net.parameters(), tuned.slot_net.parameters()))
    assert not all(torch.equal(a, b) for a, b in zip(start.value_net.parameters(), tuned.value_net.parameters()))
    # A veto that passes nothing leaves every state its offered moves: the run without one.
    _, unvetoed = short_training(tmp_path, None)
    _, none_passed = short_training(tmp_path, lambda state, slots, mask: np.zeros_like(mask))
    assert all(torch.equal(a, b) for a, b in zip(unvetoed.parameters(), none_passed.parameters()))
    assert not all(torch.equal(a, b) for a, b in zip(start.slot_net.parameters(), unvetoed.slot_net.parameters()))


def test_the_training_veto_scores_the_offered_slots_as_evaluate_s_veto_does(policy):
    head = estimate.load_head(HEAD)[0]
    env = crux_env(20000, baseline.climbing_config("kinematic"))
    obs, _ = env.reset()
    rng = np.random.default_rng(5)
    states = []  # the states of 30 random moves, a batch as the rollouts' environments give
    for _ in range(30):
        states.append(baseline.single_features(obs, policy.max_span))
        obs, *_ = env.step(int(rng.choice(np.flatnonzero(obs["candidate_mask"] > 0.5))))
    state, slots, mask = (np.concatenate(parts) for parts in zip(*states))
    for threshold in (0.1, 0.5, 0.9):
        batch = head.training_veto(threshold)(state, slots, mask)
        one_by_one = np.concatenate([head.veto(threshold)(*single[:2]) & single[2] for single in states])
        assert (batch == one_by_one).all() and not (batch & ~mask).any(), threshold
        assert 0 < batch.sum() < mask.sum(), (threshold, batch.sum(), mask.sum())


def test_train_writes_a_policy_that_names_its_veto_and_refuses_a_bad_head(tmp_path, capsys):
    out = tmp_path / "tuned.json"
    estimate.main(["train", "--init-policy", str(SHIPPED), "--head", str(HEAD), "--veto", "0.5", "--out", str(out),
                   *SHORT, "--hidden", "128"])
    training = json.loads(out.read_text())["training"]
    assert training["veto"] == {"head": str(HEAD), "threshold": 0.5}
    assert training["command"].startswith("examples/python/reach_estimate.py train --init-policy")
    assert baseline.load_policy(out)[0].hidden == 128 and json.loads(capsys.readouterr().out)["steps"] == 512
    narrow = tmp_path / "narrow.json"
    narrow.write_text(HEAD.read_text().replace('"max_span": 2.8', '"max_span": 2.5', 1))
    for option, policy, head, problem in (
            ("--head", SHIPPED, tmp_path / "missing.json", "cannot read the reach head"),
            ("--head", SHIPPED, narrow, "fitted with filter.max_span = 2.5 m"),
            ("--init-policy", tmp_path / "missing.json", HEAD, "cannot read the policy file"),
            ("--physics-model", SHIPPED, HEAD, "learnt the kinematic model's verdicts")):
        model = ["--physics-model", "static"] if option == "--physics-model" else []
        code, printed = run("train", "--init-policy", str(policy), "--head", str(head), "--veto", "0.5",
                            "--out", str(tmp_path / "x.json"), *SHORT, *model, capsys=capsys)
        assert code == 2 and printed.err.count("\n") == 1 and problem in printed.err, printed.err
        assert printed.err.startswith(f"reach_estimate.py: {option}: ") and not (tmp_path / "x.json").exists()


def test_train_validates_under_the_veto_it_trains_with(tmp_path, monkeypatch, capsys):
    vetoes = []

    def recording_evaluate(policy, wall_seeds, physics_model="kinematic", plans=None, veto=None):
        vetoes.append(veto)
        return {"finished": 1.0, "mean_length": 10.0, "mean_length_ratio": 1.2, "within_1_5_plans": 1.0}

    monkeypatch.setattr(baseline, "evaluate", recording_evaluate)
    monkeypatch.setattr(baseline, "plan_lengths", lambda walls, physics_model="kinematic": {})
    head = estimate.load_head(HEAD)[0]
    monkeypatch.setattr(estimate, "load_head", lambda path: (head, {}))
    threshold = []
    real_veto = estimate.ReachHead.veto
    monkeypatch.setattr(estimate.ReachHead, "veto", lambda self, p: threshold.append(p) or real_veto(self, p))
    estimate.main(["train", "--init-policy", str(SHIPPED), "--head", str(HEAD), "--veto", "0.4",
                   "--out", str(tmp_path / "v.json"), *SHORT, "--hidden", "128", "--validation-walls", "1",
                   "--validate-every", "1"])
    capsys.readouterr()
    assert len(vetoes) == 2 and all(callable(veto) for veto in vetoes) and threshold == [0.4]


def test_the_shipped_head_climbs_its_record_s_first_held_out_wall(policy):
    record = json.loads((SEARCH / "reach_estimate.json").read_text())["held_out_walls_20000_20299"]
    head, file = estimate.load_head(HEAD)
    assert file["training"]["held_out"] == json.loads((SEARCH / "reach_estimate.json").read_text())["fits"][
        "28k_walls"]["held_out"]
    assert "--out models/policies/reach-ppo.reach-head.json" in file["training"]["command"]
    plans = baseline.plan_lengths([20000])
    climbed = baseline.evaluate(policy, [20000], plans=plans, veto=head.veto(record["veto"]))["walls"]
    assert climbed == record["evaluation"]["walls"][:1]


def length_ratios(climbs, plans):
    """Each climb's length over its wall's plan, None when it did not finish (or has no plan)."""
    return [c["length"] / plan if c["finished"] and plan else None for c, plan in zip(climbs, plans)]


def finished_shares(climbs):
    return [float(c["finished"]) for c in climbs]


def bracket(c, digits=2, sign=""):
    return f"{c['mean']:{sign}.{digits}f} [{c['low']:.{digits}f}, {c['high']:.{digits}f}]"


def listed(rows):
    """Validation vetoes' ratios as the docs list them: 1.50, 1.49, 1.48 and 1.51."""
    ratios = [f"{row['mean_length_ratio']:.2f}" for row in rows]
    return ", ".join(ratios[:-1]) + f" and {ratios[-1]}"


def test_baselines_reach_estimate_quotes_its_record():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    labels = record["labels"]
    assert sum(run["moves"] for run in labels["runs"]) == labels["moves"] and len(labels["runs"]) == 8
    assert (f"{labels['walls']:,} walls, {labels['moves']:,} moves, {labels['reaching_share']:.0%} of them reach"
            ).replace("%", " %") in flat
    assert f"({labels['skipped_walls']} walls skipped" in flat
    fits = record["fits"]
    assert labels["walls"] == fits["28k_walls"]["walls"]
    for name, moves in (("14k_walls", "4,038,592 training moves"), ("28k_walls", "8,109,496 training moves")):
        fit, held = fits[name], fits[name]["held_out"]
        assert f"{fit['training_moves']:,} training moves" == moves and moves in flat
        choice = held["at_the_policy_choice"]
        assert (f"right on {held['accuracy']:.1%}" in flat.replace(" %", "%") and f"(AUC {held['auc']:.3f})" in flat)
        assert (f"on {choice['accuracy']:.1%} of the policy's own choices (it passes {choice['failing_passed']}"
                ).replace("%", " %") in flat
        assert f"rejects {choice['reaching_rejected']}" in flat
    first, both = (record["veto_on_validation_walls_10000_10299"][name] for name in ("14k_walls", "28k_walls"))
    assert f"Its veto gives {listed(first)} at p = 0.1, 0.2, 0.3 and 0.5" in flat
    assert f"Its veto gives {listed(both)} at p = 0.2, 0.3, 0.5 and 0.7" in flat
    finished = sorted(row["finished"] for row in both)
    failed = sorted(row["failed_moves"] for row in both)
    assert (f"finishing {finished[-1]:.0%} to {finished[0]:.0%} of the climbs and failing {failed[0]} to {failed[-1]} "
            f"moves").replace("%", " %") in flat
    # The rule: the lowest ratio among the vetoes whose climbs finish at least 95 %.
    chosen = min((row for row in both if row["finished"] >= 0.95), key=lambda row: row["mean_length_ratio"])
    held = record["held_out_walls_20000_20299"]
    assert held["veto"] == chosen["veto"] and f"p = {chosen['veto']}, the lowest ratio among the vetoes" in flat
    walls = held["evaluation"]["walls"]
    zero = json.loads((SEARCH / "heldout_300.json").read_text())["policies"][0]["evaluation"]["walls"]
    oracle = json.loads((SEARCH / "oracle_verdict_300.json").read_text())["policies"][0]["evaluation"]["walls"]
    assert [w["wall_seed"] for w in walls] == [w["wall_seed"] for w in zero] == list(range(20000, 20300))

    def ratios_of(climbs):
        return length_ratios(climbs, [w["plan_length"] for w in climbs])

    mine = ratios_of(walls)
    assert interval(mine) == held["ratio"] and paired(mine, ratios_of(zero)) == held["ratio_minus_zero_shot"]
    assert paired(mine, [1.5] * 300) == held["ratio_minus_1_5"]
    assert paired(mine, ratios_of(oracle)) == held["ratio_minus_oracle"]
    share = held["finished"]
    assert (f"finishes {share['mean'] * 100:.1f} % [{share['low'] * 100:.1f}, {share['high'] * 100:.1f}] of the "
            f"climbs, in {bracket(held['ratio'])} times the plan") in flat
    assert f"That is {bracket(held['ratio_minus_1_5'])} against 1.5 (p = {held['ratio_minus_1_5']['p']:.2f})" in flat
    shorter = held["ratio_minus_zero_shot"]
    assert (f"it is {-shorter['mean']:.2f} [{-shorter['high']:.2f}, {-shorter['low']:.2f}] shorter than the policy "
            f"alone ({held['zero_shot_ratio']['mean']:.2f}, p = {shorter['p']:.1e})") in flat
    longer = held["ratio_minus_oracle"]
    assert (f"{bracket(longer)} longer than with the verdict oracle ({held['oracle_ratio']['mean']:.2f}, "
            f"p = {longer['p']:.1e})") in flat
    assert (f"Its climbs fail {held['failed_moves']['veto']} moves, against {held['failed_moves']['zero_shot']} alone"
            ) in flat
    thirty = held["first_30_walls"]
    assert thirty["finished"] == 1 and f"it finishes all 30, in {bracket(thirty['ratio'])} times the plan" in flat
    # The lead and "Not done" quote the held-out climbs too.
    assert f"brings the shipped policy's zero-shot climbs of the 300 walls to {bracket(held['ratio'])}" in flat
    assert (f"{-shorter['mean']:.2f} [{-shorter['high']:.2f}, {-shorter['low']:.2f}] shorter than alone, below 1.5 in "
            f"the mean but not significantly (p = {held['ratio_minus_1_5']['p']:.2f}") in flat
    pilot_record = json.loads((SEARCH / "reach_pilots.json").read_text())
    pilots = pilot_record["classifier"]
    trend = [pilots["accuracy"], pilots["twice_the_walls"]["accuracy"],
             pilots["longer_training"]["accuracy_24_epochs_6000_walls"], fits["14k_walls"]["held_out"]["accuracy"],
             fits["28k_walls"]["held_out"]["accuracy"], fits["56k_walls"]["held_out"]["accuracy"]]
    best = [min(row["mean_length_ratio"] for row in rows) for rows in (
        pilot_record["veto_on_validation_walls_10000_10299"],
        pilots["twice_the_walls"]["veto_on_validation_walls_10000_10299"],
        pilots["longer_training"]["veto_on_validation_walls_10000_10299"], first, both,
        record["veto_on_validation_walls_10000_10299"]["56k_walls"])]
    assert (", ".join(f"{b:.2f}" for b in best[:-1]) + f" and {best[-1]:.2f} on the validation walls at "
            + ", ".join(f"{a:.1%}" for a in trend[:-1]) + f" and {trend[-1]:.1%}").replace("%", " %") in flat


def test_baselines_quotes_the_1500_held_out_walls():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    wide = record["held_out_walls_20000_21499"]
    walls = wide["walls"]
    assert [w["wall_seed"] for w in walls] == list(range(20000, 21500))
    assert [{"wall_seed": w["wall_seed"], "plan_length": w["plan_length"], **w["veto"]} for w in walls[:300]] \
        == record["held_out_walls_20000_20299"]["evaluation"]["walls"]

    def ratios(method):
        return length_ratios([w[method] for w in walls], [w["plan_length"] for w in walls])

    def finished(method):
        return finished_shares(w[method] for w in walls)

    mine = ratios("veto")
    assert interval(mine) == wide["ratio"] and paired(mine, [1.5] * 1500) == wide["ratio_minus_1_5"]
    assert paired(mine, ratios("alone")) == wide["ratio_minus_alone"]
    assert paired(finished("veto"), finished("alone")) == wide["finished_minus_alone"]

    gap, shorter, fewer = wide["ratio_minus_1_5"], wide["ratio_minus_alone"], wide["finished_minus_alone"]
    assert (f"the veto's climbs take {three(wide['ratio'])} times the plan: {three(gap)} against 1.5 "
            f"(p = {gap['p']:.2f}). That is {three(shorter, -1)} shorter than the policy alone "
            f"({wide['ratio_alone']['mean']:.3f}, p = {shorter['p']:.1e}), with {wide['failed_moves']['veto']} failed "
            f"moves against {wide['failed_moves']['alone']}") in flat
    share = wide["finished"]
    assert (f"finish {share['mean'] * 100:.1f} % [{share['low'] * 100:.1f}, {share['high'] * 100:.1f}] of the "
            f"climbs against {wide['finished_alone']['mean'] * 100:.1f} % alone, {-fewer['mean'] * 100:.1f} "
            f"[{-fewer['high'] * 100:.1f}, {-fewer['low'] * 100:.1f}] points fewer (p = {fewer['p']:.1g})") in flat
    assert f"nor on 1500 held-out walls ({three(wide['ratio'])}, p = {gap['p']:.2f};" in flat


def quoted_points(c):
    """A paired difference of shares in points, as the docs write it: 0.9 [0.4, 1.4]."""
    return "{:.1f} [{:.1f}, {:.1f}]".format(*(round(100 * c[key], 1) + 0.0 for key in ("mean", "low", "high")))


def three(c, sign=1):
    """An interval to three decimals, as the docs write it; sign -1 turns a difference round."""
    low, high = sorted((sign * c["low"], sign * c["high"]))
    return f"{sign * c['mean']:.3f} [{low:.3f}, {high:.3f}]"


def climbs_needed(gap, alpha):
    """Finished climbs whose interval at alpha clears 1.5 at even odds, at gap's mean and
    spread (a normal approximation), to the hundred."""
    from scipy import stats
    spread = (gap["high"] - gap["low"]) / 2 / stats.t.ppf(0.975, gap["n"] - 1) * gap["n"] ** 0.5
    return round((stats.norm.ppf(1 - alpha / 2) * spread / gap["mean"]) ** 2, -2)


def test_baselines_quotes_the_sharper_head():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    more, fit, first_fit = record["labels_beyond"], record["fits"]["56k_walls"], record["fits"]["28k_walls"]
    assert sum(run["moves"] for run in more["runs"]) == more["moves"] and len(more["runs"]) == 8
    assert fit["walls"] == record["labels"]["walls"] + more["walls"]
    firsts = [[run["wall_seeds"].split(":")[0] for run in runs] for runs in (record["labels"]["runs"], more["runs"])]
    assert all(f"build/labels-{first}.npz" in fit["command"] for first in firsts[0] + firsts[1])
    assert f'first_eight="{" ".join(firsts[0])}"' in flat and f'next_eight="{" ".join(firsts[1])}"' in flat
    epochs = [command.split("--epochs ")[1].split()[0] for command in (fit["command"], first_fit["command"])]
    assert (f"Eight more runs of `label` over seeds {int(firsts[1][0]):,} to {int(firsts[1][-1]) + 3499:,} "
            f"({more['walls']:,} walls, {more['skipped_walls']} skipped; {more['moves']:,} moves) and a fit on all "
            f"{fit['walls']:,} walls ({fit['training_moves']:,} training moves, {epochs[0]} epochs where the first "
            f"head had {epochs[1]};") in flat
    held, choice = fit["held_out"], fit["held_out"]["at_the_policy_choice"]
    assert (f"right on {held['accuracy']:.1%} of its held-out tenth's moves (AUC {held['auc']:.3f}), and on "
            f"{choice['accuracy']:.1%} of the policy's own choices there (it passes {choice['failing_passed']} and "
            f"rejects {choice['reaching_rejected']}, of twice as many choices as above); that tenth, walls "
            f"{fit['held_out_walls'][0]:,} to {fit['held_out_walls'][1]:,}, is not the first head's"
            ).replace("%", " %") in flat
    assert 1.9 < choice["moves"] / first_fit["held_out"]["at_the_policy_choice"]["moves"] < 2.1
    assert first_fit["held_out_walls"] != fit["held_out_walls"]
    rows = record["veto_on_validation_walls_10000_10299"]["56k_walls"]
    first_rows = record["veto_on_validation_walls_10000_10299"]["28k_walls"]
    vetoes = [row["veto"] for row in rows]
    best = [min(row["mean_length_ratio"] for row in table) for table in (rows, first_rows)]
    assert best[0] >= best[1]
    assert vetoes == [row["veto"] for row in first_rows]
    assert (f"Its veto gives {listed(rows)} at p = {', '.join(map(str, vetoes[:-1]))} and {vetoes[-1]} on the "
            f"validation walls, failing {', '.join(str(row['failed_moves']) for row in rows[:-1])} and "
            f"{rows[-1]['failed_moves']} moves where the first head's failed "
            f"{', '.join(str(row['failed_moves']) for row in first_rows[:-1])} and {first_rows[-1]['failed_moves']}: "
            f"fewer failures at p = 0.5 and above, more below, and at the best threshold of each no shorter climbs "
            f"({best[0]:.2f} against {best[1]:.2f})") in flat
    assert all((row["failed_moves"] < old["failed_moves"]) == (row["veto"] >= 0.5)
               for row, old in zip(rows, first_rows))
    sharper = record["sharper_head_held_out_walls_20000_21499"]
    chosen = min((row for row in rows if row["finished"] >= 0.95), key=lambda row: row["mean_length_ratio"])
    first_veto = record["held_out_walls_20000_20299"]["veto"]
    assert sharper["veto"] == chosen["veto"] and (f"The same rule chose p = {chosen['veto']}, where the first head's "
                                                  f"is {first_veto}") in flat
    assert all(f"--veto {chosen['veto']}" in command for command in sharper["commands"])
    wide = record["held_out_walls_20000_21499"]
    assert [w["wall_seed"] for w in sharper["walls"]] == [w["wall_seed"] for w in wide["walls"]]

    def ratios(climbs):
        return length_ratios(climbs, [w["plan_length"] for w in wide["walls"]])

    first, alone = [w["veto"] for w in wide["walls"]], [w["alone"] for w in wide["walls"]]
    mine = ratios(sharper["walls"])
    assert interval(mine) == sharper["ratio"] and paired(mine, [1.5] * 1500) == sharper["ratio_minus_1_5"]
    assert paired(mine, ratios(first)) == sharper["ratio_minus_first_head"]
    assert paired(mine, ratios(alone)) == sharper["ratio_minus_alone"]
    assert paired(finished_shares(sharper["walls"]), finished_shares(first)) == sharper["finished_minus_first_head"]
    assert paired(finished_shares(sharper["walls"]), finished_shares(alone)) == sharper["finished_minus_alone"]
    assert sum(w["failed_moves"] for w in sharper["walls"]) == sharper["failed_moves"]
    gap, versus = sharper["ratio_minus_1_5"], sharper["ratio_minus_first_head"]
    assert (f"its climbs take {three(sharper['ratio'])} times the plan: {three(gap)} against 1.5 (p = {gap['p']:.2f}), "
            f"and no shorter than the first head's ({three(versus)}, p = {versus['p']:.2f})") in flat
    more_finished, versus_alone, share = (sharper["finished_minus_first_head"], sharper["finished_minus_alone"],
                                          sharper["finished"])
    assert (f"They finish {share['mean']:.1%} [{share['low'] * 100:.1f}, {share['high'] * 100:.1f}] of the climbs, "
            f"{quoted_points(more_finished)} points more than the first head's veto (p = {more_finished['p']:.1g}), "
            f"and not measurably fewer than alone ({quoted_points(versus_alone)}, p = {versus_alone['p']:.2f})"
            ).replace("%", " %") in flat
    assert versus_alone["p"] > 0.05 and more_finished["p"] < 0.05
    finished_fails = [sum(c["failed_moves"] for c in climbs if c["finished"]) for climbs in (sharper["walls"], first)]
    assert (f"Its finished climbs fail {finished_fails[0]} moves, the first head's {finished_fails[1]} "
            f"({sharper['failed_moves']} and {wide['failed_moves']['veto']} with the unfinished ones)") in flat
    on_3000 = record["held_out_walls_20000_22999"]["sharper"]["ratio"]
    assert f"a head fitted on twice the labels climbs no shorter ({three(on_3000)})" in flat
    pilot = record["pilot_veto_standing_down_on_a_seen_stance"]
    assert (f"finished {pilot['finished']:.0%} of the climbs but took {pilot['mean_length_ratio']:.2f} times the plan "
            f"and failed {pilot['failed_moves']} moves").replace("%", " %") in flat
    release = record["pilot_veto_releasing_a_rejected_move_on_each_return"]
    assert (f"finished {release['finished']:.0%} in {release['mean_length_ratio']:.2f} times the plan, failing "
            f"{release['failed_moves']} moves").replace("%", " %") in flat
    assert f"(up to {release['longest_ratio']:.1f} times the plan)" in flat


def held_out_3000(record):
    """The plans of the 3000 held-out walls 20000-22999, and the climbs of each head's veto
    and of the policy alone there, from the record's two halves."""
    wide, sharp, further = (record[key] for key in (
        "held_out_walls_20000_21499", "sharper_head_held_out_walls_20000_21499", "held_out_walls_21500_22999"))
    assert [w["wall_seed"] for w in further["walls"]] == list(range(21500, 23000))
    plans = [w["plan_length"] for w in wide["walls"] + further["walls"]]
    return plans, {"first": [w["veto"] for w in wide["walls"]] + [w["first"] for w in further["walls"]],
                   "sharper": sharp["walls"] + [w["sharper"] for w in further["walls"]],
                   "alone": [w["alone"] for w in wide["walls"]] + [w["alone"] for w in further["walls"]]}


def test_baselines_quotes_the_3000_held_out_walls():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    wide, sharp = record["held_out_walls_20000_21499"], record["sharper_head_held_out_walls_20000_21499"]
    tested = record["held_out_walls_20000_22999"]
    plans, climbs = held_out_3000(record)
    ratios = {m: length_ratios(cs, plans) for m, cs in climbs.items()}
    done = {m: finished_shares(cs) for m, cs in climbs.items()}
    for m in ("first", "sharper"):
        assert interval(ratios[m]) == tested[m]["ratio"]
        assert paired(ratios[m], [1.5] * 3000) == tested[m]["ratio_minus_1_5"]
        assert paired(done[m], done["alone"]) == tested[m]["finished_minus_alone"]
        assert tested[m]["ratio_minus_1_5"]["p"] > 0.05  # "neither is below 1.5 even at 0.05"
    assert paired(ratios["sharper"], ratios["first"]) == tested["sharper_minus_first"]["ratio"]
    assert paired(done["sharper"], done["first"]) == tested["sharper_minus_first"]["finished"]
    assert interval(ratios["alone"]) == tested["alone"]["ratio"]
    first, sharper = tested["first"], tested["sharper"]
    assert (f"the first head's veto takes {three(first['ratio'])} times the plan, {three(first['ratio_minus_1_5'])} "
            f"against 1.5 (p = {first['ratio_minus_1_5']['p']:.2f}), and the sharper head's {three(sharper['ratio'])} "
            f"(p = {sharper['ratio_minus_1_5']['p']:.2f}), against {tested['alone']['ratio']['mean']:.3f} alone"
            ) in flat
    # Five tests against 1.5: the first head on 300, 1500 and 3000 walls, the sharper on 1500 and 3000.
    looks = [record["held_out_walls_20000_20299"]["ratio_minus_1_5"], wide["ratio_minus_1_5"],
             first["ratio_minus_1_5"], sharp["ratio_minus_1_5"], sharper["ratio_minus_1_5"]]
    assert tested["alpha"] == 0.05 / len(looks) and all(look["p"] > 0.05 for look in looks)
    assert f"so each is read at {tested['alpha']} (Bonferroni over the five;" in flat
    versus = tested["sharper_minus_first"]["ratio"]
    assert (f"paired, the sharper head's climbs are {three(versus)} against the first's (p = {versus['p']:.2f})"
            ) in flat
    second = {m: [r for r in ratios[m][1500:] if r is not None] for m in ("first", "sharper")}
    halves = {f"{sum(r) / len(r):.3f}" for r in second.values()}
    assert len(halves) == 1 and f"On the second 1500 walls by themselves both vetoes take {halves.pop()}." in flat
    gain, cost = tested["sharper_minus_first"]["finished"], sharper["finished_minus_alone"]
    first_cost = first["finished_minus_alone"]
    fewer = {"mean": -cost["mean"], "low": -cost["high"], "high": -cost["low"]}
    assert (f"The first head's veto finishes {first['finished']['mean']:.1%} of the climbs, "
            f"{quoted_points(first_cost)} points against alone (p = {first_cost['p']:.0e}); the sharper head's "
            f"{sharper['finished']['mean']:.1%}, {quoted_points(gain)} points more than the first's "
            f"(p = {gain['p']:.0e}) and {quoted_points(fewer)} fewer than "
            f"alone's {tested['alone']['finished']['mean']:.1%} (p = {cost['p']:.2g})").replace("%", " %") in flat
    unfinished = {m: [c for c in cs if not c["finished"]] for m, cs in climbs.items()}
    assert all(c["length"] == baseline.CLIMB_CAP for cs in unfinished.values() for c in cs)
    alone_fails = sorted(c["failed_moves"] for c in unfinished["alone"])
    assert (f"The policy alone's {len(unfinished['alone'])} fail {alone_fails[0]} to {alone_fails[-1]} moves each"
            ) in flat and alone_fails[0] > 5
    few = [sum(c["failed_moves"] <= 5 for c in unfinished[m]) for m in ("first", "sharper")]
    rest = sorted(c["failed_moves"] for m in ("first", "sharper") for c in unfinished[m] if c["failed_moves"] > 5)
    assert (f"Of the vetoes' {len(unfinished['first'])} and {len(unfinished['sharper'])}, {few[0]} and {few[1]} fail "
            f"at most 5 moves and go round among moves that reach; the others fail {rest[0]} to {rest[-1]} moves "
            f"each") in flat
    low, high = ({f"{tested[m]['ratio'][k]:.3f}" for m in ("first", "sharper")} for k in ("low", "high"))
    assert len(low) == len(high) == 1 and f"on 3000 held-out walls both intervals, [{low.pop()}, {high.pop()}], " \
        "hold 1.5" in flat
    assert (f"the last two heads climb alike: {wide['ratio']['mean']:.3f} and {sharp['ratio']['mean']:.3f} on 1500 "
            f"walls, paired {three(sharp['ratio_minus_first_head'])}, and {first['ratio']['mean']:.3f} and "
            f"{sharper['ratio']['mean']:.3f} on 3000, paired {three(versus)}") in flat
    assert all(c["p"] > 0.05 for c in (sharp["ratio_minus_first_head"], versus))
    needed = [climbs_needed(sharper["ratio_minus_1_5"], alpha) for alpha in (0.05, tested["alpha"])]
    assert (f"an interval clear of 1.5 would take about {needed[0]:.0f} finished climbs at 0.05, and {needed[1]:.0f} "
            f"at {tested['alpha']}") in flat
    fails = [sum(c["failed_moves"] for c in climbs[m] if c["finished"]) for m in ("first", "sharper", "alone")]
    assert (f"({fails[0]} and {fails[1]} in the finished climbs of the 3000 walls, under half a move a climb, against "
            f"{fails[2]} alone)") in flat and max(fails[:2]) < 0.5 * 3000
    # The lead and "Not done" quote the 3000 walls too.
    assert (f"nor on 3000 ({three(first['ratio'])}, p = {first['ratio_minus_1_5']['p']:.2f}), where a head fitted on "
            f"twice the labels") in flat
    assert (f"nor on 3000 ({three(first['ratio'])}, p = {first['ratio_minus_1_5']['p']:.2f}): at the target, not "
            f"shown below it. One fitted on twice the labels ({record['fits']['56k_walls']['held_out']['accuracy']:.1%}"
            " "
            f"of all moves) climbs no shorter ({sharper['ratio']['mean']:.3f}) but finishes {gain['mean'] * 100:.1f} "
            f"points more").replace("%", " %") in flat


def test_baselines_quotes_the_policy_trained_under_its_veto():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    tuned = record["trained_under_the_veto"]
    shipped = json.loads((REPOSITORY / "models" / "policies" / "reach-ppo-vetoed.json").read_text())["training"]
    assert shipped["command"] == tuned["commands"]["train"] and shipped["veto"] == {"head": str(HEAD.relative_to(
        REPOSITORY)), "threshold": 0.5} and tuned["rerun_gives_the_same_weights"]
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    assert "R=examples/python/reach_estimate.py; H=models/policies/reach-ppo.reach-head.json" in text
    (line,) = [line for line in text.splitlines() if line.startswith("/usr/bin/python3 $R train ")]
    expanded = line.split("#")[0].strip().replace("$R", "examples/python/reach_estimate.py").replace("$H", str(
        HEAD.relative_to(REPOSITORY)))
    assert expanded == "/usr/bin/python3 " + shipped["command"], expanded
    # The validation table, and the threshold the rule of the heads above chose.
    first_head = next(row for row in record["veto_on_validation_walls_10000_10299"]["28k_walls"] if row["veto"] == 0.5)
    labelled = [("trained under the veto", row) for row in tuned["validation"]] + [
        ("control: trained as long without it", tuned["validation_control"]), ("the shipped policy", first_head)]
    for label, row in labelled:
        assert (f"| {label} | {row['veto']} | {row['finished']:.1%} | {row['mean_length_ratio']:.3f} "
                f"| {row['failed_moves']} |").replace("%", " %") in flat, label
    chosen = min((row for row in tuned["validation"] if row["finished"] >= 0.95), key=lambda r: r["mean_length_ratio"])
    assert chosen["veto"] == 0.5 and all("--veto 0.5 " in command for command in tuned["commands"]["held_out"])
    assert (f"climbs those walls in {tuned['validation_alone']['mean_length_ratio']:.2f} times the plan: it leans on "
            f"its veto") in flat
    control = tuned["validation_control"]["mean_length_ratio"]
    assert (f"({control:.3f} against {first_head['mean_length_ratio']:.3f}; one run each, on these 300 walls, "
            f"untested)") in flat
    assert control > first_head["mean_length_ratio"] > chosen["mean_length_ratio"]
    assert (f"1 M steps, seed 1, {tuned['training_seconds']:.0f} s (the run that wrote the committed file, the same "
            f"command again beside two other runs, took {tuned['rerun_seconds']:.0f} s)") in flat
    assert shipped["history"][-1]["seconds"] == tuned["rerun_seconds"]
    # The 3000 held-out walls, recomputed from the per-wall climbs.
    plans, climbs = held_out_3000(record)
    first, alone, mine = climbs["first"], climbs["alone"], tuned["held_out_walls"]
    assert [w["wall_seed"] for w in mine] == list(range(20000, 23000))
    ratios = length_ratios(mine, plans)
    assert interval(ratios) == tuned["ratio"] and paired(ratios, [1.5] * 3000) == tuned["ratio_minus_1_5"]
    assert paired(ratios, length_ratios(first, plans)) == tuned["ratio_minus_first_head"]
    assert paired(finished_shares(mine), finished_shares(first)) == tuned["finished_minus_first_head"]
    assert paired(finished_shares(mine), finished_shares(alone)) == tuned["finished_minus_alone"]
    assert interval(finished_shares(mine)) == tuned["finished"]
    # Six tests against 1.5 now: the five of the 3000 walls' record and this one.
    gap, versus = tuned["ratio_minus_1_5"], tuned["ratio_minus_first_head"]
    assert tuned["alpha"] == record["held_out_walls_20000_22999"]["alpha"] * 5 / 6 and gap["p"] < tuned["alpha"]
    assert (f"climbs in {three(tuned['ratio'])} times the plan: {three(gap)} against 1.5 (p = {gap['p']:.0e}), the "
            f"sixth test against 1.5, read at {tuned['alpha']:.4f} (Bonferroni over the six)") in flat
    assert (f"its climbs are {three(versus)} against the shipped policy's under the same veto (p = "
            f"{versus['p']:.0e})") in flat and versus["high"] < 0
    share, fewer, fewer_alone = tuned["finished"], tuned["finished_minus_first_head"], tuned["finished_minus_alone"]
    assert (f"It finishes {share['mean']:.1%} [{share['low'] * 100:.1f}, {share['high'] * 100:.1f}] of the climbs, "
            f"{quoted_points(fewer)} points against the shipped policy's under the veto (p = {fewer['p']:.2g}) and "
            f"{quoted_points(fewer_alone)} against the policy alone (p = {fewer_alone['p']:.0e}): above the target's "
            f"90%").replace("%", " %") in flat and share["low"] > 0.9
    unfinished = [c for c in mine if not c["finished"]]
    assert all(c["length"] == baseline.CLIMB_CAP for c in unfinished)
    fails = [sum(c["failed_moves"] for c in climbs if c["finished"]) for climbs in (mine, first)]
    assert (f"Its {len(unfinished)} unfinished climbs all run to the cap of 200 actions, "
            f"{sum(c['failed_moves'] <= 5 for c in unfinished)} of them failing at most 5 moves; its finished climbs "
            f"fail {fails[0]} moves, against {fails[1]} for the shipped policy under the veto") in flat
    within = sum(c["finished"] and c["length"] <= 1.5 * plan for c, plan in zip(mine, plans)) / 3000
    assert f"{within:.1%} of the climbs finish within 1.5 times their plan".replace("%", " %") in flat
    # The lead and "Not done".
    assert (f"climbs the 3000 held-out walls with the same veto in {three(tuned['ratio'])} times the plan, below 1.5 "
            f"(p = {gap['p']:.0e}), finishing {share['mean']:.1%} of them").replace("%", " %") in flat
    assert f"{three(tuned['ratio'])} times the plan on the 3000 walls (p = {gap['p']:.0e})" in flat
    assert "(its command, run a second time, gave the same weights to the bit)" in flat


def test_baselines_quotes_seeds_2_and_3_trained_under_the_veto():
    from wall_statistics import interval, paired
    record = json.loads((SEARCH / "reach_estimate.json").read_text())
    flat = " ".join((REPOSITORY / "docs" / "BASELINES.md").read_text().split())
    tuned = record["trained_under_the_veto"]
    seeds, seed_one = tuned["seeds_2_and_3"]["runs"], tuned["seeds_2_and_3"]["seed_1_on_walls_20000_21499"]
    wide = record["held_out_walls_20000_21499"]
    plans = [w["plan_length"] for w in wide["walls"]]
    first = length_ratios([w["veto"] for w in wide["walls"]], plans)
    one = length_ratios(tuned["held_out_walls"][:1500], plans)
    assert interval(one) == seed_one["ratio"] and paired(one, first) == seed_one["ratio_minus_first_head"]
    for run in seeds:
        assert [w["wall_seed"] for w in run["held_out_walls_20000_21499"]] == [w["wall_seed"] for w in wide["walls"]]
        mine = length_ratios(run["held_out_walls_20000_21499"], plans)
        assert interval(mine) == run["ratio"] and paired(mine, first) == run["ratio_minus_first_head"]
        assert paired(mine, one) == run["ratio_minus_seed_1"]
        assert run["command"] == tuned["commands"]["train"].replace("--seed 1", f"--seed {run['seed']}").replace(
            "models/policies/reach-ppo-vetoed.json", f"build/reach-ppo-vetoed-s{run['seed']}.json")
        assert run["ratio_minus_first_head"]["p"] < 0.025 < run["ratio_minus_seed_1"]["p"]  # two seeds

    def p(c):
        return f"p = {c['p']:.2f}" if c["p"] >= 0.01 else f"p = {c['p']:.0e}"

    validation = [run["validation"]["mean_length_ratio"] for run in seeds]
    versus_shipped = [f"{three(run['ratio_minus_first_head'])} ({p(run['ratio_minus_first_head'])})" for run in seeds]
    versus_one = [f"{three(run['ratio_minus_seed_1'])} ({p(run['ratio_minus_seed_1'])})" for run in seeds]
    assert (f"Seeds 2 and 3 of the same training (their weights not kept) climb the validation walls under the veto "
            f"in {validation[0]:.3f} and {validation[1]:.3f} times the plan, and the held-out walls 20000-21499 in "
            f"{three(seeds[0]['ratio'])} and {three(seeds[1]['ratio'])}, where seed 1 takes {three(seed_one['ratio'])} "
            f"and the shipped policy under the veto {wide['ratio']['mean']:.3f}. Paired against the shipped policy "
            f"under the veto, seeds 2 and 3 are {versus_shipped[0]} and {versus_shipped[1]}, seed 1 "
            f"{three(seed_one['ratio_minus_first_head'])}; against seed 1, {versus_one[0]} and {versus_one[1]}."
            ) in flat

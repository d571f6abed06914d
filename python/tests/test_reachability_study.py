"""The reachability study of examples/python/reachability_study.py (docs/BASELINES.md): its
labels are the MDP's verdicts, stepped action by action in a fresh MDP; its features are
the observation's slot and the reach computed by hand; its AUC is the hand-computed one."""

import importlib.util
import pathlib

import numpy as np
import pytest

import crux

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "reachability_study.py"


@pytest.fixture(scope="module")
def study():
    spec = importlib.util.spec_from_file_location("reachability_study", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_each_label_is_the_verdict_of_the_move_stepped_in_a_fresh_mdp(study):
    # ik.guess = standing: a verdict does not depend on which route solved its configuration
    # first, so a fresh MDP stepped along the route must give the label.
    config = {"ik.guess": "standing"}
    features, labels, visits = study.generate_wall(3, 12, np.random.default_rng(5), config=config)
    assert len(labels) == len(features) == sum(len(candidates) for _, candidates in visits)
    assert 0 < labels.mean() < 1, "a random climb meets both verdicts"
    wall = crux.Wall.random(3)
    row = 0
    for history, candidates in visits:
        for hold in candidates:
            mdp = crux.ClimbMdp(wall, config=config, max_steps=None)
            mdp.reset()
            for action in history:
                mdp.step(action)
            observation = mdp.numeric_observation(study.MAX_CANDIDATES)
            assert list(np.flatnonzero(mdp.action_mask())) == list(candidates)
            slot = list(candidates).index(hold)
            np.testing.assert_allclose(features[row, :3], observation["candidates"][slot], rtol=0, atol=1e-6)
            assert labels[row] == mdp.step(int(hold))[4]["reached"], f"state {history}, hold {hold}"
            row += 1


def test_the_reach_features_are_the_candidate_from_the_free_limbs_shoulder_or_hip(study):
    mdp = crux.ClimbMdp(crux.Wall.random(4))
    mdp.reset()
    observation = mdp.numeric_observation(study.MAX_CANDIDATES)
    origins = crux.forward_kinematics(mdp.model, observation["posture"].astype(float), joints=True)["joint_origins"]
    shoulder = origins[list(mdp.model.joint_names).index("right_shoulder_flexion")]  # the right hand is free first
    roots = origins[[list(mdp.model.joint_names).index(name) for name in study.LIMB_ROOT_JOINTS]]
    rows = study.slot_features(observation, roots)
    assert rows.shape == (int(observation["candidate_mask"].sum()), study.BASE_FEATURES + study.REACH_FEATURES)
    base = study.BASE_FEATURES
    for slot, row in enumerate(rows):
        candidate = observation["candidates"][slot].astype(float)
        np.testing.assert_allclose(row[base:base + 3], candidate - shoulder, atol=1e-12)
        assert row[base + 3] == pytest.approx(np.linalg.norm(candidate - shoulder))
        others = [np.linalg.norm(candidate - observation["held"][limb]) for limb in (1, 2, 3)]
        np.testing.assert_allclose(row[base + 4:], others, rtol=1e-6)


def test_the_auc_is_the_share_of_reached_unreached_pairs_ranked_right(study):
    # Pairs (reached, unreached): (0.35, 0.1), (0.35, 0.4) wrong, (0.8, 0.1), (0.8, 0.4): 3 of 4.
    assert study.auc(np.array([0.1, 0.4, 0.35, 0.8]), np.array([False, False, True, True])) == 0.75
    assert study.auc(np.array([1.0, 1.0]), np.array([True, False])) == 0.5
    assert study.auc(np.array([2.0, 1.0, 0.0]), np.array([True, False, False])) == 1.0


def test_the_best_candidate_share_counts_states_that_offer_a_reachable_move(study):
    # State 0: the best-scored move (0.9) fails, a uniform choice reaches 2 in 3; state 1
    # offers no reachable move and is not counted.
    result = study.best_candidate_reaches(np.array([0.9, 0.1, 0.5, 0.2, 0.3]),
                                          np.array([False, True, True, False, False]), np.zeros(5, dtype=int),
                                          np.array([0, 0, 0, 1, 1]))
    assert result == {"states": 1, "best": 0.0, "uniform": pytest.approx(2 / 3)}


def test_the_script_labels_walls_and_reports_held_out_ones(tmp_path):
    pytest.importorskip("torch", reason="the classifier needs Debian's python3-torch")
    import json
    import subprocess
    import sys

    data = tmp_path / "moves.npz"
    done = subprocess.run([sys.executable, str(SCRIPT), "generate", "--wall-seeds", "0:5", "--states-per-wall", "10",
                           "--out", str(data)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stderr.count("reachable") == 6, "a line per wall"
    done = subprocess.run([sys.executable, str(SCRIPT), "fit", "--data", str(data), "--held-out-walls", "2",
                           "--epochs", "1", "--json"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert (result["walls"], result["held_out_walls"]) == (6, 2)
    assert result["training_moves"] + result["held_out_moves"] == result["moves"] == len(np.load(data)["reached"])
    for name in ("observation", "with_reach"):
        assert 0 <= result[name]["auc"] <= 1
        assert sum(row["moves"] for row in result[name]["errors_by_reach"]) == result["held_out_moves"]
    done = subprocess.run([sys.executable, str(SCRIPT), "generate", "--wall-seeds", "5:1", "--out", str(data)],
                          capture_output=True, text=True)
    assert done.returncode == 2 and "'5:1' is not A:B" in done.stderr

"""examples/python/climb_diagnosis.py: each move is classified by the climb graph's
distances, the climbs are the evaluator's, a fall under the static model follows a dead
end, and bad input is one line and exit code 2."""

import contextlib
import importlib.util
import io
import json
import pathlib
import sys

import pytest

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"], "the climb diagnosis needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and python3-torch"
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = REPOSITORY / "examples" / "python"
sys.path.insert(0, str(EXAMPLES))  # climb_diagnosis imports policy_baseline from its folder
_spec = importlib.util.spec_from_file_location("climb_diagnosis", EXAMPLES / "climb_diagnosis.py")
diagnosis = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(diagnosis)
baseline = diagnosis.baseline
SHIPPED = REPOSITORY / "models" / "policies" / "reach-ppo.json"


@pytest.mark.parametrize("before, reached, finished, after, kind", [
    (5, False, False, 5, "failed"),
    (5, True, False, 4, "optimal"),
    (5, True, False, 5, "detour"),
    (5, True, False, 7, "detour"),
    (5, True, False, -1, "into_dead_end"),
    (-1, True, False, -1, "within_dead_end"),
    (1, True, True, None, "optimal"),
    (3, True, True, None, "detour"),  # a finish the graph did not expect of that state
    (None, True, False, 4, "off_graph"),
    (5, True, False, None, "off_graph"),
])
def test_a_move_is_classified_by_the_distances_before_and_after(before, reached, finished, after, kind):
    assert diagnosis.move_kind(before, reached, finished, after) == kind


def run(*arguments):
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        diagnosis.main([*arguments, "--json"])
    return json.loads(printed.getvalue())


def test_the_climbs_are_the_evaluators_and_every_action_is_counted_once():
    result = run("--policy", str(SHIPPED), "--wall-seeds", "20000:20001")
    policy, _ = baseline.load_policy(SHIPPED)
    evaluated = baseline.evaluate(policy, range(20000, 20002), plans={})
    assert result["climbs"] == evaluated["climbs"] == 2
    for wall, climb in zip(result["walls"], evaluated["walls"]):
        assert wall["wall_seed"] == climb["wall_seed"]
        assert (wall["ending"] == "finished") == climb["finished"]
        assert wall["actions"] == climb["length"] == sum(wall["moves"].values())
        assert wall["moves"]["failed"] == climb["failed_moves"]
    assert result["finished"] + result["fell"] + result["cap"] == result["climbs"]
    assert result["moves"] == {kind: sum(w["moves"][kind] for w in result["walls"]) for kind in diagnosis.MOVE_KINDS}


def test_a_fall_under_the_static_model_follows_a_dead_end():
    # A fall comes when every move of the stance fails: the graph's state has no move that
    # finishes, so the climb entered a dead end (or a state off the graph) on its way.
    # The shipped (kinematic) policy falls on both walls under the static model.
    result = run("--policy", str(SHIPPED), "--wall-seeds", "20004:20005", "--physics-model", "static")
    assert result["fell"] == 2
    for wall in result["walls"]:
        assert wall["entered_dead_end"] or wall["moves"]["off_graph"], wall


@pytest.mark.parametrize("arguments, problem", [
    (["--policy", "missing.json", "--wall-seeds", "1:2"], "climb_diagnosis.py: --policy: "),
    (["--policy", str(SHIPPED), "--wall-seeds", "2:1"], "climb_diagnosis.py: argument --wall-seeds: "),
])
def test_bad_input_is_one_line_and_exit_code_2(capsys, arguments, problem):
    with pytest.raises(SystemExit) as stopped:
        diagnosis.main(arguments)
    assert stopped.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(problem) and err.count("\n") == 1, err

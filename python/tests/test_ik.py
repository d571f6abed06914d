"""IK from Python gives what crux ik gives, with either solver."""

import numpy as np
import pytest

import crux

HOLDS = np.array([[0.0, 0.3, 1.6], [0.0, 0.7, 1.6], [0.0, 0.35, 0.2], [0.0, 0.65, 0.2]])


@pytest.mark.parametrize("solver", ["fast", "paper"])
def test_solve_ik_equals_the_cli(cli_json, solver):
    out = cli_json("ik", "--ik-solver", solver, "--rh", "0.3,1.6", "--lh", "0.7,1.6", "--rf", "0.35,0.2",
                   "--lf", "0.65,0.2")
    result = crux.solve_ik(None, HOLDS, config={"ik": {"solver": solver}})
    assert result.reached == out["reached"] and result.reached
    assert result.iterations == out["iterations"]
    assert result.residual_m == out["residual_m"]
    assert np.array_equal(result.posture, out["posture"])
    assert np.array_equal(result.root_target, out["root_target"])
    assert result.path is None


def test_path_starts_at_the_start_and_ends_at_the_result():
    result = crux.solve_ik(None, HOLDS, path_every=5)
    assert result.path.shape[1] == 35 and len(result.path) >= 2
    assert np.array_equal(result.path[0], crux.BodyModel.load().standing_posture(result.root_target))
    assert np.array_equal(result.path[-1], result.posture)


def test_out_of_reach_holds_are_not_reached_and_return_the_start():
    far = HOLDS.copy()
    far[0, 2] = 4.0
    result = crux.solve_ik(None, far)
    assert not result.reached
    assert np.array_equal(result.posture, crux.BodyModel.load().standing_posture(result.root_target))


def test_unknown_solver_is_the_cli_problem_naming_the_key(run_cli):
    code, _, err = run_cli("ik", "--ik-solver", "magic", "--rh", "0.3,1.6", "--lh", "0.7,1.6", "--rf", "0.35,0.2",
                           "--lf", "0.65,0.2")
    assert code == 2
    with pytest.raises(ValueError) as error:
        crux.solve_ik(None, HOLDS, config={"ik.solver": "magic"})
    # The CLI names the flag it was given, Python the config key; the problem is the same.
    assert err.strip() == "crux: --ik-solver: unknown solver 'magic' (expected fast or paper)"
    assert str(error.value) == "ik.solver: unknown solver 'magic' (expected fast or paper)"

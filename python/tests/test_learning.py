"""Q-tables to and from numpy, and Q-table files, from Python."""

import numpy as np
import pytest

import crux


def test_q_tables_to_numpy_and_back(wall7, tmp_path):
    table = crux.run_learning(wall7, {"experiment.iterations": 300}, seed=1).q_grid
    states, values, visits = table.to_numpy()
    assert np.all(np.diff(states.astype(np.float64)) > 0) and values.shape == (len(states), 35)
    back = crux.QTable.from_numpy(states, values, visits)
    for a, b in zip(back.to_numpy(), (states, values, visits)):
        assert np.array_equal(a, b)
    table.save(tmp_path / "t.bin", "tables")
    loaded = crux.QTable.load(tmp_path / "t.bin", 35, "tables")
    assert np.array_equal(loaded.to_numpy()[1], values)
    with pytest.raises(ValueError, match="listed twice"):
        crux.QTable.from_numpy([1, 1], np.zeros((2, 3)))


def test_bad_q_table_file_is_the_cli_message(run_cli, tmp_path):
    bad = tmp_path / "q.bin"
    bad.write_bytes(b"CRUXQTAB and then nothing useful")
    code, _, err = run_cli("transfer", "--wall-seed", 4, "--q-grid", bad, "-o", tmp_path / "out")
    assert code == 2
    with pytest.raises(ValueError) as error:
        crux.run_learning(config={"wall.seed": 4}, q_grid=bad)
    assert err.strip() == "crux: " + str(error.value)


def test_bad_table_arguments_are_value_errors():
    table = crux.QTable(3)
    table.set_value(5, 2, 1.5)
    assert table.value(5, 2) == 1.5 and table.value(6, 0) == 0.0
    with pytest.raises(ValueError, match="^action: must be an integer from 0 to 2$"):
        table.value(5, 10**8)
    with pytest.raises(ValueError, match="^action: must be an integer from 0 to 2$"):
        table.set_value(5, -1, 1.0)
    with pytest.raises(ValueError, match="^state: must be an integer from 0 to 18446744073709551615$"):
        table.value(-1, 0)
    with pytest.raises(ValueError, match="^action_count: must be an integer from 1 to"):
        crux.QTable(0)
    with pytest.raises(ValueError, match="^states: must be state codes, 0 or more$"):
        crux.QTable.from_numpy(np.array([-1]), np.zeros((1, 3)))
    with pytest.raises(ValueError, match="^states: must be an array of integers$"):
        crux.QTable.from_numpy(np.array([0.5]), np.zeros((1, 3)))
    with pytest.raises(ValueError, match="^visits: must be counts from 0 to 4294967295$"):
        crux.QTable.from_numpy([1], np.zeros((1, 3)), np.array([[0, -1, 0]]))


def test_from_numpy_takes_the_action_counts_the_constructor_takes():
    limit = "must be an integer from 1 to 1048576$"
    with pytest.raises(ValueError, match="^action_count: " + limit):
        crux.QTable(2**20 + 1)
    for columns in (2**32 + 1, 2**20 + 1):  # an empty array of any width: 2^32 + 1 once wrapped to 1
        with pytest.raises(ValueError, match=r"^values' columns \(the action count\): " + limit):
            crux.QTable.from_numpy(np.zeros(0, dtype=np.uint64), np.zeros((0, columns)))
    assert crux.QTable.from_numpy(np.zeros(0, dtype=np.uint64), np.zeros((0, 2**20))).action_count == 2**20


def test_a_transferred_table_must_fit_the_grid():
    wrong_width = crux.QTable(5)
    with pytest.raises(ValueError, match="^q_grid: has 5 actions, but the grid has 35 tiles$"):
        crux.run_learning(crux.Wall.random(4), q_grid=wrong_width)
    foreign_state = crux.QTable(35)
    foreign_state.set_value(10**9, 0, 1.0)
    with pytest.raises(ValueError, match="^q_grid: state code 1000000000 does not exist on a 5 x 7 grid$"):
        crux.run_learning(crux.Wall.random(4), q_grid=foreign_state)

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

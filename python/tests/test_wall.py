"""Walls, the geometric filter, possible actions and the moving grid from Python."""

import json

import numpy as np
import pytest

import crux


def test_random_wall_equals_crux_wall_generate(run_cli, tmp_path):
    code, _, err = run_cli("wall", "generate", "--wall-seed", 7, "--wall-rows", 9, "-o", tmp_path / "w.json")
    assert code == 0, err
    wall = crux.Wall.random(7, config={"wall.rows": 9})
    assert wall.to_json() == (tmp_path / "w.json").read_text()
    assert crux.Wall.load(tmp_path / "w.json").to_json() == wall.to_json()


def test_holds_as_arrays_and_a_save_that_loads_back(wall7, tmp_path):
    document = json.loads(wall7.to_json())
    assert wall7.hold_count == len(document["holds"]) == 45
    assert np.array_equal(wall7.positions, [h["position"] for h in document["holds"]])
    assert np.array_equal(wall7.hold_ids, [h["id"] for h in document["holds"]])
    assert np.array_equal(wall7.radii, [h["radius"] for h in document["holds"]])
    start_ids = [document["start"][limb] for limb in crux.LIMB_NAMES]
    assert [wall7.hold_ids[i] for i in wall7.start] == start_ids
    wall7.save(tmp_path / "copy.json")
    assert (tmp_path / "copy.json").read_text() == wall7.to_json()


def test_possible_actions_pass_the_filter_and_the_others_do_not(wall7):
    configuration = wall7.start.copy()
    configuration[0] = -1
    possible = set(crux.possible_actions(wall7, configuration))
    assert possible
    for hold in range(wall7.hold_count):
        complete = configuration.copy()
        complete[0] = hold
        taken = hold in configuration[1:]
        assert (hold in possible) == (not taken and crux.passes_filter(wall7, complete)), hold


def test_a_tighter_span_leaves_fewer_possible_actions(wall7):
    configuration = wall7.start.copy()
    configuration[0] = -1
    loose = crux.possible_actions(wall7, configuration)
    tight = crux.possible_actions(wall7, configuration, config={"filter": {"max_span": 1.5}})
    assert set(tight) < set(loose)


def test_grid_is_centred_on_the_free_limbs_anchor_tile():
    position = np.array([0.0, 0.5, 1.2])
    placement = crux.place_grid("right_hand", position)
    assert placement.columns == 5 and placement.rows == 7
    assert placement.anchor_tile == 4 * 5 + 1
    assert np.allclose(placement.tile_centre(placement.anchor_tile), position)
    assert placement.tile_of(position) == placement.anchor_tile
    assert placement.tile_of([0.0, 10.0, 10.0]) == -1


def test_bad_wall_file_is_the_cli_message(run_cli, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "crux-wall", "version": 1, "name": "x"}')
    code, _, err = run_cli("wall", "show", "--wall-file", bad)
    assert code == 2
    with pytest.raises(ValueError) as error:
        crux.Wall.load(bad)
    assert err.strip() == "crux: " + str(error.value)


def test_a_configuration_with_a_hold_outside_the_wall_is_a_value_error(wall7):
    with pytest.raises(ValueError, match="hold index 99 is not -1"):
        crux.possible_actions(wall7, [-1, 99, 1, 2])


def test_walls_pickle_and_copy_exactly(wall7):
    import copy
    import pickle

    for again in (pickle.loads(pickle.dumps(wall7)), copy.deepcopy(wall7)):
        assert again is not wall7 and again.name == wall7.name and again.to_json() == wall7.to_json()
        assert np.array_equal(again.positions, wall7.positions) and np.array_equal(again.start, wall7.start)

"""The paper's agent and experiment from Python give the CLI's numbers, by seed."""

import json
import os
import signal
import subprocess
import sys

import numpy as np
import pytest

import crux

SMALL_PAPER = {"experiment": {"walls": 2, "iterations": 400, "plan": False, "threads": 2,
                              "bootstrap_resamples": 200}}


def without_caller(summary):
    """A summary apart from the provenance's line naming who ran the job."""
    summary = json.loads(json.dumps(summary))
    summary["provenance"].pop("produced_by")
    return summary


def folder_without_callers(folder):
    """Every file of an output folder, by relative path, with the lines that name the caller
    (config.toml's and summary.json's produced_by) left out."""
    files = {}
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        data = path.read_bytes()
        if path.name in ("config.toml", "summary.json"):
            data = b"".join(line for line in data.splitlines(keepends=True) if b"produced_by" not in line)
        files[str(path.relative_to(folder))] = data
    return files


def test_one_learning_job_writes_one_folder_from_the_cli_python_and_a_sweep(run_cli, tmp_path):
    code, out, err = run_cli("sweep", "--walls", 1, "--iterations", 400, "--plan", "false",
                             "--bootstrap-resamples", 100, "--threads", 1, "-o", tmp_path / "sweep")
    assert code == 0, err
    for run, command in (("training_0", "train"), ("transfer_0", "transfer")):
        from_sweep = tmp_path / "sweep" / "runs" / "c0" / run
        config = from_sweep / "config.toml"
        assert b'produced_by = "crux sweep"' in config.read_bytes()
        code, out, err = run_cli(command, "--config", config, "-o", tmp_path / f"cli-{run}")
        assert code == 0, err
        crux.run_learning(config=config, output=tmp_path / f"py-{run}")
        expected = folder_without_callers(from_sweep)
        assert {"config.toml", "summary.json", "wall.json", "iterations.csv", "q_grid.bin"} <= set(expected)
        assert folder_without_callers(tmp_path / f"cli-{run}") == expected, run
        assert folder_without_callers(tmp_path / f"py-{run}") == expected, run
        assert b'produced_by = "crux.run_learning"' in (tmp_path / f"py-{run}" / "config.toml").read_bytes()


def test_run_experiment_equals_crux_paper(run_cli, tmp_path):
    (tmp_path / "small.toml").write_text(
        "[experiment]\nwalls = 2\niterations = 400\nplan = false\nthreads = 2\nbootstrap_resamples = 200\n")
    code, out, err = run_cli("paper", "--config", tmp_path / "small.toml", "-o", tmp_path / "cli", "--json")
    assert code == 0, err
    from_cli = json.loads(out)
    from_dict = crux.run_experiment(SMALL_PAPER, output=tmp_path / "py")
    assert without_caller(from_dict) == without_caller(from_cli)
    assert without_caller(crux.run_experiment(tmp_path / "small.toml")) == without_caller(from_cli)
    # The folder written is crux paper's, byte for byte but for the lines naming the caller.
    assert folder_without_callers(tmp_path / "py") == folder_without_callers(tmp_path / "cli")


def test_run_experiment_takes_training_walls_of_their_own(run_cli, tmp_path):
    code, out, err = run_cli("paper", "--walls", 1, "--iterations", 200, "--plan", "false", "--bootstrap-resamples",
                             200, "--training-wall-sigma", 0.16, "-o", tmp_path / "cli", "--json")
    assert code == 0, err
    config = {"experiment": {"walls": 1, "iterations": 200, "plan": False, "bootstrap_resamples": 200},
              "training_wall": {"sigma": 0.16}}
    assert without_caller(crux.run_experiment(config)) == without_caller(json.loads(out))
    same_walls = {"experiment": config["experiment"]}
    assert without_caller(crux.run_experiment(same_walls)) != without_caller(json.loads(out))


def test_run_learning_equals_crux_train_and_transfer(run_cli, tmp_path):
    code, out, err = run_cli("train", "--wall-seed", 3, "--seed", 5, "--iterations", 600, "-o", tmp_path / "train",
                             "--json")
    assert code == 0, err
    run = crux.run_learning(config={"wall.seed": 3, "experiment.iterations": 600}, seed=5)
    assert without_caller(run.summary) == without_caller(json.loads(out))
    assert run.episode_lengths.sum() <= 600 and len(run.iterations["reward"]) == 600
    run.q_grid.save(tmp_path / "q_grid.bin", crux.grid_state_space())
    assert (tmp_path / "q_grid.bin").read_bytes() == (tmp_path / "train" / "q_grid.bin").read_bytes()

    code, out, err = run_cli("transfer", "--wall-seed", 4, "--seed", 6, "--iterations", 600, "--q-grid",
                             tmp_path / "train" / "q_grid.bin", "-o", tmp_path / "transfer", "--json")
    assert code == 0, err
    config = {"wall.seed": 4, "experiment.iterations": 600}
    from_file = crux.run_learning(config=config, seed=6, q_grid=tmp_path / "train" / "q_grid.bin")
    from_table = crux.run_learning(crux.Wall.random(4), config={"experiment.iterations": 600}, seed=6,
                                   q_grid=run.q_grid)
    assert without_caller(from_file.summary) == without_caller(json.loads(out))
    assert np.array_equal(from_table.episode_lengths, from_file.episode_lengths)


@pytest.mark.parametrize("mode", ["prior", "ordered"])
def test_a_transfer_mode_is_a_config_key_as_on_the_command_line(run_cli, tmp_path, mode):
    code, out, err = run_cli("train", "--wall-seed", 3, "--seed", 5, "--iterations", 1500, "-o", tmp_path / "train")
    assert code == 0, err
    code, out, err = run_cli("transfer", "--wall-seed", 4, "--seed", 6, "--iterations", 1500, "--q-grid",
                             tmp_path / "train" / "q_grid.bin", "--transfer", mode, "-o", tmp_path / "transfer",
                             "--json")
    assert code == 0, err
    config = {"wall.seed": 4, "experiment.iterations": 1500, "experiment.transfer": mode}
    moded = crux.run_learning(config=config, seed=6, q_grid=tmp_path / "train" / "q_grid.bin")
    assert without_caller(moded.summary) == without_caller(json.loads(out))
    paper = crux.run_learning(config={**config, "experiment.transfer": "paper"}, seed=6,
                              q_grid=tmp_path / "train" / "q_grid.bin")
    assert not np.array_equal(moded.iterations["hold_id"], paper.iterations["hold_id"])
    with pytest.raises(ValueError, match="^experiment.transfer: unknown transfer 'best'"):
        crux.run_learning(config={**config, "experiment.transfer": "best"}, seed=6)


def test_same_seed_same_run_and_another_seed_another(wall7):
    config = {"experiment.iterations": 500}
    first, again, other = (crux.run_learning(wall7, config, seed=s) for s in (1, 1, 2))
    assert without_caller(first.summary) == without_caller(again.summary)
    for a, b in zip(first.q_grid.to_numpy(), again.q_grid.to_numpy()):
        assert np.array_equal(a, b)
    assert not np.array_equal(first.iterations["hold_id"], other.iterations["hold_id"])


def test_config_errors_name_the_key():
    with pytest.raises(ValueError, match=r"^experiment.walls: must be from 1 to 1000000$"):
        crux.run_experiment({"experiment": {"walls": 0}})
    with pytest.raises(ValueError, match=r"^training_wall.sigma: must be in \[0, 10\]$"):
        crux.run_experiment({"training_wall": {"sigma": -0.1}})
    with pytest.raises(ValueError, match="^config: unknown key learning.epsilonn$"):
        crux.run_experiment({"learning": {"epsilonn": 0.1}})
    with pytest.raises(ValueError, match=r"^physics.strength: unknown strength 'pro' \(expected intermediate \(383.0 N\), "
                                         r"advanced \(575.7 N\) or elite \(563.1 N\)\)$"):
        crux.run_experiment({"physics": {"strength": "pro"}})
    with pytest.raises(ValueError, match="^config: crux.run_experiment does not take wall.seed$"):
        crux.run_experiment({"wall.seed": 1})
    with pytest.raises(ValueError, match="^config: grid.columns must be an integer from -2147483648 to 2147483647$"):
        crux.run_learning(crux.Wall.random(1), {"grid.columns": 2**70})
    with pytest.raises(ValueError, match="^config: reward.step must be a finite number$"):
        crux.run_learning(crux.Wall.random(1), {"reward.step": 10**400})
    with pytest.raises(ValueError, match="^seed: must be an integer from 0 to 18446744073709551615$"):
        crux.run_learning(crux.Wall.random(1), seed=-1)
    with pytest.raises(ValueError, match="^seed: must be an integer from 0 to 18446744073709551615$"):
        crux.Wall.random(2**64)
    with pytest.raises(ValueError, match="^wall: give the wall as wall or as config's wall.file or wall.seed"):
        crux.run_learning(crux.Wall.random(8), {"wall.seed": 3})
    with pytest.raises(ValueError, match="^experiment.checkpoint_every: a run that writes no folder keeps no checkpoint"):
        crux.run_learning(crux.Wall.random(1), {"experiment.checkpoint_every": 100})
    with pytest.raises(ValueError, match="^config: learning.epsilon must be one value; only crux sweep takes lists$"):
        crux.run_experiment({"learning": {"epsilon": [0.1, 0.2]}})


def test_numpy_numbers_are_config_values(wall7):
    config = {"experiment.iterations": np.int64(200), "learning.epsilon": np.float32(0.25)}
    plain = {"experiment.iterations": 200, "learning.epsilon": float(np.float32(0.25))}
    assert without_caller(crux.run_learning(wall7, config).summary) == without_caller(
        crux.run_learning(wall7, plain).summary)


# With a switch interval far longer than any test, a thread that holds the GIL keeps it
# until it blocks or releases it: another thread that is waiting for the GIL then runs
# only while the holder is blocked or inside a call that released it. The tests below use
# that to order events without timers; their calls run for minutes unless interrupted, so
# the only thing assumed of the machine is that a runnable thread runs within minutes.
SWITCH_NEVER = 1000.0

# while_the_call_runs(action) runs action() on another thread once the main thread has
# gone on into its next call and that call has released the GIL: the helper waits for
# `go`, which the main thread sets just before the call, and then for the GIL, which the
# main thread keeps until the call releases it. Needs sys.setswitchinterval(SWITCH_NEVER).
# The GIL is also released by the file reads of an import the call makes on its way in
# (crux imports numpy on first use): the helper then sees the main thread in an import's
# Python frames, not in the script's own, and waits for the next release.
WHILE_THE_CALL_RUNS = """
import sys, threading, time
def while_the_call_runs(action):
    go = threading.Event()
    main = threading.main_thread().ident
    def wait_then_act():
        go.wait()
        while sys._current_frames()[main].f_code.co_name != '<module>':
            time.sleep(0.001)
        action()
    threading.Thread(target=wait_then_act, daemon=True).start()
    return go
"""


def test_a_long_call_releases_the_gil():
    script = f"""
import os, sys, threading, crux
sys.setswitchinterval({SWITCH_NEVER})
wall = crux.Wall.random(7)
returned = []
def call():
    crux.run_learning(wall, {{'experiment.iterations': 10**7}})
    returned.append(True)
worker = threading.Thread(target=call)
# start() waits for the worker to start; the worker then keeps the GIL until the call
# releases it, so this thread runs on only inside the call, or once the worker has ended.
worker.start()
print('ran during the call' if not returned and worker.is_alive() else 'ran after the call', flush=True)
os._exit(0)
"""
    # A call that held the GIL would end only after minutes: the timeout is a hang guard.
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ, timeout=120)
    assert done.stdout == "ran during the call\n", (done.stdout, done.stderr)


def run_interrupted(script):
    """Runs a script that prints 'in call' from another thread while its main thread is in
    a long call (WHILE_THE_CALL_RUNS), then sends it SIGINT as a user's Ctrl-C would.
    Returns (stdout after 'in call', stderr)."""
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=os.environ)
    try:
        assert child.stdout.readline().strip() == "in call"
        child.send_signal(signal.SIGINT)
        # Only a guard against a hang: every call below runs for minutes unless interrupted.
        return child.communicate(timeout=120)
    finally:
        child.kill()


@pytest.mark.parametrize("call", [
    "crux.run_learning(crux.Wall.random(7), {'experiment.iterations': 10**7})",
    "crux.run_experiment({'experiment': {'walls': 2, 'iterations': 10**7, 'plan': False}})",
])
def test_ctrl_c_interrupts_a_long_call(call):
    script = f"""{WHILE_THE_CALL_RUNS}
import crux
sys.setswitchinterval({SWITCH_NEVER})
go = while_the_call_runs(lambda: print('in call', flush=True))
go.set()
{call}
print('the call ran to its end')
"""
    out, err = run_interrupted(script)
    assert "KeyboardInterrupt" in err, err
    assert out == "", out


def test_after_a_ctrl_c_other_calls_run_and_a_script_keeps_its_own_handler():
    script = f"""{WHILE_THE_CALL_RUNS}
import signal, crux
sys.setswitchinterval({SWITCH_NEVER})
wall = crux.Wall.random(7)
go = while_the_call_runs(lambda: print('in call', flush=True))
try:
    go.set()
    crux.run_learning(wall, {{'experiment.iterations': 10**7}})
except KeyboardInterrupt:
    print('interrupted')
lengths = []
worker = threading.Thread(target=lambda: lengths.append(len(crux.run_learning(wall, {{'experiment.iterations': 300}}).episode_lengths)))
worker.start()
worker.join()
print('thread call finished', len(lengths))
caught = []
signal.signal(signal.SIGINT, lambda *args: caught.append(1))
# The script's own handler: SIGINT raised while the call runs neither interrupts it nor is
# lost; Python runs the handler once the call has returned. The call is short (seconds)
# since it must end by itself: the helper must run within it.
go = while_the_call_runs(lambda: signal.raise_signal(signal.SIGINT))
go.set()
run = crux.run_learning(wall, {{'experiment.iterations': 100000}})
print('own handler', len(caught), len(run.iterations['reward']))
"""
    out, err = run_interrupted(script)
    assert out.split("\n")[:3] == ["interrupted", "thread call finished 1", "own handler 1 100000"], (out, err)


def test_a_folder_replays_from_its_config_so_objects_write_none(tmp_path):
    with pytest.raises(ValueError, match="^wall: a run folder replays from its config.toml"):
        crux.run_learning(crux.Wall.random(3), {"experiment.iterations": 100}, output=tmp_path / "objects")
    assert not (tmp_path / "objects").exists()
    with pytest.raises(ValueError, match="^output: the output folder name is empty$"):
        crux.run_learning(config={"wall.seed": 3, "experiment.iterations": 100}, output="")
    run = crux.run_learning(config={"wall.seed": 3, "experiment.iterations": 300, "experiment.checkpoint_every": 100},
                            output=tmp_path / "checkpointed")
    assert run.resumed_at == 0 and not (tmp_path / "checkpointed" / "checkpoint.bin").exists()


def test_wall_generator_keys_beside_a_wall_file_are_refused(tmp_path):
    crux.Wall.random(5).save(tmp_path / "wall.json")
    with pytest.raises(ValueError, match="^wall.sigma: shapes a random wall, and the wall file gives the wall itself"):
        crux.run_learning(config={"wall.file": str(tmp_path / "wall.json"), "wall.sigma": 0.2})


def test_wall_generator_keys_beside_a_wall_object_are_refused():
    """Issue 39: run_learning(wall, {"wall.incline": 30}) ran on the wall, ignoring the key."""
    wall = crux.Wall.random(5)
    for key, value in (("wall.incline", 30), ("wall.rows", 9), ("wall.sigma", 0.2)):
        with pytest.raises(ValueError, match=f"^{key}: shapes a random wall, and the wall argument gives the wall"):
            crux.run_learning(wall, config={key: value, "experiment.iterations": 5})


def test_config_keys_are_the_declarations_flags_and_files_use():
    keys = {k["key"]: k for k in crux.config_keys()}
    assert len(keys) == len(crux.config_keys()), "each key is declared once"
    radius = keys["ik.grasp_radius"]
    assert radius["flag"] == "--ik-grasp-radius"
    assert radius["type"] == "number" and radius["unit"] == "m"
    assert radius["min"] == 0.0 and radius["min_open"] and radius["max"] == 100.0
    assert keys["experiment.iterations"]["sizes_work"] and not radius["sizes_work"]
    assert keys["wall.seed"]["max"] is None
    assert radius["default"] == 0.04
    assert keys["ik.solver"]["type"] == "choice"
    assert keys["ik.solver"]["choices"] == "fast or paper"
    assert keys["ik.solver"]["default"] == "fast"
    assert keys["experiment.threads"]["min"] == 0.0 and keys["experiment.threads"]["max"] == 1024.0
    assert keys["wall.seed"]["default"] is None
    assert keys["output.progress"]["choices"] == "bar, lines or none"
    # A bound declared there is the one a dict meets.
    with pytest.raises(ValueError, match=r"^ik.grasp_radius: must be in \(0, 100\]$"):
        crux.run_learning(config={"wall.seed": 3, "experiment.iterations": 5, "ik.grasp_radius": 0.0})


def test_perform_equals_crux_perform(run_cli, tmp_path):
    wall = ["--wall-seed", 10, "--wall-finish-height", 1.4]
    code, out, err = run_cli("perform", *wall, "--json", "-o", tmp_path / "perform")
    assert code == 0, err
    cli = json.loads(out)
    record = crux.perform(config={"wall.seed": 10, "wall.finish_height": 1.4})
    assert record["wall_s"] > 0
    for key in ("wall_s",):
        del cli[key], record[key]
    assert record == cli
    assert record["physics_model"] == "static" and record["climb"] == "the wall's exact plan"
    assert record["moves_performed"] == sum(move["performed"] for move in record["moves"])


def test_perform_refuses_what_it_cannot_do():
    with pytest.raises(ValueError, match="wall"):
        crux.perform()
    with pytest.raises(ValueError, match="experiment.climb"):
        crux.perform(config={"wall.seed": 10, "experiment.climb": "last"})
    with pytest.raises(ValueError, match="physics.model: dynamic is not taken by crux.run_experiment"):
        crux.run_experiment({"experiment.walls": 1, "physics.model": "dynamic", "experiment.iterations": 5})


def test_run_learning_under_the_dynamic_model_performs_its_moves_in_mujoco():
    """A run of the dynamic model, as crux train runs it, says how many moves MuJoCo performed."""
    run = crux.run_learning(config={"wall.seed": 3, "physics.model": "dynamic", "experiment.iterations": 20}, seed=5)
    facts = run.summary["run_facts"]["training"][0]
    assert 1 <= facts["moves_simulated"] <= 20
    assert 0 <= facts["moves_performed"] <= facts["moves_simulated"]


def test_climb_graph_agrees_with_the_plan_and_marks_the_moves_one_action_nearer():
    wall = crux.Wall.random(10, config={"wall.finish_height": 1.4})  # a few moves: the whole graph in 0.2 s
    for model in ("kinematic", "static"):
        graph = crux.climb_graph(wall, config={"physics.model": model})
        plan = crux.plan(wall, config={"physics.model": model})
        assert not graph["stopped_at_limit"] and graph["ik_solves"] > 0
        assert graph["expanded_states"] == len(graph["distances"])
        configurations, distances, moves = graph["configurations"], graph["distances"], graph["moves"]
        assert distances[0] == plan["length"]
        assert list(configurations[0]) == [-1, *wall.start[1:]], "the start, right hand free"
        after = np.where(moves[:, 2] < 0, 0, distances[moves[:, 2]])
        reaches_finish = (distances[moves[:, 0]] >= 0) & (after >= 0)
        assert np.array_equal(moves[:, 3] == 1, reaches_finish & (after + 1 == distances[moves[:, 0]]))
        # The plan's climb takes an optimal move from each state it passes through.
        state = 0
        for hold_id in plan["holds"]:
            row = moves[(moves[:, 0] == state) & (moves[:, 1] == wall.index_of(hold_id))]
            assert len(row) == 1 and row[0, 3] == 1
            state = row[0, 2]
        assert state == -1, "the plan's last move finishes"


def test_climb_graph_refuses_keys_it_does_not_take_and_stops_at_its_budget():
    for key, value in (("reward.height", 1.0), ("experiment.plan_check_moves", True),
                       ("experiment.plan_max_solves", 300)):
        with pytest.raises(ValueError, match=key.replace(".", r"\.")):
            crux.climb_graph(crux.Wall.random(10), config={key: value})
    with pytest.raises(ValueError, match="max_ik_solves"):
        crux.climb_graph(crux.Wall.random(10), max_ik_solves=0)
    graph = crux.climb_graph(crux.Wall.random(3), max_ik_solves=300)
    assert graph["stopped_at_limit"] and graph["ik_solves"] == 300
    assert 0 < graph["expanded_states"] < len(graph["distances"]), "states found but never explored"

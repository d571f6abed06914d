"""The study's scripts (docs/TRANSFER.md, "Many walls, both planners and the reach
space"): the confirmation test and the table maker, on small inputs written here whose
statistics are computed by hand (Student's t with 2 degrees of freedom has a closed form:
its CDF is 1/2 + t / (2 sqrt(2 + t^2)))."""

import csv
import json
import math
import pathlib
import subprocess
import sys

SCRIPTS = pathlib.Path(__file__).resolve().parents[2] / "scripts"
METRICS = ["first_5_iterations", "time_to_threshold_half", "time_to_threshold", "time_to_threshold_2x",
           "time_to_threshold_4x"]
# Iterations to the first 5 episodes, by wall (3 walls x 2 learning seeds).
TRANSFER = {0: [100, 200], 1: [300, 300], 2: [50, 150]}
CONTROL = {0: [400, 400], 1: [500, 700], 2: [200, 400]}


def run_script(name, *args):
    done = subprocess.run([sys.executable, str(SCRIPTS / name), *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def write_results(folder, cells=("0",)):
    folder.mkdir()
    with open(folder / "results.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["cell", "condition", "wall_pair", "seed_index", *METRICS])
        writer.writeheader()
        for cell in cells:
            for condition, values in (("transfer", TRANSFER), ("control", CONTROL)):
                for wall, runs in values.items():
                    for seed, value in enumerate(runs):
                        writer.writerow({"cell": cell, "condition": condition, "wall_pair": wall, "seed_index": seed,
                                         **{metric: value for metric in METRICS}})


def t2_cdf(t):
    return 0.5 + t / (2 * math.sqrt(2 + t * t))


def test_confirmation_test_by_hand(tmp_path):
    write_results(tmp_path / "sweep")
    out = run_script("transfer_confirmation.py", tmp_path / "sweep")
    # Wall means: transfer 150, 300, 100; control 400, 600, 300; differences -250, -300, -200.
    sem = 50 / math.sqrt(3)
    t = -250 / sem
    p_effect = 2 * t2_cdf(t)
    quantile = math.sqrt(2 * 0.95**2 / (1 - 0.95**2))  # t2_cdf(quantile) = 0.975
    low, high = -250 - quantile * sem, -250 + quantile * sem
    assert f"transfer minus control -250 [{low:+.0f}, {high:+.0f}], p = {p_effect:.2g}: confirmed" in out, out
    assert "saving 58 % of control's" in out, out  # 250 / 433.3
    # Halving: transfer - 0.5 x control per wall: -50, 0, -50; mean -33.3, standard error 16.7, t = -2.
    assert f"one-sided p = {t2_cdf(-2.0):.2g}: not confirmed" in out, out
    # The four thresholds carry the same numbers here: Holm multiplies the smallest p by four.
    assert out.count(f"p = {p_effect:.2g} (Holm over four {4 * p_effect:.2g})") == 4, out


def test_confirmation_refuses_more_than_one_cell(tmp_path):
    write_results(tmp_path / "sweep", cells=("0", "1"))
    done = subprocess.run([sys.executable, str(SCRIPTS / "transfer_confirmation.py"), str(tmp_path / "sweep")],
                          capture_output=True, text=True)
    assert done.returncode != 0
    assert "exactly one cell" in done.stderr


def test_table_gives_the_saving_and_the_total(tmp_path):
    metric = {"transfer": {"mean": 1500.0}, "control": {"mean": 3000.0},
              "transfer_minus_control": {"mean": -1500.0, "ci95_t_over_walls": [-1800.0, -1200.0], "p_value": 1e-6,
                                         "p_value_holm_over_cells": 2e-6},
              "iqm": {"difference": {"value": -1400.0, "low": -1600.0, "high": -1100.0}},
              "probability_of_improvement": {"value": 0.875, "low": 0.8, "high": 0.95}}
    summary = {"cells": [{"parameters": {"experiment.training_walls": "16", "experiment.transfer": "prior"},
                          "iterations_spent": {"training": 128000},
                          "transfer_vs_control": {"first_5_iterations": metric}}]}
    (tmp_path / "sweep").mkdir()
    (tmp_path / "sweep" / "summary.json").write_text(json.dumps(summary))
    out = run_script("transfer_walls_table.py", tmp_path / "sweep")
    row = out.splitlines()[2]
    assert row == ("| K=16, prior | 1500, 3000 | -1500 [-1800, -1200], p = 1e-06 (2e-06) | 50 % | -1400 [-1600, -1100] "
                   "| 0.88 [0.80, 0.95] | 128000 + 1500 = 129500 (3000) |"), row
    # One seed per wall: summary.json has no stratified interval, and the table says so.
    for estimate in (metric["iqm"]["difference"], metric["probability_of_improvement"]):
        estimate["low"] = estimate["high"] = None
    (tmp_path / "sweep" / "summary.json").write_text(json.dumps(summary))
    row = run_script("transfer_walls_table.py", tmp_path / "sweep").splitlines()[2]
    assert "| -1400 (no interval) | 0.88 (no interval) |" in row, row

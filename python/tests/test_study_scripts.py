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

import numpy as np
from scipy import stats

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


def network_transfer():
    sys.path.insert(0, str(SCRIPTS))
    try:
        import network_transfer as module  # it imports crux and scipy
    finally:
        sys.path.remove(str(SCRIPTS))
    return module


def test_network_transfers_comparison_and_amortised_total_by_hand():
    # Walls' means 100, 300, 50 against 400, 600, 200: differences -300, -300, -150.
    result = network_transfer().compare([100, 300, 50], [400, 600, 200], 1000)
    sem = math.sqrt((50**2 * 2 + 100**2) / 2) / math.sqrt(3)  # deviations 50, 50, 100 from the mean
    quantile = math.sqrt(2 * 0.95**2 / (1 - 0.95**2))
    assert result["difference"]["mean"] == -250
    assert math.isclose(result["difference"]["low"], -250 - quantile * sem)
    assert math.isclose(result["difference"]["high"], -250 + quantile * sem)
    assert math.isclose(result["difference"]["p_value"], 2 * t2_cdf(-250 / sem))
    assert result["walls_lower"] == 3 and math.isclose(result["saving_share"], 250 / 400)
    # Amortised over N walls: 1000 / N + 150 < 400 from N = 5 on (at N = 4 the totals are equal).
    assert result["walls_to_beat_control"] == 5


def test_transfer_docs_quote_the_network_transfer_record():
    root = SCRIPTS.parent
    record = json.loads((root / "models" / "policies" / "search" / "network_transfer.json").read_text())
    text = (root / "docs" / "TRANSFER.md").read_text()

    def row(label, c, training=None):
        first, control = c["first_5_iterations"]
        d = c["difference"]
        cells = [label, f"{first:.0f}", f"{control:.0f}",
                 f"{d['mean']:.0f} [{d['low']:.0f}, {d['high']:.0f}], {d['p_value']:.0e}",
                 f"{c['saving_share']:.0%}".replace("%", " %"), f"{c['walls_lower']} of {record['walls']} walls",
                 f"{c['walls_to_beat_control']} walls ({training})" if training else ""]
        return ("| " + " | ".join(cells) + " |").replace("|  |", "| |")

    shipped, six_m = record["shipped"], record["six_m"]
    steps = shipped["comparisons"]["network"]["training"]
    assert steps == json.loads((root / "models" / "policies" / "reach-ppo.json").read_text())["training"]["steps"]
    assert row("the policy (`network`)", shipped["comparisons"]["network"], f"{steps:,} training steps") in text
    grid = shipped["comparisons"]["reused_q_grid"]
    assert row("one reused Q_grid (`prior`, reach)", grid, f"{grid['training']:,} training iterations") in text
    assert row("the policy against the reused Q_grid", shipped["network_against_reused_q_grid"]) in text
    earlier = six_m["comparisons"]["network"]
    assert earlier["training"] == 5_996_544
    assert row("the 6 M policy (`network`)", earlier, f"{earlier['training']:,} training steps") in text
    # The two policies on the same walls and seeds, paired over walls.
    shorter = np.subtract(shipped["per_wall"]["network"]["treated"], six_m["per_wall"]["network"]["treated"])
    half = stats.t.ppf(0.975, len(shorter) - 1) * stats.sem(shorter)
    assert (f"({shorter.mean():.1f} [{shorter.mean() - half:.1f}, {shorter.mean() + half:.1f}], "
            f"p = {stats.ttest_1samp(shorter, 0).pvalue:.1g}, lower on {np.sum(shorter < 0)} of 30 walls)") \
        in " ".join(text.split())
    # The walls up to which the 6 M policy's amortised total stays the lower one, and from the interval's ends.
    extra = shipped["comparisons"]["network"]["training"] - earlier["training"]
    flat = " ".join(text.split())
    assert f"{extra:,} more training steps for {-shorter.mean():.0f} iterations a wall" in flat
    assert f"up to about {round(extra / -shorter.mean(), -4):,.0f} walls" in flat
    assert (f"({round(extra / -(shorter.mean() - half), -4):,.0f} to {extra / -(shorter.mean() + half) / 1e6:.1f} "
            f"million from the interval of the difference)") in flat
    # The policy's total against the reused Q_grid's: training / N + first, equal at N = (T - T') / (first' - first).
    crossing = (steps - grid["training"]) / (grid["first_5_iterations"][0] - shipped["comparisons"]["network"]
                                            ["first_5_iterations"][0])
    assert f"falls below the Q_grid's from about {round(crossing, -2):,.0f} walls" in flat
    baselines = " ".join((root / "docs" / "BASELINES.md").read_text().split())
    network = shipped["comparisons"]["network"]
    assert (f"brings the first 5 episodes down from {network['first_5_iterations'][1]:.0f} iterations to "
            f"{network['first_5_iterations'][0]:.0f}, and its training pays for itself from "
            f"{network['walls_to_beat_control']} walls on") in baselines
    assert (f"take {network['first_5_iterations'][0]:.0f} iterations against control's "
            f"{network['first_5_iterations'][1]:.0f}, and the policy's {steps:,} training steps") in baselines
    assert (f"The 6 M policy took {earlier['first_5_iterations'][0]:.0f} iterations and beat control from "
            f"{earlier['walls_to_beat_control']} walls on") in baselines
    assert (f"the longer training saved Dyna-Q {-shorter.mean():.1f} more iterations (p = "
            f"{stats.ttest_1samp(shorter, 0).pvalue:.1g}), for {extra:,} more training steps") in baselines

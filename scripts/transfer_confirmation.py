#!/usr/bin/python3
"""The confirmation test of docs/TRANSFER.md, "Confirmation on a fresh seed", fixed before
it was run: from a sweep folder's results.csv with one cell, walls as the unit (each
wall's mean over its learning seeds is one observation):

1. the effect: transfer minus control in iterations to the first 5 episodes, paired t over
   walls, two-sided, at 0.05;
2. the halving: per wall, transfer - 0.5 x control, one-sided t over walls (the mean is
   below 0), at 0.05; transfer halves the transfer phase's early learning when it holds;
3. time to threshold at 30, 60, 120 and 240 iterations, transfer minus control, paired t
   over walls, Holm over the four (secondary).

    scripts/transfer_confirmation.py SWEEP_FOLDER
"""
import csv
import sys
from collections import defaultdict

from scipy import stats


def wall_means(rows, condition, metric):
    by_wall = defaultdict(list)
    for row in rows:
        if row["condition"] == condition:
            by_wall[int(row["wall_pair"])].append(float(row[metric]))
    return [sum(v) / len(v) for _, v in sorted(by_wall.items())]


def holm(p_values):
    order = sorted(range(len(p_values)), key=lambda i: (p_values[i], i))
    adjusted, running = [0.0] * len(p_values), 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (len(p_values) - rank) * p_values[i]))
        adjusted[i] = running
    return adjusted


def interval(differences):
    n = len(differences)
    mean = sum(differences) / n
    half = stats.t.ppf(0.975, n - 1) * stats.sem(differences)
    return mean, mean - half, mean + half


def main():
    with open(f"{sys.argv[1]}/results.csv") as f:
        rows = list(csv.DictReader(f))
    if len({row["cell"] for row in rows}) != 1:
        sys.exit("transfer_confirmation.py: the sweep must have exactly one cell")
    transfer = wall_means(rows, "transfer", "first_5_iterations")
    control = wall_means(rows, "control", "first_5_iterations")
    differences = [t - c for t, c in zip(transfer, control)]
    mean, low, high = interval(differences)
    p_effect = stats.ttest_1samp(differences, 0.0).pvalue
    control_mean = sum(control) / len(control)
    halves = [t - 0.5 * c for t, c in zip(transfer, control)]
    p_halving = stats.ttest_1samp(halves, 0.0, alternative="less").pvalue
    print(f"walls: {len(transfer)}; first 5 episodes: transfer {sum(transfer) / len(transfer):.0f}, "
          f"control {control_mean:.0f}")
    print(f"1. effect: transfer minus control {mean:+.0f} [{low:+.0f}, {high:+.0f}], p = {p_effect:.2g}: "
          f"{'confirmed' if p_effect < 0.05 and mean < 0 else 'not confirmed'}")
    print(f"   saving {100 * -mean / control_mean:.0f} % of control's")
    h_mean, h_low, h_high = interval(halves)
    print(f"2. halving: transfer - 0.5 x control {h_mean:+.0f} [{h_low:+.0f}, {h_high:+.0f}], one-sided p = "
          f"{p_halving:.2g}: {'confirmed' if p_halving < 0.05 else 'not confirmed'}")
    metrics = ["time_to_threshold_half", "time_to_threshold", "time_to_threshold_2x", "time_to_threshold_4x"]
    results = []
    for metric in metrics:
        d = [t - c for t, c in zip(wall_means(rows, "transfer", metric), wall_means(rows, "control", metric))]
        results.append((metric, *interval(d), stats.ttest_1samp(d, 0.0).pvalue))
    for (metric, m, lo, hi, p), p_holm in zip(results, holm([r[4] for r in results])):
        print(f"3. {metric}: {m:+.0f} [{lo:+.0f}, {hi:+.0f}], p = {p:.2g} (Holm over four {p_holm:.2g})")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The tables of docs/TRANSFER.md from a `crux sweep` folder.

  transfer_modes.py SWEEP_DIR [--iterations 2000]

First, per cell (a transfer mode, when experiment.transfer is the listed key), transfer
minus control for each metric of summary.json: the mean over walls, its Student-t 95 %
interval, the p-value and the p-value Holm-adjusted over the cells; for total reward,
the difference relative to control's total. Where summary.json has them (since issue
28): the same for time to threshold at half, once, twice and four times the threshold
length, and rliable's view of every metric: the interquartile mean of the pair
differences and the probability that transfer beats control, each with its stratified
bootstrap interval. Then, per cell and for its
transfer and control runs, over their first N iterations: the share of actions each
regime of Algorithm 3 took, how often those actions reached, the mean rise of the root
per action, and how often an action retried the hold that failed at the iteration
before. Markdown on standard output. Only the standard library of Debian's
/usr/bin/python3 is used.
"""
import argparse
import csv
import json
import os

REGIMES = ("w_greedy", "g_greedy", "random")
METRICS = ("jumpstart", "early_episodes", "first_5_iterations", "time_to_threshold", "total_reward", "late_episodes",
           "last_10_length")
THRESHOLDS = ("time_to_threshold_half", "time_to_threshold", "time_to_threshold_2x", "time_to_threshold_4x")


def cell_name(cell):
    return ", ".join(str(v) for v in cell["parameters"].values()) or str(cell["cell"])


def has_metric(summary, metric, field="transfer_minus_control"):
    return any(field in cell["transfer_vs_control"].get(metric, {}) for cell in summary["cells"])


def table(summary, metrics, cell_text):
    """One row per cell, one column per metric, each written by cell_text(metric, comparison)
    ("-" where the cell lacks the metric or cell_text returns None)."""
    print("| cell | " + " | ".join(metrics) + " |")
    print("|---" * (len(metrics) + 1) + "|")
    for cell in summary["cells"]:
        cells = []
        for metric in metrics:
            comparison = cell["transfer_vs_control"].get(metric)
            text = cell_text(metric, comparison) if comparison is not None else None
            cells.append("-" if text is None else text)
        print(f"| {cell_name(cell)} | " + " | ".join(cells) + " |")


def metric_table(summary, metrics):
    table(summary, metrics, difference_text)


def difference_text(metric, comparison):
    d = comparison["transfer_minus_control"]
    scale = 1e6 if metric == "total_reward" else 1.0
    text = f"{d['mean'] / scale:+.3g}"
    if d["ci95_t_over_walls"]:
        low, high = d["ci95_t_over_walls"]
        text += f" [{low / scale:+.3g}, {high / scale:+.3g}]"
    if metric == "total_reward" and comparison.get("relative_difference") is not None:
        text += f" ({100 * comparison['relative_difference']:+.0f} %)"
    return text + f", p = {d['p_value']:.2g} (Holm {d['p_value_holm_over_cells']:.2g})"


def estimate(e, form):
    """rliable's {value, low, high} as "value [low, high]"; "-" for null."""
    parts = [format(e[k], form) if e[k] is not None else "-" for k in ("value", "low", "high")]
    return f"{parts[0]} [{parts[1]}, {parts[2]}]"


def rliable_text(metric, comparison):
    if "iqm" not in comparison:
        return None
    scale = 1e6 if metric == "total_reward" else 1.0
    difference = {k: (v / scale if v is not None else None) for k, v in comparison["iqm"]["difference"].items()}
    return f"{estimate(difference, '+.3g')}, P {estimate(comparison['probability_of_improvement'], '.2f')}"


def rliable_table(summary, metrics):
    table(summary, metrics, rliable_text)


def profile(run_folders, iterations):
    counts = {r: {"actions": 0, "reached": 0, "rise_cm": 0.0, "retries": 0} for r in REGIMES}
    for folder in run_folders:
        previous = None  # (hold, success) at the iteration before
        with open(os.path.join(folder, "iterations.csv"), newline="") as f:
            for row in csv.DictReader(f):
                if int(row["iteration"]) > iterations:
                    break
                c = counts[row["regime"]]
                c["actions"] += 1
                c["reached"] += int(row["success"])
                c["rise_cm"] += float(row["root_rise_cm"])
                if previous is not None and previous == (row["hold"], "0"):
                    c["retries"] += 1
                previous = (row["hold"], row["success"])
    return counts


def percent(part, whole):
    return f"{100.0 * part / whole:.0f} %" if whole else "-"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sweep")
    parser.add_argument("--iterations", type=int, default=2000)
    args = parser.parse_args()
    with open(os.path.join(args.sweep, "summary.json")) as f:
        summary = json.load(f)
    metric_table(summary, METRICS)
    print("\nTotal reward in millions, its difference relative to control's total in brackets.\n")
    if all(has_metric(summary, m) for m in THRESHOLDS):
        print("Time to threshold at half, once, twice and four times the threshold length.\n")
        metric_table(summary, THRESHOLDS)
        print()
    if has_metric(summary, "jumpstart", "iqm"):
        rliable = METRICS + THRESHOLDS[:1] + THRESHOLDS[2:]
        print("rliable's view: IQM of transfer minus control (pairs: same wall, same seed) and P(transfer beats "
              "control), 95 % stratified bootstrap intervals (walls kept, seeds resampled).\n")
        rliable_table(summary, [m for m in rliable if has_metric(summary, m, "iqm")])
        print()
    print(f"First {args.iterations} iterations; per regime: share of actions, reached, mean root rise per action, "
          "retries of the hold that failed just before.\n")
    print("| cell | condition | " + " | ".join(REGIMES) + " | all actions reached |")
    print("|---|---|---|---|---|---|")
    for cell in summary["cells"]:
        name = cell_name(cell)
        runs = cell["wall_pairs"] * cell["seeds_per_wall"]
        for condition in ("transfer", "control"):
            folders = [os.path.join(args.sweep, "runs", f"c{cell['cell']}", f"{condition}_{r}") for r in range(runs)]
            counts = profile(folders, args.iterations)
            total = sum(c["actions"] for c in counts.values())
            cells = []
            for r in REGIMES:
                c = counts[r]
                if c["actions"] == 0:
                    cells.append("0 %")
                    continue
                cells.append(f"{percent(c['actions'], total)}: reached {percent(c['reached'], c['actions'])}, "
                             f"{c['rise_cm'] / c['actions']:+.2f} cm, retries {percent(c['retries'], c['actions'])}")
            reached = sum(c["reached"] for c in counts.values())
            print(f"| {name} | {condition} | " + " | ".join(cells) + f" | {percent(reached, total)} |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The tables of docs/TRANSFER.md, "Many walls, both planners and the reach space", from
the summary.json of one or more sweeps: per cell, the transfer phase's iterations to the
first 5 episodes (transfer, control, transfer minus control with its 95 % t-interval over
walls, p and Holm over the sweep's cells, the saving as a share of control's), rliable's
IQM difference and probability of improvement with their stratified bootstrap intervals,
and Taylor and Stone's total (training plus the transfer phase's iterations to the first
5 episodes, against control's).

    scripts/transfer_walls_table.py SWEEP_FOLDER [METRIC]
"""
import json
import sys


def cell_name(parameters):
    short = {"experiment.training_walls": "K", "experiment.transfer": "", "learning.planner": "",
             "grid.agent_space": "", "training_wall.sigma": "sigma", "training_wall.tile_width": "tile width",
             "training_wall.incline": "training incline"}
    parts = []
    for key, value in parameters.items():
        label = short.get(key, key)
        parts.append(f"{label}={value}" if label else value.strip('"'))
    return ", ".join(parts)


def estimate(e, form):
    """rliable's {value, low, high} as "value [low, high]", or "value (no interval)" when the
    stratified bootstrap had nothing to resample (one seed per wall)."""
    if e["low"] is None or e["high"] is None:
        return f"{e['value']:{form}} (no interval)"
    return f"{e['value']:{form}} [{e['low']:{form}}, {e['high']:{form}}]"


def main():
    folder = sys.argv[1]
    metric = sys.argv[2] if len(sys.argv) > 2 else "first_5_iterations"
    with open(f"{folder}/summary.json") as f:
        summary = json.load(f)
    print(f"| cell | {metric}: transfer, control | transfer minus control [95 % t over walls], p (Holm over the sweep's "
          "cells) | saving, of control's | IQM difference [stratified bootstrap] | P(transfer beats control) "
          "| total: training + transfer phase (control) |")
    print("|---|---|---|---|---|---|---|")
    for cell in summary["cells"]:
        m = cell["transfer_vs_control"][metric]
        d = m["transfer_minus_control"]
        transfer, control = m["transfer"]["mean"], m["control"]["mean"]
        spent = cell["iterations_spent"]
        iqm = m["iqm"]["difference"]
        poi = m["probability_of_improvement"]
        lo, hi = d["ci95_t_over_walls"]
        saving = -d["mean"] / control if control else float("nan")
        total = ""
        if metric == "first_5_iterations":
            total = f"{spent['training']} + {transfer:.0f} = {spent['training'] + transfer:.0f} ({control:.0f})"
        print(f"| {cell_name(cell['parameters'])} | {transfer:.0f}, {control:.0f} | {d['mean']:+.0f} [{lo:+.0f}, {hi:+.0f}], "
              f"p = {d['p_value']:.2g} ({d['p_value_holm_over_cells']:.2g}) | {100 * saving:.0f} % | "
              f"{estimate(iqm, '+.0f')} | {estimate(poi, '.2f')} | {total} |")


if __name__ == "__main__":
    main()

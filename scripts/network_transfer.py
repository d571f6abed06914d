#!/usr/bin/python3
"""The network transfer mode against its control (docs/TRANSFER.md, "A policy learnt once"):
crux train on each random wall A..B with each learning seed, once with
`--transfer network --policy FILE` and once with its control (`--transfer seeded`, the same
rule with nothing to order ties by), paired by wall and seed. With --q-grid, also one
Q_grid learnt once (by `crux paper --training-walls 16` in the reach space, its training's
iterations given as --q-grid-iterations) reused by `crux transfer --transfer prior` on
every wall, against prior's control (the same rule from an empty Q_grid).

    PYTHONPATH=build/release/python /usr/bin/python3 scripts/network_transfer.py \
        --policy models/policies/reach-ppo.json --wall-seeds 20000:20029 --seeds 1:3 [--iterations 8000] \
        [--q-grid out/qgrid16/runs/training_0/q_grid.bin --q-grid-iterations 128000]

Reports, walls as the unit (each wall's mean over its seeds one observation): iterations to
complete the first 5 episodes (capped at the run's length, as summary.json's
first_5_iterations) per condition, network minus control with its 95 % t interval over walls
and the paired t-test, and the amortised total: the policy's training steps (read from the
policy file) divided by the walls it serves, plus the wall's own iterations, with the number
of walls from which it beats control.
"""
import argparse
import json
import math
import sys

import numpy as np
from scipy import stats

import crux

EARLY_EPISODES = 5
# The confirmed cell of docs/TRANSFER.md ("Confirmation on a fresh seed"): prior in the
# reach agent space with uniform planning, which the reused Q_grid was learnt in.
REACH_PRIOR = {"experiment.transfer": "prior", "grid.agent_space": "reach", "grid.columns": 8, "grid.rows": 4,
               "grid.tile_height": 0.3, "learning.planner": "uniform"}


def seed_range(text):
    first, _, last = text.partition(":")
    if not first.isdigit() or not last.isdigit() or int(last) < int(first):
        raise argparse.ArgumentTypeError(f"'{text}' is not A:B with 0 <= A <= B")
    return list(range(int(first), int(last) + 1))


def first_episodes(lengths, iterations):
    """Iterations to complete the first 5 episodes, the run's length when it completes fewer."""
    return float(sum(lengths[:EARLY_EPISODES])) if len(lengths) >= EARLY_EPISODES else float(iterations)


def run(wall_seed, seed, iterations, config, q_grid=None):
    result = crux.run_learning(crux.Wall.random(wall_seed), dict(config, **{"experiment.iterations": iterations}),
                               seed=seed, q_grid=q_grid)
    return first_episodes(list(result.episode_lengths), iterations)


def compare(first, second, training_steps):
    """first against second, walls as the unit, and the walls from which first's amortised total beats second."""
    differences = np.array(first) - np.array(second)
    mean, low, high = interval(differences)
    saving = float(np.mean(second) - np.mean(first))
    return {
        "first_5_iterations": [float(np.mean(first)), float(np.mean(second))],
        "difference": {"mean": mean, "low": low, "high": high,
                       "p_value": float(stats.ttest_1samp(differences, 0.0).pvalue)},
        "walls_lower": int(np.sum(differences < 0)),
        "saving_share": saving / float(np.mean(second)),
        "training": training_steps,
        # Amortised over N walls: training / N + first < second when N > training / saving.
        "walls_to_beat_control": math.floor(training_steps / saving) + 1 if saving > 0 else None,
    }


def interval(differences):
    n = len(differences)
    mean = float(np.mean(differences))
    half = float(stats.t.ppf(0.975, n - 1) * stats.sem(differences)) if n > 1 else math.nan
    return mean, mean - half, mean + half


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--policy", required=True)
    parser.add_argument("--wall-seeds", type=seed_range, required=True)
    parser.add_argument("--seeds", type=seed_range, default=[1, 2, 3])
    parser.add_argument("--iterations", type=int, default=8000)
    parser.add_argument("--q-grid", help="a Q_grid learnt once, reused by prior on every wall")
    parser.add_argument("--q-grid-iterations", type=int, help="the iterations that learnt it")
    args = parser.parse_args()
    if args.q_grid and args.q_grid_iterations is None:
        parser.error("--q-grid-iterations: give the iterations that learnt the Q_grid")
    with open(args.policy) as f:
        policy_steps = json.load(f)["training"]["steps"]
    network_config = {"experiment.transfer": "network", "experiment.policy": args.policy}
    conditions = {"network": ({"experiment.transfer": "seeded"}, network_config, None)}
    if args.q_grid:
        conditions["reused_q_grid"] = (REACH_PRIOR, REACH_PRIOR, args.q_grid)
    means = {name: ([], []) for name in conditions}
    for wall in args.wall_seeds:
        for name, (control, treated, q_grid) in conditions.items():
            means[name][0].append(np.mean([run(wall, s, args.iterations, treated, q_grid) for s in args.seeds]))
            means[name][1].append(np.mean([run(wall, s, args.iterations, control) for s in args.seeds]))
        print(f"wall {wall}: " + ", ".join(f"{name} {m[0][-1]:.0f} (control {m[1][-1]:.0f})"
                                           for name, m in means.items()), file=sys.stderr)
    training = {"network": policy_steps, "reused_q_grid": args.q_grid_iterations}
    result = {"walls": len(args.wall_seeds), "seeds": args.seeds, "iterations": args.iterations,
              "comparisons": {name: compare(*means[name], training[name]) for name in conditions},
              "per_wall": {name: {"wall_seeds": args.wall_seeds, "treated": m[0], "control": m[1]}
                           for name, m in means.items()}}
    if args.q_grid:  # the two kinds of knowledge on the same walls, each in its own mode
        result["network_against_reused_q_grid"] = compare(means["network"][0], means["reused_q_grid"][0], 0)
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()

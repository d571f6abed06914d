#!/usr/bin/python3
"""The network transfer mode against its control (docs/TRANSFER.md, "A policy learnt once"):
crux train on each random wall A..B with each learning seed, once with
`--transfer network --policy FILE` and once with its control (`--transfer seeded`, the same
rule with nothing to order ties by), paired by wall and seed.

    PYTHONPATH=build/release/python /usr/bin/python3 scripts/network_transfer.py \
        --policy models/policies/ppo.json --wall-seeds 20000:20029 --seeds 1:3 [--iterations 8000]

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


def seed_range(text):
    first, _, last = text.partition(":")
    if not first.isdigit() or not last.isdigit() or int(last) < int(first):
        raise argparse.ArgumentTypeError(f"'{text}' is not A:B with 0 <= A <= B")
    return list(range(int(first), int(last) + 1))


def first_episodes(lengths, iterations):
    """Iterations to complete the first 5 episodes, the run's length when it completes fewer."""
    return float(sum(lengths[:EARLY_EPISODES])) if len(lengths) >= EARLY_EPISODES else float(iterations)


def run(wall_seed, seed, iterations, transfer, policy=None):
    config = {"experiment.iterations": iterations, "experiment.transfer": transfer}
    if policy:
        config["experiment.policy"] = policy
    result = crux.run_learning(crux.Wall.random(wall_seed), config, seed=seed)
    return first_episodes(list(result.episode_lengths), iterations)


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
    args = parser.parse_args()
    with open(args.policy) as f:
        policy_steps = json.load(f)["training"]["steps"]
    network, control = [], []
    for wall in args.wall_seeds:
        network.append(np.mean([run(wall, s, args.iterations, "network", args.policy) for s in args.seeds]))
        control.append(np.mean([run(wall, s, args.iterations, "seeded") for s in args.seeds]))
        print(f"wall {wall}: network {network[-1]:.0f}, control {control[-1]:.0f}", file=sys.stderr)
    differences = np.array(network) - np.array(control)
    mean, low, high = interval(differences)
    saving = float(np.mean(control) - np.mean(network))
    result = {
        "walls": len(args.wall_seeds), "seeds": args.seeds, "iterations": args.iterations,
        "first_5_iterations": {"network": float(np.mean(network)), "control": float(np.mean(control))},
        "network_minus_control": {"mean": mean, "low": low, "high": high,
                                  "p_value": float(stats.ttest_1samp(differences, 0.0).pvalue)},
        "saving_share": saving / float(np.mean(control)),
        "policy_training_steps": policy_steps,
        # Amortised over N walls: steps / N + network < control when N > steps / saving.
        "walls_to_beat_control": math.floor(policy_steps / saving) + 1 if saving > 0 else None,
        "per_wall": [{"wall_seed": w, "network": n, "control": c}
                     for w, n, c in zip(args.wall_seeds, network, control)],
    }
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""How closely paired learning runs stay together (docs/REPRODUCTION.md, "Paired runs").

It reads only the per-run CSV files, so it measures any build of crux, including
those from before summary.json reported divergence and correlations.

  paired_runs.py folder PAPER_DIR
      transfer_i against control_i of a `crux paper` folder: the iteration at which each
      pair first tries a different hold or gets a different verdict, and the correlation
      of early-episode counts between the pairs.
  paired_runs.py solvers CRUX OUT_DIR [--walls 1-6] [--seeds 1-4] [--jobs 2]
      `crux train --wall-seed W --seed S --ik-solver fast|paper` on every wall seed W x
      learning seed S (--walls and --seeds are ranges of seeds), then the same
      comparison between the two solvers, with the paired difference in episodes per
      run analysed over walls. A build that predates --ik-solver gets --solver.

Only the standard library of Debian's /usr/bin/python3 is used.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import statistics
import subprocess
import sys


def read_run(folder):
    with open(os.path.join(folder, "iterations.csv"), newline="") as f:
        return [(row["hold"], row["success"]) for row in csv.DictReader(f)]


def episode_lengths(folder):
    with open(os.path.join(folder, "episodes.csv"), newline="") as f:
        return [int(row["length"]) for row in csv.DictReader(f)]


def first_divergence(a, b):
    """1-based iteration of the first different (hold, verdict); None if none."""
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return i + 1
    return None


def episodes_within(lengths, window):
    end, count = 0, 0
    for length in lengths:
        end += length
        if end <= window:
            count += 1
    return count


def median_divergence(values, iterations):
    return statistics.median(v if v is not None else iterations + 1 for v in values)


def correlation(a, b):
    try:
        return statistics.correlation(a, b)
    except statistics.StatisticsError:
        return float("nan")


def t_quantile_975(dof):
    """Two-sided 95 % Student-t critical value (standard tables); between rows, the row
    of fewer degrees of freedom, whose wider interval errs on the safe side."""
    table = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262,
             10: 2.228, 15: 2.131, 20: 2.086, 25: 2.060, 29: 2.045, 40: 2.021, 60: 2.000, 120: 1.980}
    return table[max(k for k in table if k <= dof)]


def over_walls(differences_by_wall):
    means = [statistics.fmean(v) for v in differences_by_wall.values()]
    n = len(means)
    mean = statistics.fmean(means)
    sd = statistics.stdev(means) if n > 1 else 0.0
    half = t_quantile_975(n - 1) * sd / math.sqrt(n) if n > 1 else 0.0
    t = mean / (sd / math.sqrt(n)) if sd > 0 else (0.0 if mean == 0 else math.copysign(math.inf, mean))
    return mean, half, t, n


def folder_report(args):
    runs = os.path.join(args.folder, "runs")
    pairs = sorted({name.split("_", 1)[1] for name in os.listdir(runs) if name.startswith("transfer_")}, key=int)
    divergence, early_t, early_c = [], [], []
    iterations = 0
    for i in pairs:
        t_dir, c_dir = os.path.join(runs, "transfer_" + i), os.path.join(runs, "control_" + i)
        a, b = read_run(t_dir), read_run(c_dir)
        iterations = len(a)
        divergence.append(first_divergence(a, b))
        early_t.append(episodes_within(episode_lengths(t_dir), args.window))
        early_c.append(episodes_within(episode_lengths(c_dir), args.window))
    print(f"{len(pairs)} transfer/control pairs")
    print(f"  first divergence: median {median_divergence(divergence, iterations)}; "
          f"values {sorted(d if d is not None else iterations + 1 for d in divergence)}")
    print(f"  episodes in the first {args.window} iterations: correlation of the pairs "
          f"{correlation(early_t, early_c):.2f}")


def solver_flag(crux):
    """`--ik-solver` (ik.solver); builds from before the command line was redesigned
    named it `--solver`."""
    usage = subprocess.run([crux, "train", "--help"], check=True, capture_output=True, text=True).stdout
    return "--ik-solver" if "--ik-solver" in usage else "--solver"


def run_train(crux, flag, out, wall, seed, solver):
    folder = os.path.join(out, f"w{wall}_s{seed}_{solver}")
    if not os.path.exists(os.path.join(folder, "episodes.csv")):
        subprocess.run([crux, "train", "--wall-seed", str(wall), "--seed", str(seed), flag, solver,
                        "-o", folder], check=True, stdout=subprocess.DEVNULL)
    return folder


def parse_range(text):
    low, _, high = text.partition("-")
    return range(int(low), int(high or low) + 1)


def solvers_report(args):
    walls, seeds = parse_range(args.walls), parse_range(args.seeds)
    jobs = [(w, s, solver) for w in walls for s in seeds for solver in ("paper", "fast")]
    flag = solver_flag(args.crux)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        folders = dict(zip(jobs, pool.map(lambda j: run_train(args.crux, flag, args.out, *j), jobs)))
    by_wall, divergence, fast_episodes, paper_episodes = {}, [], [], []
    iterations = 0
    for w in walls:
        for s in seeds:
            fast, paper = folders[(w, s, "fast")], folders[(w, s, "paper")]
            a, b = read_run(fast), read_run(paper)
            iterations = len(a)
            divergence.append(first_divergence(a, b))
            ef, ep = len(episode_lengths(fast)), len(episode_lengths(paper))
            fast_episodes.append(ef)
            paper_episodes.append(ep)
            by_wall.setdefault(w, []).append(ep - ef)
    mean, half, t, n = over_walls(by_wall)
    print(f"{len(fast_episodes)} wall/seed pairs over {n} walls")
    print(f"  episodes per run: fast {statistics.fmean(fast_episodes):.1f}, paper {statistics.fmean(paper_episodes):.1f}")
    print(f"  paper - fast over walls: {mean:+.1f} +- {half:.1f} (95 % t over {n} walls), t = {t:.2f}")
    print(f"  correlation of the pairs' episode counts: {correlation(fast_episodes, paper_episodes):.2f}")
    print(f"  first divergence: median {median_divergence(divergence, iterations)}; "
          f"at iteration 1 in {sum(1 for d in divergence if d == 1)} of {len(divergence)} pairs; "
          f"never in {sum(1 for d in divergence if d is None)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    folder = sub.add_parser("folder")
    folder.add_argument("folder")
    folder.add_argument("--window", type=int, default=2000)
    solvers = sub.add_parser("solvers")
    solvers.add_argument("crux")
    solvers.add_argument("out")
    solvers.add_argument("--walls", default="1-6")
    solvers.add_argument("--seeds", default="1-4")
    solvers.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    (folder_report if args.command == "folder" else solvers_report)(args)


if __name__ == "__main__":
    sys.exit(main())

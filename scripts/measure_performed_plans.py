#!/usr/bin/python3
"""Plans repaired in MuJoCo on random walls (docs/PHYSICS.md, "Plans repaired in MuJoCo").

For each wall seed: the static model's exact plan (crux plan --physics-model static) and
the same plan performed and repaired (crux plan --physics-model dynamic): whether the
first plan was performed as planned, whether a repaired plan reached the top, its length
against the static plan's, the replans, the moves simulated, the causes of the failed
moves, and the wall-clock cost of each.

    scripts/measure_performed_plans.py [--crux build/release/crux] [--walls 1:30]
        [--incline 0] [--max-replans 20] [--check-moves]
"""

import argparse
import collections
import json
import subprocess
import sys
import time


def run(crux, args):
    started = time.monotonic()
    done = subprocess.run([crux, *args, "--json"], capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr, time.monotonic() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--crux", default="build/release/crux")
    parser.add_argument("--walls", default="1:30", help="first:last wall seed")
    parser.add_argument("--incline", type=float, default=0.0)
    parser.add_argument("--max-replans", type=int, default=20)
    parser.add_argument("--check-moves", action="store_true",
                        help="both plans with experiment.plan_check_moves: each move's IK path must hold still too")
    options = parser.parse_args()
    first, last = map(int, options.walls.split(":"))
    wall_flags = ["--wall-incline", str(options.incline)]
    if options.check_moves:
        wall_flags += ["--plan-check-moves", "true"]
    planned = performed_first = repaired = 0
    causes = collections.Counter()
    extra_moves, replans, static_s, dynamic_s = [], [], 0.0, 0.0
    print("wall  static  first  repaired  length  replans  simulated  static_s  dynamic_s  causes")
    for seed in range(first, last + 1):
        wall = ["--wall-seed", str(seed), *wall_flags]
        code, out, err, seconds = run(options.crux, ["plan", *wall, "--physics-model", "static"])
        if code != 0 or not json.loads(out)["found"]:
            print(f"{seed:4d}  no static plan ({err.strip() or 'none found'})")
            continue
        planned += 1
        static_s += seconds
        plan_s = seconds
        static_length = json.loads(out)["length"]
        code, out, err, seconds = run(
            options.crux,
            ["plan", *wall, "--physics-model", "dynamic", "--plan-max-replans", str(options.max_replans)])
        if code != 0:
            print(f"{seed:4d}  crux plan --physics-model dynamic failed: {err.strip()}", file=sys.stderr)
            return 1
        dynamic_s += seconds
        record = json.loads(out)
        first_ok = not record["failed_moves"] and record["reached_top"]
        performed_first += first_ok
        repaired += record["reached_top"]
        replans.append(record["replans"])
        # Under the dynamic model every failed move, the last one included, is in failed_moves.
        wall_causes = [move["cause"] for move in record["failed_moves"]]
        causes.update(wall_causes)
        if record["reached_top"]:
            extra_moves.append(record["length"] - static_length)
        length = record["length"] if record["found"] else "-"
        print(f"{seed:4d}  {static_length:6d}  {'yes' if first_ok else 'no':>5}  "
              f"{'yes' if record['reached_top'] else 'no':>8}  {length!s:>6}  {record['replans']:7d}  "
              f"{record['moves_simulated']:9d}  {plan_s:8.1f}  {seconds:9.1f}  {','.join(wall_causes)}")
    print(f"\n{planned} walls with a static plan at {options.incline:g} degrees")
    if planned:
        print(f"first plan performed as planned: {performed_first} ({100 * performed_first / planned:.1f} %)")
        print(f"a climb performed to the top after repair: {repaired} ({100 * repaired / planned:.1f} %)")
        if extra_moves:
            print(f"repaired climbs' extra moves over the static plan: mean "
                  f"{sum(extra_moves) / len(extra_moves):.2f}, max {max(extra_moves)}")
        print(f"replans: mean {sum(replans) / len(replans):.1f}, max {max(replans)}")
        print("failed moves by cause: " + ", ".join(f"{c} {n}" for c, n in causes.most_common()))
        print(f"wall-clock: static plans {static_s:.1f} s, dynamic plans {dynamic_s:.1f} s "
              f"({dynamic_s / max(static_s, 1e-9):.1f} times)")
    return 0


if __name__ == "__main__":
    sys.exit(main())

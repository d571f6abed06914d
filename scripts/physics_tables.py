#!/usr/bin/python3
"""The rows of docs/PHYSICS.md's two tables in "Which stances hold", computed by `crux
stances --json` (about a second per row): which stances hold at 0, 20 and 40 degrees, and
the same survey with each climbing level's grip.

    scripts/physics_tables.py CRUX            print both tables' rows
    scripts/physics_tables.py CRUX --check DOC    exit 1, naming the rows, unless DOC holds
                                              every row as printed

CRUX is the crux binary (build/release/crux). A row's failure reasons are the four most
frequent, joints summed over both sides, ties in alphabetical order.
"""
import json
import subprocess
import sys
from collections import Counter

INCLINES = {0: "0 (vertical)", 20: "20 (overhang)", 40: "40 (overhang)"}
LEVELS = ("intermediate", "advanced", "elite")


def survey(crux, *flags):
    done = subprocess.run([crux, "stances", "--json", *flags], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def share(estimate):
    return f"{100 * estimate['mean']:.1f} % ± {100 * estimate['ci95_half_width']:.1f}"


def reasons(failures, total):
    """"39: contacts 29, shoulder flexion 6, ...": the total, then the four most frequent
    reasons with a joint's sides summed."""
    summed = Counter()
    for name, count in failures.items():
        summed[name.removeprefix("left_").removeprefix("right_").replace("_", " ")] += count
    top = sorted(summed.items(), key=lambda item: (-item[1], item[0]))[:4]
    return f"{total}: " + ", ".join(f"{name} {count}" for name, count in top)


def held_cells(s):
    return f"{share(s['share_four_held'])} | {share(s['share_three_held_of_four_held'])} | {share(s['share_held'])}"


def rows(crux):
    held = []
    for incline, label in INCLINES.items():
        s = survey(crux, "--wall-incline", str(incline))
        held.append(f"| {label} | {held_cells(s)} | {reasons(s['four_failures'], s['stances'] - s['four_held'])} | "
                    f"{reasons(s['three_failures'], s['four_held'] - s['three_held'])} |")
    grips = []
    for incline in INCLINES:
        for level in LEVELS:
            s = survey(crux, "--wall-incline", str(incline), "--physics-strength", level)
            four_failing, three_failing = s["stances"] - s["four_held"], s["four_held"] - s["three_held"]
            grips.append(f"| {incline} | `{level}` ({s['physics']['grip_n']:.1f} N) | {held_cells(s)} | "
                         f"{s['four_failures'].get('grip', 0)} of {four_failing} | "
                         f"{s['three_failures'].get('grip', 0)} of {three_failing} | "
                         f"{s['path_moves_failing']} of {s['path_moves']} |")
    return held + grips


def main():
    if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != "--check"):
        sys.exit(__doc__)
    computed = rows(sys.argv[1])
    if len(sys.argv) == 2:
        print("\n".join(computed))
        return
    with open(sys.argv[3], encoding="utf-8") as f:
        documented = set(f.read().splitlines())
    missing = [row for row in computed if row not in documented]
    for row in missing:
        print(f"{sys.argv[3]} lacks the row crux stances gives now:\n  {row}", file=sys.stderr)
    sys.exit(1 if missing else 0)


if __name__ == "__main__":
    main()

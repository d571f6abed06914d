#!/usr/bin/python3
"""The Fig. 3 and Fig. 4 tables of docs/REPRODUCTION.md from a `crux paper` folder.

  figure_tables.py OUT_DIR

Fig. 3: mean cumulative actions per regime (w-greedy / g-greedy / random) at chosen
iterations, from figures/fig3_regimes.csv. Fig. 4: mean episode length by episode
index over the runs that reached it, from figures/fig4_episode_lengths.csv.
Only the standard library of Debian's /usr/bin/python3 is used.
"""
import csv
import os
import statistics
import sys

CONDITIONS = ("training", "transfer", "control")


def fig3(folder, iterations=(500, 1000, 2000, 4000, 8000)):
    rows = {}
    with open(os.path.join(folder, "figures", "fig3_regimes.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if int(row["iteration"]) in iterations:
                rows[(row["condition"], int(row["iteration"]))] = row
    print("| iteration | " + " | ".join(CONDITIONS) + " |")
    print("|---|---|---|---|")
    for i in iterations:
        cells = []
        for c in CONDITIONS:
            r = rows.get((c, i))
            cells.append(" / ".join(f"{float(r[k]):.0f}" for k in ("w_greedy", "g_greedy", "random")) if r else "-")
        print(f"| {i} | " + " | ".join(cells) + " |")


def fig4(folder, episodes=(1, 2, 3, 4, 5, 10, 20, 30, 40, 60, 80)):
    lengths = {}
    with open(os.path.join(folder, "figures", "fig4_episode_lengths.csv"), newline="") as f:
        for row in csv.DictReader(f):
            lengths.setdefault((row["condition"], int(row["episode"]) + 1), []).append(int(row["length"]))
    print("| episode | " + " | ".join(str(e) for e in episodes) + " |")
    print("|---" * (len(episodes) + 1) + "|")
    for c in CONDITIONS:
        cells = [f"{statistics.fmean(lengths[(c, e)]):.0f} ({len(lengths[(c, e)])})" if (c, e) in lengths else "-"
                 for e in episodes]
        print(f"| {c} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    fig3(sys.argv[1])
    print()
    fig4(sys.argv[1])

"""Fig. 4 of the paper from a `crux paper` output folder, with pandas and matplotlib:
each condition's episode lengths on a log axis, episode k averaged over the runs that
completed k + 1 episodes.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/fig4_from_paper_folder.py out/paper fig4.png
"""

import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

folder, output = pathlib.Path(sys.argv[1]), sys.argv[2]
frames = []
for run in sorted((folder / "runs").iterdir()):
    condition, index = run.name.rsplit("_", 1)
    episodes = pd.read_csv(run / "episodes.csv")
    frames.append(episodes.assign(condition=condition, run=int(index)))
episodes = pd.concat(frames)
mean_lengths = episodes.groupby(["condition", "episode"])["length"].mean().unstack(0)

summary = json.loads((folder / "summary.json").read_text())
figure, axes = plt.subplots(figsize=(7, 4))
for condition in mean_lengths.columns:
    axes.plot(mean_lengths.index, mean_lengths[condition], marker=".", label=condition)
axes.set(yscale="log", xlabel="episode", ylabel="episode length (actions)",
         title=f"Fig. 4: {summary['iterations']} iterations per run, {summary['wall_pairs']} wall pairs")
axes.legend()
figure.savefig(output, dpi=100, bbox_inches="tight")
print(f"wrote {output}: {len(frames)} runs, {len(mean_lengths)} episodes")

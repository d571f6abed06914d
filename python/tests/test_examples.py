"""The examples of examples/python run, and say what they did."""

import pathlib
import re
import subprocess
import sys

import crux

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run_example(name, *args):
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_q_learning_climbs_episodes():
    out = run_example("q_learning.py", "--steps", 4000)
    episodes = int(re.match(r"(\d+) episodes", out).group(1))
    assert episodes >= 2, out


def test_fig4_is_drawn_from_a_paper_folder(tmp_path):
    crux.run_experiment({"experiment": {"walls": 2, "iterations": 500, "plan": False, "bootstrap_resamples": 100}},
                        output=tmp_path / "paper")
    out = run_example("fig4_from_paper_folder.py", tmp_path / "paper", tmp_path / "fig4.png")
    assert "6 runs" in out
    assert (tmp_path / "fig4.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

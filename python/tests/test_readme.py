"""README's "From Python" lines run as written, with the PYTHONPATH README gives, so that
README cannot drift from the module. Of its two ways to get Gymnasium, the test takes the
source on the path (the tests' own Gymnasium); pip needs PyPI, which CI does not reach."""

import json
import os
import pathlib
import re
import subprocess
import textwrap

import numpy as np
import pytest

import crux

from needed import GYMNASIUM, need

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"


def from_python():
    text = README.read_text()
    start = text.index("\n## From Python\n")
    return text[start : text.index("\n## ", start + 1)]


def fenced(language):
    """The section's code blocks in `language`, those indented in list items dedented."""
    pattern = re.compile(rf"^( *)```{language}\n(.*?)^\1```$", re.S | re.M)
    return [textwrap.dedent(match.group(2)) for match in pattern.finditer(from_python())]


@pytest.fixture
def repository(tmp_path):
    """A folder whose build/release/python is the module under test, for README's relative paths."""
    (tmp_path / "build" / "release").mkdir(parents=True)
    (tmp_path / "build" / "release" / "python").symlink_to(pathlib.Path(crux.__file__).absolute().parents[1])
    return tmp_path


def run_shell(script, cwd, stdin=None, **variables):
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}  # README sets its own
    return subprocess.run(["bash", "-c", script], cwd=cwd, input=stdin, capture_output=True, text=True,
                          env=dict(env, **variables), timeout=120)


def test_import_crux_runs_with_readmes_pythonpath(repository):
    (line,) = [line for block in fenced("sh") for line in block.splitlines()
               if line.startswith("PYTHONPATH=build/release/python /usr/bin/python3 -c")]
    done = run_shell(line, repository)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("<crux.BodyModel 'crux_human'"), done.stdout


def test_the_python_block_runs_with_gymnasiums_source_on_readmes_pythonpath(repository):
    (gymnasium,) = need(["gymnasium"], GYMNASIUM)
    (source_way,) = [block for block in fenced("sh") if block.startswith("GYMNASIUM=")]
    _, command = source_way.splitlines()
    (python,) = fenced("python")
    # README's GYMNASIUM names the reader's unpacked source; here, the tests' one.
    done = run_shell(command, repository, stdin=python, GYMNASIUM=str(pathlib.Path(gymnasium.__file__).parents[1]))
    assert done.returncode == 0, done.stderr


def run_policy_line(repository, script):
    """README's one shell line that runs the example script, from a folder with the
    repository's examples and models, Gymnasium's source on the path: the line and its run."""
    (gymnasium,) = need(["gymnasium"], GYMNASIUM)
    need(["torch"], "the policy needs Debian's python3-torch")
    (line,) = [line for block in fenced("sh") for line in block.splitlines() if script in line]
    for folder in ("examples", "models"):
        (repository / folder).symlink_to(README.parent / folder)
    done = run_shell(line, repository, GYMNASIUM=str(pathlib.Path(gymnasium.__file__).parents[1]))
    assert done.returncode == 0, done.stderr
    return line, done


def test_the_shipped_policy_climbs_the_held_out_walls_as_readme_says(repository):
    line, done = run_policy_line(repository, "policy_baseline.py evaluate")
    # The same walls' climbs in the shipped policy's held-out record, which docs/BASELINES.md quotes.
    first, last = (int(seed) for seed in line.split("--wall-seeds ")[1].split()[0].split(":"))
    record = json.loads((README.parent / "models" / "policies" / "reach-ppo.heldout.json").read_text())
    climbs = record["walls"][:last - first + 1]
    assert [c["wall_seed"] for c in climbs] == list(range(first, last + 1))
    finished = [c for c in climbs if c["finished"]]
    assert done.stdout == (f"{len(climbs)} climbs, {len(finished) / len(climbs):.1%} finished, mean length "
                           f"{float(np.mean([c['length'] for c in finished]))}, mean plan length "
                           f"{float(np.mean([c['plan_length'] for c in finished]))}\n"), done.stdout
    baselines = (README.parent / "docs" / "BASELINES.md").read_text()
    assert (f"| held-out, 20000-20029 | {record['finished']:.0%} (30 of 30) | {record['mean_length']:.1f} "
            f"| {record['mean_plan_length']:.1f} | {record['mean_length_ratio']:.2f} "
            f"| {record['within_1_5_plans']:.0%} |").replace("%", " %") in baselines


def quick_tour():
    text = README.read_text()
    start = text.index("\n## A quick tour\n")
    block = text[text.index("```sh\n", start) + 6:]
    return block[: block.index("\n```")].splitlines()


def test_the_tours_static_model_lines_show_a_climb(tmp_path):
    """Each static-model line of the tour learns a climb (not "0 episodes"), and the view
    that follows draws it (a run without a climb has no posture to show: exit 2)."""
    binary = os.environ.get("CRUX_BINARY")
    if not binary:
        pytest.skip("CRUX_BINARY names the crux binary (ctest sets it)")
    (tmp_path / "bin").mkdir()
    (tmp_path / "bin" / "crux").symlink_to(binary)
    lines = [line for line in quick_tour()
             if "--physics-model static" in line or line.startswith("crux view --run out/climbs")]
    assert len(lines) >= 3, lines
    path = f"{tmp_path / 'bin'}{os.pathsep}{os.environ['PATH']}"
    for line in lines:
        done = run_shell(line, tmp_path, PATH=path)
        assert done.returncode == 0, f"{line}\n{done.stderr}"
        if line.startswith("crux train"):
            episodes = int(re.search(r": (\d+) episodes? in ", done.stdout).group(1))
            assert episodes > 0, f"{line}\n{done.stdout}"
            assert "greedy climb: does not finish" not in done.stdout, done.stdout


def test_the_tours_performed_climb_is_reported_and_viewed(tmp_path):
    """The tour's static plan performed in MuJoCo, then its report and its view, and its learning
    run under the dynamic model, run as written."""
    binary = os.environ.get("CRUX_BINARY")
    if not binary:
        pytest.skip("CRUX_BINARY names the crux binary (ctest sets it)")
    (tmp_path / "bin").mkdir()
    (tmp_path / "bin" / "crux").symlink_to(binary)
    lines = [line for line in quick_tour() if line.startswith(
        ("crux perform --wall-seed", "crux report out/perform ", "crux view --run out/perform ",
         "crux train --wall-seed 3 --physics-model dynamic"))]
    assert len(lines) == 4, lines
    path = f"{tmp_path / 'bin'}{os.pathsep}{os.environ['PATH']}"
    for line in lines:
        done = run_shell(line, tmp_path, PATH=path)
        assert done.returncode == 0, f"{line}\n{done.stderr}"
    assert 'id="crux-performed-data"' in (tmp_path / "perform.html").read_text()
    assert 'class="hold-forces"' in (tmp_path / "performed.svg").read_text()
    facts = json.loads((tmp_path / "out" / "dynamic" / "summary.json").read_text())["run_facts"]["training"][0]
    assert facts["moves_simulated"] > 0


def test_the_policy_trained_under_its_veto_climbs_as_its_record_says(repository):
    line, done = run_policy_line(repository, "reach_estimate.py evaluate")
    # The same walls' climbs in the record docs/BASELINES.md quotes, and their plans.
    first, last = (int(seed) for seed in line.split("--wall-seeds ")[1].split()[0].split(":"))
    record = json.loads((README.parent / "models" / "policies" / "search" / "reach_estimate.json").read_text())
    tuned = record["trained_under_the_veto"]
    climbs = tuned["held_out_walls"][:last - first + 1]
    plans = record["held_out_walls_20000_21499"]["walls"][:last - first + 1]
    assert [c["wall_seed"] for c in climbs] == [p["wall_seed"] for p in plans] == list(range(first, last + 1))
    ratios = [c["length"] / p["plan_length"] for c, p in zip(climbs, plans) if c["finished"]]
    finished = sum(c["finished"] for c in climbs) / len(climbs)
    assert (f"climbs 3000 held-out walls with it in {tuned['ratio']['mean']:.3f} times their exact plans on average "
            f"(over the {tuned['finished']['mean']:.1%} of climbs that finish)").replace("%", " %") in " ".join(
        README.read_text().split())
    assert done.stdout == (f"veto 0.5: {len(climbs)} climbs, {finished:.1%} finished, {sum(ratios) / len(ratios):.3f} "
                           f"times the plan, {sum(c['failed_moves'] for c in climbs)} failed moves\n"), done.stdout


"""Every config key at its extremes (docs/RELIABILITY.md, "Every key at its extremes").

The keys and their bounds come from the one declaration of each key, as each command
prints it (`crux COMMAND --dry-run --json`), so that a key added later is walked without
touching this file. For each numeric key of each command below: its minimum, maximum,
just beyond each, a huge finite value, NaN and infinities; for each choice, the empty
string and an unknown name. A value beyond the bounds must be refused in one line with
exit 2 and nothing left behind; a value within them either is refused so (when other
keys rule it out) or completes a small run whose outputs are finite and which crux reads
back (crux report, crux figures). A key that sizes the work is checked at its maximum by
--dry-run alone. Python's run_learning and run_experiment take the same values: a
ValueError naming the key, or a finite run.
"""

import atexit
import concurrent.futures
import csv
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import tempfile

import pytest

import crux

WALL_FILE = pathlib.Path(__file__).resolve().parents[2] / "walls" / "home_12.json"
# A wall that one move climbs, for crux perform's keys (tests/support/jug_ladder.hpp): feet
# at knee height, hands above the shoulders, a jug 20 cm above the right hand. The finish
# lies between the centres of mass of the right hand's two stances as the planner reaches
# them, back on its hold (1.437 m) and on the jug (1.445 to 1.45 m), so that the exact
# plan is the one move up to the jug; test_the_ladder_is_climbed_by_one_move checks it.
LADDER = {
    "format": "crux-wall", "version": 1, "name": "jug ladder", "finish_height": 1.444,
    "start": {"right_hand": 1, "left_hand": 2, "right_foot": 3, "left_foot": 4},
    "holds": [{"id": i + 1, "position": [0.0, y, z], "radius": 0.04}
              for i, (y, z) in enumerate([(-0.25, 1.75), (0.25, 1.75), (-0.15, 0.45), (0.15, 0.45), (-0.25, 1.95)])],
}
LADDER_FOLDER = pathlib.Path(tempfile.mkdtemp(prefix="crux-key-walk-"))
atexit.register(shutil.rmtree, LADDER_FOLDER, True)
LADDER_FILE = LADDER_FOLDER / "jug_ladder.json"
LADDER_FILE.write_text(json.dumps(LADDER))
# Each command's small run (a second or less) and how its output folder is read back.
# Plan gets a solve budget, since an exact plan can take seconds.
COMMANDS = {
    "train": {
        "base": ["--wall-seed", "1", "--iterations", "40", "--physics-model", "static"],
        "output": True,
        "read_back": [["report", "{out}", "-o", "{scratch}/page.html"]],
    },
    "paper": {
        "base": ["--walls", "1", "--iterations", "30", "--plan", "false", "--bootstrap-resamples", "100"],
        "output": True,
        "read_back": [["figures", "{out}"]],
    },
    "plan": {"base": ["--wall-seed", "1", "--physics-model", "static", "--plan-max-solves", "300"]},
    "stances": {"base": ["--wall-count", "1", "--stances-moves", "10"]},
    "ik-compare": {"base": ["--compare-queries", "5"]},
    "filter-stats": {"base": ["--wall-count", "1"]},
    "perform": {"base": ["--wall-file", str(LADDER_FILE), "--physics-model", "dynamic"], "output": True},
}
RUN_SECONDS = 60  # a small run's allowance; every one takes well under a second


def crux_binary():
    path = os.environ.get("CRUX_BINARY") or str(pathlib.Path(crux.__file__).resolve().parents[2] / "crux")
    assert os.access(path, os.X_OK), f"no crux binary at {path}: set CRUX_BINARY"
    return path


def run(args, timeout=RUN_SECONDS):
    done = subprocess.run([crux_binary(), *map(str, args)], capture_output=True, text=True, timeout=timeout)
    return done.returncode, done.stdout, done.stderr


def declared_keys(command):
    code, out, err = run([command, *COMMANDS[command]["base"], "--dry-run", "--json"])
    assert code == 0, err
    return json.loads(out)["keys"]


def walked_keys(command, train_keys):
    """Each key through the commands that use it: train (read back by report) walks the
    learning's, the wall's and the physics' keys; paper (read back by figures) what train
    does not take (the experiment's design, the training walls) and the figures' keys
    (grid.*); plan, stances, ik-compare and filter-stats the keys of a stance, a plan and
    a reaching query; perform the keys of a climb performed in MuJoCo."""
    keys = declared_keys(command)
    if command == "paper":
        return [k for k in keys if k["key"] not in train_keys or k["key"].startswith("grid.")]
    if command == "perform":
        return [k for k in keys if k["key"].startswith(("perform.", "experiment.plan_max_replans"))]
    if command in ("plan", "stances", "ik-compare", "filter-stats"):
        sections = ("ik.", "physics.", "filter.", "compare.", "stances.", "wall.count", "experiment.plan_max_solves")
        return [k for k in keys if k["key"].startswith(sections)]
    return keys


def number_text(value, integer):
    if integer:
        return str(value)
    return repr(float(value))


def extremes(declaration):
    """(value, within bounds) pairs: each bound, just beyond it, huge values, NaN, infinities."""
    integer = declaration["type"] == "integer"
    low, high = declaration["min"], declaration["max"]
    values = []
    if integer:
        if low is not None:
            first = int(low) + (1 if declaration["min_open"] else 0)
            values += [(first, True), (first - 1, False)]
        if high is not None:
            last = int(high) - (1 if declaration["max_open"] else 0)
            values += [(last, True), (last + 1, False)]
        # An int flag: the largest C int, and beyond it and nothing like a number.
        values += [(2**31 - 1, high is None), (-(2**31), low is None), (2**63, False)]
        values += [("nan", False), ("inf", False)]
    else:
        if low is not None:
            inside = math.nextafter(low, math.inf) if declaration["min_open"] else low
            outside = low if declaration["min_open"] else math.nextafter(low, -math.inf)
            values += [(inside, True), (outside, False)]
        if high is not None:
            inside = math.nextafter(high, -math.inf) if declaration["max_open"] else high
            outside = high if declaration["max_open"] else math.nextafter(high, math.inf)
            values += [(inside, True), (outside, False)]
        values += [(1e300, high is None), (-1e300, low is None)]
        values += [(math.nan, False), (math.inf, False), (-math.inf, False)]
    return [(v, ok) for v, ok in values if not (isinstance(v, float) and math.isnan(v) and integer)]


def finite_json(path):
    def refuse(constant):
        raise ValueError(f"{path}: {constant}")

    json.loads(path.read_text(), parse_constant=refuse)


def finite_csv(path):
    with path.open() as f:
        for row in csv.reader(f):
            for cell in row:
                try:
                    number = float(cell)
                except ValueError:
                    continue
                assert math.isfinite(number), f"{path}: {cell!r}"


def check_outputs_finite(folder):
    for path in folder.rglob("*"):
        if path.suffix == ".json":
            finite_json(path)
        elif path.suffix == ".csv":
            finite_csv(path)


def refused_in_one_line(code, err):
    lines = err.strip().splitlines()
    return code == 2 and len(lines) == 1 and lines[0].startswith("crux: ")


def at_sizing_maximum(declaration, value, within):
    """Whether `value` is the maximum of a key that sizes the work: accepted, but checked
    without running, since it may take hours."""
    if not (declaration["sizes_work"] and within) or declaration["max"] is None or isinstance(value, str):
        return False
    return float(value) >= float(declaration["max"]) - (1 if declaration["max_open"] else 0)


def attempt(command, declaration, value, within):
    """One (command, key, value): None when it behaved, else what went wrong."""
    spec = COMMANDS[command]
    flag = declaration["flag"]
    text = value if isinstance(value, str) else number_text(value, declaration["type"] == "integer")
    case = f"crux {command} {flag} {text}"
    sizing_maximum = at_sizing_maximum(declaration, value, within)
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(scratch) / "out"
        # "--flag=-1e300" keeps a negative number a value; a text goes on its own, since
        # CLI11 reads "--flag=" as a flag without its value.
        args = [command, *spec["base"], *([flag, text] if isinstance(value, str) else [f"{flag}={text}"])]
        if sizing_maximum:
            args.append("--dry-run")
        elif spec.get("output"):
            args += ["-o", out]
        try:
            code, _, err = run(args)
        except subprocess.TimeoutExpired:
            return f"{case}: still running after {RUN_SECONDS} s"
        if code == 2:
            # Beyond its bounds the key itself is named; within them another key may be at fault.
            if not refused_in_one_line(code, err) or (not within and flag not in err):
                return f"{case}: refused, but not in one line naming {flag}: {err!r}"
            if out.exists():
                return f"{case}: refused, but left {out}"
            return None
        if not within:
            return f"{case}: accepted a value beyond the bounds (exit {code}, {err.strip()[:200]!r})"
        if code != 0:
            return f"{case}: exit {code}: {err.strip()[:300]!r}"
        if sizing_maximum or not spec.get("output"):
            return None
        try:
            check_outputs_finite(out)
        except (AssertionError, ValueError) as e:
            return f"{case}: {e}"
        for read_back in spec.get("read_back", []):
            rcode, _, rerr = run([a.format(out=out, scratch=scratch) for a in read_back])
            if rcode != 0:
                return f"{case}: crux {read_back[0]} of its output: exit {rcode}: {rerr.strip()[:300]!r}"
    return None


def choice_attempts(command, declaration):
    return [(command, declaration, text, False) for text in ("", "no-such-choice")]


def all_attempts():
    train_keys = {k["key"] for k in declared_keys("train")}
    attempts = []
    for command in COMMANDS:
        for declaration in walked_keys(command, train_keys):
            if declaration["type"] in ("number", "integer"):
                attempts += [(command, declaration, v, ok) for v, ok in extremes(declaration)]
            elif declaration["type"] == "choice":
                attempts += choice_attempts(command, declaration)
    return attempts


def test_every_key_of_every_command_at_its_extremes():
    attempts = all_attempts()
    assert len(attempts) > 500, "the commands declare their keys through --dry-run --json"
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        failures = [f for f in pool.map(lambda a: attempt(*a), attempts) if f is not None]
    assert not failures, f"{len(failures)} of {len(attempts)} attempts:\n" + "\n".join(failures[:40])


def with_value(toml_text, section, name, value):
    """config.toml's text with [section] name set to value; None if it does not set it."""
    lines = toml_text.splitlines(keepends=True)
    current = None
    for i, line in enumerate(lines):
        if line.startswith("["):
            current = line.strip()[1:-1]
        elif current == section and line.startswith(f"{name} = "):
            lines[i] = f"{name} = {value}\n"
            return "".join(lines)
    return None


def test_a_config_file_beyond_a_bound_is_refused_on_reading_back(tmp_path):
    """config.toml edited beyond a bound: crux report refuses it, naming the file's line."""
    folder = tmp_path / "run"
    code, _, err = run(["train", *COMMANDS["train"]["base"], "-o", folder])
    assert code == 0, err
    text = (folder / "config.toml").read_text()
    failures = []
    edited_keys = 0
    for declaration in declared_keys("train"):
        if declaration["type"] not in ("number", "integer") or declaration["max"] is None:
            continue
        section, name = declaration["key"].split(".")
        beyond = int(declaration["max"]) + 1 if declaration["type"] == "integer" else declaration["max"] * 10 + 1
        edited_text = with_value(text, section, name, beyond)
        if edited_text is None:
            continue  # an unset optional key, or one a wall file leaves out
        edited_keys += 1
        edited = tmp_path / "edited"
        shutil.rmtree(edited, ignore_errors=True)
        shutil.copytree(folder, edited)
        (edited / "config.toml").write_text(edited_text)
        rcode, _, rerr = run(["report", edited, "-o", tmp_path / "page.html"])
        if not (rcode == 2 and "config.toml" in rerr and declaration["key"] in rerr and len(rerr.splitlines()) == 1):
            failures.append(f"{declaration['key']} = {beyond}: exit {rcode}: {rerr.strip()[:200]!r}")
        if (tmp_path / "page.html").exists():
            failures.append(f"{declaration['key']} = {beyond}: left page.html")
    assert edited_keys >= 50, "config.toml records train's numbers"
    assert not failures, "\n".join(failures)


def python_value(value, integer):
    if isinstance(value, str):
        return {"nan": math.nan, "inf": math.inf}[value] if value in ("nan", "inf") else value
    return int(value) if integer else float(value)


@pytest.mark.parametrize("function", ["run_learning", "run_experiment"])
def test_python_takes_the_same_keys_at_their_extremes(function, tmp_path):
    """The same values through Python: ValueError naming the key, or (run_learning) a finite run."""
    command = "train" if function == "run_learning" else "paper"
    base = {
        "run_learning": {"wall.seed": 1, "experiment.iterations": 40, "physics.model": "static"},
        "run_experiment": {"experiment.walls": 1, "experiment.iterations": 30, "experiment.plan": False,
                           "experiment.bootstrap_resamples": 100},
    }[function]
    failures = []
    for declaration in declared_keys(command):
        key = declaration["key"]
        if key == "output.progress":
            continue  # the CLI's display; Python shows none
        if declaration["type"] in ("number", "integer"):
            cases = extremes(declaration)
        elif declaration["type"] == "choice":
            cases = [("", False), ("no-such-choice", False)]
        else:
            continue
        for value, within in cases:
            sized = at_sizing_maximum(declaration, value, within)
            # Python runs what it accepts: a maximum that sizes the work, and run_experiment's
            # accepted values (the CLI's paper runs walk them), are checked as refusals only.
            if within and (sized or function == "run_experiment"):
                continue
            config = dict(base)
            config[key] = python_value(value, declaration["type"] == "integer")
            case = f"crux.{function}({{{key!r}: {config[key]!r}}})"
            try:
                result = getattr(crux, function)(config=config)
            except ValueError as e:
                # Beyond its bounds the key itself is named; within them the wall or another key may be at fault.
                if not within and key not in str(e):
                    failures.append(f"{case}: ValueError not naming the key: {e}")
                continue
            except Exception as e:  # noqa: BLE001 - any other error is what this test finds
                failures.append(f"{case}: {type(e).__name__}: {e}")
                continue
            if not within:
                failures.append(f"{case}: accepted a value beyond the bounds")
                continue
            summary = json.dumps(result.summary)
            if "NaN" in summary or "Infinity" in summary:
                failures.append(f"{case}: a non-finite number in its summary")
    assert not failures, f"{len(failures)} failures:\n" + "\n".join(failures[:40])


def test_the_regression_tests_reliability_names_exist():
    """docs/RELIABILITY.md's issue-39 section names its regression tests: each exists."""
    root = pathlib.Path(__file__).resolve().parents[2]
    text = (root / "docs" / "RELIABILITY.md").read_text()
    section = text[text.index("## Every key at its extremes") :]
    section = section[: section.index("\n## ", 1)]
    sources = "\n".join(p.read_text() for p in (root / "tests").rglob("*.cpp"))
    python_sources = "\n".join(p.read_text() for p in (root / "python").rglob("test_*.py"))
    named = 0
    for name in sorted(set(re.findall(r"`([A-Z][A-Za-z]+\.[A-Z][A-Za-z0-9]+|test_[a-z0-9_]+)`", section))):
        named += 1
        if name.startswith("test_"):
            assert f"def {name}(" in python_sources, name
        else:
            suite, case = name.split(".")
            assert re.search(rf"TEST(_P|_F)?\({suite},\s*{case}\)", sources), name
    assert named >= 10


def test_the_ladder_is_climbed_by_one_move():
    code, out, err = run(["plan", "--wall-file", LADDER_FILE, "--physics-model", "static", "--json"])
    assert code == 0, err
    assert json.loads(out)["holds"] == [5], "the finish no longer lies between the two stances: see LADDER"

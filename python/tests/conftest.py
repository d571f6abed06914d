"""Shared fixtures: the crux CLI of the same build, to compare the module with it."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

import crux

# Gymnasium 1.4.0's unmodified source, beside the repository (../shared) here and in CI's
# clean clone; crux.gym's tests skip without it, or fail under CI (test_gym.py).
GYMNASIUM_SOURCE = pathlib.Path(__file__).resolve().parents[3] / "shared" / "third_party" / "gymnasium-1.4.0"
if GYMNASIUM_SOURCE.is_dir():
    sys.path.insert(0, str(GYMNASIUM_SOURCE))
# The examples, which the tests load by path, import their shared argument types and
# statistics (examples/python/example_arguments.py, wall_statistics.py) from their folder,
# as a script run there does.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"))


@pytest.fixture(scope="session")
def crux_binary():
    path = os.environ.get("CRUX_BINARY")
    if not path:
        path = str(pathlib.Path(crux.__file__).resolve().parents[2] / "crux")
    assert os.access(path, os.X_OK), f"no crux binary at {path}: set CRUX_BINARY"
    return path


@pytest.fixture(scope="session")
def run_cli(crux_binary):
    """Runs `crux ARGS`; returns (exit code, stdout, stderr)."""

    def run(*args, cwd=None):
        done = subprocess.run([crux_binary, *map(str, args)], capture_output=True, text=True, cwd=cwd)
        return done.returncode, done.stdout, done.stderr

    return run


@pytest.fixture(scope="session")
def cli_json(run_cli):
    def run(*args):
        code, out, err = run_cli(*args, "--json")
        assert code == 0, err
        return json.loads(out)

    return run


@pytest.fixture(scope="session")
def wall7():
    return crux.Wall.random(7)

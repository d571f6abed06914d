"""The cost of ClimbEnv.step above the C++ step it wraps (docs/PERFORMANCE.md).

A seeded random policy over the action mask records N actions on a wall (which also
fills the MDP's posture cache, so the timed passes measure the step, not new IK
solves). Then, from the same start, the same actions are stepped through twice, each
the best of R repetitions: by env.step from Python (observation and info dicts built at
every step), and by env.replay_actions, the same C++ MDP steps in one C++ loop.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_step_overhead.py
"""

import argparse
import time

import numpy as np

import crux

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--steps", type=int, default=20000)
parser.add_argument("--repeats", type=int, default=7)
parser.add_argument("--wall-seed", type=int, default=7)
args = parser.parse_args()

env = crux.ClimbEnv(crux.Wall.random(args.wall_seed), max_steps=10**9)
rng = np.random.default_rng(1)
env.reset()
actions = []
for _ in range(args.steps):
    action = int(rng.choice(np.flatnonzero(env.action_mask())))
    actions.append(action)
    if env.step(action)[2]:
        env.reset()
actions_array = np.array(actions, dtype=np.int32)


def python_pass():
    env.reset()
    start = time.perf_counter()
    for action in actions:
        if env.step(action)[2]:
            env.reset()
    return time.perf_counter() - start


def cpp_pass():
    env.reset()
    start = time.perf_counter()
    env.replay_actions(actions_array)
    return time.perf_counter() - start


python_s = min(python_pass() for _ in range(args.repeats))
cpp_s = min(cpp_pass() for _ in range(args.repeats))
per_step = lambda seconds: seconds / args.steps * 1e6  # noqa: E731
print(f"{args.steps} steps on wall seed {args.wall_seed}, best of {args.repeats}")
print(f"C++ step (replay_actions): {per_step(cpp_s):.2f} us/step")
print(f"env.step from Python:      {per_step(python_s):.2f} us/step")
print(f"binding overhead:          {per_step(python_s - cpp_s):.2f} us/step "
      f"({python_s / cpp_s:.2f}x the C++ step)")

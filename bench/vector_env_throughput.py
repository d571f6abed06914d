"""Environment steps per second of crux.gym.VectorClimbEnv against Gymnasium's
SyncVectorEnv of single ClimbEnvs (docs/PERFORMANCE.md).

For each environment count, both vector envs are reset with the same seed and stepped
with the same actions, drawn from the action masks by one seeded sampler: they climb the
same walls through the same states (VectorClimbEnv's results equal SyncVectorEnv's bit
for bit), so they do the same IK work. Only the step calls are timed; a rate is
environment steps (num_envs per call) per second of step calls. By default every episode
climbs a new random wall (new IK solves all along); --wall-seed fixes one wall and
--warmup steps it untimed first, so that the timed steps mostly find their postures in
the cache and measure the rest of the step.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/vector_env_throughput.py
"""

import argparse
import os
import pathlib
import sys
import time

import numpy as np

GYMNASIUM_SOURCE = pathlib.Path(__file__).resolve().parents[2] / "shared" / "third_party" / "gymnasium-1.4.0"
if GYMNASIUM_SOURCE.is_dir():
    sys.path.insert(0, str(GYMNASIUM_SOURCE))

import gymnasium  # noqa: E402

import crux.gym  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--envs", type=int, nargs="+", default=[1, 8, 64])
parser.add_argument("--steps", type=int, default=2000, help="step calls per environment count")
parser.add_argument("--observation", choices=crux.gym.OBSERVATION_FORMS, default="numeric")
parser.add_argument("--seed", type=int, default=0)
parser.add_argument("--wall-seed", type=int, default=None, help="one random wall for every episode")
parser.add_argument("--warmup", type=int, default=0, help="untimed step calls first")
args = parser.parse_args()


def run(envs):
    """Seconds spent in envs.step over the timed calls, and the rewards' sum (the same for both)."""
    sampler = np.random.default_rng(args.seed)
    _, info = envs.reset(seed=args.seed)
    seconds, total = 0.0, 0.0
    for call in range(args.warmup + args.steps):
        # A random offered action per environment: the masked argmax of uniform noise.
        actions = np.argmax(sampler.random(info["action_mask"].shape) * info["action_mask"], axis=1)
        start = time.perf_counter()
        _, rewards, _, _, info = envs.step(actions)
        if call >= args.warmup:
            seconds += time.perf_counter() - start
        total += float(rewards.sum())
    return seconds, total


wall = None if args.wall_seed is None else crux.Wall.random(args.wall_seed)
walls = "random walls per episode" if wall is None else f"random wall {args.wall_seed}"


print(f"{args.steps} step calls per count after {args.warmup} untimed, {args.observation} observations, {walls}, "
      f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
print(f"{'envs':>5} {'SyncVectorEnv steps/s':>22} {'VectorClimbEnv steps/s':>23} {'ratio':>6}")
for count in args.envs:
    sync = gymnasium.vector.SyncVectorEnv(
        [lambda: gymnasium.make(crux.gym.ENV_ID, wall=wall, observation=args.observation) for _ in range(count)]
    )
    vector = crux.gym.VectorClimbEnv(count, wall, observation=args.observation)
    sync_s, sync_total = run(sync)
    vector_s, vector_total = run(vector)
    assert sync_total == vector_total, "the two vector envs took different paths"
    sync_rate, vector_rate = count * args.steps / sync_s, count * args.steps / vector_s
    print(f"{count:>5} {sync_rate:>22.0f} {vector_rate:>23.0f} {vector_rate / sync_rate:>5.1f}x")
    sync.close()
    vector.close()

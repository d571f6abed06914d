"""Tabular Q-learning against crux.ClimbMdp: the problem-space state, the hold as the
action, epsilon-greedy over the action mask. Prints the episode lengths it climbs in.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/q_learning.py [--steps N]
"""

import argparse
from collections import defaultdict

import numpy as np

import crux

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--steps", type=int, default=8000, help="real actions to learn from")
parser.add_argument("--seed", type=int, default=1)
args = parser.parse_args()

env = crux.ClimbMdp(crux.Wall.random(7), max_steps=2000)
rng = np.random.default_rng(args.seed)
q = defaultdict(lambda: np.zeros(env.action_count))
alpha, gamma, epsilon = 0.5, 0.9, 0.1

obs, _ = env.reset(seed=args.seed)
episode_lengths, length = [], 0
for _ in range(args.steps):
    state, possible = obs["wall_state"], np.flatnonzero(env.action_mask())
    if rng.random() < epsilon:
        action = rng.choice(possible)
    else:  # ties broken at random: holds are numbered from the bottom, so "first" would mean "down"
        values = q[state][possible]
        action = rng.choice(possible[values == values.max()])
    obs, reward, terminated, truncated, _ = env.step(action)
    best_next = 0.0 if terminated else q[obs["wall_state"]][np.flatnonzero(env.action_mask())].max()
    q[state][action] += alpha * (reward + gamma * best_next - q[state][action])
    length += 1
    if terminated or truncated:
        episode_lengths.append(length)
        obs, _ = env.reset()
        length = 0

print(f"{len(episode_lengths)} episodes; lengths {episode_lengths[:5]} ... {episode_lengths[-5:]}")

"""A deep-RL baseline for crux/Climb-v0: a masked DQN on the numeric features, trained on
random walls and evaluated greedily on held-out walls, beside the paper's Dyna-Q and the
random policy on the same walls (docs/BASELINES.md).

    export PYTHONPATH=build/release/python:../shared/third_party/gymnasium-1.4.0
    /usr/bin/python3 examples/python/dqn_baseline.py train --steps 20000         # one run, as JSON
    /usr/bin/python3 examples/python/dqn_baseline.py search --out build/baseline # the tuning grid, 3 seeds a setting
    /usr/bin/python3 examples/python/dqn_baseline.py compare --out build/baseline   # on the held-out walls
    /usr/bin/python3 examples/python/dqn_baseline.py plot --out build/baseline docs/images/baseline_curves.png

At the PPO search's budget: the chosen setting, 6 M steps a run over 64 environments
stepped together (--envs; --part K/3 runs the K-th seed):

    /usr/bin/python3 examples/python/dqn_baseline.py search --out build/baseline-6m --setting lr0.0003-decay0.6-h64 \
        --steps 6000000 --envs 64 --batch 256 --replay 1000000 --checkpoints 6 --part 1/3

search writes OUT/search.jsonl (OUT/search-KofN.jsonl with --part K/N), one JSON record
per run, and the networks in OUT/nets/; compare writes OUT/comparison.json; plot writes
the figure it is given (.png or .svg). docs/BASELINES.md times the full run (about half
an hour on 2 cores) and gives the same pipeline at a scale that runs in minutes.

Walls are random walls named by their seeds: training walls 0 .. N-1, validation walls
from 10000 (to choose the setting), held-out evaluation walls from 20000 (to report).
One --seed fixes everything else; torch runs deterministically on one CPU thread.
"""

import argparse
import collections
import hashlib
import itertools
import json
import math
import pathlib
import sys
import time

import numpy as np
import torch
from torch import nn

import crux
import crux.gym  # registers crux/Climb-v0
import gymnasium
from example_arguments import OneLineParser, positive
from wall_statistics import interval, paired, per_wall_mean

VALIDATION_FIRST_SEED = 10000
HELD_OUT_FIRST_SEED = 20000
# The greedy climbs' cap, experiment.greedy_cap's default: Dyna-Q's greedy climb gets as many.
GREEDY_CAP = 500
# Per held-out wall, the runs that count the iterations to the first 5 episodes (docs/REPRODUCTION.md).
DYNA_ITERATIONS = 8000
EARLY_EPISODES = 5
# The paper's rewards (-1000 unreachable, -1 a step, +200000 the finish) scaled so that the
# finish is worth 20: the same optimal policy, targets of a size a network fits.
REWARD_SCALE = 1e-4
# The paper's discount. Pilots with 0.99 and height shaping, or 0.95, learnt no ranking of
# the candidates (docs/BASELINES.md, "Pilots").
GAMMA = 0.9
N_STEP = 3
BATCH = 32  # --batch's default, the 20,000-step search's
TRAIN_EVERY = 2
TARGET_EVERY = 500
FINAL_EPSILON = 0.05
STATE_SIZE = 55  # free limb 4, held holds 12, root 3, joint angles 32, centre of mass 3, height to the finish 1
CHECKPOINTS = 2  # validation evaluations, evenly spaced, the last at the end (--checkpoints)
SEARCH_GRID = {"lr": [3e-4, 1e-3], "epsilon_decay": [0.2, 0.6], "hidden": [64, 128]}
SEEDS_PER_SETTING = 3
COMPARISON_FILE = "comparison.json"
DYNA_CONDITIONS = [("Dyna-Q paper, from scratch", "paper", False), ("Dyna-Q paper, transfer", "paper", True),
                   ("Dyna-Q prior, from scratch", "prior", False), ("Dyna-Q prior, transfer", "prior", True)]


def fraction(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number, got {text!r}") from None
    if not 0 < value <= 1:
        raise argparse.ArgumentTypeError(f"must be in (0, 1], got {value}")
    return value


def positive_number(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number, got {text!r}") from None
    if not (value > 0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"must be a positive number, got {text}")
    return value


class Progress:
    """Progress on stderr as crux's long commands show it: a bar redrawn in place on a
    terminal; elsewhere a line every ten seconds, and a last one at the end once one was
    written (nothing for work done within ten seconds); nothing at all when quiet. stdout,
    where train prints its record, never changes with it."""

    def __init__(self, label, total, quiet=False, stream=None, every_s=10.0):
        self.label, self.total, self.every_s = label, total, every_s
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = not quiet and total > 0
        self.terminal = self.enabled and self.stream.isatty()
        self.started = self.shown = time.perf_counter()
        self.written = False

    def update(self, done):
        if not self.enabled:
            return
        now = time.perf_counter()
        finished = done >= self.total
        if finished and not (self.terminal or self.written):
            return
        if not finished and now - self.shown < (0.25 if self.terminal else self.every_s):
            return
        self.shown, self.written = now, True
        rate = done / (now - self.started) if now > self.started else 0.0
        left = f"{int((self.total - done) / rate) // 60}m{int((self.total - done) / rate) % 60:02d}s" if rate else "?"
        filled = 40 * done // self.total
        line = (f"{self.label} [{'#' * filled}{'.' * (40 - filled)}] {100 * done // self.total:3d}% "
                f"({done}/{self.total}, {rate:.0f}/s, {left} left)")
        self.stream.write(("\r" + line) if self.terminal else line + "\n")
        self.stream.flush()

    def close(self):
        if self.terminal and self.written:
            self.stream.write("\n")
            self.stream.flush()


def deterministic(seed):
    torch.manual_seed(seed)
    torch.set_num_threads(1)
    torch.use_deterministic_algorithms(True)


def wall_seeds(first, count):
    return list(range(first, first + count))


def split(train_walls, evaluation_seeds):
    return {"train": wall_seeds(0, train_walls), "evaluation": evaluation_seeds}


# --- features and network ------------------------------------------------------------------


def batch_features(obs, span):
    """The numeric observation, batched (leading axis: environments), as (state (E, 55),
    candidates (E, K, 3), mask (E, K) bool), lengths in max_spans."""
    posture = obs["posture"]
    envs = posture.shape[0]
    state = np.concatenate([obs["free_limb"], obs["held"].reshape(envs, -1) / span, posture[:, :3] / span,
                            posture[:, 3:], obs["centre_of_mass"] / span, obs["to_finish"] / span], axis=1)
    return state.astype(np.float32), (obs["candidates"] / span).astype(np.float32), obs["candidate_mask"] > 0.5


def features(obs, span):
    """batch_features of one environment's observation: (state (55,), candidates (K, 3), mask (K,))."""
    state, candidates, mask = batch_features({key: value[None] for key, value in obs.items()}, span)
    return state[0], candidates[0], mask[0]


class SlotQNetwork(nn.Module):
    """Q(s, slot) from the state's features and the slot's candidate hold, the same weights
    for every slot, so that a slot means "this hold", whatever wall and whatever order.
    Width-1 convolutions over the slots are per-slot linear layers (Debian's torch runs
    them through oneDNN, its linear layers through the reference BLAS, ten times slower)."""

    def __init__(self, state_size, hidden):
        super().__init__()
        self.layers = nn.Sequential(nn.Conv1d(state_size + 3, hidden, 1), nn.ReLU(), nn.Conv1d(hidden, hidden, 1),
                                    nn.ReLU(), nn.Conv1d(hidden, 1, 1))

    def forward(self, state, candidates, mask):
        batch, slots, _ = candidates.shape
        x = torch.cat([state.unsqueeze(2).expand(batch, state.shape[1], slots), candidates.transpose(1, 2)], dim=1)
        q = self.layers(x).squeeze(1)
        return q.masked_fill(~mask, -math.inf)  # a masked action is never the argmax nor the max


def greedy_action(net, state, candidates, mask):
    with torch.no_grad():
        q = net(torch.from_numpy(state)[None], torch.from_numpy(candidates)[None], torch.from_numpy(mask)[None])
    return int(torch.argmax(q[0]))


def network_digest(net):
    digest = hashlib.sha256()
    for name, tensor in net.state_dict().items():
        digest.update(name.encode())
        digest.update(tensor.numpy().tobytes())
    return digest.hexdigest()


class Replay:
    """n-step transitions, the last `capacity` of them (a ring: the oldest is overwritten)."""

    def __init__(self, capacity, state_size, slots):
        self.capacity, self.added = capacity, 0
        self.state = np.zeros((capacity, state_size), np.float32)
        self.candidates = np.zeros((capacity, slots, 3), np.float32)
        self.mask = np.zeros((capacity, slots), bool)
        self.action = np.zeros(capacity, np.int64)
        self.reward = np.zeros(capacity, np.float32)
        self.discount = np.zeros(capacity, np.float32)  # gamma^n, 0 after a termination
        self.next_state = np.zeros_like(self.state)
        self.next_candidates = np.zeros_like(self.candidates)
        self.next_mask = np.zeros_like(self.mask)

    @property
    def size(self):
        return min(self.added, self.capacity)

    def add(self, pending, following, terminated):
        (state, candidates, mask, action, _), index = pending[0], self.added % self.capacity
        self.state[index], self.candidates[index], self.mask[index], self.action[index] = state, candidates, mask, action
        self.reward[index] = sum(GAMMA**k * step[4] for k, step in enumerate(pending))
        self.discount[index] = 0.0 if terminated else GAMMA ** len(pending)
        self.next_state[index], self.next_candidates[index], self.next_mask[index] = following
        self.added += 1

    def batch(self, indices):
        def t(array):
            return torch.from_numpy(array[indices])

        return (t(self.state), t(self.candidates), t(self.mask), t(self.action), t(self.reward), t(self.discount),
                t(self.next_state), t(self.next_candidates), t(self.next_mask))


def td_loss(net, target, batch):
    """Double DQN's n-step target, maxima over the next state's possible actions only."""
    state, candidates, mask, action, reward, discount, next_state, next_candidates, next_mask = batch
    q = net(state, candidates, mask).gather(1, action[:, None]).squeeze(1)
    with torch.no_grad():
        best = torch.argmax(net(next_state, next_candidates, next_mask), dim=1, keepdim=True)
        next_q = target(next_state, next_candidates, next_mask).gather(1, best).squeeze(1)
        next_q = torch.where(next_mask.any(dim=1), next_q, torch.zeros_like(next_q))  # no move left: no future
        y = reward + discount * next_q
    return nn.functional.smooth_l1_loss(q, y)


# --- training and evaluation ---------------------------------------------------------------


def make_env(wall_split, evaluation=False, max_episode_steps=None, config=None):
    return gymnasium.make("crux/Climb-v0", observation="numeric", wall_split=wall_split, evaluation=evaluation,
                          wall_order="cycle" if evaluation else "sample", max_episode_steps=max_episode_steps,
                          config=config)


def training_config(args):
    """The training environments' config: the paper's rewards, or with --reward-height the
    potential-based height shaping of docs/PHYSICS.md, discounted with the DQN's gamma so
    that the optimal policy stays the paper's."""
    if args.reward_height is None:
        return None
    return {"reward.height": args.reward_height, "learning.gamma": GAMMA}


def greedy_climbs(net, env, walls, span):
    """The greedy policy once on each wall of env's list, up to GREEDY_CAP actions.

    A failed move leaves the state as it was, so the greedy policy repeats it forever: its
    climb ends there ("finished" false), as Dyna-Q's greedy climb does. The same rollout goes
    on as the greedy policy without retries, which passes over the moves that failed in the
    current state (action elimination, as crux's `informed` transfer mode):
    "finished_no_retry", "length_no_retry" (actions, failed ones included). Also: its failed
    moves and all its moves, the greedy policy's successful moves before its first failure,
    and the highest rise of the centre of mass (m) over the whole rollout."""
    results = []
    obs, info = env.reset(seed=0)  # a seeded reset starts the list again
    for index in range(walls):
        if index:
            obs, info = env.reset()
        failed, failures, result, before_failure = set(), 0, None, None
        start = lowest = float(obs["to_finish"][0])
        for length in itertools.count(1):
            state, candidates, mask = features(obs, span)
            allowed = mask.copy()
            allowed[list(failed)] = False
            if not allowed.any():
                break
            action = greedy_action(net, state, candidates, allowed)
            assert mask[action], "the greedy action is a masked one"
            obs, _, terminated, truncated, info = env.step(action)
            lowest = min(lowest, float(obs["to_finish"][0]))
            if terminated or truncated:
                result = (terminated, length)
                break
            if info["reached"]:
                failed.clear()
            else:
                failed.add(action)
                failures += 1
                if before_failure is None:
                    before_failure = length - 1
        finished = result is not None and result[0]
        results.append({"wall": info["wall_name"],
                        "finished": bool(finished and failures == 0), "length": length if finished and not failures
                        else None,
                        "finished_no_retry": bool(finished), "length_no_retry": length if finished else None,
                        "failed_moves": failures, "moves": length,
                        "moves_before_failure": length if before_failure is None else before_failure,
                        "rise_m": round(start - lowest, 4)})
    return results


def check_run(args):
    for name in ("steps", "hidden", "train_walls", "envs", "batch", "checkpoints"):
        value = getattr(args, name)
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise ValueError(f"{name}: must be a positive integer, got {value!r}")
    if args.replay is not None and (isinstance(args.replay, bool) or not isinstance(args.replay, int)
                                    or args.replay < args.batch):
        raise ValueError(f"replay: must be None or an integer of at least the batch, got {args.replay!r}")
    if not 0 < args.epsilon_decay <= 1:
        raise ValueError(f"epsilon_decay: must be in (0, 1], got {args.epsilon_decay!r}")
    if not (args.lr > 0 and math.isfinite(args.lr)):
        raise ValueError(f"lr: must be a positive number, got {args.lr!r}")


class Learner:
    """One run's network, its target, their optimiser and the replay."""

    def __init__(self, args, slots):
        self.net = SlotQNetwork(STATE_SIZE, args.hidden)
        self.target = SlotQNetwork(STATE_SIZE, args.hidden)
        self.target.load_state_dict(self.net.state_dict())
        self.optimiser = torch.optim.Adam(self.net.parameters(), lr=args.lr)
        self.replay = Replay(min(args.steps, args.replay or args.steps), STATE_SIZE, slots)
        self.batch, self.losses = args.batch, []

    def ready(self):
        return self.replay.size >= self.batch

    def update(self, rng):
        loss = td_loss(self.net, self.target, self.replay.batch(rng.integers(self.replay.size, size=self.batch)))
        self.optimiser.zero_grad()
        loss.backward()
        nn.utils.clip_grad_norm_(self.net.parameters(), 10.0)
        self.optimiser.step()
        self.losses.append(float(loss))

    def copy_to_target(self):
        self.target.load_state_dict(self.net.state_dict())


class Validation:
    """The greedy policy's climbs on the validation walls at the checkpoints, timed apart."""

    def __init__(self, args, walls, log):
        self.walls, self.log, self.curve, self.seconds = walls, log, [], 0.0
        self.env = None
        if walls:
            self.env = make_env(split(args.train_walls, wall_seeds(VALIDATION_FIRST_SEED, walls)), evaluation=True,
                                max_episode_steps=GREEDY_CAP)

    def __call__(self, step, net, span, episodes):
        if self.env is None:
            return
        started = time.perf_counter()
        self.curve.append({"step": step, "validation": greedy_climbs(net, self.env, self.walls, span)})
        self.seconds += time.perf_counter() - started
        if self.log:
            done = sum(r["finished"] for r in self.curve[-1]["validation"])
            no_retry = sum(r["finished_no_retry"] for r in self.curve[-1]["validation"])
            self.log(f"  step {step}: {len(episodes)} episodes, validation {done}/{self.walls} finished, "
                     f"{no_retry} without retries")


def train(args, validation_walls=None, log=None, progress=None):
    """One DQN run; returns its record (deterministic), the network and the seconds spent
    on validation. `progress`, if given, hears the environment steps done (a Progress).
    args.envs environments: one (the search at 20,000 steps) or a VectorClimbEnv of them."""
    check_run(args)
    deterministic(args.seed)
    rng = np.random.default_rng(args.seed)
    validation = Validation(args, validation_walls, log)
    run = train_one_env if args.envs == 1 else train_vector
    learner, episodes, masked_choices, steps = run(args, rng, validation, progress)
    record = {
        "setting": {"lr": args.lr, "epsilon_decay": args.epsilon_decay, "hidden": args.hidden},
        "collection": {"envs": args.envs, "batch": args.batch, "replay": learner.replay.capacity},
        "reward_height": args.reward_height,
        "seed": args.seed,
        "steps": steps,
        "train_walls": args.train_walls,
        "episodes": episodes,
        "masked_choices": masked_choices,
        "mean_loss_per_tenth": [float(np.mean(part)) for part in np.array_split(np.array(learner.losses), 10)
                                if part.size],
        "curve": validation.curve,
        "network_sha256": network_digest(learner.net),
    }
    return record, learner.net, validation.seconds


def checkpoint_steps(total, count):
    return {round(total * k / count) for k in range(1, count + 1)}


def train_one_env(args, rng, validation, progress):
    """One environment, one update of args.batch every TRAIN_EVERY steps."""
    env = make_env(split(args.train_walls, [HELD_OUT_FIRST_SEED]), max_episode_steps=1000, config=training_config(args))
    span = env.unwrapped._span
    obs, info = env.reset(seed=args.seed)
    state, candidates, mask = features(obs, span)
    learner = Learner(args, mask.size)
    decay_steps = max(1, round(args.epsilon_decay * args.steps))
    learning_starts = min(1000, args.steps // 10)
    pending = collections.deque()
    episodes, length, masked_choices = [], 0, 0
    checkpoints = checkpoint_steps(args.steps, args.checkpoints)
    for step in range(1, args.steps + 1):
        epsilon = max(FINAL_EPSILON, 1.0 - (1.0 - FINAL_EPSILON) * (step - 1) / decay_steps)
        possible = np.flatnonzero(mask)
        if rng.random() < epsilon:
            action = int(rng.choice(possible))
        else:
            action = greedy_action(learner.net, state, candidates, mask)
        masked_choices += not mask[action]
        obs, reward, terminated, truncated, info = env.step(action)
        length += 1
        pending.append((state, candidates, mask, action, reward * REWARD_SCALE))
        state, candidates, mask = features(obs, span)
        if terminated or truncated or not mask.any():
            while pending:
                learner.replay.add(pending, (state, candidates, mask), terminated)
                pending.popleft()
            episodes.append({"end_step": step, "length": length, "finished": bool(terminated)})
            length = 0
            obs, info = env.reset()
            state, candidates, mask = features(obs, span)
        elif len(pending) == N_STEP:
            learner.replay.add(pending, (state, candidates, mask), False)
            pending.popleft()
        if step >= learning_starts and step % TRAIN_EVERY == 0 and learner.ready():
            learner.update(rng)
        if step % TARGET_EVERY == 0:
            learner.copy_to_target()
        if progress:
            progress.update(step)
        if step in checkpoints:
            validation(step, learner.net, span, episodes)
    return learner, episodes, masked_choices, args.steps


def explore(mask, greedy, epsilon, rng):
    """Per environment: with probability epsilon a uniform draw among its possible actions
    (the argmax of uniform noise over them), else its greedy action."""
    drawn = np.argmax(rng.random(mask.shape) * mask, axis=1)
    return np.where(rng.random(len(mask)) < epsilon, drawn, greedy)


def train_vector(args, rng, validation, progress):
    """args.envs environments stepped together (one greedy inference for all of them) and
    one update of args.batch transitions a step of them all, so that a run of millions of
    steps takes minutes; the replay keeps the last args.replay transitions, and the target
    is copied every TARGET_EVERY / TRAIN_EVERY updates, as in the one-environment run."""
    span = make_env(split(args.train_walls, [HELD_OUT_FIRST_SEED])).unwrapped._span
    envs = crux.gym.VectorClimbEnv(args.envs, wall=wall_seeds(0, args.train_walls), observation="numeric",
                                   wall_order="sample", max_episode_steps=1000, config=training_config(args))
    obs, _ = envs.reset(seed=args.seed)
    state, candidates, mask = batch_features(obs, span)
    learner = Learner(args, mask.shape[1])
    rounds = max(1, args.steps // args.envs)
    decay_rounds = max(1, round(args.epsilon_decay * rounds))
    learning_starts = min(1000, args.steps // 10)
    pending = [collections.deque() for _ in range(args.envs)]
    lengths, resetting = np.zeros(args.envs, np.int64), np.zeros(args.envs, bool)
    episodes, masked_choices, updates = [], 0, 0
    checkpoints = checkpoint_steps(rounds, args.checkpoints)
    for round_ in range(1, rounds + 1):
        step = round_ * args.envs
        epsilon = max(FINAL_EPSILON, 1.0 - (1.0 - FINAL_EPSILON) * (round_ - 1) / decay_rounds)
        with torch.no_grad():
            # A resetting environment's action is unused; a row with no possible action scores all -inf.
            q = learner.net(torch.from_numpy(state), torch.from_numpy(candidates), torch.from_numpy(mask))
        action = explore(mask, torch.argmax(q, dim=1).numpy(), epsilon, rng)
        masked_choices += int(np.sum(~mask[np.arange(args.envs), action] & ~resetting))
        obs, reward, terminated, truncated, _ = envs.step(action)
        following = batch_features(obs, span)
        for env in np.flatnonzero(~resetting):
            pending[env].append((state[env], candidates[env], mask[env], action[env], reward[env] * REWARD_SCALE))
            lengths[env] += 1
            after = tuple(part[env] for part in following)
            if terminated[env] or truncated[env]:
                while pending[env]:
                    learner.replay.add(pending[env], after, terminated[env])
                    pending[env].popleft()
                episodes.append({"end_step": step, "length": int(lengths[env]), "finished": bool(terminated[env])})
                lengths[env] = 0
            elif len(pending[env]) == N_STEP:
                learner.replay.add(pending[env], after, False)
                pending[env].popleft()
        resetting = terminated | truncated
        state, candidates, mask = following
        if step >= learning_starts and learner.ready():
            learner.update(rng)
            updates += 1
            if updates % (TARGET_EVERY // TRAIN_EVERY) == 0:
                learner.copy_to_target()
        if progress:
            progress.update(step)
        if round_ in checkpoints:
            validation(step, learner.net, span, episodes)
    return learner, episodes, masked_choices, rounds * args.envs


def early_episodes(policy, env, rng, span, cap=DYNA_ITERATIONS):
    """Iterations to complete the first EARLY_EPISODES episodes on one wall (capped at cap, as
    crux paper's first_5_iterations), and the ends of the episodes completed within cap."""
    obs, _ = env.reset(seed=0)
    ends = []
    for step in range(1, cap + 1):
        state, candidates, mask = features(obs, span)
        obs, _, terminated, _, _ = env.step(policy(state, candidates, mask, rng))
        if terminated:
            ends.append(step)
            obs, _ = env.reset()
    return (ends[EARLY_EPISODES - 1] if len(ends) >= EARLY_EPISODES else cap), ends


def random_policy(state, candidates, mask, rng):
    return int(rng.choice(np.flatnonzero(mask)))


def epsilon_greedy(net):
    def policy(state, candidates, mask, rng):
        if rng.random() < FINAL_EPSILON:
            return random_policy(state, candidates, mask, rng)
        return greedy_action(net, state, candidates, mask)

    return policy


def single_wall_env(seed):
    # No TimeLimit: an episode runs until it finishes, as Dyna-Q's learning episodes do.
    return crux.gym.ClimbEnv(wall=[seed], observation="numeric")


# --- commands ---------------------------------------------------------------------------------


def command_train(args):
    started = time.perf_counter()
    progress = Progress("dqn train", args.steps, quiet=args.quiet)
    record, net, validation_seconds = train(args, validation_walls=args.validation_walls, progress=progress)
    progress.close()
    if args.save:
        torch.save(net.state_dict(), args.save)
    # Machine-dependent, apart from the rest of the record, which the seed fixes.
    record["wall_clock_s"] = {"training": round(time.perf_counter() - started - validation_seconds, 3),
                              "validation": round(validation_seconds, 3)}
    print(json.dumps(record, sort_keys=True))


def settings():
    for lr, decay, hidden in itertools.product(*SEARCH_GRID.values()):
        yield {"lr": lr, "epsilon_decay": decay, "hidden": hidden}


def setting_name(setting):
    return f"lr{setting['lr']:g}-decay{setting['epsilon_decay']:g}-h{setting['hidden']}"


def part(text):
    try:
        index, count = map(int, text.split("/"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be K/N, got {text!r}") from None
    if not 1 <= index <= count:
        raise argparse.ArgumentTypeError(f"must be K/N with 1 <= K <= N, got {text!r}")
    return index, count


def grid_setting(text):
    names = [setting_name(setting) for setting in settings()]
    if text not in names:
        raise argparse.ArgumentTypeError(f"{text!r} is not a setting of the grid ({', '.join(names)})")
    return text


def search_log_name(index, count):
    """The file that part index of count of the search appends its records to."""
    return "search.jsonl" if count == 1 else f"search-{index}of{count}.jsonl"


def search_records(out):
    """The records of every part of the search, in the grid's order."""
    records = [json.loads(line) for path in sorted(out.glob("search*.jsonl")) for line in path.read_text().splitlines()]
    order = {setting_name(setting): rank for rank, setting in enumerate(settings())}
    return sorted(records, key=lambda r: (order[setting_name(r["setting"])], r["seed"]))


def command_search(args):
    out = pathlib.Path(args.out)
    (out / "nets").mkdir(parents=True, exist_ok=True)
    index, count = args.part
    log_path = out / search_log_name(index, count)
    done = set()
    if log_path.exists():
        done = {(setting_name(r["setting"]), r["seed"]) for r in map(json.loads, log_path.read_text().splitlines())}
    grid = [setting for setting in settings() if args.setting in (None, setting_name(setting))]
    runs = [(setting, seed) for setting in grid for seed in range(args.seed, args.seed + SEEDS_PER_SETTING)]
    for setting, seed in runs[index - 1::count]:  # the K-th of every N runs: the parts alternate the widths
        name = setting_name(setting)
        if (name, seed) in done:
            continue
        run = argparse.Namespace(**{key: getattr(args, key) for key in RUN_OPTIONS}, seed=seed, **setting)
        print(f"{name} seed {seed}", flush=True)
        started = time.perf_counter()
        record, net, validation_seconds = train(run, validation_walls=args.validation_walls,
                                                log=lambda m: print(m, flush=True))
        record["wall_clock_s"] = {"training": round(time.perf_counter() - started - validation_seconds, 3),
                                  "validation": round(validation_seconds, 3)}
        torch.save(net.state_dict(), out / "nets" / f"{name}-s{seed}.pt")
        with log_path.open("a") as file:
            file.write(json.dumps(record, sort_keys=True) + "\n")


def search_table(records):
    """Per setting: final validation success (mean over seeds, each seed's rate over the walls)."""
    table = collections.defaultdict(list)
    for record in records:
        final = record["curve"][-1]["validation"]
        lengths = [r["length"] for r in final if r["finished"]]
        table[setting_name(record["setting"])].append({
            "setting": record["setting"], "seed": record["seed"],
            "success": float(np.mean([r["finished"] for r in final])),
            "success_no_retry": float(np.mean([r["finished_no_retry"] for r in final])),
            "length": float(np.mean(lengths)) if lengths else None,
            "train_episodes": sum(e["finished"] for e in record["episodes"]),
            "wall_clock_s": sum(record["wall_clock_s"].values()),
        })
    return table


def command_compare(args):
    out = pathlib.Path(args.out)
    records = search_records(out)
    table = search_table(records)
    best = max(table, key=lambda name: (np.mean([r["success"] for r in table[name]]),
                                        np.mean([r["success_no_retry"] for r in table[name]]),
                                        -np.mean([r["length"] or GREEDY_CAP for r in table[name]])))
    best_records = [r for r in records if setting_name(r["setting"]) == best]
    print(f"best on the validation walls: {best}", flush=True)
    held_out = wall_seeds(HELD_OUT_FIRST_SEED, args.held_out_walls)
    train_walls = best_records[0]["train_walls"]
    walls_env = make_env(split(train_walls, held_out), evaluation=True, max_episode_steps=GREEDY_CAP)
    span = walls_env.unwrapped._span
    results = {}

    # The DQN: zero-shot on each held-out wall, with no learning there.
    dqn, dqn_no_retry = [[] for _ in held_out], [[] for _ in held_out]
    for record in best_records:
        deterministic(record["seed"])
        net = SlotQNetwork(STATE_SIZE, record["setting"]["hidden"])
        net.load_state_dict(torch.load(out / "nets" / f"{best}-s{record['seed']}.pt"))
        climbs = greedy_climbs(net, walls_env, len(held_out), span)
        for index, wall in enumerate(held_out):
            rng = np.random.default_rng([record["seed"], wall])
            started = time.perf_counter()
            first5, _ = early_episodes(epsilon_greedy(net), single_wall_env(wall), rng, span)
            early = {"first5": first5, "steps_to_first5": record["steps"] + first5,
                     "seconds_to_first5": record["wall_clock_s"]["training"] + time.perf_counter() - started}
            climb = climbs[index]
            dqn[index].append(dict(early, finished=float(climb["finished"]), length=climb["length"],
                                   moves_before_failure=climb["moves_before_failure"]))
            dqn_no_retry[index].append(dict(early, finished=float(climb["finished_no_retry"]),
                                            length=climb["length_no_retry"], rise_m=climb["rise_m"],
                                            moves_before_failure=climb["moves_before_failure"],
                                            reached_share=1 - climb["failed_moves"] / climb["moves"]))
        print(f"DQN seed {record['seed']}: {sum(c['finished'] for c in climbs)}/{len(held_out)} held-out walls, "
              f"{sum(c['finished_no_retry'] for c in climbs)} without retries", flush=True)
    results["DQN, greedy (zero-shot)"] = dqn
    results["DQN, greedy without retries (zero-shot)"] = dqn_no_retry

    # The random policy: one capped episode for success, a walk of DYNA_ITERATIONS for the first 5 episodes.
    rand, rand_no_retry = [[] for _ in held_out], [[] for _ in held_out]
    curves = {"random": [], "Dyna-Q paper, from scratch": [], "Dyna-Q prior, from scratch": []}
    for index, wall in enumerate(held_out):
        for seed in range(args.seed, args.seed + SEEDS_PER_SETTING):
            rng = np.random.default_rng([seed, wall])
            env = single_wall_env(wall)
            for retries, rows in ((True, rand), (False, rand_no_retry)):
                obs, info = env.reset(seed=0)
                finished, length, failed, failures, before_failure = False, None, set(), 0, None
                start = lowest = float(obs["to_finish"][0])
                for count in range(1, GREEDY_CAP + 1):
                    allowed = info["action_mask"].copy()
                    allowed[list(failed)] = 0
                    if not allowed.any():
                        break
                    action = random_policy(None, None, allowed, rng)
                    obs, _, terminated, _, info = env.step(action)
                    lowest = min(lowest, float(obs["to_finish"][0]))
                    if terminated:
                        finished, length = True, count
                        break
                    if info["reached"]:
                        failed.clear()
                    else:
                        failures += 1
                        before_failure = count - 1 if before_failure is None else before_failure
                        if not retries:
                            failed.add(action)
                rows[index].append({"finished": float(finished), "length": length,
                                    "reached_share": 1 - failures / count, "rise_m": start - lowest,
                                    "moves_before_failure": count if before_failure is None else before_failure})
            started = time.perf_counter()
            first5, ends = early_episodes(random_policy, single_wall_env(wall), rng, span)
            early = {"first5": first5, "steps_to_first5": first5, "seconds_to_first5": time.perf_counter() - started}
            rand[index][-1].update(early)
            rand_no_retry[index][-1].update({key: None for key in early})
            curves["random"].append(ends)
    results["random (masked uniform)"] = rand
    results["random without retries"] = rand_no_retry

    # Dyna-Q, learning on each held-out wall itself; transfer starts from the Q_grid of the
    # same seed's run on training wall i (one of the DQN's training walls).
    for label, mode, transfer in DYNA_CONDITIONS:
        runs = [[] for _ in held_out]
        for index, wall_seed in enumerate(held_out):
            wall = crux.Wall.random(wall_seed)
            for seed in range(args.seed, args.seed + SEEDS_PER_SETTING):
                config = {"experiment.iterations": DYNA_ITERATIONS, "experiment.transfer": mode}
                q_grid, before = None, 0
                if transfer:
                    trained = crux.run_learning(crux.Wall.random(index % train_walls), config, seed=seed)
                    q_grid, before = trained.q_grid, DYNA_ITERATIONS
                run = crux.run_learning(wall, config, seed=seed, q_grid=q_grid)
                ends = np.cumsum(run.episode_lengths).tolist()
                first5 = ends[EARLY_EPISODES - 1] if len(ends) >= EARLY_EPISODES else DYNA_ITERATIONS
                # The same seed repeats the same first iterations: a run stopped at first5 is
                # the wall-clock to reach them (the training run's included for transfer).
                started = time.perf_counter()
                if transfer:
                    trained = crux.run_learning(crux.Wall.random(index % train_walls), config, seed=seed)
                crux.run_learning(wall, dict(config, **{"experiment.iterations": first5}), seed=seed,
                                  q_grid=trained.q_grid if transfer else None)
                seconds = time.perf_counter() - started
                finished = run.greedy_length >= 0
                runs[index].append({"finished": float(finished), "length": run.greedy_length if finished else None,
                                    "first5": first5, "steps_to_first5": before + first5,
                                    "seconds_to_first5": seconds})
                if label in curves:
                    curves[label].append(ends)
        results[label] = runs
        print(f"{label}: done", flush=True)

    summary = {"best_setting": best, "held_out_walls": held_out, "methods": {}, "paired": {}}
    for label, runs in results.items():
        summary["methods"][label] = {key: interval(per_wall_mean(runs, key))
                                     for key in ("finished", "length", "first5", "steps_to_first5",
                                                 "seconds_to_first5", "moves_before_failure", "rise_m",
                                                 "reached_share") if key in runs[0][0]}
    def success(label):
        return per_wall_mean(results[label], "finished")

    for dqn_label in ("DQN, greedy (zero-shot)", "DQN, greedy without retries (zero-shot)"):
        for label in results:
            if not label.startswith("DQN"):
                summary["paired"][f"{dqn_label} - {label}"] = paired(success(dqn_label), success(label))
    summary["search"] = {name: rows for name, rows in table.items()}
    summary["episode_ends"] = curves
    summary["runs"] = results
    (out / COMPARISON_FILE).write_text(json.dumps(summary, indent=1, sort_keys=True))
    print(markdown(summary))


def fmt(cell, digits=0, percent=False, walls=30):
    if cell["mean"] is None:
        return "-"
    scale = 100 if percent else 1
    unit = " %" if percent else ""
    if cell["low"] is None:
        return f"{cell['mean'] * scale:.{digits}f}{unit} (n = {cell['n']})"
    text = f"{cell['mean'] * scale:.{digits}f} [{cell['low'] * scale:.{digits}f}, {cell['high'] * scale:.{digits}f}]"
    return text + unit + ("" if cell["n"] == walls else f" (n = {cell['n']})")


def markdown(summary):
    lines = ["| method | greedy climbs finished | climb length (finished) | iterations to the first 5 episodes "
             "| environment steps to them | wall-clock to them (s) |", "|---|---|---|---|---|---|"]
    walls = len(summary["held_out_walls"])
    for label, m in summary["methods"].items():
        lines.append(f"| {label} | {fmt(m['finished'], 0, True, walls)} | {fmt(m['length'], 1, walls=walls)} "
                     f"| {fmt(m['first5'], walls=walls)} | {fmt(m['steps_to_first5'], walls=walls)} "
                     f"| {fmt(m['seconds_to_first5'], 2, walls=walls)} |")
    lines += ["", "| rollout | greedy moves before the first failure | moves that reached | highest rise (m) |",
              "|---|---|---|---|"]
    for label, m in summary["methods"].items():
        if "rise_m" in m:
            lines.append(f"| {label} | {fmt(m['moves_before_failure'], 1, walls=walls)} | {fmt(m['reached_share'], 0, True, walls)} "
                         f"| {fmt(m['rise_m'], 2, walls=walls)} |")
    lines += ["", "| climbs finished, paired over walls | difference | p |", "|---|---|---|"]
    for label, cell in summary["paired"].items():
        p = "-" if cell["p"] is None else f"{cell['p']:.2g}"
        lines.append(f"| {label} | {fmt(cell, 0, True, walls)} | {p} |")
    lines += ["", "| setting | validation greedy climbs finished, per seed | mean | without retries, per seed "
              "| mean | climb length | training episodes finished | wall-clock per run (s) |",
              "|---|---|---|---|---|---|---|---|"]
    for name, rows in summary["search"].items():
        lengths = [r["length"] for r in rows if r["length"] is not None]
        per_seed = ", ".join(f"{100 * r['success']:.0f} %" for r in rows)
        no_retry = ", ".join(f"{100 * r['success_no_retry']:.0f} %" for r in rows)
        mean_length = f"{np.mean(lengths):.1f}" if lengths else "-"
        lines.append(f"| {name} | {per_seed} "
                     f"| {100 * np.mean([r['success'] for r in rows]):.0f} % | {no_retry} "
                     f"| {100 * np.mean([r['success_no_retry'] for r in rows]):.0f} % | {mean_length} "
                     f"| {np.mean([r['train_episodes'] for r in rows]):.0f} "
                     f"| {np.mean([r['wall_clock_s'] for r in rows]):.0f} |")
    return "\n".join(lines)


def command_plot(args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = pathlib.Path(args.out)
    records = search_records(out)
    summary = json.loads((out / COMPARISON_FILE).read_text())
    matplotlib.rcParams["svg.hashsalt"] = "crux"  # the same figure, the same bytes
    figure, (left, middle, right) = plt.subplots(1, 3, figsize=(16, 4.6))
    by_setting = collections.defaultdict(list)
    for record in records:
        by_setting[setting_name(record["setting"])].append(record)
    for axes, key, title in ((left, "finished", "greedy"), (middle, "finished_no_retry", "greedy without retries")):
        for name, runs in sorted(by_setting.items()):
            steps = [point["step"] for point in runs[0]["curve"]]
            rates = np.mean([[np.mean([r[key] for r in point["validation"]]) for point in run["curve"]]
                             for run in runs], axis=0)
            best = name == summary["best_setting"]
            axes.plot(steps, 100 * rates, marker="o", linewidth=2.5 if best else 1, alpha=1 if best else 0.6,
                      label=name + (" (chosen)" if best else ""))
        axes.set(xlabel="environment steps of training (across training walls)",
                 ylabel="climbs finished on the validation walls (%)", ylim=(-3, 103),
                 title=f"DQN {title}, mean of 3 seeds")
    left.legend(fontsize=7)
    grid = np.arange(0, DYNA_ITERATIONS + 1, 100)
    for label, ends_per_run in summary["episode_ends"].items():
        counts = np.mean([np.searchsorted(ends, grid, side="right") for ends in ends_per_run], axis=0)
        right.plot(grid, counts, label=f"{label} (held-out walls, per wall)")
    best_runs = by_setting[summary["best_setting"]]
    budget = best_runs[0]["steps"]
    dqn_grid = np.arange(0, budget + 1, 100)
    counts = np.mean([np.searchsorted([e["end_step"] for e in run["episodes"] if e["finished"]], dqn_grid,
                                      side="right") for run in best_runs], axis=0)
    right.plot(dqn_grid, counts, color="black", label="DQN chosen setting (training walls, across walls)")
    right.set(xscale="log", yscale="log", xlim=(100, budget), xlabel="environment steps",
              ylabel="episodes finished", title="Episodes finished while learning")
    right.legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(args.figure, metadata={"Date": None} if str(args.figure).endswith(".svg") else None)
    print(f"wrote {args.figure}")


# What search passes on to each run's train, as collection_options declares them.
RUN_OPTIONS = ("steps", "train_walls", "envs", "batch", "replay", "checkpoints", "reward_height")


def collection_options(parser):
    """How a run collects and learns: train's and search's shared options."""
    parser.add_argument("--train-walls", type=positive, default=500)
    parser.add_argument("--validation-walls", type=positive, default=30)
    parser.add_argument("--envs", type=positive, default=1,
                        help="environments stepped together: 1 (an update every 2 steps) or a VectorClimbEnv "
                             "of them (an update every step of them all)")
    parser.add_argument("--batch", type=positive, default=BATCH, help="transitions an update")
    parser.add_argument("--replay", type=positive, help="transitions the replay keeps (default: every one)")
    parser.add_argument("--checkpoints", type=positive, default=CHECKPOINTS,
                        help="validations, evenly spaced, the last at the end")
    parser.add_argument("--reward-height", type=positive_number, default=None,
                        help="reward.height in training (potential-based height shaping, per metre, in the paper's "
                             "reward units); default: none, the paper's rewards")


def main(argv=None):
    # The whole docstring, so that --help gives the commands and the files they write.
    parser = OneLineParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True, parser_class=OneLineParser)
    one = commands.add_parser("train", help="one DQN run; prints its record as JSON")
    one.add_argument("--steps", type=positive, default=20000, help="environment steps of training")
    one.add_argument("--seed", type=int, default=1)
    one.add_argument("--lr", type=positive_number, default=1e-3)
    one.add_argument("--epsilon-decay", type=fraction, default=0.2,
                     help="share of the steps over which epsilon falls from 1 to 0.05")
    one.add_argument("--hidden", type=positive, default=64, help="width of the two hidden layers")
    collection_options(one)
    one.add_argument("--save", help="where to write the network's state_dict")
    one.add_argument("--quiet", action="store_true",
                     help="no progress on stderr (a bar on a terminal, else a line every ten seconds)")
    search = commands.add_parser(
        "search", help="the tuning grid, appending to OUT/search.jsonl (search-KofN.jsonl with --part K/N)")
    search.add_argument("--out", required=True)
    search.add_argument("--steps", type=positive, default=20000)
    search.add_argument("--seed", type=int, default=1)
    search.add_argument("--setting", type=grid_setting, help="one setting of the grid only, by its name (e.g. lr0.001-decay0.2-h64)")
    collection_options(search)
    search.add_argument("--part", type=part, default=(1, 1),
                        help="K/N: run the K-th of every N runs of the grid, for N processes (one core each)")
    compare = commands.add_parser("compare", help="the chosen setting, Dyna-Q and random on the held-out walls")
    compare.add_argument("--out", required=True)
    compare.add_argument("--seed", type=int, default=1)
    compare.add_argument("--held-out-walls", type=positive, default=30)
    plot = commands.add_parser("plot", help="the learning curves' figure")
    plot.add_argument("--out", required=True)
    plot.add_argument("figure")
    args = parser.parse_args(argv)
    if getattr(args, "replay", None) is not None and args.replay < args.batch:
        parser.error(f"argument --replay: must be at least --batch ({args.batch}), got {args.replay}")
    {"train": command_train, "search": command_search, "compare": command_compare, "plot": command_plot}[
        args.command](args)


if __name__ == "__main__":
    main()

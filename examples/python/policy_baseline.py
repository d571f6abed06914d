"""A learnt policy that climbs walls it has never seen: masked PPO on crux/Climb-v0's
"reach" observation, trained on random walls and evaluated zero-shot on held-out ones
(docs/BASELINES.md).

    export PYTHONPATH=build/release/python:../shared/third_party/gymnasium-1.4.0
    /usr/bin/python3 examples/python/policy_baseline.py train --steps 2000000 --seed 1 --out build/policy.json
    /usr/bin/python3 examples/python/policy_baseline.py evaluate --policy models/policies/reach-ppo.json --wall-seeds 20000:20029 --json
    /usr/bin/python3 examples/python/policy_baseline.py compare --policy A.json B.json C.json --wall-seeds 20000:20029
    /usr/bin/python3 examples/python/policy_baseline.py plot --search models/policies/search curves.png

train writes the policy as plain weights in JSON (the format below), with the command and
the seed that trained it; evaluate climbs each random wall A..B once with the policy's
greedy action (the highest-scored offered candidate; the observation marks the moves that
failed from the current state, so a policy that learnt to can avoid them) and compares
the climb's length, failed moves included, with the wall's exact shortest plan (with
--oracle verdict, only among the offered moves that reach: what knowing reach would
give, no longer zero-shot). A policy file whose training record names a veto
(reach_estimate.py train's reach head and threshold) climbs among the moves the head lets
through, unless --no-veto, in evaluate and in compare. compare puts policies beside
Dyna-Q and the random policy on the same walls, paired over walls; plot draws the
search's validation curves.
models/policies/reach-ppo.json is the shipped policy, its training command inside it.

Training walls are random walls whose seeds each environment draws from its own stream,
uniform over [0, 2^63): the validation walls (seeds from 10000) and the held-out ones
(from 20000) are never among them but with a chance of about 1e-17. One --seed fixes
everything else; torch runs deterministically on one CPU thread.

The policy file: {"format": "crux-policy", "version": 1, "observation": "reach",
"max_candidates", "max_span", "activation": "relu", "slot_layers": [...], "value_layers":
[...], "training": {...}}, each layer {"weight": rows of columns, "bias": [...]}, ReLU
between layers. The slot network scores each candidate from [state (55), slot (11)]; the
value network (training only) reads the state's 55 numbers.
"""

import argparse
import copy
import json
import math
import os
import pathlib
import shlex
import sys
import time

import numpy as np
import torch
from torch import nn

import crux
import crux.gym  # registers crux/Climb-v0
from example_arguments import OneLineParser, integer_at_least, positive, wall_seed_range
from wall_statistics import interval, paired, per_wall_mean

POLICY_FORMAT = "crux-policy"
POLICY_VERSION = 1
OBSERVATION = "reach"
MAX_CANDIDATES = crux.gym.DEFAULT_MAX_CANDIDATES
VALIDATION_FIRST_SEED = 10000
HELD_OUT_FIRST_SEED = 20000
# The paper's rewards (-1000 unreachable, -1 a step, +200000 the finish) scaled so that the
# finish is worth 2: the same optimal policy, value targets of a size a network fits.
REWARD_SCALE = 1e-5
# A greedy climb stops after this many actions (the plans take 7 to 20 moves).
CLIMB_CAP = 200
STATE_SIZE = 55  # free limb 4, held holds 12, root 3, joint angles 32, centre of mass 3, height to the finish 1
SLOT_SIZE = 3 + 7 + 1  # the candidate, its reach features, whether its move failed here


non_negative = integer_at_least(0)


def finite_float(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"must be a finite number, got {text!r}")
    return value


def finish_height(text):
    """A wall.finish_height that crux's random walls take (their key's range)."""
    value = finite_float(text)
    try:
        crux.Wall.random(0, {"wall.finish_height": value})
    except ValueError as error:
        raise argparse.ArgumentTypeError(str(error)) from None
    return value


def non_negative_float(text):
    value = finite_float(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be a finite number >= 0, got {text!r}")
    return value


def positive_float(text):
    value = non_negative_float(text)
    if value == 0:
        raise argparse.ArgumentTypeError(f"must be > 0, got {text!r}")
    return value


def unit_interval(text):
    value = non_negative_float(text)
    if value > 1:
        raise argparse.ArgumentTypeError(f"must be within [0, 1], got {text!r}")
    return value


def deterministic(seed, threads=1):
    torch.manual_seed(seed)
    torch.set_num_threads(threads)
    torch.use_deterministic_algorithms(True)


def climbing_config(physics_model, reward_height=None, gamma=None):
    """The environment's config: the paper's rules, or the static model with the learner's
    remedy of docs/PHYSICS.md (height shaping, a failed move in a stuck stance is a fall).
    reward_height: reward.height instead of the model's (0, or 100 under the static model);
    gamma: the learner's discount, which makes that shaping potential-based for it."""
    config = {} if gamma is None else {"learning.gamma": gamma}
    if physics_model == "static":
        config = {"physics.model": "static", "reward.height": 100.0, "physics.fall_when_stuck": True}
    if reward_height is not None:
        config["reward.height"] = reward_height
    return config


# --- features and network ------------------------------------------------------------------


def batch_features(obs, span):
    """The reach observation, batched (leading axis: environments), as (state (E, 55),
    slots (E, K, 11), mask (E, K) bool), lengths in max_spans."""
    posture = obs["posture"]
    envs = posture.shape[0]
    state = np.concatenate(
        [obs["free_limb"], obs["held"].reshape(envs, 12) / span, posture[:, :3] / span, posture[:, 3:],
         obs["centre_of_mass"] / span, obs["to_finish"] / span], axis=1)
    reach = obs["candidate_reach"] / span
    slots = np.concatenate([obs["candidates"] / span, reach, obs["candidate_failed"][..., None]], axis=2)
    return state.astype(np.float32), slots.astype(np.float32), obs["candidate_mask"] > 0.5


def single_features(obs, span):
    """batch_features of one environment's observation, with a leading axis of one."""
    return batch_features({key: value[None] for key, value in obs.items()}, span)


def mlp(sizes):
    """Width-1 convolutions with ReLUs between: per-slot linear layers (Debian's torch runs
    them through oneDNN, its linear layers through the reference BLAS, ten times slower)."""
    layers = []
    for i, (inputs, outputs) in enumerate(zip(sizes, sizes[1:])):
        layers.append(nn.Conv1d(inputs, outputs, 1))
        if i < len(sizes) - 2:
            layers.append(nn.ReLU())
    return nn.Sequential(*layers)


class SlotPolicy(nn.Module):
    """Scores each candidate slot from its features and the state's with the same weights,
    so that a slot means "this hold" whatever the wall and the order; the value reads the
    state alone."""

    def __init__(self, hidden, max_span):
        super().__init__()
        self.hidden = hidden
        self.max_span = max_span  # the lengths' scale: filter.max_span in training
        self.slot_net = mlp([STATE_SIZE + SLOT_SIZE, hidden, hidden, 1])
        self.value_net = mlp([STATE_SIZE, hidden, hidden, 1])

    def logits(self, state, slots, mask):
        # The first layer on [state, slot] is the state's part, once per state, plus the
        # slot's: the same numbers as on the concatenation, for a fifth of the work.
        first = self.slot_net[0]
        weight = first.weight
        from_state = nn.functional.conv1d(state.unsqueeze(2), weight[:, :STATE_SIZE], first.bias)
        from_slots = nn.functional.conv1d(slots.transpose(1, 2), weight[:, STATE_SIZE:])
        hidden = self.slot_net[2:](torch.relu(from_state + from_slots))
        return hidden.squeeze(1).masked_fill(~mask, -1e9)

    def value(self, state):
        return self.value_net(state.unsqueeze(2)).reshape(-1)


def greedy_slot(policy, state, slots, mask):
    with torch.no_grad():
        scores = policy.logits(torch.from_numpy(state), torch.from_numpy(slots), torch.from_numpy(mask))
    return int(torch.argmax(scores[0]))


def layers_of(sequential):
    return [{"weight": layer.weight.detach()[:, :, 0].tolist(), "bias": layer.bias.detach().tolist()}
            for layer in sequential if isinstance(layer, nn.Conv1d)]


def configured_max_span():
    """filter.max_span's default, which the environments train under (climbing_config sets no other)."""
    return next(key["default"] for key in crux.config_keys() if key["key"] == "filter.max_span")


def save_policy(policy, path, training):
    record = {"format": POLICY_FORMAT, "version": POLICY_VERSION, "observation": OBSERVATION,
              "max_candidates": MAX_CANDIDATES, "max_span": policy.max_span, "activation": "relu",
              "slot_layers": layers_of(policy.slot_net), "value_layers": layers_of(policy.value_net),
              "training": training}
    write_whole(path, json.dumps(record) + "\n")


def write_whole(path, text):
    """Writes text to path through a file of this process's own, renamed over it: never a
    half-written file, and processes that write the same file at once each write it whole."""
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f"{path.name}.{os.getpid()}.partial")
    temporary.write_text(text)
    os.replace(temporary, path)


def read_record(path, record_format, version, file_kind):
    """The JSON record of a weights file of this format, version and the reach observation;
    ValueError naming the file (a file_kind: "policy file", "reach head") on anything else."""
    kind = file_kind.removesuffix(" file")
    try:
        record = json.loads(pathlib.Path(path).read_text())
    except OSError as error:
        raise ValueError(f"{path}: cannot read the {file_kind} ({error.strerror})") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as error:
        raise ValueError(f"{path}: not a {file_kind} (not JSON: {error})") from None
    if not isinstance(record, dict) or record.get("format") != record_format:
        raise ValueError(f"{path}: not a {file_kind} (format is not {record_format!r})")
    if record.get("version") != version or record.get("observation") != OBSERVATION:
        raise ValueError(f"{path}: a {kind} for observation {record.get('observation')!r} version "
                         f"{record.get('version')!r}; this takes {OBSERVATION!r} version {version}")
    return record


def load_policy(path):
    """The policy of a file train wrote; ValueError naming the file on anything else."""
    record = read_record(path, POLICY_FORMAT, POLICY_VERSION, "policy file")
    try:
        hidden = len(record["slot_layers"][0]["bias"])
        policy = SlotPolicy(hidden, float(record["max_span"]))
        for sequential, layers in ((policy.slot_net, record["slot_layers"]), (policy.value_net, record["value_layers"])):
            load_layers(sequential, layers)
    except (KeyError, TypeError, IndexError, ValueError) as error:
        raise ValueError(f"{path}: not a policy file ({error})") from None
    return policy, record


def load_layers(sequential, layers):
    """Copies a file's layers ({"weight", "bias"} each) into the network's convolutions;
    ValueError when their number or shapes differ."""
    convolutions = [layer for layer in sequential if isinstance(layer, nn.Conv1d)]
    if len(convolutions) != len(layers):
        raise ValueError("a network has the wrong number of layers")
    for convolution, layer in zip(convolutions, layers):
        weight = torch.tensor(layer["weight"], dtype=torch.float32)[:, :, None]
        bias = torch.tensor(layer["bias"], dtype=torch.float32)
        if weight.shape != convolution.weight.shape or bias.shape != convolution.bias.shape:
            raise ValueError(f"a layer of shape {tuple(weight.shape[:2])} where "
                             f"{tuple(convolution.weight.shape[:2])} belongs")
        convolution.weight.data.copy_(weight)
        convolution.bias.data.copy_(bias)


# --- training: masked PPO (Huang and Ontanon 2020's invalid-action masking) ----------------


class Rollout:
    """One rollout of T steps of E environments. A step whose environment was resetting
    (Gymnasium's next-step autoreset) is no transition and weighs nothing."""

    def __init__(self, steps, envs):
        shape = (steps, envs)
        self.state = np.zeros(shape + (STATE_SIZE,), np.float32)
        self.slots = np.zeros(shape + (MAX_CANDIDATES, SLOT_SIZE), np.float32)
        self.mask = np.zeros(shape + (MAX_CANDIDATES,), bool)
        self.action = np.zeros(shape, np.int64)
        self.log_prob = np.zeros(shape, np.float32)
        self.value = np.zeros(shape, np.float32)
        self.reward = np.zeros(shape, np.float32)
        self.terminated = np.zeros(shape, bool)
        self.done = np.zeros(shape, bool)  # terminated or truncated
        self.valid = np.zeros(shape, bool)


def advantages(rollout, last_value, gamma, lam):
    """GAE over the rollout; the value after a step is that of the next stored observation,
    which after an episode's end is its final observation (next-step autoreset)."""
    steps = rollout.reward.shape[0]
    values = np.concatenate([rollout.value, last_value[None]], axis=0)
    advantage = np.zeros_like(rollout.reward)
    running = np.zeros_like(last_value)
    for t in reversed(range(steps)):
        following = values[t + 1] * (~rollout.terminated[t])
        delta = rollout.reward[t] + gamma * following - values[t]
        running = delta + gamma * lam * running * (~rollout.done[t])
        running = np.where(rollout.valid[t], running, 0.0)
        advantage[t] = running
    return advantage, advantage + rollout.value


def ppo_update(policy, optimiser, rollout, advantage, returns, args, rng):
    valid = rollout.valid.reshape(-1)
    index = np.flatnonzero(valid)
    flat = {name: getattr(rollout, name).reshape((-1,) + getattr(rollout, name).shape[2:])[index]
            for name in ("state", "slots", "mask", "action", "log_prob")}
    flat_advantage = advantage.reshape(-1)[index]
    flat_returns = returns.reshape(-1)[index]
    statistics = {"policy_loss": 0.0, "value_loss": 0.0, "entropy": 0.0, "updates": 0}
    for _ in range(args.epochs):
        order = rng.permutation(len(index))
        for start in range(0, len(order), args.minibatch):
            batch = order[start:start + args.minibatch]
            mask = flat["mask"][batch]
            # The slots past the last one offered in the batch only pad (a veto can leave gaps).
            count = int(np.flatnonzero(mask.any(axis=0)).max(initial=0)) + 1
            state = torch.from_numpy(flat["state"][batch])
            logits = policy.logits(state, torch.from_numpy(flat["slots"][batch][:, :count]),
                                   torch.from_numpy(mask[:, :count]))
            log_probs = torch.log_softmax(logits, dim=1)
            action = torch.from_numpy(flat["action"][batch])
            new_log_prob = log_probs.gather(1, action[:, None]).squeeze(1)
            probs = log_probs.exp()
            entropy = -(probs * log_probs.masked_fill(~torch.from_numpy(mask[:, :count]), 0.0)).sum(1).mean()
            adv = torch.from_numpy(flat_advantage[batch])
            adv = (adv - adv.mean()) / (adv.std() + 1e-8) if len(batch) > 1 else adv
            ratio = torch.exp(new_log_prob - torch.from_numpy(flat["log_prob"][batch]))
            policy_loss = -torch.min(ratio * adv, torch.clamp(ratio, 1 - args.clip, 1 + args.clip) * adv).mean()
            value_loss = ((policy.value(state) - torch.from_numpy(flat_returns[batch])) ** 2).mean()
            loss = policy_loss + args.value_weight * value_loss - args.entropy * entropy
            optimiser.zero_grad()
            loss.backward()
            nn.utils.clip_grad_norm_(policy.parameters(), 0.5)
            optimiser.step()
            statistics["policy_loss"] += float(policy_loss)
            statistics["value_loss"] += float(value_loss)
            statistics["entropy"] += float(entropy)
            statistics["updates"] += 1
    updates = max(1, statistics.pop("updates"))
    return {key: value / updates for key, value in statistics.items()}


def sample_actions(policy, state, slots, mask, generator):
    with torch.no_grad():
        # A state that offers nothing (a fall's dead end, about to reset) still needs an
        # action, which the reset ignores.
        safe_mask = mask.copy()
        safe_mask[~mask.any(axis=1), 0] = True
        logits = policy.logits(torch.from_numpy(state), torch.from_numpy(slots), torch.from_numpy(safe_mask))
        log_probs = torch.log_softmax(logits, dim=1)
        action = torch.multinomial(log_probs.exp(), 1, generator=generator).squeeze(1)
        value = policy.value(torch.from_numpy(state))
    return action.numpy(), log_probs.gather(1, action[:, None]).squeeze(1).numpy(), value.numpy()


def train(args, progress=None, veto=None, validation_veto=None):
    """Masked PPO; returns (policy, history, training), history a record per validation.
    veto: None, or a function (state (E, 55), slots (E, K, 11), mask (E, K)) -> the slots
    a reach estimate lets through, among which the rollouts sample and the updates learn;
    validation_veto: the same estimate's, for evaluate's validation climbs."""
    deterministic(args.seed, args.threads)
    config = climbing_config(args.physics_model, args.reward_height, args.gamma)
    # A lower finishing height makes finishes common early (a curriculum); validation keeps the walls' own.
    wall_config = None if args.finish_height is None else {"wall.finish_height": args.finish_height}
    envs = crux.gym.VectorClimbEnv(args.envs, wall=args.train_walls, observation=OBSERVATION, wall_order="sample",
                                   config=config, max_episode_steps=args.episode_steps, wall_config=wall_config)
    span = configured_max_span()
    policy = SlotPolicy(args.hidden, span)
    if getattr(args, "init_policy", None):
        start, _ = load_policy(args.init_policy)  # e.g. the kinematic policy, fine-tuned under the static model
        if start.hidden != args.hidden:
            raise ValueError(f"{args.init_policy}: a policy of width {start.hidden}, and --hidden is {args.hidden}")
        policy.load_state_dict(start.state_dict())
    optimiser = torch.optim.Adam(policy.parameters(), lr=args.lr, eps=1e-5)
    generator = torch.Generator().manual_seed(args.seed)
    rng = np.random.default_rng([args.seed, 1])
    obs, _ = envs.reset(seed=args.seed)
    resetting = np.zeros(args.envs, bool)
    rollout = Rollout(args.rollout, args.envs)
    updates = max(1, args.steps // (args.rollout * args.envs))
    history, episodes, finished = [], 0, 0
    validation_plans = getattr(args, "validation_plans", None)
    if args.validation_walls and validation_plans is None:
        validation_plans = plan_lengths(args.validation_walls, args.physics_model)
    started = time.monotonic()
    best = None  # with --keep-best: (score, steps, weights) of the best validation so far
    for update in range(updates):
        optimiser.param_groups[0]["lr"] = args.lr * (1 - update / updates)
        for t in range(args.rollout):
            state, slots, mask = batch_features(obs, span)
            if veto is not None:
                mask = vetoed(mask, veto(state, slots, mask))
            action, log_prob, value = sample_actions(policy, state, slots, mask, generator)
            obs, reward, terminated, truncated, info = envs.step(action)
            rollout.state[t], rollout.slots[t], rollout.mask[t] = state, slots, mask
            rollout.action[t], rollout.log_prob[t], rollout.value[t] = action, log_prob, value
            rollout.reward[t] = reward * REWARD_SCALE
            rollout.terminated[t], rollout.done[t] = terminated, terminated | truncated
            rollout.valid[t] = ~resetting
            episodes += int(np.sum((terminated | truncated) & ~resetting))
            finished += int(np.sum(terminated & ~resetting & ~info.get("fell", np.zeros(args.envs, bool))))
            resetting = terminated | truncated
        with torch.no_grad():
            last_value = policy.value(torch.from_numpy(batch_features(obs, span)[0])).numpy()
        advantage, returns = advantages(rollout, last_value, args.gamma, args.lam)
        losses = ppo_update(policy, optimiser, rollout, advantage, returns, args, rng)
        steps = (update + 1) * args.rollout * args.envs
        if args.validate_every and ((update + 1) % args.validate_every == 0 or update + 1 == updates):
            record = {"steps": steps, "episodes": episodes, "finished_episodes": finished,
                      "seconds": round(time.monotonic() - started, 1), **losses}
            if args.validation_walls:
                validation = evaluate(policy, args.validation_walls, args.physics_model, validation_plans,
                                      veto=validation_veto)
                record.update({key: validation[key] for key in VALIDATION_KEYS})
                score = (validation["finished"], -(validation["mean_length_ratio"] or math.inf))
                if getattr(args, "keep_best", False) and (best is None or score > best[0]):
                    best = (score, steps, copy.deepcopy(policy.state_dict()))
            history.append(record)
            if progress:
                progress(record)
    training = {"command": args.command, "seed": args.seed, "steps": updates * args.rollout * args.envs,
                "settings": {key: getattr(args, key) for key in SETTINGS}}
    if best is not None:
        policy.load_state_dict(best[2])
        training["kept_steps"] = best[1]  # the weights are those after these steps, not the last ones
    return policy, history, training


VALIDATION_KEYS = ("finished", "mean_length", "mean_length_ratio", "within_1_5_plans")
SETTINGS = ("lr", "entropy", "hidden", "rollout", "envs", "epochs", "minibatch", "clip", "gamma", "lam",
            "value_weight", "episode_steps", "physics_model", "reward_height", "finish_height")


# --- evaluation ------------------------------------------------------------------------------


def vetoed(mask, allowed):
    """The offered slots that are allowed, per state (rows); in a state where none is, all
    the offered ones: the policy's own choice, perhaps to fail."""
    kept = mask & allowed
    return np.where(kept.any(axis=1, keepdims=True), kept, mask)


def climb(policy, env, cap=CLIMB_CAP, allowed=None):
    """One greedy climb: (finished, actions taken, failed moves). allowed: None, or a
    function (actions so far, state, slots, mask) -> the offered slots to choose among (the
    verdict oracle's, or a reach estimate's veto); when it allows none, the policy's own."""
    obs, _ = env.reset()
    failed, history = 0, []
    for taken in range(1, cap + 1):
        state, slots, mask = single_features(obs, policy.max_span)
        if allowed is not None:
            mask = vetoed(mask, allowed(history, state, slots, mask))
        action = greedy_slot(policy, state, slots, mask)
        obs, _, terminated, truncated, info = env.step(action)
        history.append(action)
        failed += not info["reached"]
        if terminated:
            return not info.get("fell", False), taken, failed
    return False, cap, failed


def verdict_mask(wall_seed, config, history, mask):
    """Which offered slots' moves reach from the state the actions in history lead to: each
    tried in a new environment on the same wall that first takes those actions. Its
    verdicts are the climb's own: they depend on the route (docs/MODEL.md, C30), and a new
    environment's are a function of the actions it has taken."""
    reaches = np.zeros_like(mask)
    for slot in np.flatnonzero(mask[0]):
        # A new environment for each slot: the IK's cache keeps the first verdict on a
        # configuration, so a move tried in one environment would change its later verdicts.
        trial = crux.gym.ClimbEnv(wall_seed, OBSERVATION, config=config)
        trial.reset()
        for action in history:
            trial.step(action)
        reaches[0, slot] = trial.step(int(slot))[4]["reached"]
    return reaches


def allowed_moves(wall_seed, config, oracle, veto):
    """climb's allowed for one wall: the verdict oracle's, the veto's, or None."""
    if oracle:
        return lambda history, state, slots, mask: verdict_mask(wall_seed, config, history, mask)
    if veto is not None:
        return lambda history, state, slots, mask: veto(state, slots)
    return None


def plan_lengths(wall_seeds, physics_model="kinematic"):
    """{seed: its exact shortest plan's length, or None when the planner finds none}, for
    the walls whose start the climber can take."""
    config = climbing_config(physics_model)
    lengths = {}
    for seed in wall_seeds:
        wall = crux.Wall.random(seed)
        try:
            crux.ClimbMdp(wall, config=config)
        except ValueError:
            continue  # a start that does not hold: evaluate skips the wall too
        plan = crux.plan(wall, config={"physics.model": physics_model})  # the planner takes no reward
        lengths[seed] = plan["length"] if plan["found"] else None
    return lengths


def evaluate(policy, wall_seeds, physics_model="kinematic", plans=None, oracle=False, veto=None):
    """Greedy climbs on random walls: the finished share and the finished climbs' mean
    length; given plans (plan_lengths), the plans' mean length on the walls climbed, the
    mean ratio and the share of climbs that finish within 1.5 times their plan's length.
    oracle: choose only among the offered moves that reach (no longer a zero-shot climb);
    veto: None, or a function (state, slots) -> the slots a learnt estimate lets through."""
    if oracle and veto is not None:
        raise ValueError("evaluate takes the verdict oracle or a veto, not both")
    config = climbing_config(physics_model)
    lengths, plan_sum, ratios, skipped, walls = [], [], [], [], []
    for seed in wall_seeds:
        try:
            env = crux.gym.ClimbEnv(seed, OBSERVATION, config=config)
        except ValueError as error:  # under the static model, a start that does not hold
            skipped.append({"wall_seed": seed, "why": str(error)})
            continue
        done, length, failed = climb(policy, env, allowed=allowed_moves(seed, config, oracle, veto))
        wall = {"wall_seed": seed, "finished": done, "length": length, "failed_moves": failed}
        if plans is not None:
            wall["plan_length"] = plans.get(seed)
        if done:
            lengths.append(length)
            if wall.get("plan_length"):
                plan_sum.append(wall["plan_length"])
                ratios.append(length / wall["plan_length"])
        walls.append(wall)
    climbs = len(walls)
    result = {"climbs": climbs, "finished": sum(w["finished"] for w in walls) / climbs if climbs else 0.0,
              "mean_length": float(np.mean(lengths)) if lengths else None}
    if plans is not None:
        result["mean_plan_length"] = float(np.mean(plan_sum)) if plan_sum else None
        result["mean_length_ratio"] = float(np.mean(ratios)) if ratios else None
        within = [w["finished"] and bool(w["plan_length"]) and w["length"] <= 1.5 * w["plan_length"] for w in walls]
        result["within_1_5_plans"] = sum(within) / climbs if climbs else 0.0
        result["walls"] = walls
        result["skipped_walls"] = skipped
    return result


# --- the comparison on held-out walls (docs/BASELINES.md) ----------------------------------

# Dyna-Q's and the random policy's rows are those of the DQN's comparison (dqn_baseline.py
# compare): the paper's Dyna-Q learning 8000 iterations on each wall from scratch, then its
# greedy climb; the random policy's one episode; both capped at experiment.greedy_cap's 500.
DYNA_ITERATIONS = 8000
OTHERS_CAP = 500


def dyna_q_climb(wall_seed, seed):
    """The paper's Dyna-Q on the wall, from scratch: its greedy climb's (finished, length)."""
    run = crux.run_learning(crux.Wall.random(wall_seed),
                            {"experiment.iterations": DYNA_ITERATIONS, "experiment.transfer": "paper"}, seed=seed)
    return run.greedy_length >= 0, (run.greedy_length if run.greedy_length >= 0 else None)


def random_climb(wall_seed, seed):
    """One episode of the masked uniform random policy: (finished, length)."""
    env = crux.gym.ClimbEnv(wall=[wall_seed], observation="numeric")
    rng = np.random.default_rng([seed, wall_seed])
    _, info = env.reset(seed=0)
    for taken in range(1, OTHERS_CAP + 1):
        if not info["action_mask"].any():
            break
        _, _, terminated, _, info = env.step(int(rng.choice(np.flatnonzero(info["action_mask"]))))
        if terminated:
            return True, taken
    return False, None


def compare(policies, wall_seeds, seeds, vetoes=None):
    """Per held-out wall: its plan, each policy's greedy climb (under the veto vetoes gives
    it, one per policy, None for none), and Dyna-Q's and random's runs with each learning seed;
    then each method's mean over walls (each wall its runs' mean) with 95 % t-intervals, and
    the policy's differences paired over walls."""
    plans = plan_lengths(wall_seeds)
    walls = [{"wall_seed": seed, "plan_length": plans.get(seed), "policy": [], "dyna_q": [], "random": []}
             for seed in wall_seeds if seed in plans]
    for policy, veto in zip(policies, vetoes or [None] * len(policies)):
        climbs = evaluate(policy, [w["wall_seed"] for w in walls], plans=plans, veto=veto)["walls"]
        for wall, climb in zip(walls, climbs):
            length = climb["length"] if climb["finished"] else None
            wall["policy"].append({"finished": float(climb["finished"]), "length": length,
                                   "ratio": length / wall["plan_length"] if length and wall["plan_length"] else None,
                                   "failed_moves": climb["failed_moves"]})
    for wall in walls:
        for seed in seeds:
            for method, climb in (("dyna_q", dyna_q_climb), ("random", random_climb)):
                done, length = climb(wall["wall_seed"], seed)
                wall[method].append({"finished": float(done), "length": length})
    runs = {method: [wall[method] for wall in walls] for method in ("policy", "dyna_q", "random")}
    summary = {"wall_seeds": [w["wall_seed"] for w in walls], "learning_seeds": list(seeds), "walls": walls,
               "plan_length": interval([w["plan_length"] for w in walls]), "methods": {}, "paired": {}}
    for method, rows in runs.items():
        summary["methods"][method] = {key: interval(per_wall_mean(rows, key)) for key in ("finished", "length")}
    summary["methods"]["policy"]["ratio"] = interval(per_wall_mean(runs["policy"], "ratio"))
    for other in ("dyna_q", "random"):
        for key in ("finished", "length"):
            summary["paired"][f"policy - {other}, {key}"] = paired(per_wall_mean(runs["policy"], key),
                                                                     per_wall_mean(runs[other], key))
    summary["paired"]["policy - plan, length"] = paired(per_wall_mean(runs["policy"], "length"),
                                                        [w["plan_length"] for w in walls])
    return summary


def comparison_markdown(summary):
    def cell(c, digits=1, percent=False):
        if c["mean"] is None:
            return "-"
        k, unit = (100, " %") if percent else (1, "")
        text = f"{c['mean'] * k:.{digits}f}"
        if c["low"] is not None:
            text += f" [{c['low'] * k:.{digits}f}, {c['high'] * k:.{digits}f}]"
        return text + unit + ("" if c["n"] == len(summary["walls"]) else f" (n = {c['n']})")

    def lengths(runs):
        return ", ".join("-" if r["length"] is None else str(r["length"]) for r in runs)

    names = {"policy": "learnt policy, greedy (zero-shot)",
             "dyna_q": f"Dyna-Q paper, {DYNA_ITERATIONS} iterations on the wall", "random": "random (masked uniform)"}
    lines = ["| method | climbs finished | climb length (finished) |", "|---|---|---|"]
    for method, m in summary["methods"].items():
        lines.append(f"| {names[method]} | {cell(m['finished'], 0, True)} | {cell(m['length'])} |")
    lines.append(f"| exact plan | | {cell(summary['plan_length'])} |")
    lines += ["", f"Policy's length over the plan's: {cell(summary['methods']['policy']['ratio'], 2)}", "",
              "| paired over walls | difference | p |", "|---|---|---|"]
    for label, c in summary["paired"].items():
        percent = label.endswith("finished")
        lines.append(f"| {label} | {cell(c, 0 if percent else 1, percent)} | "
                     f"{'-' if c['p'] is None else format(c['p'], '.2g')} |")
    lines += ["", "| wall | plan | policy, per seed | Dyna-Q, per seed | random finished, per seed |",
              "|---|---|---|---|---|"]
    for w in summary["walls"]:
        lines.append(f"| {w['wall_seed']} | {w['plan_length']} | {lengths(w['policy'])} | {lengths(w['dyna_q'])} "
                     f"| {', '.join(str(int(r['finished'])) for r in w['random'])} |")
    return "\n".join(lines)


# --- commands --------------------------------------------------------------------------------


def command_train(args, script="policy_baseline.py", veto=None, validation_veto=None, record=None):
    """train from the command line; veto and validation_veto as train takes them, and record:
    more entries for the policy file's training record."""
    args.command = " ".join([f"examples/python/{script}"] + [shlex.quote(a) for a in args.argv])

    def progress(record):
        print(json.dumps(record), file=sys.stderr, flush=True)

    try:
        policy, history, training = train(args, progress, veto, validation_veto)
    except ValueError as error:  # a bad --init-policy file, named by the message
        print(f"{script}: --init-policy: {error}", file=sys.stderr)
        sys.exit(2)
    training.update(record or {})
    training["history"] = history
    save_policy(policy, args.out, training)
    print(json.dumps({"policy": str(args.out), "steps": training["steps"], "last": history[-1] if history else None}))




def load_for_walls(path, prog="policy_baseline.py", option="--policy"):
    """load_policy, for the walls crux builds now (the same filter.max_span), or exit 2 with one line."""
    try:
        policy, _ = load_policy(path)
        if abs(policy.max_span - configured_max_span()) > 1e-9:
            raise ValueError(f"{path}: a policy trained with filter.max_span = {policy.max_span} m, and the "
                             f"walls are climbed with {configured_max_span()} m: its observation would be another")
    except ValueError as error:
        print(f"{prog}: {option}: {error}", file=sys.stderr)
        sys.exit(2)
    return policy


def named_veto(path):
    """The veto the policy file's training record names, as recorded, or None; ValueError
    naming the file when that record is not an object."""
    training = read_record(path, POLICY_FORMAT, POLICY_VERSION, "policy file").get("training", {})
    if not isinstance(training, dict):
        raise ValueError(f"{path}: its training record is not an object")
    return training.get("veto")


def recorded_veto(path, policy):
    """(the veto the policy file's training record names, as evaluate takes it, {"head": its
    path, "threshold"}), or (None, None) when the record names none. Such a veto is
    reach_estimate.py train's: a reach head and a threshold. The head's recorded path is
    read from the nearest folder above the policy file that holds it or, failing that, from
    the current folder. ValueError naming the file on a veto that cannot be applied."""
    named = named_veto(path)
    if named is None:
        return None, None
    import reach_estimate  # it imports this module: at the top, the import would be circular
    try:
        recorded, threshold = pathlib.Path(named["head"]), float(named["threshold"])
    except (KeyError, TypeError, ValueError) as error:
        raise ValueError(f"{path}: its training record's veto is not a head and a threshold ({error})") from None
    if not 0 <= threshold < 1:
        raise ValueError(f"{path}: its training record's veto threshold must be in [0, 1), got {threshold}")
    folders = list(pathlib.Path(path).resolve().parents) + [pathlib.Path()]
    head_path = next((folder / recorded for folder in folders if (folder / recorded).is_file()), recorded)
    try:
        head, _ = reach_estimate.load_head(head_path)
        reach_estimate.check_span(head, policy, head_path)
    except ValueError as error:
        raise ValueError(f"{path}: the reach head of its veto: {error}") from None
    return head.veto(threshold), {"head": str(head_path), "threshold": threshold}


def veto_for_walls(path, policy):
    """recorded_veto, or exit 2 with one line."""
    try:
        return recorded_veto(path, policy)
    except ValueError as error:
        print(f"policy_baseline.py: --policy: {error}", file=sys.stderr)
        sys.exit(2)


def command_evaluate(args):
    policy = load_for_walls(args.policy)
    veto, named = veto_for_walls(args.policy, policy) if not args.no_veto and args.oracle == "none" else (None, None)
    if named and args.physics_model != "kinematic":
        # reach_estimate.py label climbs only under the kinematic model: every head learnt its verdicts.
        print(f"policy_baseline.py: --physics-model: {args.policy} names a veto whose reach head learnt the "
              f"kinematic model's verdicts, not the {args.physics_model} model's; --no-veto climbs without it",
              file=sys.stderr)
        sys.exit(2)
    result = evaluate(policy, args.wall_seeds, args.physics_model, plan_lengths(args.wall_seeds, args.physics_model),
                      oracle=args.oracle == "verdict", veto=veto)
    result["oracle"] = args.oracle
    result["veto"] = named
    if args.json:
        print(json.dumps(result, indent=2))
        return
    told = ", told which moves reach" if args.oracle == "verdict" else ""
    under = f", under its veto ({named['head']} at {named['threshold']})" if named else ""
    print(f"{result['climbs']} climbs, {result['finished']:.1%} finished, mean length {result['mean_length']}, "
          f"mean plan length {result['mean_plan_length']}{told}{under}")


def command_compare(args):
    policies = [load_for_walls(path) for path in args.policy]
    vetoes = [veto_for_walls(path, policy) if not args.no_veto else (None, None)
              for path, policy in zip(args.policy, policies)]
    summary = compare(policies, args.wall_seeds, args.seeds, [veto for veto, _ in vetoes])
    summary["policies"] = [str(path) for path in args.policy]
    summary["vetoes"] = [named for _, named in vetoes]
    if args.out:
        write_whole(args.out, json.dumps(summary, indent=1) + "\n")
    print(json.dumps(summary, indent=1) if args.json else comparison_markdown(summary))


def command_plot(args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    records = search_records(args.search)
    if not records:
        print(f"policy_baseline.py: --search: {args.search} has no {SEARCH_LOG}", file=sys.stderr)
        sys.exit(2)
    panels = (("finished", "validation climbs finished (%)", 100), ("mean_length_ratio", "mean length / plan's", 1),
              ("within_1_5_plans", "climbs within 1.5 x the plan (%)", 100))
    figure, axes = plt.subplots(1, len(panels) + (args.comparison is not None), figsize=(5 * len(panels) + 5, 4.2))
    colours = {0: "0.7", 1: "tab:blue", 2: "tab:red", 3: "tab:green"}
    for record in records:
        steps = [point["steps"] for point in record["history"]]
        for axis, (key, label, scale) in zip(axes, panels):
            values = [scale * point[key] if point[key] is not None else np.nan for point in record["history"]]
            axis.plot(steps, values, color=colours[record["stage"]], linewidth=1.6 if record["stage"] >= 2 else 0.8,
                      alpha=0.9 if record["stage"] else 0.5)
            axis.set(xscale="log", xlabel="environment steps of training", ylabel=label)
    axes[1].axhline(1.5, color="black", linestyle="--", linewidth=1)
    axes[0].legend(handles=[matplotlib.lines.Line2D([], [], color=c, label=f"stage {stage}")
                            for stage, c in colours.items()], loc="lower right")
    if args.comparison is not None:
        summary = json.loads(args.comparison.read_text())
        axis, plans = axes[-1], [w["plan_length"] for w in summary["walls"]]
        # Plans share a few lengths: each method's points sit a little to its side.
        for method, colour, offset, label in (("policy", "tab:green", -0.15, "learnt policy (zero-shot)"),
                                              ("dyna_q", "tab:purple", 0.15, f"Dyna-Q after {DYNA_ITERATIONS} iterations")):
            lengths = per_wall_mean([w[method] for w in summary["walls"]], "length")
            axis.scatter(np.array(plans) + offset, [np.nan if v is None else v for v in lengths], color=colour,
                         label=label, s=18)
        top = max(plans) + 2
        axis.plot([0, top], [0, top], color="black", linewidth=1, label="the plan's length")
        axis.plot([0, top], [0, 1.5 * top], color="black", linestyle="--", linewidth=1, label="1.5 x the plan's")
        axis.set(xlabel="exact plan's length (moves)", ylabel="greedy climb's length (actions, mean over seeds)",
                 title="held-out walls")
        axis.legend(loc="upper left", fontsize=8)
    figure.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    temporary = args.out.with_name(args.out.stem + ".partial" + args.out.suffix)
    figure.savefig(temporary, dpi=90)
    os.replace(temporary, args.out)


# The search (docs/BASELINES.md): every setting of the grid for STAGES[0]'s steps, then the
# best `keep` of the stage before for more steps, and 3 seeds of the best two; a setting's
# score is its validation climbs' share that finish within 1.5 times the plan's length.
# Stage 3, added after stage 2 saw seed 3 never finish an episode, gives the best setting
# height shaping (reward.height, in the paper's units), which rewards every rise.
SEARCH_GRID = {"lr": [3e-4, 1e-3], "entropy": [0.003, 0.01], "hidden": [64, 128], "rollout": [64, 128],
               "gamma": [0.95, 0.99]}
STAGES = [{"steps": 500_000, "keep": None, "seeds": [1]}, {"steps": 2_000_000, "keep": 8, "seeds": [1]},
          {"steps": 6_000_000, "keep": 2, "seeds": [1, 2, 3]},
          {"steps": 6_000_000, "keep": 1, "seeds": [1, 2, 3], "reward_height": 100_000.0}]
SEARCH_LOG = "search.jsonl"


def setting_name(setting):
    return "-".join(f"{key}{setting[key]:g}" for key in SEARCH_GRID)


def search_records(out):
    path = out / SEARCH_LOG
    return [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []


def score(record):
    """What the search ranks by: the target's share, then the finished share, then shortness."""
    validation = record["validation"]
    return (validation["within_1_5_plans"], validation["finished"], -(validation["mean_length_ratio"] or math.inf))


def stage_settings(records, stage):
    if stage == 0:
        keys = list(SEARCH_GRID)
        grid = np.array(np.meshgrid(*SEARCH_GRID.values(), indexing="ij"), dtype=object).reshape(len(keys), -1).T
        return [dict(zip(keys, values)) for values in grid]
    before = [r for r in records if r["stage"] == stage - 1]
    expected = len(stage_settings(records, stage - 1)) * len(STAGES[stage - 1]["seeds"])
    if len(before) < expected:
        raise SystemExit(f"policy_baseline.py: --stage: stage {stage - 1} has {len(before)} of its {expected} runs")
    by_setting = {}
    for record in before:
        by_setting.setdefault(setting_name(record["setting"]), []).append(record)
    ranked = sorted(by_setting.values(), key=lambda runs: np.mean([score(r) for r in runs], axis=0).tolist(),
                    reverse=True)
    return [runs[0]["setting"] for runs in ranked[:STAGES[stage]["keep"]]]


def command_search(args):
    args.out.mkdir(parents=True, exist_ok=True)
    records = search_records(args.out)
    plans_path = args.out / "validation_plans.json"
    if not plans_path.exists():
        plans = plan_lengths(args.validation_walls, args.physics_model)
        write_whole(plans_path, json.dumps({str(seed): length for seed, length in plans.items()}))
    args.validation_plans = {int(seed): length for seed, length in json.loads(plans_path.read_text()).items()}
    stage = STAGES[args.stage]
    done = {(setting_name(r["setting"]), r["seed"]) for r in records if r["stage"] == args.stage}
    runs = [(setting, seed) for setting in stage_settings(records, args.stage) for seed in stage["seeds"]]
    runs = runs[args.part[0] - 1::args.part[1]]
    for setting, seed in runs:
        name = setting_name(setting)
        if (name, seed) in done:
            continue
        run = argparse.Namespace(**vars(args))
        run.__dict__.update(setting)
        run.seed, run.steps = seed, args.steps or stage["steps"]
        run.reward_height = stage.get("reward_height", args.reward_height)
        run.command = (f"examples/python/policy_baseline.py train --steps {run.steps} --seed {seed} "
                       + " ".join(f"--{key} {value:g}" for key, value in setting.items())
                       + (f" --reward-height {run.reward_height:g}" if run.reward_height is not None else ""))
        policy, history, training = train(run)
        validation = evaluate(policy, args.validation_walls, args.physics_model, args.validation_plans)
        path = args.out / "policies" / f"stage{args.stage}-{name}-seed{seed}.json"
        save_policy(policy, path, dict(training, history=history))
        record = {"stage": args.stage, "setting": setting, "seed": seed, "steps": run.steps,
                  "seconds": history[-1]["seconds"] if history else None, "history": history,
                  "validation": {key: validation[key] for key in VALIDATION_KEYS}, "policy": str(path)}
        with open(args.out / SEARCH_LOG, "a") as log:
            log.write(json.dumps(record) + "\n")
        print(json.dumps({key: record[key] for key in ("stage", "setting", "seed", "seconds", "validation")}),
              flush=True)


def part(text):
    index, _, count = text.partition("/")
    if not index.isdigit() or not count.isdigit() or not 1 <= int(index) <= int(count):
        raise argparse.ArgumentTypeError(f"'{text}' is not K/N with 1 <= K <= N")
    return int(index), int(count)


def training_options(command):
    """The training settings, as train and search take them."""
    command.add_argument("--lr", type=positive_float, default=3e-4, help="Adam's learning rate, decayed linearly to 0")
    command.add_argument("--entropy", type=non_negative_float, default=0.01, help="the entropy bonus's weight")
    command.add_argument("--hidden", type=positive, default=128, help="units in each hidden layer")
    command.add_argument("--rollout", type=positive, default=128, help="steps per environment between updates")
    command.add_argument("--envs", type=positive, default=64, help="environments stepped together")
    command.add_argument("--epochs", type=positive, default=4, help="passes over a rollout")
    command.add_argument("--minibatch", type=positive, default=2048, help="transitions per gradient step")
    command.add_argument("--clip", type=unit_interval, default=0.2, help="PPO's ratio clip")
    command.add_argument("--gamma", type=unit_interval, default=0.99, help="discount")
    command.add_argument("--lam", type=unit_interval, default=0.95, help="GAE's lambda")
    command.add_argument("--value-weight", type=non_negative_float, default=0.5, help="the value loss's weight")
    command.add_argument("--episode-steps", type=positive, default=100, help="an episode's truncation in training")
    command.add_argument("--train-walls", type=positive, default=None,
                         help="train on random walls 0..N-1 (N <= 10000, sampled at each reset) instead of a new "
                         "random wall each episode")
    command.add_argument("--validation-walls", type=non_negative, default=30,
                         help="greedy climbs on walls 10000.. at each validation (0: none)")
    command.add_argument("--validate-every", type=non_negative, default=20,
                         help="updates between validations (0: none)")
    command.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic")
    command.add_argument("--reward-height", type=non_negative_float, default=None,
                         help="reward.height in training (potential-based height shaping, per metre, in the paper's "
                         "reward units); default: the model's rules (0, or 100 under the static model)")
    command.add_argument("--finish-height", type=finish_height, default=None,
                         help="the training walls' finishing height (wall.finish_height, m; default the generator's "
                         "3): lower for a curriculum; validation keeps 3")
    command.add_argument("--threads", type=positive, default=1, help="torch's CPU threads (1: deterministic)")


def parser():
    top = OneLineParser(prog="policy_baseline.py", description=__doc__.split("\n\n")[0])
    commands = top.add_subparsers(dest="command_name", required=True, parser_class=OneLineParser)
    t = commands.add_parser("train", help="Trains a policy with masked PPO and writes it")
    t.add_argument("--out", type=pathlib.Path, required=True, help="the policy file to write (JSON)")
    t.add_argument("--steps", type=positive, default=1_000_000, help="environment steps")
    t.add_argument("--seed", type=int, default=1, help="fixes the walls, the network and the sampling")
    t.add_argument("--init-policy", type=pathlib.Path, default=None,
                   help="start from this policy file's weights (of the same --hidden) instead of random ones")
    t.add_argument("--keep-best", action="store_true",
                   help="write the weights of the best validation (most finished, then the shortest climbs "
                   "against the plans), not the last ones")
    training_options(t)
    h = commands.add_parser("search", help="The settings' search, resumable: runs the stage's runs not yet logged")
    h.add_argument("--out", type=pathlib.Path, required=True, help="the folder of search.jsonl and the policies")
    h.add_argument("--stage", type=int, choices=range(len(STAGES)), required=True,
                   help="0: the grid; 1, 2: the best of the stage before, longer; 3: stage 2's best with height "
                   "shaping")
    h.add_argument("--part", type=part, default=(1, 1), help="K/N: this process's share of the stage's runs")
    h.add_argument("--steps", type=positive, default=None, help="override the stage's steps (a quick pilot)")
    training_options(h)
    e = commands.add_parser("evaluate", help="Greedy climbs of a policy on random walls")
    e.add_argument("--policy", type=pathlib.Path, required=True, help="a policy file train wrote")
    e.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, as A:B")
    e.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic")
    e.add_argument("--oracle", choices=("none", "verdict"), default="none",
                   help="verdict: the climbs choose only among the offered moves that reach, each tried first "
                   "in a copy of the climb (what knowing reach would give; no longer zero-shot), without the "
                   "file's veto")
    e.add_argument("--no-veto", action="store_true",
                   help="climb without the veto the policy file's training record names (a reach head and a "
                   "threshold, reach_estimate.py train's), which evaluate otherwise applies")
    e.add_argument("--json", action="store_true", help="print the result as JSON")
    c = commands.add_parser("compare", help="Policies against Dyna-Q and random on held-out walls, paired over walls")
    c.add_argument("--policy", type=pathlib.Path, nargs="+", required=True,
                   help="policy files (a setting's seeds): each climbs each wall once")
    c.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, as A:B")
    c.add_argument("--seeds", type=wall_seed_range, default=range(1, 4),
                   help="Dyna-Q's and random's learning seeds A:B (default 1:3)")
    c.add_argument("--no-veto", action="store_true",
                   help="climb without the vetoes the policy files' training records name, which compare "
                   "otherwise applies")
    c.add_argument("--out", type=pathlib.Path, default=None, help="also write the comparison (JSON) to this file")
    c.add_argument("--json", action="store_true", help="print the comparison as JSON, not as tables")
    g = commands.add_parser("plot", help="The search's validation curves (and a comparison's walls) as a PNG")
    g.add_argument("--search", type=pathlib.Path, required=True, help="the folder of search.jsonl")
    g.add_argument("--comparison", type=pathlib.Path, default=None, help="a file compare --out wrote")
    g.add_argument("out", type=pathlib.Path, help="the PNG to write")
    return top


def training_walls(args, command_parser):
    """training_options' wall counts as the seeds they name; exit 2 with one line on a count
    that would reach the validation walls."""
    if args.train_walls and args.train_walls > VALIDATION_FIRST_SEED:
        command_parser.error(f"--train-walls: must be at most {VALIDATION_FIRST_SEED}, the first validation wall")
    args.train_walls = list(range(args.train_walls)) if args.train_walls else None
    args.validation_walls = list(range(VALIDATION_FIRST_SEED, VALIDATION_FIRST_SEED + args.validation_walls))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = parser().parse_args(argv)
    args.argv = argv
    if args.command_name in ("train", "search"):
        training_walls(args, parser())
    {"train": command_train, "search": command_search, "evaluate": command_evaluate, "compare": command_compare,
     "plot": command_plot}[args.command_name](args)


if __name__ == "__main__":
    main()

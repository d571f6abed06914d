"""How short a climb the learnt policy's network could take if it copied exact plans
(docs/BASELINES.md, "The length target"): behavioural cloning of crux.plan's climbs.

    demonstrate --wall-seeds A:B --out FILE.npz [--physics-model static]
        Plans each random wall A..B exactly (crux.plan) and replays the plan in the reach
        form's environment: each step stores the policy's features of the state and the
        slot of the plan's hold; the file also records the physics model. A replay stops
        at the first plan move the environment does not reach: under ik.guess = previous
        a verdict can depend on the route that first met its configuration (docs/MODEL.md,
        C11), and the planner's route is not the replay's. Prints what the walls gave (JSON).
    imitate --demonstrations FILE.npz [...] --out POLICY.json [--epochs E] [--failed-share P] [--physics-model static]
        Trains policy_baseline.py's slot network to choose the plan's slot (cross-entropy),
        validates its greedy climbs after each epoch on walls 10000.. (under the files'
        physics model, which --physics-model must name) and writes a policy file
        that policy_baseline.py evaluate reads. The plans never fail a move, so the network
        would never see the observation's "this move failed here" flag: --failed-share marks
        that share of the other offered slots as failed in each minibatch (a failed move is
        never the plan's), which teaches a greedy climb not to repeat a failed move.

Deterministic on one thread: the same files and seed give the same weights.
"""

import json
import os
import pathlib
import shlex
import sys
import time
import zipfile

import numpy as np
import torch
from torch import nn

import crux
import crux.gym
import policy_baseline as baseline
from example_arguments import OneLineParser, integer_at_least, positive, wall_seed_range

FAILED_FLAG = baseline.SLOT_SIZE - 1  # the slot feature "its move failed from this state"
FIELDS = ("state", "slots", "mask", "action", "wall")
# Each field's shape after the steps' axis, and its type.
SHAPES = {"state": ((baseline.STATE_SIZE,), np.float32),
          "slots": ((baseline.MAX_CANDIDATES, baseline.SLOT_SIZE), np.float32),
          "mask": ((baseline.MAX_CANDIDATES,), bool), "action": ((), np.int64), "wall": ((), np.int64)}


def plan_slots(wall_seed, physics_model):
    """(the features and the plan's slot at each replayed step, how the replay ended), or
    (None, why) for a wall without a start or a plan."""
    config = baseline.climbing_config(physics_model)
    try:
        env = crux.gym.ClimbEnv(wall_seed, baseline.OBSERVATION, config=config)
    except ValueError:
        return None, "no start"
    wall = env.wall
    plan = crux.plan(wall, config={"physics.model": physics_model})
    if not plan["found"]:
        return None, "no plan"
    obs, info = env.reset()
    steps = []
    span = baseline.configured_max_span()
    for hold_id in plan["holds"]:
        slot = int(np.flatnonzero(info["candidate_holds"] == wall.index_of(hold_id))[0])
        features = baseline.single_features(obs, span)
        obs, _, terminated, _, info = env.step(slot)
        if not info["reached"]:
            return steps, "replay failed"
        steps.append((*(part[0] for part in features), slot))
        if terminated:
            return steps, "finished"
    return steps, "unfinished"  # every move reached, yet the replay's postures stayed below the finish


def demonstrate(wall_seeds, physics_model="kinematic"):
    """({field: array}, counts): the plans' steps on the walls and how their replays ended."""
    rows, counts = {field: [] for field in FIELDS}, {}
    for seed in wall_seeds:
        steps, ending = plan_slots(seed, physics_model)
        counts[ending] = counts.get(ending, 0) + 1
        for state, slots, mask, slot in steps or []:
            for field, value in zip(FIELDS, (state, slots, mask, slot, seed)):
                rows[field].append(value)
    data = {field: np.array(rows[field], dtype).reshape((-1, *shape)) for field, (shape, dtype) in SHAPES.items()}
    return data, counts


def read_demonstrations(path):
    """One file's fields, checked: ValueError naming what is wrong."""
    try:
        with np.load(path, allow_pickle=False) as data:
            fields = {field: data[field] for field in (*FIELDS, "physics_model")}
    except (OSError, ValueError, KeyError, TypeError, AttributeError, zipfile.BadZipFile) as error:
        raise ValueError(f"not a demonstrations file ({error})") from None
    for field, (shape, dtype) in SHAPES.items():
        kind = np.dtype(dtype).kind
        if fields[field].shape[1:] != shape or fields[field].dtype.kind != kind:
            raise ValueError(f"not a demonstrations file ({field} of shape {fields[field].shape[1:]} and kind "
                             f"{fields[field].dtype.kind!r}, where {shape} and {kind!r} belong)")
    if len({len(fields[field]) for field in FIELDS}) != 1:
        raise ValueError("not a demonstrations file (its fields have different numbers of steps)")
    action = fields["action"]
    inside = (action >= 0) & (action < baseline.MAX_CANDIDATES)
    if not inside.all() or not fields["mask"][np.arange(len(action)), action].all():
        raise ValueError("not a demonstrations file (a plan's slot that its state does not offer)")
    return fields


def load_demonstrations(paths, physics_model):
    """The files' steps, concatenated; ValueError naming a file that demonstrate did not
    write, one made under another physics model, or files without a step."""
    parts = []
    for path in paths:
        try:
            part = read_demonstrations(path)
        except ValueError as error:
            raise ValueError(f"{path}: {error}") from None
        if str(part["physics_model"]) != physics_model:
            raise ValueError(f"{path}: plans made under the {part['physics_model']} model, and --physics-model "
                             f"is {physics_model}")
        parts.append(part)
    data = {field: np.concatenate([part[field] for part in parts]) for field in FIELDS}
    if not len(data["action"]):
        raise ValueError(f"{', '.join(map(str, paths))}: no step to imitate (no wall gave a plan)")
    return data


def flag_failed(slots, mask, action, share, rng):
    """slots with `share` of the offered slots other than the plan's marked as failed moves."""
    flagged = (torch.from_numpy(rng.random(mask.shape)) < share) & mask
    flagged[torch.arange(len(action)), action] = False
    slots = slots.clone()
    slots[:, :, FAILED_FLAG] = torch.maximum(slots[:, :, FAILED_FLAG], flagged.float())
    return slots


def imitate(data, args, progress=None):
    """Behavioural cloning: (policy, history), a validation record per epoch."""
    baseline.deterministic(args.seed)
    policy = baseline.SlotPolicy(args.hidden, baseline.configured_max_span())
    optimiser = torch.optim.Adam(policy.parameters(), lr=args.lr)
    rng = np.random.default_rng([args.seed, 2])
    tensors = {field: torch.from_numpy(data[field]) for field in ("state", "slots", "mask", "action")}
    validation = list(range(baseline.VALIDATION_FIRST_SEED, baseline.VALIDATION_FIRST_SEED + args.validation_walls))
    plans = baseline.plan_lengths(validation, args.physics_model) if validation else None
    history, started = [], time.monotonic()
    for epoch in range(args.epochs):
        order = rng.permutation(len(data["action"]))
        loss_sum = correct = 0.0
        for start in range(0, len(order), args.minibatch):
            batch = torch.from_numpy(order[start:start + args.minibatch])
            mask, action = tensors["mask"][batch], tensors["action"][batch]
            slots = flag_failed(tensors["slots"][batch], mask, action, args.failed_share, rng)
            logits = policy.logits(tensors["state"][batch], slots, mask)
            loss = nn.functional.cross_entropy(logits, action)
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            loss_sum += float(loss) * len(batch)
            correct += int((logits.argmax(1) == action).sum())
        record = {"epoch": epoch + 1, "loss": loss_sum / len(order), "plan_slot_chosen": correct / len(order),
                  "seconds": round(time.monotonic() - started, 1)}
        if validation:
            result = baseline.evaluate(policy, validation, args.physics_model, plans)
            record.update({key: result[key] for key in baseline.VALIDATION_KEYS})
        history.append(record)
        if progress:
            progress(record)
    return policy, history


def writable_folder(path, option, prog="plan_imitation.py"):
    """Makes path's folder, or exits 2 with one line before any work is done."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        if not os.access(path.parent, os.W_OK):
            raise PermissionError(f"cannot write in {path.parent}")
    except OSError as error:
        print(f"{prog}: {option}: {path}: {error}", file=sys.stderr)
        sys.exit(2)


def command_demonstrate(args):
    writable_folder(args.out, "--out")
    data, counts = demonstrate(args.wall_seeds, args.physics_model)
    data["physics_model"] = np.array(args.physics_model)
    partial = args.out.with_name(f"{args.out.name}.{os.getpid()}.partial.npz")  # never a half-written file
    try:
        np.savez_compressed(partial, **data)
        partial.replace(args.out)
    finally:
        partial.unlink(missing_ok=True)
    print(json.dumps({"demonstrations": str(args.out), "steps": len(data["action"]),
                      "walls": len(args.wall_seeds), "replays": counts}))


def command_imitate(args):
    writable_folder(args.out, "--out")
    try:
        data = load_demonstrations(args.demonstrations, args.physics_model)
    except ValueError as error:
        print(f"plan_imitation.py: --demonstrations: {error}", file=sys.stderr)
        sys.exit(2)

    def progress(record):
        print(json.dumps(record), file=sys.stderr, flush=True)

    policy, history = imitate(data, args, progress)
    command = " ".join(["examples/python/plan_imitation.py"] + [shlex.quote(a) for a in args.argv])
    settings = {key: getattr(args, key)
                for key in ("epochs", "hidden", "lr", "minibatch", "failed_share", "physics_model")}
    baseline.save_policy(policy, args.out, {"command": command, "seed": args.seed, "steps": 0,
                                            "imitated_steps": len(data["action"]), "settings": settings,
                                            "history": history})
    print(json.dumps({"policy": str(args.out), "last": history[-1] if history else None}))


def parser():
    top = OneLineParser(prog="plan_imitation.py", description=__doc__.split("\n\n")[0])
    commands = top.add_subparsers(dest="command_name", required=True, parser_class=OneLineParser)
    d = commands.add_parser("demonstrate", help="Exact plans replayed as (features, plan's slot) steps")
    d.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, as A:B")
    d.add_argument("--out", type=pathlib.Path, required=True, help="the demonstrations file to write (.npz)")
    d.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic")
    i = commands.add_parser("imitate", help="Behavioural cloning of the plans' slots; writes a policy file")
    i.add_argument("--demonstrations", type=pathlib.Path, nargs="+", required=True, help="files demonstrate wrote")
    i.add_argument("--out", type=pathlib.Path, required=True, help="the policy file to write (JSON)")
    i.add_argument("--epochs", type=positive, default=30, help="passes over the demonstrations")
    i.add_argument("--seed", type=int, default=1, help="fixes the network and the minibatches")
    i.add_argument("--hidden", type=positive, default=128, help="units in each hidden layer")
    i.add_argument("--lr", type=baseline.positive_float, default=1e-3, help="Adam's learning rate")
    i.add_argument("--minibatch", type=positive, default=512, help="steps per gradient step")
    i.add_argument("--failed-share", type=baseline.unit_interval, default=0.15,
                   help="share of the other offered slots marked as failed moves in each minibatch")
    i.add_argument("--validation-walls", type=integer_at_least(0), default=30,
                   help="greedy climbs on walls 10000.. after each epoch (0: none)")
    i.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic",
                   help="the model the demonstrations' plans were made under, which the validation climbs under")
    return top


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = parser().parse_args(argv)
    args.argv = argv
    {"demonstrate": command_demonstrate, "imitate": command_imitate}[args.command_name](args)


if __name__ == "__main__":
    main()

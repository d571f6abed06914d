"""A learnt reach estimate beside the shipped policy: which offered moves reach, told from
what the policy sees, and the policy's greedy climbs with the moves it rejects vetoed
(docs/BASELINES.md, "A reach estimate in the repository").

    export PYTHONPATH=build/release/python:../shared/third_party/gymnasium-1.4.0
    /usr/bin/python3 examples/python/reach_estimate.py label --policy models/policies/reach-ppo.json \\
        --wall-seeds 3000000:3005999 --out build/labels-1.npz
    /usr/bin/python3 examples/python/reach_estimate.py fit --labels build/labels-*.npz --out build/reach-head.json
    /usr/bin/python3 examples/python/reach_estimate.py evaluate --policy models/policies/reach-ppo.json \\
        --head build/reach-head.json --veto 0.2 0.3 --wall-seeds 10000:10299 --json
    /usr/bin/python3 examples/python/reach_estimate.py train --init-policy models/policies/reach-ppo.json \\
        --head build/reach-head.json --veto 0.5 --out build/reach-ppo-vetoed.json

label climbs each random wall once with the policy, greedy but for a share of uniformly
random moves (so that the labels also cover moves the policy would not take), and labels
every offered move of every state visited with the climb's own verdict: each is tried in a
new MDP that first takes the climb's moves (policy_baseline.verdict_mask's verdicts, which
evaluate --oracle verdict uses). A row is what the policy's slot network reads, [state
(55), slot (11)]; the file also names the policy. Walls whose start cannot be taken are
skipped.

fit trains a classifier of the same shape as the slot network on all walls but the last
tenth, which it reports on (accuracy, AUC, and at the policy's own greedy choice), and
writes it as plain weights: {"format": "crux-reach-head", "version": 1, "observation":
"reach", "max_span", "input_mean", "input_scale", "layers": [...], "training": {...}}.

train goes on with masked PPO from a policy, its rollouts sampling and its updates learning
only among the offered moves the estimate lets through at P (all of them in a state where
it passes none), so that the policy learns to rank the moves its veto will leave it; its
validation climbs take the same veto. The policy file's training record names the head
and P.

evaluate climbs each wall greedily among the offered moves the estimate gives a
probability of reaching of at least P (all of them, when it gives none that much): a
zero-shot climb, since the estimate learnt on other walls.
"""

import argparse
import json
import os
import pathlib
import shlex
import sys
import zipfile

import numpy as np
import torch

import crux
import policy_baseline as baseline
from example_arguments import OneLineParser, positive, wall_seed_range
from reachability_study import auc

HEAD_FORMAT = "crux-reach-head"
HEAD_VERSION = 1
ROW_SIZE = baseline.STATE_SIZE + baseline.SLOT_SIZE
# A labelled climb stops after this many actions: the plans take 7 to 20 moves, and longer
# climbs would mostly label the states of walls the policy is lost on.
LABEL_CAP = 40
SCORING_BATCH = 65536  # rows scored at once: the whole set at once needs more memory than the machine has


# --- labels ----------------------------------------------------------------------------------


def label_wall(policy, wall_seed, config, random_share, rng):
    """(rows, reached, chosen) of one climb of the wall: per offered move of each state
    visited, the policy's row, the climb's verdict, and whether it is the policy's greedy choice."""
    wall = crux.Wall.random(wall_seed)
    env = crux.gym.ClimbEnv(wall_seed, baseline.OBSERVATION, config=config)
    obs, info = env.reset()
    rows, reached, chosen, holds_taken = [], [], [], []
    for _ in range(LABEL_CAP):
        state, slots, mask = baseline.single_features(obs, policy.max_span)
        offered = np.flatnonzero(mask[0])
        if offered.size == 0:
            break
        greedy = baseline.greedy_slot(policy, state, slots, mask)
        rows.append(np.concatenate([np.repeat(state, offered.size, axis=0), slots[0, offered]], axis=1))
        reached.append(verdicts(wall, config, holds_taken, info["candidate_holds"][offered]))
        chosen.append(offered == greedy)
        explore = rng.random() < random_share  # drawn at every state, so that one choice shifts no other draw
        action = int(rng.choice(offered)) if explore else greedy
        holds_taken.append(int(info["candidate_holds"][action]))
        obs, _, terminated, _, info = env.step(action)
        if terminated:
            break
    if not rows:  # a start that offers no move
        empty = no_labels()
        return empty["rows"], empty["reached"], empty["chosen"]
    return np.concatenate(rows), np.concatenate(reached), np.concatenate(chosen)


def verdicts(wall, config, holds_taken, holds):
    """Whether the move to each hold reaches from the state holds_taken leads to: the
    verdicts of policy_baseline.verdict_mask, each move tried in a new MDP that first takes
    those moves, without the Gymnasium environment's observation around it (40 % of the time)."""
    out = np.zeros(len(holds), bool)
    route = np.asarray(holds_taken, dtype=np.int64)
    for i, hold in enumerate(holds):
        trial = crux.ClimbMdp(wall, config=config, max_steps=None)
        trial.reset()
        trial.replay_actions(route)
        out[i] = trial.step(int(hold))[4]["reached"]
    return out


def label(policy, wall_seeds, random_share, seed, progress=None):
    """label_wall over the walls (each with its own stream from seed and the wall's seed),
    as arrays (rows, reached, chosen, and each row's wall seed)."""
    config = baseline.climbing_config("kinematic")
    parts = {"rows": [], "reached": [], "chosen": [], "wall": []}
    for wall_seed in wall_seeds:
        try:
            rows, reached, chosen = label_wall(policy, wall_seed, config, random_share,
                                               np.random.default_rng([seed, wall_seed]))
        except ValueError as error:
            if "the start configuration" not in str(error):
                raise
            continue  # a start the climber cannot take: evaluate skips such walls too
        for key, value in (("rows", rows), ("reached", reached), ("chosen", chosen),
                           ("wall", np.full(len(reached), wall_seed, np.int64))):
            parts[key].append(value)
        if progress:
            progress(wall_seed, len(reached))
    if not parts["wall"]:  # no wall whose start the climber can take
        return no_labels()
    return {key: np.concatenate(value) for key, value in parts.items()}


def no_labels():
    return {"rows": np.zeros((0, ROW_SIZE), np.float32), "reached": np.zeros(0, bool), "chosen": np.zeros(0, bool),
            "wall": np.zeros(0, np.int64)}


# --- the classifier ----------------------------------------------------------------------------


def logit(probability):
    """The logit a probability threshold in [0, 1) sets on the head's output (-inf at 0)."""
    return np.log(probability / (1 - probability)) if probability > 0 else -np.inf


class ReachHead:
    """P(the move reaches) per offered slot, from the slot network's row: an MLP of width-1
    convolutions (oneDNN, as the policy's) over standardised rows."""

    def __init__(self, hidden, mean, scale, max_span):
        self.net = baseline.mlp([ROW_SIZE, hidden, hidden, 1])
        self.mean = np.asarray(mean, np.float32)
        self.scale = np.asarray(scale, np.float32)
        self.max_span = max_span

    def logits(self, rows):
        """The logit of each row of (N, 66), scored SCORING_BATCH rows at a time."""
        out = []
        with torch.no_grad():
            for start in range(0, len(rows), SCORING_BATCH):
                batch = (rows[start:start + SCORING_BATCH] - self.mean) / self.scale
                out.append(self.net(torch.from_numpy(batch.T.copy()).unsqueeze(0))[0, 0].numpy())
        return np.concatenate(out) if out else np.zeros(0, np.float32)

    def veto(self, threshold):
        """evaluate's veto: the slots of one observation's (state (1, 55), slots (1, K, 11))
        estimated to reach with a probability of at least threshold, as (1, K) booleans."""
        logit_threshold = logit(threshold)

        def allowed(state, slots):
            rows = np.concatenate([np.repeat(state, slots.shape[1], axis=0), slots[0]], axis=1)
            return (self.logits(rows) >= logit_threshold)[None]

        return allowed

    def training_veto(self, threshold):
        """train's veto: of a batch of observations (state (E, 55), slots (E, K, 11), mask
        (E, K)), the offered slots estimated to reach with a probability of at least
        threshold; only the offered slots are scored."""
        logit_threshold = logit(threshold)

        def allowed(state, slots, mask):
            env_of, slot_of = np.nonzero(mask)
            passed = np.zeros_like(mask)
            passed[env_of, slot_of] = self.logits(np.concatenate([state[env_of], slots[env_of, slot_of]], axis=1)) \
                >= logit_threshold
            return passed

        return allowed


def fit_head(rows, reached, hidden, epochs, seed, max_span, batch=4096, lr=1e-3, threads=1, progress=None):
    """A ReachHead trained with Adam on the logistic loss, its learning rate decayed
    linearly to 0 over the epochs."""
    baseline.deterministic(seed, threads)
    mean = rows.mean(axis=0, dtype=np.float64).astype(np.float32)
    scale = (rows.std(axis=0, dtype=np.float64) + 1e-6).astype(np.float32)
    head = ReachHead(hidden, mean, scale, max_span)
    inputs = torch.from_numpy(((rows - mean) / scale).T.copy())
    targets = torch.from_numpy(reached.astype(np.float32))
    optimiser = torch.optim.Adam(head.net.parameters(), lr=lr)
    generator = torch.Generator().manual_seed(seed)
    steps = epochs * -(-len(reached) // batch)
    step = 0
    for epoch in range(epochs):
        for index in torch.randperm(len(reached), generator=generator).split(batch):
            optimiser.param_groups[0]["lr"] = lr * (1 - step / steps)
            logits = head.net(inputs[:, index].unsqueeze(0))[0, 0]
            loss = torch.nn.functional.binary_cross_entropy_with_logits(logits, targets[index])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            step += 1
        if progress:
            progress(epoch + 1, float(loss))
    return head


def report(head, rows, reached, chosen):
    """The head's accuracy and AUC on the rows, and at the policy's greedy choices."""
    logits = head.logits(rows)
    right = (logits > 0) == reached
    return {"moves": int(len(reached)), "reaching_share": float(reached.mean()), "accuracy": float(right.mean()),
            "auc": auc(logits.astype(np.float64), reached),
            "at_the_policy_choice": {"moves": int(chosen.sum()), "accuracy": float(right[chosen].mean()),
                                     "choice_reaches": float(reached[chosen].mean()),
                                     "failing_passed": int((chosen & ~reached & (logits > 0)).sum()),
                                     "reaching_rejected": int((chosen & reached & (logits <= 0)).sum())}}


def save_head(head, path, training):
    layers = baseline.layers_of(head.net)
    record = {"format": HEAD_FORMAT, "version": HEAD_VERSION, "observation": baseline.OBSERVATION,
              "max_span": head.max_span, "input_mean": head.mean.tolist(), "input_scale": head.scale.tolist(),
              "activation": "relu", "layers": layers, "training": training}
    baseline.write_whole(path, json.dumps(record) + "\n")


def load_head(path):
    """The ReachHead of a file fit wrote; ValueError naming the file on anything else."""
    record = baseline.read_record(path, HEAD_FORMAT, HEAD_VERSION, "reach head")
    try:
        head = ReachHead(len(record["layers"][0]["bias"]), record["input_mean"], record["input_scale"],
                         float(record["max_span"]))
        if head.mean.shape != (ROW_SIZE,) or head.scale.shape != (ROW_SIZE,) or not (head.scale > 0).all():
            raise ValueError(f"input_mean and input_scale must be {ROW_SIZE} numbers, the scales positive")
        baseline.load_layers(head.net, record["layers"])
    except (KeyError, TypeError, IndexError, ValueError) as error:
        raise ValueError(f"{path}: not a reach head ({error})") from None
    return head, record


# --- commands ----------------------------------------------------------------------------------


def command_label(args):
    policy = baseline.load_for_walls(args.policy, "reach_estimate.py")

    def progress(wall_seed, moves):
        if args.progress:
            print(f"wall {wall_seed}: {moves} moves", file=sys.stderr, flush=True)

    labels = label(policy, args.wall_seeds, args.random_share, args.seed, progress)
    # Through a file of this process's own, renamed over the output: never a half-written file.
    partial = args.out.with_name(f"{args.out.name}.{os.getpid()}.partial.npz")
    try:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        np.savez_compressed(partial, **labels, policy=str(args.policy), random_share=args.random_share,
                            seed=args.seed)
        partial.replace(args.out)
    except OSError as error:
        fail("--out", f"{args.out}: cannot write it ({error.strerror})")
    walls = len(np.unique(labels["wall"]))
    print(json.dumps({"labels": str(args.out), "walls": walls, "skipped_walls": len(args.wall_seeds) - walls,
                      "moves": int(len(labels["reached"])),
                      "reaching_share": float(labels["reached"].mean()) if len(labels["reached"]) else None}))


def fail(argument, problem):
    """Bad input: one line naming the argument, exit code 2."""
    print(f"reach_estimate.py: {argument}: {problem}", file=sys.stderr)
    sys.exit(2)


LABEL_KEYS = ("rows", "reached", "chosen", "wall", "policy")


def read_labels(paths):
    """The label files' arrays, concatenated, and the policy that labelled them; exit 2 with
    one line on a file that is not one, or on files of different policies."""
    parts = []
    for path in paths:
        try:
            with open(path, "rb") as file, np.load(file) as data:
                parts.append({key: data[key] for key in LABEL_KEYS})
        except (OSError, ValueError, KeyError, TypeError, zipfile.BadZipFile) as error:
            fail("--labels", f"{path}: not a label file ({error or type(error).__name__})")
        rows, count = parts[-1]["rows"], len(parts[-1]["reached"])
        if rows.ndim != 2 or rows.shape[1] != ROW_SIZE:
            fail("--labels", f"{path}: rows of {rows.shape[1:]} numbers, not {ROW_SIZE}")
        if not len(rows) == count == len(parts[-1]["chosen"]) == len(parts[-1]["wall"]):
            fail("--labels", f"{path}: its arrays differ in length")
    policies = {str(part["policy"]) for part in parts}
    if len(policies) > 1:
        fail("--labels", f"files of different policies ({', '.join(sorted(policies))})")
    return {key: np.concatenate([part[key] for part in parts]) for key in LABEL_KEYS[:-1]}, policies.pop()


def command_fit(args):
    labels, labelled_by = read_labels(args.labels)
    walls = np.unique(labels["wall"])
    held_out_count = max(1, round(len(walls) * args.held_out_share))
    if held_out_count >= len(walls):
        fail("--held-out-share", f"leaves no wall to train on (the labels hold {len(walls)} walls)")
    held_out_walls = walls[len(walls) - held_out_count:]
    test = np.isin(labels["wall"], held_out_walls)
    try:  # found before the fit, not after it
        args.out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        fail("--out", f"{args.out}: cannot write it ({error.strerror})")
    if not os.access(args.out.parent, os.W_OK):
        fail("--out", f"{args.out}: cannot write in its folder")

    def progress(epoch, loss):
        print(json.dumps({"epoch": epoch, "last_loss": loss}), file=sys.stderr, flush=True)

    head = fit_head(labels["rows"][~test], labels["reached"][~test], args.hidden, args.epochs, args.seed,
                    baseline.configured_max_span(), threads=args.threads, progress=progress)
    training = {"command": " ".join(["examples/python/reach_estimate.py"] + [shlex.quote(a) for a in args.argv]),
                "seed": args.seed, "labelled_by": labelled_by, "walls": int(len(walls)),
                "training_moves": int((~test).sum()),
                "held_out_walls": [int(held_out_walls[0]), int(held_out_walls[-1])],
                "held_out": report(head, labels["rows"][test], labels["reached"][test], labels["chosen"][test])}
    save_head(head, args.out, training)
    print(json.dumps({"head": str(args.out), **training}, indent=1))


def check_span(head, policy, path):
    """ValueError naming the head's file unless it reads the policy's observation (the same
    filter.max_span)."""
    if abs(head.max_span - policy.max_span) > 1e-9:
        raise ValueError(f"{path}: fitted with filter.max_span = {head.max_span} m, and the policy reads "
                         f"{policy.max_span} m")


def head_for(path, policy):
    """The reach head of the file, for the policy's observation; exit 2 with one line on
    anything else."""
    try:
        head, _ = load_head(path)
        check_span(head, policy, path)
    except ValueError as error:
        fail("--head", error)
    return head


def command_train(args):
    baseline.training_walls(args, parser())
    if args.physics_model != "kinematic":
        # label climbs only under the kinematic model, so every head's verdicts are that model's.
        fail("--physics-model", "the reach head learnt the kinematic model's verdicts; its veto would misjudge the "
             f"{args.physics_model} model's moves")
    head = head_for(args.head, baseline.load_for_walls(args.init_policy, "reach_estimate.py", "--init-policy"))
    baseline.command_train(args, "reach_estimate.py", head.training_veto(args.veto), head.veto(args.veto),
                           {"veto": {"head": str(args.head), "threshold": args.veto}})


def command_evaluate(args):
    policy = baseline.load_for_walls(args.policy, "reach_estimate.py")
    head = head_for(args.head, policy)
    plans = baseline.plan_lengths(args.wall_seeds)
    results = []
    for threshold in args.veto:
        result = baseline.evaluate(policy, args.wall_seeds, plans=plans, veto=head.veto(threshold))
        result["veto"] = threshold
        result["failed_moves"] = sum(wall["failed_moves"] for wall in result["walls"])
        results.append(result)
        if not args.json:
            ratio = result["mean_length_ratio"]
            print(f"veto {threshold}: {result['climbs']} climbs, {result['finished']:.1%} finished, "
                  f"{'no' if ratio is None else format(ratio, '.3f')} times the plan, "
                  f"{result['failed_moves']} failed moves")
    if args.json:
        print(json.dumps(results if len(results) > 1 else results[0], indent=1))


def probability(text):
    value = baseline.unit_interval(text)
    if value >= 1:
        raise argparse.ArgumentTypeError(f"must be below 1, got {value}")
    return value


def parser():
    top = OneLineParser(prog="reach_estimate.py", description=__doc__.split("\n\n")[0])
    commands = top.add_subparsers(dest="command_name", required=True, parser_class=OneLineParser)
    labelling = commands.add_parser("label",
                                    help="Labels every offered move of the policy's climbs with the climb's verdict")
    labelling.add_argument("--policy", type=pathlib.Path, required=True,
                           help="the policy file whose climbs are labelled")
    labelling.add_argument("--wall-seeds", type=wall_seed_range, required=True,
                           help="random walls A to B inclusive, as A:B")
    labelling.add_argument("--random-share", type=baseline.unit_interval, default=0.2,
                           help="the share of the climb's moves chosen uniformly at random instead of greedily")
    labelling.add_argument("--seed", type=int, default=1, help="the random moves' seed")
    labelling.add_argument("--out", type=pathlib.Path, required=True, help="the .npz file to write")
    labelling.add_argument("--progress", action="store_true", help="a line per wall on stderr")
    fitting = commands.add_parser("fit", help="Trains the reach head on label files and reports it on held-out walls")
    fitting.add_argument("--labels", type=pathlib.Path, nargs="+", required=True, help="files label wrote")
    fitting.add_argument("--out", type=pathlib.Path, required=True, help="the reach head to write (JSON)")
    fitting.add_argument("--epochs", type=positive, default=24, help="passes over the training moves")
    fitting.add_argument("--hidden", type=positive, default=256, help="units in each of the two hidden layers")
    fitting.add_argument("--held-out-share", type=baseline.unit_interval, default=0.1,
                         help="the share of the walls (the last by seed) kept out of training and reported on")
    fitting.add_argument("--seed", type=int, default=1, help="the network's and the minibatches' seed")
    fitting.add_argument("--threads", type=positive, default=1, help="torch's CPU threads (1: deterministic)")
    training = commands.add_parser("train", help="Masked PPO from a policy, sampling and learning only among the "
                                   "moves the head lets through")
    training.add_argument("--init-policy", type=pathlib.Path, required=True,
                          help="the policy file policy_baseline.py wrote to start from")
    training.add_argument("--head", type=pathlib.Path, required=True, help="a reach head fit wrote")
    training.add_argument("--veto", type=probability, required=True,
                          help="one threshold P (evaluate takes several): the rollouts and the validation climbs "
                          "choose among the moves estimated to reach with at least P")
    training.add_argument("--out", type=pathlib.Path, required=True, help="the policy file to write (JSON)")
    training.add_argument("--steps", type=positive, default=1_000_000, help="environment steps")
    training.add_argument("--seed", type=int, default=1, help="fixes the walls, the network and the sampling")
    baseline.training_options(training)
    evaluating = commands.add_parser("evaluate", help="The policy's greedy climbs with the head's veto")
    evaluating.add_argument("--policy", type=pathlib.Path, required=True, help="a policy file policy_baseline.py wrote")
    evaluating.add_argument("--head", type=pathlib.Path, required=True, help="a reach head fit wrote")
    evaluating.add_argument("--veto", type=probability, nargs="+", required=True,
                            help="thresholds P: the climbs choose among the moves estimated to reach with at least P")
    evaluating.add_argument("--wall-seeds", type=wall_seed_range, required=True,
                            help="random walls A to B inclusive, as A:B")
    evaluating.add_argument("--json", action="store_true", help="print the result as JSON")
    return top


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = parser().parse_args(argv)
    args.argv = argv
    {"label": command_label, "fit": command_fit, "train": command_train,
     "evaluate": command_evaluate}[args.command_name](args)


if __name__ == "__main__":
    main()

"""What a network can tell of reachability from the numeric observation (docs/BASELINES.md,
"What the observation tells of reachability").

    generate --wall-seeds A:B --states-per-wall N --out FILE.npz [--seed S]
        Climbs each random wall A..B with a random policy and, at each visited state, labels
        every candidate move with the MDP's own verdict: the state is rebuilt by replaying its
        actions from the start and the move is stepped (info["reached"]). Stores, per label,
        what the observation gives for its slot and the reach features below.
    fit --data FILE.npz [FILE.npz ...] --held-out-walls K [--epochs E] [--json]
        Trains a per-slot classifier (an MLP, one row per candidate) on the walls before the
        last K and reports its accuracy and AUC on those K, once on the observation's slot
        alone and once with the reach features added, and where each goes wrong.

A slot's view of the observation: the candidate (3), the free limb (4), the held holds
(12), the posture (35), the centre of mass (3) and the height to the finish (1), positions
relative to the free limb's grasp point. The reach features: the candidate relative to the
free limb's shoulder or hip at the current posture (3) and that distance (1), and the
candidate's distance to each of the three held holds (3).
"""

import argparse
import json
import sys

import numpy as np

import crux
from example_arguments import wall_seed_range

MAX_CANDIDATES = 32
# The joint at the root of each limb, in crux's limb order (right hand, left hand, right
# foot, left foot): the shoulder's or the hip's first joint.
LIMB_ROOT_JOINTS = ["right_shoulder_flexion", "left_shoulder_flexion", "right_hip_flexion", "left_hip_flexion"]
# A random climb starts again after this many actions, so that the replays stay short.
EPISODE_ACTIONS = 40
BASE_FEATURES = 58
REACH_FEATURES = 7


def slot_features(observation, limb_roots):
    """The base and reach features of each candidate slot of one observation: (slots, 58 + 7)."""
    count = int(observation["candidate_mask"].sum())
    candidates = observation["candidates"][:count].astype(np.float64)
    free = int(np.argmax(observation["free_limb"]))
    shared = np.concatenate([observation["free_limb"], observation["held"].ravel(), observation["posture"],
                             observation["centre_of_mass"], observation["to_finish"]]).astype(np.float64)
    from_root = candidates - limb_roots[free]
    held = observation["held"].astype(np.float64)
    to_held = np.stack([np.linalg.norm(candidates - held[limb], axis=1) for limb in range(4) if limb != free], axis=1)
    return np.concatenate([candidates, np.broadcast_to(shared, (count, shared.size)), from_root,
                           np.linalg.norm(from_root, axis=1, keepdims=True), to_held], axis=1)


def label_state(mdp, history, candidates):
    """The MDP's verdict on each candidate move of the state that `history` leads to."""
    labels = []
    for hold in candidates:
        mdp.reset()
        mdp.replay_actions(np.asarray(history, dtype=np.int64))
        labels.append(bool(mdp.step(int(hold))[4]["reached"]))
    return labels


def generate_wall(wall_seed, states, rng, config=None):
    """(features, labels, visits) of `states` states of random climbs on one random wall;
    visits: each state's actions from the start and its candidate holds, in label order."""
    mdp = crux.ClimbMdp(crux.Wall.random(wall_seed), config=config, max_steps=None)
    joint_names = list(mdp.model.joint_names)
    root_joints = [joint_names.index(name) for name in LIMB_ROOT_JOINTS]
    features, labels, visits = [], [], []
    history = []
    mdp.reset()
    for _ in range(states):
        observation = mdp.numeric_observation(MAX_CANDIDATES)
        candidates = np.flatnonzero(mdp.action_mask())
        origins = crux.forward_kinematics(mdp.model, observation["posture"].astype(np.float64),
                                          joints=True)["joint_origins"]
        features.append(slot_features(observation, origins[root_joints]))
        labels.extend(label_state(mdp, history, candidates))
        visits.append((list(history), candidates))
        action = int(rng.choice(candidates))
        mdp.reset()
        mdp.replay_actions(np.asarray(history, dtype=np.int64))
        terminated = mdp.step(action)[2]
        history.append(action)
        if terminated or len(history) >= EPISODE_ACTIONS:
            history = []
            mdp.reset()
    return np.concatenate(features), np.array(labels, dtype=bool), visits


def generate(args):
    rows, labels, walls, states = [], [], [], []
    for wall_seed in args.wall_seeds:
        rng = np.random.default_rng([args.seed, wall_seed])
        x, y, visits = generate_wall(wall_seed, args.states_per_wall, rng)
        rows.append(x.astype(np.float32))
        labels.append(y)
        walls.append(np.full(len(y), wall_seed, dtype=np.int64))
        states.append(np.repeat(np.arange(len(visits)), [len(candidates) for _, candidates in visits]))
        print(f"wall {wall_seed}: {len(y)} moves, {y.mean():.1%} reachable", file=sys.stderr)
    np.savez_compressed(args.out, features=np.concatenate(rows), reached=np.concatenate(labels),
                        wall=np.concatenate(walls), state=np.concatenate(states))


def auc(scores, labels):
    """The area under the ROC curve: the chance that a reached move scores above an
    unreached one (Mann-Whitney, ties counted half)."""
    order = np.argsort(scores, kind="mergesort")
    ranks = np.empty(len(scores))
    sorted_scores = scores[order]
    # Average ranks over ties.
    _, first, counts = np.unique(sorted_scores, return_index=True, return_counts=True)
    for start, count in zip(first, counts):
        ranks[order[start:start + count]] = start + (count + 1) / 2
    positives = labels.sum()
    negatives = len(labels) - positives
    return float((ranks[labels].sum() - positives * (positives + 1) / 2) / (positives * negatives))


def train_classifier(x, y, epochs, seed, hidden=128, batch=4096, lr=1e-3):
    """A two-layer MLP as width-1 convolutions (oneDNN; Debian's torch multiplies matrices
    with the reference BLAS), trained with Adam on the logistic loss. Returns a scorer."""
    import torch

    torch.manual_seed(seed)
    torch.set_num_threads(1)
    mean, std = x.mean(axis=0), x.std(axis=0) + 1e-6
    net = torch.nn.Sequential(torch.nn.Conv1d(x.shape[1], hidden, 1), torch.nn.ReLU(),
                              torch.nn.Conv1d(hidden, hidden, 1), torch.nn.ReLU(), torch.nn.Conv1d(hidden, 1, 1))
    optimiser = torch.optim.Adam(net.parameters(), lr=lr)
    inputs = torch.from_numpy(((x - mean) / std).T.copy()).float()
    targets = torch.from_numpy(y.astype(np.float32))
    generator = torch.Generator().manual_seed(seed)
    for _ in range(epochs):
        for index in torch.randperm(len(y), generator=generator).split(batch):
            loss = torch.nn.functional.binary_cross_entropy_with_logits(net(inputs[:, index].unsqueeze(0))[0, 0],
                                                                        targets[index])
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()

    def score(rows):
        with torch.no_grad():
            return net(torch.from_numpy(((rows - mean) / std).T.copy()).float().unsqueeze(0))[0, 0].numpy()

    return score


def best_candidate_reaches(scores, labels, wall, state):
    """Over the states with a reachable candidate: the share whose highest-scored candidate
    reaches (what a greedy policy needs), beside a uniform choice's expected share."""
    _, state_of = np.unique(wall * 1_000_000 + state, return_inverse=True)
    order = np.lexsort((-scores, state_of))
    first = np.ones(len(order), dtype=bool)
    first[1:] = state_of[order][1:] != state_of[order][:-1]
    best = labels[order][first]
    reachable = np.bincount(state_of, weights=labels)
    uniform = reachable / np.bincount(state_of)
    any_reachable = reachable > 0
    return {"states": int(any_reachable.sum()), "best": float(best[any_reachable].mean()),
            "uniform": float(uniform[any_reachable].mean())}


def errors_by_reach(scores, labels, distance):
    """False positives and negatives by the candidate's distance from the free limb's
    shoulder or hip, in 0.2 m bins."""
    rows = []
    for low in np.arange(0.0, distance.max() + 0.2, 0.2):
        inside = (distance >= low) & (distance < low + 0.2)
        if inside.sum() == 0:
            continue
        predicted = scores[inside] > 0
        truth = labels[inside]
        rows.append({"from_m": round(float(low), 1), "moves": int(inside.sum()), "reachable": float(truth.mean()),
                     "false_positive": float((predicted & ~truth).mean()),
                     "false_negative": float((~predicted & truth).mean())})
    return rows


def fit(args):
    parts = [np.load(path) for path in args.data]
    x = np.concatenate([part["features"] for part in parts]).astype(np.float64)
    y = np.concatenate([part["reached"] for part in parts])
    wall = np.concatenate([part["wall"] for part in parts])
    state = np.concatenate([part["state"] for part in parts])
    held_out = np.unique(wall)[-args.held_out_walls:]
    test = np.isin(wall, held_out)
    result = {"moves": int(len(y)), "walls": int(len(np.unique(wall))), "held_out_walls": int(len(held_out)),
              "training_moves": int((~test).sum()), "held_out_moves": int(test.sum()),
              "reachable_share": float(y[test].mean()),
              "majority_accuracy": float(max(y[test].mean(), 1 - y[test].mean()))}
    for name, columns in (("observation", slice(0, BASE_FEATURES)), ("with_reach", slice(0, BASE_FEATURES + REACH_FEATURES))):
        score = train_classifier(x[~test, columns], y[~test], args.epochs, args.seed)
        scores = score(x[test, columns])
        result[name] = {"accuracy": float(((scores > 0) == y[test]).mean()), "auc": auc(scores, y[test]),
                        "best_candidate_reaches": best_candidate_reaches(scores, y[test], wall[test], state[test]),
                        "errors_by_reach": errors_by_reach(scores, y[test], x[test, BASE_FEATURES + 3])}
    if args.json:
        print(json.dumps(result, indent=1))
    else:
        print(f"{result['held_out_moves']} held-out moves on {len(held_out)} walls, "
              f"{result['reachable_share']:.1%} reachable (always guessing the majority: "
              f"{result['majority_accuracy']:.1%})")
        for name in ("observation", "with_reach"):
            print(f"  {name:<12} accuracy {result[name]['accuracy']:.1%}, AUC {result[name]['auc']:.3f}, "
                  f"best candidate reaches in {result[name]['best_candidate_reaches']['best']:.1%} of states")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    g = commands.add_parser("generate", help="label candidate moves of random climbs with the MDP's verdict")
    g.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, A:B")
    g.add_argument("--states-per-wall", type=int, default=200, help="states visited (and labelled) per wall")
    g.add_argument("--seed", type=int, default=1, help="the random climbs' seed")
    g.add_argument("--out", required=True, help="the .npz file written")
    f = commands.add_parser("fit", help="train the per-slot classifiers and report them on held-out walls")
    f.add_argument("--data", required=True, nargs="+", help="files of generate (their walls together)")
    f.add_argument("--held-out-walls", type=int, default=50, help="the last K walls of the file, kept out of training")
    f.add_argument("--epochs", type=int, default=8)
    f.add_argument("--seed", type=int, default=1, help="the classifier's seed")
    f.add_argument("--json", action="store_true", help="the result as JSON")
    args = parser.parse_args(argv)
    generate(args) if args.command == "generate" else fit(args)


if __name__ == "__main__":
    main()

"""Where a learnt policy's greedy climbs go wrong, measured against every climb the wall
allows (crux.climb_graph, docs/BASELINES.md).

    climb_diagnosis.py --policy FILE --wall-seeds A:B [--physics-model static]
                       [--oracle reach|live|nearest [--verdicts] [--ties first]] [--mistakes SHARE --seed S] [--json]

Each move of a climb is one of: optimal (to a state one action nearer the finish), a
shortcut (nearer by more: a move the graph's routes did not reach), a detour (no nearer,
to a state from which a climb the graph knows still finishes), into a dead end (to a
state from which the graph knows no climb that finishes), within a dead end, or failed
(not reached; the climber stays), counted apart when the graph's own route reached that
move. A state the graph does not hold is off the graph. The graph's verdicts are those of
its own routes: an IK solve starts from the posture before the move (docs/MODEL.md, C30),
so a climb arriving in another posture may meet others. Each climb finished, fell or
reached the cap of policy_baseline's evaluation (200 actions); the report also counts the
climbs that entered a dead end and those that came back, by a move that reached, to a
configuration they had held. A wall whose graph outgrows crux.climb_graph's budget of IK
solves (5 M; a random wall takes about 50,000) is skipped, named.

--oracle tells the policy what it cannot see: the climbs choose greedily among the offered
moves the graph reaches (reach), among those that also keep a climb to the finish (live),
or among the live ones nearest the finish (nearest: the graph's optimal moves, the policy
only breaking ties), less those that failed there; where that leaves none they choose
among all (counted as oracle_fallbacks). The report then measures how far knowing that
would take the policy. --mistakes adds a share of uniformly random offered moves, each
wall's draws from its own stream of --seed: with --oracle nearest, a climber that knows
the graph's best move but for that share of its choices, which measures how rarely a move
scorer may be wrong. live_choices counts the actions taken from states that still have a
climb to the finish.
"""

import json
import pathlib

import numpy as np

import crux
import policy_baseline as baseline
from example_arguments import OneLineParser, integer_at_least, wall_seed_range

MOVE_KINDS = ("optimal", "shortcut", "detour", "into_dead_end", "within_dead_end", "failed", "failed_graph_reaches",
              "off_graph")


def climb_graph(wall, physics_model):
    """(distance, moves): {configuration (hold indices in limb order, -1 free): actions to the
    finish, -1 if none}, and {configuration: {hold index: the distance after the move, 0 when
    it finishes}} for the moves the graph reaches; None when the graph outgrows its budget."""
    graph = crux.climb_graph(wall, config={"physics.model": physics_model})
    if graph["stopped_at_limit"]:
        return None
    configurations = [tuple(c) for c in graph["configurations"].tolist()]
    distance = dict(zip(configurations, graph["distances"].tolist()))
    moves = {}
    for state, hold, target, _ in graph["moves"].tolist():
        moves.setdefault(configurations[state], {})[hold] = 0 if target < 0 else distance[configurations[target]]
    return distance, moves


def oracle_mask(mask, holds, failed, after, oracle):
    """The policy's mask, narrowed to the offered moves the graph reaches ("reach"), to those
    that also keep a climb to the finish ("live"), or to the live ones nearest the finish
    ("nearest"), less those that failed here in the environment; None where that leaves none
    (the climb then chooses among all it is offered)."""
    allowed = [hold in after and not fail and (oracle == "reach" or (after[hold] is not None and after[hold] >= 0))
               for hold, fail in zip(holds, failed)]
    if oracle == "nearest" and any(allowed):
        nearest = min(after[hold] for hold, keep in zip(holds, allowed) if keep)
        allowed = [keep and after[hold] == nearest for hold, keep in zip(holds, allowed)]
    narrowed = mask.copy()
    narrowed[0, :len(holds)] &= np.array(allowed, dtype=bool)
    return narrowed if narrowed.any() else None


def move_kind(before, reached, finished, after, graph_reaches=False):
    """before, after: the states' distances, None for a state the graph does not hold;
    graph_reaches: whether the graph's own route reached the move."""
    if not reached:
        return "failed_graph_reaches" if graph_reaches else "failed"
    if before is None or (after is None and not finished):
        return "off_graph"
    if before < 0:
        return "within_dead_end"
    if finished:
        after = 0
    elif after < 0:
        return "into_dead_end"
    if after == before - 1:
        return "optimal"
    return "shortcut" if after < before - 1 else "detour"


def climb_verdicts(wall, config, history, holds, distance):
    """{hold: the graph's distance after its move (0 when it finishes, None for a state the
    graph does not hold)} for the offered holds whose move reaches in this climb: each tried
    in a new MDP on the wall that first takes the climb's moves (history), as
    policy_baseline.verdict_mask tries them; a new MDP for each, since the IK's cache keeps
    the first verdict on a configuration."""
    after = {}
    for hold in holds:
        trial = crux.ClimbMdp(wall, config=config, max_steps=None)
        trial.reset()
        for taken in history:
            trial.step(taken)
        raw, _, terminated, _, info = trial.step(int(hold))
        if info["reached"]:
            after[int(hold)] = 0 if terminated and not info["fell"] else distance.get(
                tuple(raw["configuration"].tolist()))
    return after


def diagnose_climb(policy, mdp, graph, oracle="none", cap=baseline.CLIMB_CAP, mistakes=0.0, rng=None, verdicts=None,
                   ties="policy"):
    """One greedy climb (policy_baseline's climb, on the MDP, which names its configuration),
    but for a share mistakes of uniformly random offered moves, drawn from rng. verdicts:
    None, or (wall, config): the oracle then reads the climb's own verdicts (climb_verdicts)
    instead of the graph's routes'. ties: "policy" (its greedy choice among the moves the
    oracle leaves) or "first" (the first offered of them, the order the graph explores in;
    the policy's choice where the oracle leaves none)."""
    if mistakes > 0 and rng is None:
        raise ValueError("random moves need their stream (rng)")
    distance, moves = graph
    history = []
    raw, _ = mdp.reset()
    kinds = dict.fromkeys(MOVE_KINDS, 0)
    configuration = tuple(raw["configuration"].tolist())
    held = {configuration}
    revisited, entered_dead_end, fallbacks, ending, live_choices, random_moves = False, False, 0, "cap", 0, 0
    for _ in range(cap):
        live_choices += distance.get(configuration, -1) >= 0
        holds = np.flatnonzero(mdp.action_mask())
        graph_moves = moves.get(configuration, {})
        obs = mdp.numeric_observation(baseline.MAX_CANDIDATES, reach=True)
        state, slots, mask = baseline.single_features(obs, policy.max_span)
        narrowed = None
        if oracle != "none":
            after = graph_moves if verdicts is None else climb_verdicts(*verdicts, history, holds, distance)
            narrowed = oracle_mask(mask, holds, obs["candidate_failed"][:len(holds)] > 0.5, after, oracle)
            fallbacks += narrowed is None
            mask = mask if narrowed is None else narrowed
        if mistakes > 0 and rng.random() < mistakes:
            slot = int(rng.integers(len(holds)))
            random_moves += 1
        elif ties == "first" and narrowed is not None:
            slot = int(np.flatnonzero(narrowed[0])[0])
        else:
            slot = baseline.greedy_slot(policy, state, slots, mask)
        raw, _, terminated, _, info = mdp.step(int(holds[slot]))
        history.append(int(holds[slot]))
        finished = terminated and not info["fell"]
        reached_configuration = tuple(raw["configuration"].tolist())
        kind = move_kind(distance.get(configuration), info["reached"], finished, distance.get(reached_configuration),
                         int(holds[slot]) in graph_moves)
        kinds[kind] += 1
        entered_dead_end |= kind == "into_dead_end"
        if terminated:
            ending = "fell" if info["fell"] else "finished"
            break
        if info["reached"]:  # a failed move stays where it was: not a return
            revisited |= reached_configuration in held
            held.add(reached_configuration)
        configuration = reached_configuration
    return {"ending": ending, "actions": sum(kinds.values()), "moves": kinds, "entered_dead_end": entered_dead_end,
            "revisited": revisited, "oracle_fallbacks": fallbacks, "live_choices": live_choices,
            "random_moves": random_moves}


def diagnose(policy, wall_seeds, physics_model="kinematic", oracle="none", mistakes=0.0, seed=1, verdicts=False,
             ties="policy"):
    """The climbs on the walls whose start holds, and their sums; mistakes and ties as
    diagnose_climb takes them, each wall's draws from the stream of (seed, the wall's seed);
    verdicts: the oracle reads the climb's own verdicts."""
    config = baseline.climbing_config(physics_model)
    walls, skipped = [], []
    for wall_seed in wall_seeds:
        wall = crux.Wall.random(wall_seed)
        try:
            mdp = crux.ClimbMdp(wall, config=config, max_steps=None)
        except ValueError:
            continue  # a start that does not hold, as evaluate skips it
        graph = climb_graph(wall, physics_model)
        if graph is None:
            skipped.append({"wall_seed": wall_seed, "why": "its graph outgrows crux.climb_graph's budget of IK solves"})
            continue
        climb = diagnose_climb(policy, mdp, graph, oracle, mistakes=mistakes,
                               rng=np.random.default_rng([seed, wall_seed]),
                               verdicts=(wall, config) if verdicts else None, ties=ties)
        walls.append({"wall_seed": wall_seed, **climb})
    total = {kind: sum(w["moves"][kind] for w in walls) for kind in MOVE_KINDS}
    endings = {ending: sum(w["ending"] == ending for w in walls) for ending in ("finished", "fell", "cap")}
    return {"oracle": oracle, "verdicts": verdicts, "ties": ties, "climbs": len(walls), **endings,
            "entered_dead_end": sum(w["entered_dead_end"] for w in walls),
            "revisited": sum(w["revisited"] for w in walls),
            "oracle_fallbacks": sum(w["oracle_fallbacks"] for w in walls), "mistakes": mistakes,
            "random_moves": sum(w["random_moves"] for w in walls),
            "live_choices": sum(w["live_choices"] for w in walls),
            "moves": total, "walls": walls, "skipped_walls": skipped}


def parser():
    top = OneLineParser(prog="climb_diagnosis.py", description=__doc__.split("\n\n")[0])
    top.add_argument("--policy", type=pathlib.Path, required=True, help="a policy file (policy_baseline.py's)")
    top.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, as A:B")
    top.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic")
    top.add_argument("--oracle", choices=("none", "reach", "live", "nearest"), default="none",
                     help="let the policy choose only among the moves the graph reaches (reach), among those "
                     "that also keep a climb to the finish (live), or among the live ones nearest the finish "
                     "(nearest): what the policy would do if it knew that")
    top.add_argument("--verdicts", action="store_true",
                     help="the oracle reads the climb's own verdicts (each offered move tried first in a copy of "
                     "the climb) instead of the graph's routes', and the graph's distance of the state each reaches")
    top.add_argument("--ties", choices=("policy", "first"), default="policy",
                     help="among the moves the oracle leaves, the policy's greedy choice or the first offered (the "
                     "order in which the graph explores; the policy's choice where the oracle leaves none)")
    top.add_argument("--mistakes", type=baseline.unit_interval, default=0.0,
                     help="the share of choices made uniformly at random among the offered moves instead")
    top.add_argument("--seed", type=integer_at_least(0), default=1,
                     help="the random moves' seed (each wall its own stream of it)")
    top.add_argument("--json", action="store_true", help="the whole report, per wall, as JSON")
    return top


def main(argv=None):
    top = parser()
    args = top.parse_args(argv)
    for option, given in (("--verdicts", args.verdicts), ("--ties", args.ties != "policy")):
        if given and args.oracle == "none":
            top.error(f"{option}: acts on the oracle's choice, and --oracle is none")
    policy = baseline.load_for_walls(args.policy, "climb_diagnosis.py")
    try:
        named = baseline.named_veto(args.policy)
    except ValueError as error:
        top.error(f"--policy: {error}")
    if named is not None:
        # The diagnosis climbs the policy's own greedy choice, which such a file's evaluate does not.
        top.error(f"--policy: {args.policy} names a veto (reach_estimate.py train's), which the diagnosis does "
                  "not apply")
    result = diagnose(policy, args.wall_seeds, args.physics_model, args.oracle, args.mistakes, args.seed,
                      args.verdicts, args.ties)
    if args.json:
        print(json.dumps(result, indent=2))
        return
    moves = ", ".join(f"{kind.replace('_', ' ')} {count}" for kind, count in result["moves"].items())
    print(f"{result['climbs']} climbs: {result['finished']} finished, {result['fell']} fell, {result['cap']} at the "
          f"cap; {result['entered_dead_end']} entered a dead end, {result['revisited']} came back to a "
          f"configuration; {result['live_choices']} choices from a live state. Moves: {moves}"
          + (f"; the oracle left no move {result['oracle_fallbacks']} times" if result["oracle"] != "none" else "")
          + (f"; {result['random_moves']} random moves" if result["mistakes"] > 0 else ""))


if __name__ == "__main__":
    main()

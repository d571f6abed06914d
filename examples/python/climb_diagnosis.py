"""Where a learnt policy's greedy climbs go wrong, measured against every climb the wall
allows (crux.climb_graph, docs/BASELINES.md).

    climb_diagnosis.py --policy FILE --wall-seeds A:B [--physics-model static] [--oracle reach|live] [--json]

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
moves the graph reaches (reach), or among those that also keep a climb to the finish
(live), less those that failed there; where that leaves none they choose among all
(counted as oracle_fallbacks). The report then measures how far knowing that would take
the policy.
"""

import json
import pathlib

import numpy as np

import crux
import policy_baseline as baseline
from example_arguments import OneLineParser, wall_seed_range

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
    """The policy's mask, narrowed to the offered moves the graph reaches ("reach") or to those
    that also keep a climb to the finish ("live"), less those that failed here in the
    environment; None where that leaves none (the climb then chooses among all it is offered)."""
    allowed = [hold in after and not fail and (oracle == "reach" or after[hold] >= 0)
               for hold, fail in zip(holds, failed)]
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


def diagnose_climb(policy, mdp, graph, oracle="none", cap=baseline.CLIMB_CAP):
    """One greedy climb (policy_baseline's climb, on the MDP, which names its configuration)."""
    distance, moves = graph
    raw, _ = mdp.reset()
    kinds = dict.fromkeys(MOVE_KINDS, 0)
    configuration = tuple(raw["configuration"].tolist())
    held = {configuration}
    revisited, entered_dead_end, fallbacks, ending = False, False, 0, "cap"
    for _ in range(cap):
        holds = np.flatnonzero(mdp.action_mask())
        graph_moves = moves.get(configuration, {})
        obs = mdp.numeric_observation(baseline.MAX_CANDIDATES, reach=True)
        state, slots, mask = baseline.single_features(obs, policy.max_span)
        if oracle != "none":
            narrowed = oracle_mask(mask, holds, obs["candidate_failed"][:len(holds)] > 0.5, graph_moves, oracle)
            fallbacks += narrowed is None
            mask = mask if narrowed is None else narrowed
        slot = baseline.greedy_slot(policy, state, slots, mask)
        raw, _, terminated, _, info = mdp.step(int(holds[slot]))
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
            "revisited": revisited, "oracle_fallbacks": fallbacks}


def diagnose(policy, wall_seeds, physics_model="kinematic", oracle="none"):
    """The climbs on the walls whose start holds, and their sums."""
    config = baseline.climbing_config(physics_model)
    walls, skipped = [], []
    for seed in wall_seeds:
        wall = crux.Wall.random(seed)
        try:
            mdp = crux.ClimbMdp(wall, config=config, max_steps=None)
        except ValueError:
            continue  # a start that does not hold, as evaluate skips it
        graph = climb_graph(wall, physics_model)
        if graph is None:
            skipped.append({"wall_seed": seed, "why": "its graph outgrows crux.climb_graph's budget of IK solves"})
            continue
        walls.append({"wall_seed": seed, **diagnose_climb(policy, mdp, graph, oracle)})
    total = {kind: sum(w["moves"][kind] for w in walls) for kind in MOVE_KINDS}
    endings = {ending: sum(w["ending"] == ending for w in walls) for ending in ("finished", "fell", "cap")}
    return {"oracle": oracle, "climbs": len(walls), **endings,
            "entered_dead_end": sum(w["entered_dead_end"] for w in walls),
            "revisited": sum(w["revisited"] for w in walls),
            "oracle_fallbacks": sum(w["oracle_fallbacks"] for w in walls), "moves": total, "walls": walls,
            "skipped_walls": skipped}


def parser():
    top = OneLineParser(prog="climb_diagnosis.py", description=__doc__.split("\n\n")[0])
    top.add_argument("--policy", type=pathlib.Path, required=True, help="a policy file (policy_baseline.py's)")
    top.add_argument("--wall-seeds", type=wall_seed_range, required=True, help="random walls A to B inclusive, as A:B")
    top.add_argument("--physics-model", choices=("kinematic", "static"), default="kinematic")
    top.add_argument("--oracle", choices=("none", "reach", "live"), default="none",
                     help="let the policy choose only among the moves the graph reaches (reach), or among those "
                     "that also keep a climb to the finish (live): what the policy would do if it knew that")
    top.add_argument("--json", action="store_true", help="the whole report, per wall, as JSON")
    return top


def main(argv=None):
    args = parser().parse_args(argv)
    result = diagnose(baseline.load_for_walls(args.policy, "climb_diagnosis.py"), args.wall_seeds, args.physics_model,
                      args.oracle)
    if args.json:
        print(json.dumps(result, indent=2))
        return
    moves = ", ".join(f"{kind.replace('_', ' ')} {count}" for kind, count in result["moves"].items())
    print(f"{result['climbs']} climbs: {result['finished']} finished, {result['fell']} fell, {result['cap']} at the "
          f"cap; {result['entered_dead_end']} entered a dead end, {result['revisited']} came back to a "
          f"configuration. Moves: {moves}" + (f"; the oracle left no move {result['oracle_fallbacks']} times"
                                               if result["oracle"] != "none" else ""))


if __name__ == "__main__":
    main()

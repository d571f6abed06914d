"""examples/python/climb_diagnosis.py: each move is classified by the climb graph's
distances, the climbs are the evaluator's, falls after dead ends are reported as such,
and bad input is one line and exit code 2."""

import contextlib
import io
import json
import math
import pathlib

import numpy as np
import pytest

from needed import need

gymnasium, torch = need(
    ["gymnasium", "torch"], "the climb diagnosis needs Gymnasium (../shared/third_party/gymnasium-1.4.0) and torch"
)

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
import climb_diagnosis as diagnosis  # noqa: E402 (conftest puts examples/python on the path; it needs torch)
baseline = diagnosis.baseline
# The policy the record's analyses were measured with, shipped until the 14 M-step one replaced it.
SIX_M_POLICY = REPOSITORY / "models" / "policies" / "search" / "reach-ppo-6m.json"
GRAPHS = {}  # (the wall's JSON, the physics model): its graph, built once for every test here
BUILD_GRAPH = diagnosis.climb_graph


@pytest.fixture(autouse=True)
def graphs_built_once(monkeypatch):
    """The tests climb the same few walls: each wall's graph (the costly part) is built once."""

    def graph(wall, physics_model):
        key = (wall.to_json(), physics_model)
        if key not in GRAPHS:
            GRAPHS[key] = BUILD_GRAPH(wall, physics_model)
        return GRAPHS[key]

    monkeypatch.setattr(diagnosis, "climb_graph", graph)


@pytest.mark.parametrize("before, reached, finished, after, kind", [
    (5, False, False, 5, "failed"),
    (None, False, False, None, "failed"),
    (5, True, False, 4, "optimal"),
    (5, True, False, 5, "detour"),
    (5, True, False, 7, "detour"),
    (5, True, False, -1, "into_dead_end"),
    (-1, True, False, -1, "within_dead_end"),
    (1, True, True, None, "optimal"),
    (3, True, True, None, "shortcut"),  # a finish the graph's routes did not reach from that state
    (5, True, False, 2, "shortcut"),
    (None, True, False, 4, "off_graph"),
    (5, True, False, None, "off_graph"),
])
def test_a_move_is_classified_by_the_distances_before_and_after(before, reached, finished, after, kind):
    assert diagnosis.move_kind(before, reached, finished, after) == kind


def test_a_failed_move_the_graph_reaches_is_counted_apart():
    assert diagnosis.move_kind(5, False, False, 5, graph_reaches=True) == "failed_graph_reaches"
    assert diagnosis.move_kind(5, True, False, 4, graph_reaches=True) == "optimal"


def test_the_oracles_narrow_the_mask_to_the_moves_the_graph_allows():
    mask = np.array([[True, True, True, True, True, False]])
    holds = np.array([4, 7, 9, 12, 15])
    failed = np.array([False, False, False, False, True])
    after = {7: 3, 9: -1, 15: 2, 30: 2}  # 4 and 12 do not reach, 9 leads into a dead end, 15 failed here
    assert diagnosis.oracle_mask(mask, holds, failed, after, "reach").tolist() == [[0, 1, 1, 0, 0, 0]]
    assert diagnosis.oracle_mask(mask, holds, failed, after, "live").tolist() == [[0, 1, 0, 0, 0, 0]]
    assert diagnosis.oracle_mask(mask, holds, failed, {}, "live") is None, "none allowed"


def test_the_nearest_oracle_keeps_the_live_moves_nearest_the_finish_and_off_graph_moves_only_reach():
    mask = np.array([[True, True, True, True, True, False]])
    holds = np.array([4, 7, 9, 12, 15])
    failed = np.array([False, False, False, False, True])
    after = {4: 2, 7: 2, 9: -1, 12: 3, 15: 1}  # 15, the nearest, failed here
    assert diagnosis.oracle_mask(mask, holds, failed, after, "nearest").tolist() == [[1, 1, 0, 0, 0, 0]]
    off_graph = {4: None, 7: 3}  # a verdict's state the graph does not hold: reaches, distance unknown
    assert diagnosis.oracle_mask(mask, holds, failed, off_graph, "reach").tolist() == [[1, 1, 0, 0, 0, 0]]
    assert diagnosis.oracle_mask(mask, holds, failed, off_graph, "nearest").tolist() == [[0, 1, 0, 0, 0, 0]]


def test_at_the_start_the_climbs_verdicts_are_the_graphs():
    # The graph's first state is the start in the start's posture, as every climb's: there
    # the climb's own verdicts and distances are the graph's moves.
    config = baseline.climbing_config("static")
    wall = diagnosis.crux.Wall.random(20001)
    distance, moves = diagnosis.climb_graph(wall, "static")
    mdp = diagnosis.crux.ClimbMdp(wall, config=config, max_steps=None)
    start = tuple(mdp.reset()[0]["configuration"].tolist())
    holds = np.flatnonzero(mdp.action_mask())
    assert diagnosis.climb_verdicts(wall, config, [], holds, distance) == moves[start]


def test_the_nearest_oracle_taking_the_first_offered_follows_the_graphs_routes():
    # Ties broken in the order the graph explores reproduce its routes, and their postures:
    # every move optimal, the climb as long as the exact plan.
    result = run("--policy", str(SIX_M_POLICY), "--wall-seeds", "20001:20001", "--physics-model", "static",
                 "--oracle", "nearest", "--ties", "first")
    (wall,) = result["walls"]
    plan = diagnosis.crux.plan(diagnosis.crux.Wall.random(20001), config={"physics.model": "static"})
    assert result["finished"] == 1 and result["ties"] == "first" and not result["verdicts"]
    assert wall["actions"] == wall["moves"]["optimal"] == wall["live_choices"] == plan["length"], wall


def test_mistakes_are_random_moves_of_their_own_stream():
    wall = diagnosis.crux.Wall.random(20000)
    graph = diagnosis.climb_graph(wall, "kinematic")
    policy, _ = baseline.load_policy(SIX_M_POLICY)

    def climb(mistakes, seed):
        mdp = diagnosis.crux.ClimbMdp(wall, config=baseline.climbing_config("kinematic"), max_steps=None)
        return diagnosis.diagnose_climb(policy, mdp, graph, "nearest", mistakes=mistakes,
                                        rng=np.random.default_rng([seed, 20000]))

    every = climb(1.0, 3)
    assert every["random_moves"] == every["actions"] > 0
    assert climb(1.0, 3) == every, "the same stream, the same climb"
    assert climb(1.0, 4) != every
    some = climb(0.2, 3)
    assert 0 < some["random_moves"] < some["actions"]
    assert climb(0.0, 3)["random_moves"] == 0


def test_with_the_live_oracle_no_climb_enters_a_dead_end():
    result = run("--policy", str(SIX_M_POLICY), "--wall-seeds", "20004:20005", "--physics-model", "static",
                 "--oracle", "live")
    assert result["oracle"] == "live" and result["climbs"] == 2
    assert result["entered_dead_end"] == 0 and result["moves"]["into_dead_end"] == 0


def run(*arguments):
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        diagnosis.main([*arguments, "--json"])
    return json.loads(printed.getvalue())


def test_the_climbs_are_the_evaluators_and_every_action_is_counted_once():
    result = run("--policy", str(SIX_M_POLICY), "--wall-seeds", "20000:20001")
    policy, _ = baseline.load_policy(SIX_M_POLICY)
    evaluated = baseline.evaluate(policy, range(20000, 20002), plans={})
    assert result["climbs"] == evaluated["climbs"] == 2
    for wall, climb in zip(result["walls"], evaluated["walls"]):
        assert wall["wall_seed"] == climb["wall_seed"]
        assert (wall["ending"] == "finished") == climb["finished"]
        assert wall["actions"] == climb["length"] == sum(wall["moves"].values())
        assert wall["moves"]["failed"] + wall["moves"]["failed_graph_reaches"] == climb["failed_moves"]
    assert result["finished"] + result["fell"] + result["cap"] == result["climbs"]
    assert result["moves"] == {kind: sum(w["moves"][kind] for w in result["walls"]) for kind in diagnosis.MOVE_KINDS}


def test_the_6m_policys_falls_under_the_static_model_follow_a_dead_end():
    # A fall comes in a stance whose every move fails in the environment. On these two
    # walls the 6 M (kinematic) policy falls, each time after a move into a state from
    # which the graph finishes no climb; the report must say so.
    result = run("--policy", str(SIX_M_POLICY), "--wall-seeds", "20004:20005", "--physics-model", "static")
    assert result["fell"] == 2 and result["entered_dead_end"] == 2
    for wall in result["walls"]:
        assert wall["moves"]["into_dead_end"] >= 1, wall


@pytest.mark.parametrize("arguments, problem", [
    (["--policy", "missing.json", "--wall-seeds", "1:2"], "climb_diagnosis.py: --policy: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", "2:1"], "climb_diagnosis.py: argument --wall-seeds: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", f"1:{2**64}"], "climb_diagnosis.py: argument --wall-seeds: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", "1:2", "--verdicts"], "climb_diagnosis.py: --verdicts: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", "1:2", "--ties", "first"], "climb_diagnosis.py: --ties: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", "1:2", "--mistakes", "1.5"],
     "climb_diagnosis.py: argument --mistakes: "),
    (["--policy", str(SIX_M_POLICY), "--wall-seeds", "1:2", "--mistakes", "0.1", "--seed", "-1"],
     "climb_diagnosis.py: argument --seed: "),
    (["--policy", str(REPOSITORY / "models" / "policies" / "reach-ppo-vetoed.json"), "--wall-seeds", "1:2"],
     "climb_diagnosis.py: --policy: "),
])
def test_bad_input_is_one_line_and_exit_code_2(capsys, arguments, problem):
    with pytest.raises(SystemExit) as stopped:
        diagnosis.main(arguments)
    assert stopped.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(problem) and err.count("\n") == 1, err


RECORD = REPOSITORY / "models" / "policies" / "search" / "climb_diagnosis.json"


def test_baselines_diagnosis_table_and_graph_counts_quote_their_record():
    record = json.loads(RECORD.read_text())
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    flat = " ".join(text.split())
    rows = record["diagnoses"]

    def unfinished(row):
        return [wall for wall in row["walls"] if wall["ending"] != "finished"]

    for row in rows:
        cells = [row["physics_model"], row["climbs"], row["finished"], row["fell"], row["cap"],
                 sum(wall["entered_dead_end"] for wall in unfinished(row)), row["revisited"], *row["moves"].values()]
        assert " | ".join(map(str, cells)) + " |" in text, row["name"]
    static = [row for row in rows if row["physics_model"] == "static" and row["oracle"] == "none"]
    entered = ", ".join(f"{sum(w['entered_dead_end'] for w in unfinished(row))} of {len(unfinished(row))}"
                        for row in static)
    assert entered.rsplit(", ", 1)[0] + " and " + entered.rsplit(", ", 1)[1] + " unfinished climbs" in flat
    failed = [(row["moves"]["failed"] + row["moves"]["failed_graph_reaches"]) / sum(row["moves"].values())
              for row in static]
    assert f"({min(failed):.0%} to {max(failed):.0%} of all their actions".replace("% to", " to").replace("%", " %") \
        + " are failed moves)" in flat
    odd_falls = [(wall["wall_seed"], row["name"]) for row in static for wall in row["walls"]
                 if wall["ending"] == "fell" and not (wall["entered_dead_end"] or wall["moves"]["off_graph"])]
    finished_after = [wall["wall_seed"] for row in static for wall in row["walls"]
                      if wall["ending"] == "finished" and wall["entered_dead_end"]]
    assert len(odd_falls) == 1 and f"the one (wall {odd_falls[0][0]}, the static clone)" in flat
    assert f"two climbs (walls {finished_after[0]} and {finished_after[1]}) finished" in flat
    six_m = rows[0]
    kinds = six_m["moves"]
    assert (f"the 6 M policy's {sum(kinds.values())} actions against the plans' " in flat
            and f"are {kinds['optimal']} optimal moves, {kinds['shortcut']} shortcuts, {kinds['detour']} detours, "
            f"{kinds['failed'] + kinds['failed_graph_reaches']} failed moves ({kinds['failed_graph_reaches']} of them"
            in flat)
    held_out = json.loads((REPOSITORY / "models" / "policies" / "search" / "reach-ppo-6m.heldout.json").read_text())
    plans = {wall["wall_seed"]: wall["plan_length"] for wall in held_out["walls"]}
    assert f"against the plans' {sum(plans.values())} are" in flat
    # The shipped policy's row is the diagnosis of its seed's 14 M-step run.
    long_training = json.loads((RECORD.parent / "long_training.json").read_text())
    [shipped] = [run["diagnosis"] for run in long_training["runs"] if run["seed"] == 1]
    # Every climb finishes, so its count of climbs that entered a dead end is the column's (unfinished ones).
    assert shipped["finished"] == shipped["climbs"] and shipped["entered_dead_end"] == 0
    kinds = shipped["moves"]
    cells = [shipped["climbs"], shipped["finished"], shipped["fell"], shipped["cap"], shipped["entered_dead_end"],
             shipped["revisited"], *kinds.values()]
    assert "| the shipped policy (14 M steps) | kinematic | " + " | ".join(map(str, cells)) + " |" in text
    surplus = sum(kinds.values()) - round(1.5 * sum(plans.values()))
    assert (f"The shipped policy's {sum(kinds.values())} actions are {kinds['optimal']} optimal moves, "
            f"{kinds['shortcut']} shortcuts, {kinds['detour']} detours, "
            f"{kinds['failed'] + kinds['failed_graph_reaches']} failed moves ({kinds['failed_graph_reaches']} of them "
            f"moves the graph's own route reaches) and {kinds['off_graph']} off the graph: {surplus} too many for "
            f"{round(1.5 * sum(plans.values()))}.") in flat
    without = {wall["wall_seed"]: wall["actions"] for wall in six_m["walls"]}
    reach = next(row for row in rows if row["oracle"] == "reach" and row["physics_model"] == "kinematic")
    done = [wall for wall in reach["walls"] if wall["ending"] == "finished"]
    assert (f"finishes {len(done)} of 30 kinematic walls; on those {len(done)} its climbs take "
            f"{np.mean([w['actions'] / plans[w['wall_seed']] for w in done]):.2f} times their plans, against "
            f"{np.mean([without[w['wall_seed']] / plans[w['wall_seed']] for w in done]):.2f} without the oracle, "
            f"and {reach['cap']} climbs go round to the cap") in flat
    live = [row for row in rows if row["oracle"] == "live"]
    assert [row["finished"] for row in live] == [4, 4] and [row["revisited"] for row in live] == [18, 18]
    assert "each finish 4 of 25, and 18 of their 25 climbs come back" in flat
    graphs = record["static_graphs"]
    assert (f"{graphs['dead_end_states']:,} of the {graphs['states']:,} states a climb can reach "
            f"({graphs['dead_end_states'] / graphs['states']:.0%})").replace("%", " %") in flat
    assert (f"{graphs['into_dead_end']:,} of the {graphs['moves_from_live_states']:,} moves that reach a state from a "
            f"live one ({graphs['into_dead_end'] / graphs['moves_from_live_states']:.0%})").replace("%", " %") in flat
    pilots = record["pilots"]
    for model, log in (("kinematic", "dagger_kinematic_walls_1000000_1000799"),
                       ("static", "dagger_static_walls_1100000_1100499")):
        for r in pilots[log]:
            row = (f"| {model} | {r['round']} | {r['states']:,} | {r['nearest_chosen']:.0%} | "
                   f"{r['validation']['finished']:.0%} | {r['held_out']['finished']:.0%} |").replace("%", " %")
            assert row in text, f"{model} round {r['round']}"
            ratio = r["held_out"]["mean_length_ratio"]
            assert text.split(row)[1].split("\n")[0].strip(" |") == (f"{ratio:.2f}" if ratio else "")
    first, second = pilots["cost_softmax_static_walls_1100000_1100499"]
    assert first["validation"]["finished"] == first["held_out"]["finished"]
    assert (f"finished {first['held_out']['finished']:.0%} of the static validation and held-out walls after round 0 "
            f"and {second['validation']['finished']:.0%} and {second['held_out']['finished']:.0%} after round 1") \
        .replace("%", " %") in flat
    kinematic = pilots["cost_softmax_kinematic_walls_1000000_1000799"]
    shares = [f"{r['held_out']['finished']:.0%}".replace("%", " %") for r in kinematic]
    ratios = [f"{r['held_out']['mean_length_ratio']:.2f}" for r in kinematic]
    assert f"it finished {shares[0]}, {shares[1]} and {shares[2]} of the held-out walls" in flat
    assert f"at {ratios[0]}, {ratios[1]} and {ratios[2]} times the plan" in flat
    route = pilots["route_keeping_static_walls_1100000_1100239"]
    labelled, start = route["rounds"][0], route["start_policy"]
    assert f"{labelled['states']} states were labelled" in flat
    after, before = labelled["after_training"], start["on_the_labelled_states"]
    assert (f"{labelled['states_with_tied_nearest']:.1%} had more than one nearest move "
            f"({labelled['mean_nearest_moves']:.2f} of {labelled['mean_offered_moves']:.1f} offered on average)"
            ).replace("%", " %") in flat
    assert (f"the trained network chose the label in {after['label']:.1%} and one of the nearest moves in "
            f"{after['in_nearest']:.1%}, the 6 M policy in {before['label']:.1%} and {before['in_nearest']:.1%}"
            ).replace("%", " %") in flat
    assert (f"finished {labelled['validation']['finished']:.1%} of the static validation walls "
            f"({labelled['validation']['climbs']} climbs) and {labelled['held_out']['finished']:.1%} of the "
            f"{labelled['held_out']['climbs']} held-out ones, where the 6 M policy it started from finishes "
            f"{start['validation']['finished']:.1%} and {start['held_out']['finished']:.1%}").replace("%", " %") in flat
    classifier = pilots["good_move_classifier_static"]
    assert f"gave {classifier['slots']:,} offered slots, {classifier['good_share']:.0%} of them good" \
        .replace("%", " %") in flat
    assert f"AUC of {classifier['held_out_auc']:.3f}" in flat
    assert f"({classifier['training_auc']:.3f} on training)" in flat
    assert f"good in {classifier['top_slot_good']:.1%} of the held-out states".replace("%", " %") in flat
    assert f"is good in {classifier['random_slot_good']:.1%}".replace("%", " %") in flat


def test_the_records_6m_rows_are_what_the_diagnosis_gives_now():
    record = json.loads(RECORD.read_text())
    six_m = next(row for row in record["diagnoses"] if row["policy"] == "models/policies/search/reach-ppo-6m.json"
                 and row["physics_model"] == "kinematic" and row["oracle"] == "none")
    now = run("--policy", str(SIX_M_POLICY), "--wall-seeds", "20000:20001")
    assert [{key: wall[key] for key in six_m["walls"][0]} for wall in now["walls"]] == six_m["walls"][:2]


def told_row(run_record):
    """A told_the_best_moves run as BASELINES' table prints it."""
    told = "the nearest moves that reach in the climb" if run_record["verdicts"] else "the graph's nearest moves"
    ties = "the first offered" if run_record["ties"] == "first" else "the policy"
    mistakes = f"{run_record['mistakes']:.0%}".replace("%", " %") if run_record["mistakes"] else "0"
    finished = f"{run_record['finished']} ({run_record['finished'] / run_record['climbs']:.1%})".replace("%", " %")
    failed = run_record["moves"]["failed"] + run_record["moves"]["failed_graph_reaches"]
    return (f"| {told} | {ties} | {mistakes} | {finished} | {run_record['fell']} | {run_record['cap']} "
            f"| {run_record['revisited']} | {failed} | {run_record['oracle_fallbacks']} |")


def test_baselines_quotes_the_climbs_told_the_best_moves():
    runs = json.loads(RECORD.read_text())["told_the_best_moves"]["runs"]
    text = (REPOSITORY / "docs" / "BASELINES.md").read_text()
    flat = " ".join(text.split())
    for run_record in runs:
        walls = run_record["walls"]
        assert run_record["climbs"] == len(walls) == 86 and run_record["finished"] == sum(
            w["ending"] == "finished" for w in walls)
        flags = run_record["command"]
        assert ("--verdicts" in flags) == run_record["verdicts"] and ("--ties first" in flags) == (
            run_record["ties"] == "first") and (f"--mistakes {run_record['mistakes']}" in flags) == (
            run_record["mistakes"] > 0)
        assert told_row(run_record) in text, told_row(run_record)
    by_flags = {(r["verdicts"], r["ties"], r["mistakes"]): r for r in runs}
    keeping, other = by_flags[(True, "first", 0.0)], by_flags[(True, "policy", 0.0)]
    finishes = {w["wall_seed"]: w["ending"] == "finished" for w in keeping["walls"]}
    other_finishes = {w["wall_seed"]: w["ending"] == "finished" for w in other["walls"]}
    only_keeping = sum(finishes[s] and not other_finishes[s] for s in finishes)
    only_other = sum(other_finishes[s] and not finishes[s] for s in finishes)
    sign_p = min(1.0, 2 * sum(math.comb(only_keeping + only_other, i) for i in range(min(only_keeping, only_other) + 1))
                 / 2 ** (only_keeping + only_other))
    share = other["finished"] / other["climbs"]
    assert f"finishes {other['finished']} of the {other['climbs']}; all {only_keeping} walls" in flat
    assert only_other == 0 and f"(sign test, p = {sign_p:.0e})" in flat, sign_p
    assert f"({keeping['moves']['optimal']} optimal moves, the plans' sum)" in flat
    assert f"In {other['oracle_fallbacks']} of its choices no offered move reached a state the graph holds live" in flat
    for mistakes, places in ((0.05, 2), (0.1, 4), (0.2, 3)):  # the table, the prose and (a tenth) Not done
        assert flat.count(f"{by_flags[(True, 'first', mistakes)]['finished'] / 86:.1%}".replace("%", " %")) >= places
    fifth = by_flags[(True, "first", 0.2)]
    assert f"a fifth {fifth['finished'] / 86:.1%} ({fifth['fell']} of its climbs fall)".replace("%", " %") in flat
    assert flat.count(f"{share:.1%}".replace("%", " %")) >= 3  # the table, the lead and Not done


def test_the_records_told_runs_are_what_the_diagnosis_gives_now():
    runs = json.loads(RECORD.read_text())["told_the_best_moves"]["runs"]
    # The climbs that keep to the graph's routes are test_the_nearest_oracle_taking_the_first_offered's. Each
    # wall's draws come from its own stream, so one wall's climb is the whole run's; 20005's, a fifth of its moves
    # random, falls back on the policy where no live move reaches.
    checked = {"--verdicts --json": 20004, "--verdicts --ties first --mistakes 0.2 --seed 1 --json": 20005}
    for flags, wall_seed in checked.items():
        told = [r for r in runs if r["command"].endswith("--oracle nearest " + flags)]
        assert len(told) == 1, flags
        recorded = [wall for wall in told[0]["walls"] if wall["wall_seed"] == wall_seed]
        now = run("--policy", str(SIX_M_POLICY), "--wall-seeds", f"{wall_seed}:{wall_seed}", "--physics-model",
                  "static", "--oracle", "nearest", *flags.split()[:-1])
        assert now["walls"] == recorded, flags
    assert recorded[0]["random_moves"] > 0 and recorded[0]["oracle_fallbacks"] > 0, "the fallback goes unchecked"

#!/usr/bin/python3
"""Where each agent's successful episodes end, and what decides a progress comparison there.

The goal test ends an episode within `goal_radius` (5 m) of the path's end or once the progress
reaches `goal_progress` (99 %). On the test paths (300-590 m) the 5 m circle usually comes
first, so a vessel that enters it d metres beside the path stops with its nearest path point
sqrt(25 - d^2) metres before the end, nearer the end the farther beside the path it is (at most
1 % of the path short, where the 99 % line takes over). Between two agents that both reach the
goal, the one whose last step lands farther along the path makes more progress.

Replays the test scenarios (evaluate's: COUNT of master seed SEED) under each policy, in the
single environment with the policy's observation settings and deterministic actions, and prints
per agent its goals, how far beside the path its goal episodes ended (|cross-track error| at the
last step) and how far before the path's end (metres of path left); per pair of agents, over the
scenarios where both reached the goal, P(A makes more progress than B) (ties half), the same
probability predicted from the side offsets alone (the agent whose offset leaves the shorter
stretch before the end, max(sqrt(r^2 - d^2), (1 - goal_progress) L), wins), and the share of
those scenarios where the prediction names the winner.

    PYTHONPATH=build/python /usr/bin/python3 scripts/describe_finishes.py \\
        NAME=POLICY.pt [NAME=POLICY.pt ...] [--episodes 1000] [--seed 1] [--scenario FILE ...] \\
        [--turn-away NAME=METRES ...] [--out finishes.csv]

--scenario FILE replays scenario files instead (repeatable). --out writes one row per episode.
--turn-away NAME=METRES tests that reading: in the last METRES of path agent NAME's rudder is held
hard over away from the path (its thrust stays its own), so that it enters the goal circle from
the side. A probe of the metric, not a way to steer; list a policy twice under two names to
compare it with itself.
Bad input: one line naming the argument or file, exit status 2.
"""

import argparse
import csv
import itertools
import math
import os
import statistics
import sys

import numpy as np

import colav

COLUMNS = ("model", "scenario", "goal", "progress", "path_length", "side_offset_m",
           "short_of_end_m", "predicted_short_of_end_m")


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"describe_finishes: error: {message}", file=sys.stderr)
    sys.exit(2)


def name_value(item, form, option="", names=None):
    """NAME and VALUE of a NAME=VALUE item, both non-empty and NAME one of `names` when given;
    else fail, naming the item (after `option`) and the `form` expected."""
    name, mark, value = item.partition("=")
    if not mark or not name or not value or (names is not None and name not in names):
        fail(f"{option}'{item}': expected {form}")
    return name, value


def agents(items):
    """{name: policy path} from NAME=PATH items, in their order."""
    named = {}
    for item in items:
        name, path = name_value(item, "NAME=POLICY.pt")
        if name in named:
            fail(f"'{item}': the name '{name}' is given twice")
        if not os.path.isfile(path):
            fail(f"{path}: no such policy file")
        named[name] = path
    return named


def turn_aways(items, named):
    """{name: metres} from NAME=METRES items naming agents of `named`."""
    metres = {}
    for item in items:
        name, value = name_value(item, "NAME=METRES with NAME one of the agents", "--turn-away ",
                                 named)
        try:
            metres[name] = float(value)
        except ValueError:
            metres[name] = math.nan
        if not metres[name] > 0.0:
            fail(f"--turn-away '{item}': METRES must be a number above 0")
    return metres


def turn_away(action, state, turn_away_m):
    """`action` with its rudder hard over away from the path in the last `turn_away_m` metres."""
    if state["path_length"] * (1.0 - state["progress"]) < turn_away_m:
        action = action.copy()
        action[1] = -math.copysign(1.0, state["cross_track_error"])
    return action


def finishes(policy, scenarios, turn_away_m=0.0):
    """Each scenario played to its end under the policy, all at once: one row per scenario
    (goal, progress, path length, side offset and metres of path left at the last step, and the
    metres left that the side offset predicts); with `turn_away_m`, turned away from the path
    over that many metres before its end."""
    envs = [colav.make(scenario=scenario, test_mode=True, **policy.observation_settings)
            for scenario in scenarios]
    obs = np.stack([env.reset()[0] for env in envs])
    rows = [None] * len(envs)
    starts = np.ones(len(envs), dtype=bool)
    playing = list(range(len(envs)))
    while playing:  # the policy acts for the episodes still playing only, as evaluate's does
        actions = policy.act(obs, starts, worlds=playing)
        starts[:] = False
        for k, action in zip(playing, actions):
            if turn_away_m > 0.0:
                action = turn_away(action, envs[k].state(), turn_away_m)
            obs[k], _, terminated, truncated, info = envs[k].step(action)
            if terminated or truncated:
                metrics = info["episode_metrics"]
                length = metrics["path_length"]
                side = abs(envs[k].state()["cross_track_error"])
                rows[k] = {"goal": int(metrics["goal_reached"]), "progress": metrics["progress"],
                           "path_length": length, "side_offset_m": side,
                           "short_of_end_m": (1.0 - metrics["progress"]) * length,
                           "predicted_short_of_end_m": predicted_short_of_end(
                               side, length, envs[k].settings)}
        playing = [k for k in playing if rows[k] is None]
    return rows


def predicted_short_of_end(side_offset, path_length, settings):
    """Metres of path left where the goal test first holds for a vessel running beside the path
    `side_offset` metres from it."""
    radius = settings["goal_radius"]
    circle = math.sqrt(max(radius * radius - side_offset * side_offset, 0.0))
    return max(circle, (1.0 - settings["goal_progress"]) * path_length)


def wins(a, b):
    return 1.0 if a > b else 0.5 if a == b else 0.0


def compare_at_goal(rows_a, rows_b):
    """Over the scenarios both reached the goal: (count, P(A more progress), P(A predicted to
    land farther), share where the prediction names the winner)."""
    both = [(a, b) for a, b in zip(rows_a, rows_b) if a["goal"] and b["goal"]]
    if not both:
        return 0, math.nan, math.nan, math.nan
    actual = [wins(a["progress"], b["progress"]) for a, b in both]
    predicted = [wins(b["predicted_short_of_end_m"], a["predicted_short_of_end_m"])
                 for a, b in both]
    named = [x == y for x, y in zip(actual, predicted)]
    return len(both), statistics.fmean(actual), statistics.fmean(predicted), statistics.fmean(named)


def write_rows(path, rows):
    """The episode rows to `path`, through a temporary file renamed into place."""
    temporary = path + ".tmp"
    try:
        with open(temporary, "w", newline="") as file:
            writer = csv.DictWriter(file, fieldnames=COLUMNS)
            writer.writeheader()
            writer.writerows(rows)
        os.replace(temporary, path)
    except OSError as error:
        fail(f"{path}: {error.strerror}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("agents", nargs="+", metavar="NAME=POLICY.pt", help="policies to replay")
    parser.add_argument("--episodes", type=int, default=1000, help="test scenarios (evaluate's)")
    parser.add_argument("--seed", type=int, default=1, help="master seed of the test scenarios")
    parser.add_argument("--scenario", action="append", default=[],
                        help="scenario file to replay instead (repeatable)")
    parser.add_argument("--turn-away", action="append", default=[], metavar="NAME=METRES",
                        help="turn agent NAME away from the path over its last METRES (repeatable)")
    parser.add_argument("--out", help="CSV of every episode")
    args = parser.parse_args()

    named = agents(args.agents)
    turned = turn_aways(args.turn_away, named)
    if args.episodes < 1:
        fail(f"--episodes {args.episodes}: expected at least 1")
    if args.seed < 0:
        fail(f"--seed {args.seed}: expected 0 or more")
    if args.out and not os.path.isdir(os.path.dirname(os.path.abspath(args.out))):
        fail(f"{args.out}: no such folder")
    try:
        scenarios = ([colav.load_scenario(path) for path in args.scenario] if args.scenario else
                     colav.evaluation_scenarios(args.episodes, args.seed))
        policies = {name: colav.Policy(path) for name, path in named.items()}
    except ValueError as error:
        fail(str(error))
    labels = args.scenario or [str(s) for s in colav.evaluation_scenario_seeds(args.episodes,
                                                                               args.seed)]
    results = {name: finishes(policy, scenarios, turned.get(name, 0.0))
               for name, policy in policies.items()}
    print("agent: goals; at the goal, |cross-track error| and metres of path left (mean, median)")
    for name, rows in results.items():
        at_goal = [row for row in rows if row["goal"]]
        if name in turned:
            print(f"  {name} turns away from the path over its last {turned[name]:g} m")
        if not at_goal:
            print(f"  {name}: 0 of {len(rows)}")
            continue
        side = [row["side_offset_m"] for row in at_goal]
        short = [row["short_of_end_m"] for row in at_goal]
        print(f"  {name}: {len(at_goal)} of {len(rows)}; beside the path "
              f"{statistics.fmean(side):.2f} m ({statistics.median(side):.2f}), "
              f"before its end {statistics.fmean(short):.2f} m "
              f"({statistics.median(short):.2f})")
    print("A over B where both reached the goal: P(more progress), P predicted from the side "
          "offsets, share named")
    for a, b in itertools.combinations(results, 2):
        count, actual, predicted, named_share = compare_at_goal(results[a], results[b])
        print(f"  {a} over {b}: {count} scenarios; {actual:.3f}, predicted {predicted:.3f}, "
              f"named {named_share:.3f}")
    if args.out:
        write_rows(args.out, [{"model": name, "scenario": label, **row}
                              for name, rows in results.items()
                              for label, row in zip(labels, rows)])


if __name__ == "__main__":
    main()

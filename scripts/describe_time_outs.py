#!/usr/bin/python3
"""What a configuration's agents do in the episodes that run out of time: circle, or stop?

Replays, from Python, every time-out of each seed of CONFIG in a study's evaluation
(STUDY_DIR/eval/study/episodes.csv, the study's test scenarios) and as many of the same seed's
goal episodes (the first ones), each in the single environment under the seed's policy
(STUDY_DIR/ppo/CONFIG/seed_<k>/policy.pt, with its observation settings, deterministic actions),
and measures per episode how far the vessel turned (its net heading change in full turns), its
mean speed, its mean speed over the last END_STEPS steps (a parked vessel ends at rest) and the
mean distance to the nearest thing its range-finder sees.

    PYTHONPATH=build/python /usr/bin/python3 scripts/describe_time_outs.py STUDY_DIR CONFIG \\
        [--out episodes.csv]

Prints, for the time-outs and for the goal episodes, the number replayed, how many ended as the
evaluation recorded (the replay is evaluate's episode), the mean and median of each measure, and
how many ended at rest (below AT_REST_MPS over the last END_STEPS steps);
--out writes one row per replayed episode. Bad input: one line naming the file, exit status 2.
"""

import argparse
import csv
import math
import os
import statistics
import sys

import numpy as np

import colav

SEED_MARK = ".seed_"  # the study's model names: "<config>.seed_<k>"
KINDS = ("time_out", "goal")
MEASURES = ("turns", "speed", "end_speed", "nearest_range")
END_STEPS = 100  # the end of an episode, for end_speed
AT_REST_MPS = 0.05  # an end_speed below this is a vessel at rest (cruising: about 0.57 m/s)
COLUMNS = ("model", "scenario_seed", "kind", "replayed_alike", *MEASURES)


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"describe_time_outs: error: {message}", file=sys.stderr)
    sys.exit(2)


def chosen_episodes(path, config):
    """{seed index: {"time_out": [scenario seed, ...], "goal": [...]}}: every time-out of each
    seed of `config` and as many of its goal episodes, in the file's order."""
    seeds = {}
    try:
        with open(path, newline="") as file:
            reader = csv.DictReader(file)
            missing = [c for c in ("model", "seed", "goal", "truncated")
                       if c not in (reader.fieldnames or [])]
            if missing:
                fail(f"{path}: no column '{missing[0]}'")
            for row in reader:
                name, mark, index = row["model"].rpartition(SEED_MARK)
                if name != config or not mark:
                    continue
                kinds = seeds.setdefault(int(index), {kind: [] for kind in KINDS})
                if row["truncated"] == "1":
                    kinds["time_out"].append(int(row["seed"]))
                elif row["goal"] == "1":
                    kinds["goal"].append(int(row["seed"]))
    except OSError as error:
        fail(f"{path}: {error.strerror}")
    if not seeds:
        fail(f"{path}: no episodes of configuration '{config}'")
    for episodes in seeds.values():
        episodes["goal"] = episodes["goal"][: len(episodes["time_out"])]
    return seeds


def replay(policy, scenario_seed):
    """One test scenario under the policy: (net turns, mean speed m/s, mean speed over the last
    END_STEPS steps m/s, mean nearest range m, timed out, reached the goal)."""
    env = colav.make(scenario=colav.training_scenario(scenario_seed), test_mode=True,
                     **policy.observation_settings)
    obs, _ = env.reset()
    starts = np.ones(1, dtype=bool)
    heading = env.state()["vessel"][2]
    turned, speeds, nearest = 0.0, [], []
    while True:
        obs, _, terminated, truncated, info = env.step(policy.act(obs[None, :], starts)[0])
        starts[0] = False
        state = env.state()
        _, _, psi, u, v, _ = state["vessel"]
        turned += math.remainder(psi - heading, 2 * math.pi)
        heading = psi
        speeds.append(math.hypot(u, v))
        nearest.append(min(state["ranges"]))
        if terminated or truncated:
            metrics = info["episode_metrics"]
            return (abs(turned) / (2 * math.pi), statistics.fmean(speeds),
                    statistics.fmean(speeds[-END_STEPS:]), statistics.fmean(nearest),
                    bool(metrics["truncated"]),
                    bool(metrics["goal_reached"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study", help="study folder (eval/study/episodes.csv, ppo/CONFIG/)")
    parser.add_argument("config", help="PPO configuration of the study")
    parser.add_argument("--out", help="CSV of every replayed episode")
    args = parser.parse_args()

    episodes = chosen_episodes(os.path.join(args.study, "eval", "study", "episodes.csv"),
                               args.config)
    policies = {index: os.path.join(args.study, "ppo", args.config, f"seed_{index}", "policy.pt")
                for index in episodes}
    for path in policies.values():
        if not os.path.isfile(path):
            fail(f"{path}: no such policy file")
    if args.out and not os.path.isdir(os.path.dirname(os.path.abspath(args.out))):
        fail(f"{args.out}: no such folder")
    rows = []
    for index, kinds in sorted(episodes.items()):
        policy = colav.Policy(policies[index])  # replay restarts its memory at each episode
        for kind, scenario_seeds in kinds.items():
            for scenario_seed in scenario_seeds:
                *measures, timed_out, goal = replay(policy, scenario_seed)
                alike = timed_out if kind == "time_out" else goal
                rows.append(dict(zip(COLUMNS, (f"{args.config}{SEED_MARK}{index}", scenario_seed,
                                               kind, int(alike), *measures))))
    for kind in KINDS:
        mine = [row for row in rows if row["kind"] == kind]
        if not mine:
            print(f"{kind}: none")
            continue
        alike = sum(row["replayed_alike"] for row in mine)
        summary = ", ".join(
            f"{measure} {statistics.fmean(r[measure] for r in mine):.2f} "
            f"(median {statistics.median(r[measure] for r in mine):.2f})" for measure in MEASURES)
        at_rest = sum(row["end_speed"] < AT_REST_MPS for row in mine)
        print(f"{kind}: {len(mine)} episodes, {alike} replayed alike; {summary}; "
              f"at rest at the end {at_rest}")
    if args.out:
        temporary = args.out + ".tmp"  # renamed into place once whole
        try:
            with open(temporary, "w", newline="") as file:
                writer = csv.DictWriter(file, fieldnames=COLUMNS)
                writer.writeheader()
                writer.writerows(rows)
            os.replace(temporary, args.out)
        except OSError as error:
            fail(f"{args.out}: {error.strerror}")


if __name__ == "__main__":
    main()

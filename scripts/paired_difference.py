#!/usr/bin/python3
"""The paired difference between two trained configurations, also across two studies.

A study's report compares configurations of one study. When a change can only be made in
another study (its dataset, say), both studies' evaluations run the same test scenarios (the
same `evaluation.episodes` and `evaluation.seed`), so their episodes pair scenario by scenario.
This prints A minus B per metric: the mean over seeds and scenarios of the paired differences,
with a 95 % percentile bootstrap interval that resamples training seeds (A's seed k with B's
seed k) and scenarios independently.

    /usr/bin/python3 scripts/paired_difference.py A_EPISODES.csv:CONFIG B_EPISODES.csv:CONFIG \\
        [--resamples 2000] [--seed 0]

EPISODES.csv is a study's eval/study/episodes.csv (or evaluate's episodes.csv); CONFIG the
configuration's name there (its rows are CONFIG.seed_K). Both must hold the same seeds, each over
the same scenarios with the same scenario seeds. Metrics: progress (percentage points),
cross-track error (m), collisions and time-outs (percentage points of episodes; a time-out is an
episode truncated without a collision or the goal). Bad input: one line naming the argument or
file, exit status 2.
"""

import argparse
import csv
import sys

import numpy as np

METRICS = ("progress pts", "cte m", "collisions pts", "time-outs pts")


class BadInput(Exception):
    pass


def metrics_of(row):
    """(progress %, cross-track error m, collision %, time-out %) of one episode row."""
    collision, goal, truncated = (int(row[key]) for key in ("collision", "goal", "truncated"))
    time_out = truncated == 1 and collision == 0 and goal == 0
    return (100 * float(row["progress"]), float(row["mean_cte"]), 100 * collision,
            100 * int(time_out))


def read_config(argument):
    """{seed: {scenario: (scenario seed, metrics)}} of CONFIG in EPISODES.csv."""
    path, separator, config = argument.rpartition(":")
    if not separator or not path or not config:
        raise BadInput(f"{argument}: expected EPISODES.csv:CONFIG")
    runs = {}
    try:
        with open(path, newline="") as file:
            for row in csv.DictReader(file):
                name, _, seed = row["model"].rpartition(".seed_")
                if name != config:
                    continue
                runs.setdefault(int(seed), {})[row["scenario"]] = (row["seed"], metrics_of(row))
    except OSError as error:
        raise BadInput(f"{path}: {error.strerror}")
    except (KeyError, ValueError, TypeError) as error:
        raise BadInput(f"{path}: not an episodes table ({error})")
    if not runs:
        raise BadInput(f"{path}: no episodes of configuration '{config}'")
    return runs


def paired_differences(a, b, a_name, b_name):
    """Array [seeds, scenarios, metrics] of A minus B, seeds and scenarios in sorted order."""
    if sorted(a) != sorted(b):
        raise BadInput(f"{a_name} has seeds {sorted(a)}, {b_name} {sorted(b)}")
    seeds = sorted(a)
    scenarios = sorted(a[seeds[0]])
    for seed in seeds:
        for runs, name in ((a, a_name), (b, b_name)):
            if runs[seed].keys() != set(scenarios):
                raise BadInput(f"{name}: seed {seed} has other scenarios than {a_name} seed "
                               f"{seeds[0]}")
            for scenario in scenarios:
                if runs[seed][scenario][0] != a[seeds[0]][scenario][0]:
                    raise BadInput(f"{name}: scenario {scenario} has another scenario seed: not "
                                   "the same test scenarios")
    return np.array([[np.subtract(a[s][c][1], b[s][c][1]) for c in scenarios] for s in seeds],
                    dtype=float)


def bootstrap_interval(differences, resamples, seed):
    """Percentile 95 % interval of the mean, seeds and scenarios resampled independently."""
    rng = np.random.default_rng(seed)
    seed_count, scenario_count, _ = differences.shape
    means = np.empty((resamples, differences.shape[2]))
    for k in range(resamples):
        seeds = rng.integers(seed_count, size=seed_count)
        scenarios = rng.integers(scenario_count, size=scenario_count)
        means[k] = differences[np.ix_(seeds, scenarios)].mean(axis=(0, 1))
    return np.percentile(means, 2.5, axis=0), np.percentile(means, 97.5, axis=0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("a", metavar="A_EPISODES.csv:CONFIG")
    parser.add_argument("b", metavar="B_EPISODES.csv:CONFIG")
    parser.add_argument("--resamples", type=int, default=2000, help="bootstrap resamples")
    parser.add_argument("--seed", type=int, default=0, help="seed of the bootstrap")
    args = parser.parse_args()
    try:
        if args.resamples < 100:
            raise BadInput(f"--resamples {args.resamples}: at least 100")
        differences = paired_differences(read_config(args.a), read_config(args.b), args.a,
                                         args.b)
    except BadInput as error:
        print(f"paired_difference: error: {error}", file=sys.stderr)
        return 2
    low, high = bootstrap_interval(differences, args.resamples, args.seed)
    seeds, scenarios, _ = differences.shape
    print(f"A - B over {seeds} seeds x {scenarios} scenarios (95 % bootstrap interval)")
    for k, metric in enumerate(METRICS):
        mean = differences[:, :, k].mean()
        print(f"{metric:15s} {mean:+.2f} [{low[k]:+.2f}, {high[k]:+.2f}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())

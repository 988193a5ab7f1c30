#!/usr/bin/python3
"""The paired difference between two trained configurations, also across two studies.

A study's report compares configurations of one study. When a change can only be made in
another study (its dataset, say), both studies' evaluations run the same test scenarios (the
same `evaluation.episodes` and `evaluation.seed`), so their episodes pair scenario by scenario.
This prints A minus B per metric: the mean over seeds and scenarios of the paired differences,
and the probability of improvement (P(A better than B on a random scenario and seed), ties
counting half, as the study report defines it), each with a 95 % percentile bootstrap interval
that resamples training seeds (A's seed k with B's seed k) and scenarios independently.

    /usr/bin/python3 scripts/paired_difference.py A_EPISODES.csv:CONFIG B_EPISODES.csv:CONFIG \\
        [--resamples 2000] [--seed 0]

EPISODES.csv is a study's eval/study/episodes.csv (or evaluate's episodes.csv); CONFIG the
configuration's name there (its rows are CONFIG.seed_K), or a single agent's (rows named CONFIG,
such as the authors' `ref.shallow_locked_3m`), which then pairs with every seed of the other.
Both must hold the same seeds, each over the same scenarios with the same scenario seeds.
Metrics: progress (percentage points), cross-track error (m), collisions and time-outs
(percentage points of episodes; a time-out is an episode truncated without a collision or the
goal). Bad input: one line naming the argument or file, exit status 2.
"""

import argparse
import csv
import sys

import numpy as np

METRICS = ("progress pts", "cte m", "collisions pts", "time-outs pts")
HIGHER_IS_BETTER = np.array([True, False, False, False])


class BadInput(Exception):
    pass


def metrics_of(row):
    """(progress %, cross-track error m, collision %, time-out %) of one episode row."""
    collision, goal, truncated = (int(row[key]) for key in ("collision", "goal", "truncated"))
    time_out = truncated == 1 and collision == 0 and goal == 0
    return (100 * float(row["progress"]), float(row["mean_cte"]), 100 * collision,
            100 * int(time_out))


def read_config(argument):
    """{seed: {scenario: (scenario seed, metrics)}} of CONFIG in EPISODES.csv; a single agent's
    seed is None."""
    path, separator, config = argument.rpartition(":")
    if not separator or not path or not config:
        raise BadInput(f"{argument}: expected EPISODES.csv:CONFIG")
    runs = {}
    try:
        with open(path, newline="") as file:
            for row in csv.DictReader(file):
                name, _, seed = row["model"].rpartition(".seed_")
                if row["model"] == config:
                    seed = None
                elif name == config:
                    seed = int(seed)
                else:
                    continue
                runs.setdefault(seed, {})[row["scenario"]] = (row["seed"], metrics_of(row))
    except OSError as error:
        raise BadInput(f"{path}: {error.strerror}")
    except (KeyError, ValueError, TypeError) as error:
        raise BadInput(f"{path}: not an episodes table ({error})")
    if not runs:
        raise BadInput(f"{path}: no episodes of configuration '{config}'")
    return runs


def paired_differences(a, b, a_name, b_name):
    """Array [seeds, scenarios, metrics] of A minus B, seeds and scenarios in sorted order."""
    if None in a and len(a) > 1 or None in b and len(b) > 1:
        raise BadInput(f"{a_name if None in a else b_name}: rows of a single agent and of "
                       "seeds under one name")
    if list(b) == [None]:
        b = {seed: b[None] for seed in a}
    elif list(a) == [None]:
        a = {seed: a[None] for seed in b}
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


def improvements(differences):
    """1 where A is better than B, 0.5 on a tie, 0 where worse: [seeds, scenarios, metrics]."""
    better = np.where(HIGHER_IS_BETTER, differences > 0, differences < 0)
    return better + 0.5 * (differences == 0)


def bootstrap_interval(values, resamples, seed):
    """Percentile 95 % interval of the mean of `values` [seeds, scenarios, metrics] per metric,
    seeds and scenarios resampled independently."""
    rng = np.random.default_rng(seed)
    seed_count, scenario_count, _ = values.shape
    means = np.empty((resamples, values.shape[2]))
    for k in range(resamples):
        seeds = rng.integers(seed_count, size=seed_count)
        scenarios = rng.integers(scenario_count, size=scenario_count)
        means[k] = values[np.ix_(seeds, scenarios)].mean(axis=(0, 1))
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
    # One set of resamples for both: the same seed draws the same seeds and scenarios.
    both = np.concatenate([differences, improvements(differences)], 2)
    low, high = bootstrap_interval(both, args.resamples, args.seed)
    mean = both.mean(axis=(0, 1))
    seeds, scenarios, _ = differences.shape
    print(f"A - B over {seeds} seeds x {scenarios} scenarios, and P(A better); 95 % bootstrap "
          "intervals")
    for k, metric in enumerate(METRICS):
        p = k + len(METRICS)
        print(f"{metric:15s} {mean[k]:+.2f} [{low[k]:+.2f}, {high[k]:+.2f}]   "
              f"P(A better) {mean[p]:.2f} [{low[p]:.2f}, {high[p]:.2f}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())

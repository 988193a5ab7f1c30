#!/usr/bin/python3
"""Where an agent's progress and cross-track error go: splits the mean progress lost and the mean
cross-track error of each model of an evaluate episodes.csv between the episodes that collided,
the ones that ran out of time and the rest (which stop short of 100 % because the goal test ends
them within 5 m of the end or at 99 % of the path), and tells whether the time-outs recur on the
same scenarios and whether another model of the file completes those.

The training seeds of a study configuration ("<config>.seed_<k>") are pooled into one row per
configuration. Shares are of all the model's episodes, so the three parts of a column add up to
its total (progress lost = 100 - mean progress, in points).

    /usr/bin/python3 scripts/failure_breakdown.py runs/best/eval/study/episodes.csv
"""

import argparse
import collections
import csv
import re
import sys

COLUMNS = ("model", "scenario", "progress", "mean_cte", "collision", "goal", "truncated")
SEED_SUFFIX = re.compile(r"\.seed_\d+$")


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"failure_breakdown: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_episodes(path):
    """The episodes of evaluate's episodes.csv as dicts of model, config, scenario, progress (0-1),
    cte (m), and the outcome: collision, timeout or other."""
    try:
        with open(path, newline="", encoding="utf-8") as file:
            reader = csv.DictReader(file)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                fail(f"{path}: no column {missing[0]} (an episodes.csv of evaluate expected)")
            episodes = [parse_row(path, n, row) for n, row in enumerate(reader, start=2)]
    except OSError as error:
        fail(f"{path}: {error.strerror}")
    if not episodes:
        fail(f"{path}: no episodes")
    return episodes


def parse_row(path, line, row):
    try:
        progress, cte = float(row["progress"]), float(row["mean_cte"])
        collided, truncated = int(row["collision"]) == 1, int(row["truncated"]) == 1
    except ValueError:
        fail(f"{path}:{line}: a number expected in progress, mean_cte, collision, truncated")
    outcome = "collision" if collided else "timeout" if truncated else "other"
    return {"model": row["model"], "config": SEED_SUFFIX.sub("", row["model"]),
            "scenario": row["scenario"], "progress": progress, "cte": cte,
            "goal": row["goal"] == "1", "outcome": outcome}


def breakdown(episodes):
    """{config: row} with the episodes' count, seeds, and per outcome its share of episodes (%),
    the progress it loses (points of the mean), its mean progress (%) and its part of the mean
    cross-track error (m)."""
    by_config = collections.defaultdict(list)
    for episode in episodes:
        by_config[episode["config"]].append(episode)
    rows = {}
    for config, group in sorted(by_config.items()):
        n = len(group)
        row = {"episodes": n, "seeds": len({e["model"] for e in group}),
               "progress": 100.0 * sum(e["progress"] for e in group) / n,
               "cte": sum(e["cte"] for e in group) / n}
        for outcome in ("collision", "timeout", "other"):
            part = [e for e in group if e["outcome"] == outcome]
            row[outcome] = {
                "share": 100.0 * len(part) / n,
                "lost": 100.0 * sum(1.0 - e["progress"] for e in part) / n,
                "mean_progress": 100.0 * sum(e["progress"] for e in part) / len(part) if part else None,
                "cte": sum(e["cte"] for e in part) / n,
            }
        rows[config] = row
    return rows


def recurring_timeouts(episodes):
    """{config: (scenarios with a time-out, of which timed out by every seed, of which completed
    by some other configuration of the file)}."""
    completed_by = collections.defaultdict(set)
    for episode in episodes:
        if episode["goal"]:
            completed_by[episode["scenario"]].add(episode["config"])
    result = {}
    for config in sorted({e["config"] for e in episodes}):
        group = [e for e in episodes if e["config"] == config]
        seeds = len({e["model"] for e in group})
        timeouts = collections.Counter(e["scenario"] for e in group if e["outcome"] == "timeout")
        everywhere = [s for s, count in timeouts.items() if count == seeds]
        completed = [s for s in timeouts if completed_by[s] - {config}]
        result[config] = (len(timeouts), len(everywhere), len(completed))
    return result


def number(value, digits=1):
    return "-" if value is None else f"{value:.{digits}f}"


def print_tables(rows, recurring):
    print("| model | seeds | progress % | lost to collisions (share %, mean progress %) | "
          "lost to time-outs (share %, mean progress %) | lost by the rest (share %) |")
    print("|---|---|---|---|---|---|")
    for config, row in rows.items():
        c, t, o = row["collision"], row["timeout"], row["other"]
        print(f"| {config} | {row['seeds']} | {number(row['progress'])} | "
              f"{number(c['lost'], 2)} ({number(c['share'])}, {number(c['mean_progress'], 0)}) | "
              f"{number(t['lost'], 2)} ({number(t['share'])}, {number(t['mean_progress'], 0)}) | "
              f"{number(o['lost'], 2)} ({number(o['share'])}) |")
    print()
    print("| model | cte m | of which: collisions | time-outs | the rest | "
          "scenarios with a time-out | of which every seed's | of which another model completes |")
    print("|---|---|---|---|---|---|---|---|")
    for config, row in rows.items():
        scenarios, everywhere, completed = recurring[config]
        print(f"| {config} | {number(row['cte'])} | {number(row['collision']['cte'])} | "
              f"{number(row['timeout']['cte'])} | {number(row['other']['cte'])} | {scenarios} | "
              f"{everywhere} | {completed} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("episodes", help="episodes.csv of evaluate (or of a study's eval/study/)")
    args = parser.parse_args()
    episodes = read_episodes(args.episodes)
    print_tables(breakdown(episodes), recurring_timeouts(episodes))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Every trained agent of several studies, seed by seed, against issue 16's goal.

A study's REPORT.md gives each configuration's mean over its seeds; this puts every seed on one
front instead: does any single agent reach the goal (collisions at most 3 %, progress at least
97 %, cross-track error at most 17 m), and do the seeds of one configuration trade collisions
against path-following the way the configurations do?

    /usr/bin/python3 scripts/seed_front.py STUDY_DIR... --out front.csv

Reads STUDY_DIR/eval/study/episodes.csv (the study's own scenarios) and STUDY_DIR/summary.json
(each configuration's training steps). A folder that holds episodes.csv itself instead (an
`evaluate --out` folder: agents made outside a study, such as distilled students) is read as a
study whose training steps are not recorded (its rows' "steps" stay empty). Every study must
have played the same scenarios (the same names and episode seeds). An agent of the same name in
several studies (a run reused by copying) counts once if its episodes are identical; otherwise
each other run is its own configuration, named "<config> (<study folder>)". Writes one row per
agent (means over its episodes: progress %, cte m, collisions %, time-outs %) and prints how
many of our agents meet each goal, each pair and all three, and how a configuration's seeds
trade cross-track error against collisions. Bad input: one line naming the file, exit status 2.
"""

import argparse
import csv
import json
import math
import os
import sys

GOAL_COLLISIONS = 3.0  # % of the episodes, at most
GOAL_PROGRESS = 97.0  # % of the path, at least
GOAL_CTE = 17.0  # m, at most
AUTHORS_PREFIX = "ref."  # the study runner's name for a reference agent
SEED_MARK = ".seed_"  # "<config>.seed_<k>"
MIN_SEEDS_FOR_CORRELATION = 3
COLUMNS = ("progress", "mean_cte", "collision", "truncated")


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"seed_front: error: {message}", file=sys.stderr)
    sys.exit(2)


def episodes_path(folder):
    """(the folder's episodes file, whether the folder is a study's)."""
    study = os.path.join(folder, "eval", "study", "episodes.csv")
    evaluation = os.path.join(folder, "episodes.csv")
    if not os.path.exists(study) and os.path.exists(evaluation):
        return evaluation, False
    return study, True


def read_episodes(path):
    """{agent: {(scenario, seed): (progress, cte, collision, truncated) as text}}."""
    agents = {}
    try:
        with open(path, newline="") as file:
            reader = csv.DictReader(file)
            missing = [c for c in ("model", "scenario", "seed", *COLUMNS)
                       if c not in (reader.fieldnames or [])]
            if missing:
                fail(f"{path}: no column '{missing[0]}'")
            for row in reader:
                key = (row["scenario"], row["seed"])
                agents.setdefault(row["model"], {})[key] = tuple(row[c] for c in COLUMNS)
    except OSError as error:
        fail(f"{path}: {error.strerror}")
    if not agents:
        fail(f"{path}: no episodes")
    return agents


def read_steps(study):
    """{config: training steps} from the study's summary.json ({} if it has none)."""
    path = os.path.join(study, "summary.json")
    try:
        with open(path) as file:
            return json.load(file).get("config_steps", {})
    except OSError as error:
        fail(f"{path}: {error.strerror}")
    except json.JSONDecodeError:
        fail(f"{path}: not JSON")


def agent_means(path, name, episodes):
    """Means over the agent's episodes: progress %, cte m, collisions %, time-outs %."""
    try:
        values = [[float(v) for v in episode] for episode in episodes.values()]
    except ValueError:
        fail(f"{path}: a value of '{name}' is not a number")
    n = len(values)
    progress, cte, collisions, time_outs = (sum(column) / n for column in zip(*values))
    return 100.0 * progress, cte, 100.0 * collisions, 100.0 * time_outs


def split_name(name):
    """(config, seed) of "<config>.seed_<k>", (name, "") for a single agent."""
    config, mark, seed = name.rpartition(SEED_MARK)
    return (config, seed) if mark else (name, "")


def collect(studies):
    """One record per distinct agent over the studies."""
    records, seen, scenarios, first_path = [], {}, None, None
    for study in studies:
        path, is_study = episodes_path(study)
        agents = read_episodes(path)
        steps = read_steps(study) if is_study else {}
        for name, episodes in agents.items():
            if scenarios is None:
                scenarios, first_path = set(episodes), path
            if set(episodes) != scenarios:
                fail(f"{path}: '{name}' played other scenarios than the agents of {first_path}")
            if seen.get(name) == episodes:
                continue  # the same run, reused by another study
            config, seed = split_name(name)
            if name in seen:  # another run of the same name: its own configuration
                config = f"{config} ({os.path.basename(os.path.normpath(study))})"
            seen.setdefault(name, episodes)
            authors = name.startswith(AUTHORS_PREFIX)
            progress, cte, collisions, time_outs = agent_means(path, name, episodes)
            records.append({
                "agent": name, "study": os.path.basename(os.path.normpath(study)),
                "config": config, "seed": seed, "kind": "authors" if authors else "ours",
                "steps": "" if authors else steps.get(config, ""),
                "progress": progress, "cte": cte, "collisions": collisions,
                "time_outs": time_outs})
    return records


def goals_met(record):
    return (record["collisions"] <= GOAL_COLLISIONS, record["progress"] >= GOAL_PROGRESS,
            record["cte"] <= GOAL_CTE)


def ranks(values):
    """Ranks 1..n, ties given their average rank."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    result = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            result[order[k]] = (i + j) / 2.0 + 1.0
        i = j + 1
    return result


def pearson(x, y):
    """Pearson's r, NaN when either side does not vary."""
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx, syy = sum((a - mx) ** 2 for a in x), sum((b - my) ** 2 for b in y)
    return sxy / math.sqrt(sxx * syy) if sxx > 0 and syy > 0 else float("nan")


def spearman(x, y):
    return pearson(ranks(x), ranks(y))


def sign_test(successes, trials):
    """Two-sided p of `successes` of `trials` under a fair coin (the binomial sign test)."""
    extreme = max(successes, trials - successes)
    tail = sum(math.comb(trials, k) for k in range(extreme, trials + 1)) / 2.0 ** trials
    return min(1.0, 2.0 * tail)


def within_config(records):
    """{config: [record, ...]} of our configurations with enough seeds."""
    groups = {}
    for r in records:
        if r["kind"] == "ours" and r["seed"]:
            groups.setdefault(r["config"], []).append(r)
    return {k: v for k, v in groups.items() if len(v) >= MIN_SEEDS_FOR_CORRELATION}


def report(records):
    ours = [r for r in records if r["kind"] == "ours"]
    lines = [f"{len(ours)} of our agents, {len(records) - len(ours)} of the authors'"]
    names = ("collisions", "progress", "cte")
    for picked in ((0,), (1,), (2,), (0, 1), (0, 2), (1, 2), (0, 1, 2)):
        count = sum(all(goals_met(r)[i] for i in picked) for r in ours)
        lines.append(f"goal on {' and '.join(names[i] for i in picked)}: {count}")
    groups = within_config(records)
    rhos = [spearman([r["cte"] for r in g], [r["collisions"] for r in g])
            for g in groups.values()]
    rhos = [rho for rho in rhos if not math.isnan(rho)]
    centred_cte, centred_collisions = [], []
    for group in groups.values():
        mean_cte = sum(r["cte"] for r in group) / len(group)
        mean_collisions = sum(r["collisions"] for r in group) / len(group)
        centred_cte += [r["cte"] - mean_cte for r in group]
        centred_collisions += [r["collisions"] - mean_collisions for r in group]
    if rhos:
        negative = sum(rho < 0 for rho in rhos)
        lines.append(
            f"seeds of one configuration, cte against collisions: Spearman below 0 in {negative} "
            f"of {len(rhos)} configurations (mean {sum(rhos) / len(rhos):.2f}; sign test, "
            f"two-sided p = {sign_test(negative, len(rhos)):.2g}); Pearson of the seeds' "
            f"deviations from their configuration's mean over {len(centred_cte)} seeds: "
            f"{pearson(centred_cte, centred_collisions):.2f}")
    return lines


def write_csv(records, out):
    fields = ("agent", "study", "config", "seed", "kind", "steps", "progress", "cte",
              "collisions", "time_outs")
    temporary = out + ".tmp"
    with open(temporary, "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=fields, lineterminator="\n")
        writer.writeheader()
        for r in records:
            writer.writerow({k: (f"{r[k]:.3f}" if isinstance(r[k], float) else r[k])
                             for k in fields})
    os.replace(temporary, out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("studies", nargs="+", metavar="STUDY_DIR",
                        help="study folders (or evaluate --out folders)")
    parser.add_argument("--out", required=True, help="CSV file to write, one row per agent")
    args = parser.parse_args()
    records = collect(args.studies)
    write_csv(records, args.out)
    print("\n".join(report(records)))


if __name__ == "__main__":
    main()

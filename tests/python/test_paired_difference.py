"""scripts/paired_difference.py on episode tables made here, across two files, against
hand-computed differences."""

import csv
import subprocess
import sys

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "paired_difference.py"
COLUMNS = ["model", "scenario", "seed", "progress", "mean_cte", "collision", "goal", "truncated"]


def write_episodes(path, rows):
    with open(path, "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(COLUMNS)
        writer.writerows(rows)
    return path


def episodes(config, seeds, scenarios, cte_of, collided=lambda seed, k: False, seed_offset=0):
    """Rows of `config`: progress 0.9, cross-track error cte_of(seed, k), goal unless collided."""
    rows = []
    for seed in seeds:
        for k in range(scenarios):
            collision = int(collided(seed, k))
            rows.append([f"{config}.seed_{seed}", f"test-{k:03d}", 1000 + k + seed_offset, 0.9,
                         cte_of(seed, k), collision, 1 - collision, 0])
    return rows


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


def metric_line(output, metric):
    """The difference's mean and interval, then P(A better)'s: six strings."""
    line = next(line for line in output.splitlines() if line.startswith(metric))
    difference, improvement = line[len(metric):].split("P(A better)")
    return difference.split() + improvement.split()


def test_a_constant_difference_has_a_point_interval(tmp_path):
    # B in one file, A in another: A keeps 1.5 m farther from the path in every episode and
    # collides in scenario 0 of 4 (B never): +25 points of collisions, exactly.
    b = write_episodes(tmp_path / "b.csv", episodes("plain", [0, 1, 2], 4, lambda s, k: 10 + s + k))
    a = write_episodes(tmp_path / "a.csv",
                       episodes("other", [0, 1, 2], 4, lambda s, k: 11.5 + s + k,
                                collided=lambda s, k: k == 0))
    result = run(f"{a}:other", f"{b}:plain", "--resamples", 200)
    assert result.returncode == 0, result.stderr
    assert "over 3 seeds x 4 scenarios" in result.stdout
    # P(A better): never on cross-track error, a tie (0.5) on progress and time-outs; on
    # collisions worse in scenario 0 and tied in the other 3: (0 + 3 x 0.5) / 4 = 0.375.
    assert metric_line(result.stdout, "cte m") == ["+1.50", "[+1.50,", "+1.50]", "0.00",
                                                   "[0.00,", "0.00]"]
    assert metric_line(result.stdout, "progress pts") == ["+0.00", "[+0.00,", "+0.00]", "0.50",
                                                          "[0.50,", "0.50]"]
    collisions = metric_line(result.stdout, "collisions pts")
    assert collisions[0] == "+25.00" and collisions[3] == "0.38"
    time_outs = metric_line(result.stdout, "time-outs pts")
    assert time_outs == ["+0.00", "[+0.00,", "+0.00]", "0.50", "[0.50,", "0.50]"]


def test_the_interval_spans_the_seeds(tmp_path):
    # Seed 0 differs by 0 m, seed 1 by 2 m, in every scenario: the mean is 1 m, and a resample
    # of two seeds is both seed 0 (mean 0) with probability 1/4, both seed 1 (mean 2) likewise,
    # so the 2.5th and 97.5th percentiles are 0 and 2.
    table = episodes("b", [0, 1], 5, lambda s, k: 20.0)
    table += episodes("a", [0, 1], 5, lambda s, k: 20.0 + 2 * s)
    path = write_episodes(tmp_path / "episodes.csv", table)
    result = run(f"{path}:a", f"{path}:b")
    assert result.returncode == 0, result.stderr
    assert metric_line(result.stdout, "cte m")[:3] == ["+1.00", "[+0.00,", "+2.00]"]


def test_a_single_agent_pairs_with_every_seed(tmp_path):
    # The authors' agents have one run each, named without a seed: 12 m in every scenario.
    table = episodes("x", [0], 4, lambda s, k: 12.0)
    for row in table:
        row[0] = "ref.agent"
    table += episodes("ours", [0, 1, 2], 4, lambda s, k: 10.0 + 2 * s)  # 10, 12, 14 m
    path = write_episodes(tmp_path / "episodes.csv", table)
    result = run(f"{path}:ours", f"{path}:ref.agent")
    assert result.returncode == 0, result.stderr
    assert "over 3 seeds x 4 scenarios" in result.stdout
    # Seed 0 keeps closer than the agent (better), seed 1 ties, seed 2 is farther: P = 0.5.
    assert metric_line(result.stdout, "cte m")[0] == "+0.00"
    assert metric_line(result.stdout, "cte m")[3] == "0.50"
    backwards = run(f"{path}:ref.agent", f"{path}:ours")
    assert metric_line(backwards.stdout, "cte m")[0] == "+0.00"


def refusal(result):
    assert result.returncode == 2
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


def test_tables_of_other_scenarios_or_seeds_are_refused(tmp_path):
    b = write_episodes(tmp_path / "b.csv", episodes("b", [0, 1], 3, lambda s, k: 1.0))
    other_scenarios = write_episodes(tmp_path / "a.csv",
                                     episodes("a", [0, 1], 3, lambda s, k: 1.0, seed_offset=7))
    assert "another scenario seed" in refusal(run(f"{other_scenarios}:a", f"{b}:b"))
    fewer_seeds = write_episodes(tmp_path / "c.csv", episodes("a", [0], 3, lambda s, k: 1.0))
    assert "has seeds [0]" in refusal(run(f"{fewer_seeds}:a", f"{b}:b"))
    fewer_scenarios = write_episodes(tmp_path / "d.csv", episodes("a", [0, 1], 2, lambda s, k: 1))
    assert "other scenarios" in refusal(run(f"{fewer_scenarios}:a", f"{b}:b"))
    assert "no episodes of configuration 'x'" in refusal(run(f"{b}:x", f"{b}:b"))
    assert "expected EPISODES.csv:CONFIG" in refusal(run(str(b), f"{b}:b"))
    assert "missing.csv" in refusal(run(f"{tmp_path}/missing.csv:a", f"{b}:b"))

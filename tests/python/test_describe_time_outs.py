"""scripts/describe_time_outs.py on a study folder made here: a policy that holds full rudder
circles, one without thrust stays still; an episode the replay ends otherwise is counted."""

import csv
import subprocess
import sys

import pytest
import torch

import colav
from conftest import HeldAction, SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "describe_time_outs.py"


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    """Configurations `circle` (full surge, full rudder) and `still` (no thrust, rudder amidships),
    each recorded as timing out on test scenario 0; `still` also as reaching the goal on test
    scenarios 1 and 2, which it cannot (only the first is replayed: one per time-out)."""
    folder = tmp_path_factory.mktemp("study")
    for name, action in (("circle", (1.0, 1.0)), ("still", (-1.0, 0.0))):
        run_dir = folder / "ppo" / name / "seed_0"
        run_dir.mkdir(parents=True)
        torch.jit.script(HeldAction(*action)).save(str(run_dir / "policy.pt"))
    seeds = colav.evaluation_scenario_seeds(3)
    (folder / "eval" / "study").mkdir(parents=True)
    with open(folder / "eval" / "study" / "episodes.csv", "w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["model", "scenario", "seed", "goal", "truncated"])
        writer.writerow(["circle.seed_0", "test-000", seeds[0], 0, 1])
        writer.writerow(["still.seed_0", "test-000", seeds[0], 0, 1])
        writer.writerow(["still.seed_0", "test-001", seeds[1], 1, 0])
        writer.writerow(["still.seed_0", "test-002", seeds[2], 1, 0])
    return folder


def replayed(study, config, tmp_path):
    result = run(study, config, "--out", tmp_path / f"{config}.csv")
    assert result.returncode == 0, result.stderr
    with open(tmp_path / f"{config}.csv", newline="") as file:
        return result.stdout, list(csv.DictReader(file))


def line_of(output, kind):
    """The summary line of one kind of episode."""
    return next(line for line in output.splitlines() if line.startswith(kind + ":"))


def test_a_vessel_at_full_rudder_circles_and_one_without_thrust_stops(study, tmp_path):
    output, rows = replayed(study, "circle", tmp_path)
    assert "time_out: 1 episodes" in output and "goal: none" in output, output
    assert line_of(output, "time_out").endswith("at rest at the end 0"), output
    assert [row["kind"] for row in rows] == ["time_out"]
    assert float(rows[0]["turns"]) > 5 and float(rows[0]["speed"]) > 0.1, rows
    assert float(rows[0]["end_speed"]) > 0.1, rows
    output, rows = replayed(study, "still", tmp_path)  # still: a vessel starts at rest
    time_out = rows[0]
    assert float(time_out["turns"]) < 0.01 and float(time_out["speed"]) < 0.01, rows
    assert float(time_out["end_speed"]) < 0.01, rows
    assert line_of(output, "time_out").endswith("at rest at the end 1"), output


def test_counts_the_episodes_that_the_replay_ends_otherwise(study, tmp_path):
    output, rows = replayed(study, "still", tmp_path)
    assert [(row["kind"], row["scenario_seed"], row["replayed_alike"]) for row in rows] == [
        ("time_out", str(colav.evaluation_scenario_seeds(1)[0]), "1"),
        ("goal", str(colav.evaluation_scenario_seeds(2)[1]), "0")]
    assert "goal: 1 episodes, 0 replayed alike" in output, output


@pytest.mark.parametrize("args, message", [
    (("nowhere", "circle"), "nowhere/eval/study/episodes.csv: No such file or directory"),
    (("{study}", "missing"), "episodes.csv: no episodes of configuration 'missing'"),
    (("{study}", "circle", "--out", "/no/such/folder/x.csv"),
     "/no/such/folder/x.csv: no such folder"),
])
def test_bad_input_is_one_line_and_status_2(study, args, message):
    result = run(*(arg.format(study=study) for arg in args))
    assert result.returncode == 2 and message in result.stderr, result.stderr
    assert result.stderr.count("\n") == 1

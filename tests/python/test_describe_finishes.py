"""scripts/describe_finishes.py: on a straight 100 m path a vessel held on course reaches the 5 m
goal circle 5 m before the path's end when it runs on the path and sqrt(25 - 4^2) = 3 m before it
when it runs 4 m beside it; the pair comparison counts only the scenarios both agents finish; an
agent turned away from the path over its last metres enters the circle farther along."""

import csv
import importlib.util
import math
import subprocess
import sys

import numpy as np
import pytest
import torch

from conftest import HeldAction, SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "describe_finishes.py"
MAX_STEP_M = 0.6  # the vessel's top speed is about 0.58 m/s, one step is 1 s


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


def straight_path_scenario(folder, name, start_x):
    path = folder / f"{name}.yaml"
    path.write_text(f"name: {name}\npath:\n  waypoints: [[0, 0], [0, 100]]\nvessel:\n"
                    f"  position: [{start_x}, 0]\n  heading: {math.pi / 2}\n"
                    "static_obstacles: []\ndynamic_obstacles: []\n")
    return path


@pytest.fixture(scope="module")
def finishes(tmp_path_factory):
    """Two agents held on course at full and at half thrust, on the path and 4 m beside it:
    (stdout, rows of --out)."""
    folder = tmp_path_factory.mktemp("finishes")
    for name, surge in (("full", 1.0), ("half", 0.0)):
        torch.jit.script(HeldAction(surge, 0.0)).save(str(folder / f"{name}.pt"))
    scenarios = [straight_path_scenario(folder, "on_path", 0.0),
                 straight_path_scenario(folder, "beside", 4.0)]
    result = run(f"full={folder / 'full.pt'}", f"half={folder / 'half.pt'}",
                 *(arg for path in scenarios for arg in ("--scenario", path)),
                 "--out", folder / "finishes.csv")
    assert result.returncode == 0, result.stderr
    with open(folder / "finishes.csv", newline="") as file:
        return result.stdout, list(csv.DictReader(file))


def test_the_side_offset_sets_where_the_goal_circle_is_entered(finishes):
    _, rows = finishes
    assert [(row["model"], row["scenario"].rsplit("/", 1)[-1]) for row in rows] == [
        ("full", "on_path.yaml"), ("full", "beside.yaml"),
        ("half", "on_path.yaml"), ("half", "beside.yaml")]
    for row in rows:
        assert row["goal"] == "1"
        beside = row["scenario"].endswith("beside.yaml")
        side, short = float(row["side_offset_m"]), float(row["short_of_end_m"])
        predicted = float(row["predicted_short_of_end_m"])
        assert side == pytest.approx(4.0 if beside else 0.0, abs=1e-6)
        assert predicted == pytest.approx(3.0 if beside else 5.0, abs=1e-6)
        assert predicted - MAX_STEP_M < short <= predicted
        assert float(row["progress"]) == pytest.approx(1.0 - short / 100.0, abs=1e-9)


def test_the_summary_names_each_agent_and_the_pair(finishes):
    stdout, _ = finishes
    assert "  full: 2 of 2; beside the path 2.00 m" in stdout
    # Both agents finish both scenarios at the same offsets: the prediction is a tie each time.
    assert "  full over half: 2 scenarios;" in stdout
    assert "predicted 0.500" in stdout


def load_script():
    spec = importlib.util.spec_from_file_location("describe_finishes", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_comparison_at_the_goal_by_hand():
    compare_at_goal = load_script().compare_at_goal
    a = [{"goal": 1, "progress": 0.99, "predicted_short_of_end_m": 3.0},   # A lands farther
         {"goal": 1, "progress": 0.98, "predicted_short_of_end_m": 3.0},   # the prediction misses
         {"goal": 0, "progress": 0.50, "predicted_short_of_end_m": 5.0}]   # A failed: not counted
    b = [{"goal": 1, "progress": 0.98, "predicted_short_of_end_m": 4.0},
         {"goal": 1, "progress": 0.99, "predicted_short_of_end_m": 4.0},
         {"goal": 1, "progress": 0.98, "predicted_short_of_end_m": 4.0}]
    assert compare_at_goal(a, b) == (2, 0.5, 1.0, 0.5)


def test_turning_away_from_the_path_enters_the_goal_circle_from_the_side(tmp_path):
    """The same policy 2 m beside the path, plain and turned away over its last 10 m: turned, it
    enters the circle farther beside the path, nearer the end, and wins the comparison."""
    policy = tmp_path / "full.pt"
    torch.jit.script(HeldAction(1.0, 0.0)).save(str(policy))
    result = run(f"plain={policy}", f"turned={policy}", "--turn-away", "turned=10",
                 "--scenario", straight_path_scenario(tmp_path, "beside", 2.0),
                 "--out", tmp_path / "finishes.csv")
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "finishes.csv", newline="") as file:
        plain, turned = list(csv.DictReader(file))
    assert plain["goal"] == turned["goal"] == "1"
    assert float(plain["side_offset_m"]) == pytest.approx(2.0, abs=1e-6)
    assert float(turned["side_offset_m"]) > 3.0
    assert float(turned["short_of_end_m"]) < float(plain["short_of_end_m"]) - 0.5
    assert "  turned turns away from the path over its last 10 m" in result.stdout
    assert "  plain over turned: 1 scenarios; 0.000" in result.stdout


def test_the_turn_away_by_hand():
    turn_away = load_script().turn_away
    action = np.array([0.7, 0.2], dtype=np.float32)
    near_end = {"path_length": 100.0, "progress": 0.95}  # 5 m of path left
    assert list(turn_away(action, {**near_end, "cross_track_error": 2.0}, 10.0)) == \
        pytest.approx([0.7, -1.0])
    assert list(turn_away(action, {**near_end, "cross_track_error": -2.0}, 10.0)) == \
        pytest.approx([0.7, 1.0])
    assert list(turn_away(action, {**near_end, "cross_track_error": 2.0}, 4.0)) == \
        pytest.approx([0.7, 0.2])
    assert list(action) == pytest.approx([0.7, 0.2])  # the policy's action is left as it was


@pytest.mark.parametrize("args, message", [
    (["policy.pt"], "'policy.pt': expected NAME=POLICY.pt"),
    (["=p.pt"], "'=p.pt': expected NAME=POLICY.pt"),
    (["a=missing.pt"], "missing.pt: no such policy file"),
    (["a={p}", "a={p}"], "the name 'a' is given twice"),
    (["a={p}", "--episodes", "0"], "--episodes 0: expected at least 1"),
    (["a={p}", "--out", "no/such/folder/x.csv"], "no/such/folder/x.csv: no such folder"),
    (["a={p}", "--turn-away", "b=10"], "--turn-away 'b=10': expected NAME=METRES with NAME one"),
    (["a={p}", "--turn-away", "a"], "--turn-away 'a': expected NAME=METRES with NAME one"),
    (["a={p}", "--turn-away", "a=-1"], "--turn-away 'a=-1': METRES must be a number above 0"),
    (["a={p}", "--turn-away", "a=far"], "--turn-away 'a=far': METRES must be a number above 0"),
])
def test_bad_input_is_one_line_and_status_2(tmp_path, args, message):
    policy = tmp_path / "p.pt"
    torch.jit.script(HeldAction(1.0, 0.0)).save(str(policy))
    result = run(*(arg.format(p=policy) for arg in args))
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and message in result.stderr, result.stderr

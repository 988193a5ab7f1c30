"""scripts/seed_front.py: every agent of several studies, its means, the goals it meets, the seeds'
trade-off within a configuration, and one-line refusals of studies that do not fit."""

import csv
import json
import subprocess

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "seed_front.py"
HEADER = "model,scenario,seed,progress,mean_cte,steps,collision,goal,truncated\n"


def seed_front(*args):
    return subprocess.run(["/usr/bin/python3", str(SCRIPT), *map(str, args)],
                          capture_output=True, text=True)


def make_study(folder, agents, steps=None, scenarios=("test-000", "test-001")):
    """agents: {name: [(progress, cte, collision, truncated) per scenario]}."""
    (folder / "eval" / "study").mkdir(parents=True)
    lines = [HEADER]
    for name, episodes in agents.items():
        for scenario, (progress, cte, collision, truncated) in zip(scenarios, episodes):
            lines.append(f"{name},{scenario},7,{progress},{cte},500,{collision},"
                         f"{1 - collision - truncated},{truncated}\n")
    (folder / "eval" / "study" / "episodes.csv").write_text("".join(lines))
    (folder / "summary.json").write_text(json.dumps({"config_steps": steps or {}}))
    return folder


def rows(path):
    with open(path, newline="") as file:
        return {row["agent"]: row for row in csv.DictReader(file)}


# Three seeds of "a" whose cte falls as their collisions rise, and one
# seed that meets every goal: 99 % progress, 10 m, no collision.
SEEDS_OF_A = {
    "a.seed_0": [(0.9, 30, 0, 0), (0.9, 30, 0, 0)],
    "a.seed_1": [(0.9, 20, 1, 0), (0.9, 20, 0, 0)],
    "a.seed_2": [(0.9, 10, 1, 0), (0.9, 10, 1, 0)],
    "a.seed_3": [(0.99, 10, 0, 0), (0.99, 10, 0, 0)],
}


def test_agents_their_means_and_the_goals_they_meet(tmp_path):
    first = make_study(tmp_path / "one", {**SEEDS_OF_A, "ref.theirs": [(0.5, 5, 1, 0),
                                                                          (1.0, 15, 0, 1)]},
                       {"a": 3000000})
    # The same run of a.seed_0 reused (counted once), and another run named b.seed_0.
    second = make_study(tmp_path / "two", {"a.seed_0": SEEDS_OF_A["a.seed_0"],
                                           "b.seed_0": [(0.8, 40, 0, 1), (0.8, 40, 0, 1)]})
    result = seed_front(first, second, "--out", tmp_path / "front.csv")
    assert result.returncode == 0, result.stderr
    agents = rows(tmp_path / "front.csv")
    assert sorted(agents) == ["a.seed_0", "a.seed_1", "a.seed_2", "a.seed_3", "b.seed_0",
                              "ref.theirs"]
    theirs = agents["ref.theirs"]
    assert (theirs["kind"], theirs["steps"], theirs["seed"]) == ("authors", "", "")
    assert float(theirs["progress"]) == 75.0
    assert float(theirs["cte"]) == 10.0
    assert float(theirs["collisions"]) == 50.0
    assert float(theirs["time_outs"]) == 50.0
    a1 = agents["a.seed_1"]
    assert (a1["study"], a1["config"], a1["seed"], a1["steps"]) == ("one", "a", "1", "3000000")
    assert float(a1["collisions"]) == 50.0
    assert agents["b.seed_0"]["study"] == "two"
    assert float(agents["b.seed_0"]["time_outs"]) == 100.0
    lines = result.stdout.splitlines()
    assert lines[0] == "5 of our agents, 1 of the authors'"
    assert "goal on collisions: 3" in lines  # a.seed_0, a.seed_3, b.seed_0
    assert "goal on collisions and progress and cte: 1" in lines  # a.seed_3
    assert "goal on progress and cte: 1" in lines
    # Within "a" (4 seeds), ranks of cte 4, 3, 1.5, 1.5 against collisions 1.5, 3, 4, 1.5:
    # Pearson of the ranks -1.75 / 4.5.
    assert "Spearman below 0 in 1 of 1 configurations (mean -0.39" in lines[-1]


def test_a_different_run_of_the_same_name_is_its_own_configuration(tmp_path):
    first = make_study(tmp_path / "one", {"a.seed_0": SEEDS_OF_A["a.seed_0"]})
    second = make_study(tmp_path / "two", {"a.seed_0": SEEDS_OF_A["a.seed_1"]})
    result = seed_front(first, second, "--out", tmp_path / "front.csv")
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "front.csv", newline="") as file:
        configs = [row["config"] for row in csv.DictReader(file)]
    assert configs == ["a", "a (two)"]


def test_an_evaluate_folder_is_read_without_training_steps(tmp_path):
    study = make_study(tmp_path / "study", {"a.seed_0": SEEDS_OF_A["a.seed_0"]},
                       {"a": 3000000})
    # An evaluate --out folder: episodes.csv at its top, no summary.json.
    evaluation = make_study(tmp_path / "eval_out", {"d.seed_0": SEEDS_OF_A["a.seed_3"]})
    (evaluation / "eval" / "study" / "episodes.csv").rename(evaluation / "episodes.csv")
    (evaluation / "summary.json").unlink()
    result = seed_front(study, evaluation, "--out", tmp_path / "front.csv")
    assert result.returncode == 0, result.stderr
    agents = rows(tmp_path / "front.csv")
    student = agents["d.seed_0"]
    assert (student["study"], student["config"], student["seed"], student["steps"]) == \
        ("eval_out", "d", "0", "")
    assert float(student["progress"]) == 99.0
    assert agents["a.seed_0"]["steps"] == "3000000"
    assert "goal on collisions and progress and cte: 1" in result.stdout.splitlines()


def test_studies_that_do_not_fit_are_refused_in_one_line(tmp_path):
    one = make_study(tmp_path / "one", {"a.seed_0": SEEDS_OF_A["a.seed_0"]})
    other = make_study(tmp_path / "other", {"a.seed_1": SEEDS_OF_A["a.seed_1"]},
                       scenarios=("test-000", "test-002"))
    out = tmp_path / "front.csv"
    cases = [
        ((one, other), f"{other}/eval/study/episodes.csv: 'a.seed_1' played other scenarios"),
        ((one, tmp_path / "missing"), f"{tmp_path}/missing/eval/study/episodes.csv: No such file"),
    ]
    broken = make_study(tmp_path / "broken", {"a.seed_0": [(0.9, "x", 0, 0), (0.9, 1, 0, 0)]})
    cases.append(((broken,), f"{broken}/eval/study/episodes.csv: a value of 'a.seed_0' is not"))
    (tmp_path / "bad_json").mkdir()
    make_study(tmp_path / "bad_json" / "s", {"a.seed_0": SEEDS_OF_A["a.seed_0"]})
    (tmp_path / "bad_json" / "s" / "summary.json").write_text("{")
    cases.append(((tmp_path / "bad_json" / "s",), "summary.json: not JSON"))
    for studies, message in cases:
        result = seed_front(*studies, "--out", out)
        assert result.returncode == 2, result.stdout
        assert len(result.stderr.splitlines()) == 1
        assert message in result.stderr
    assert not out.exists()

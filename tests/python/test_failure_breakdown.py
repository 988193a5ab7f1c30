"""scripts/failure_breakdown.py: the progress lost and the cross-track error split by how the
episodes ended, on a hand-made episodes.csv, and one-line refusals of files that do not fit."""

import subprocess

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "failure_breakdown.py"
HEADER = "model,scenario,seed,progress,mean_cte,steps,collision,goal,truncated,reward,path_length\n"


def breakdown(path):
    return subprocess.run(["/usr/bin/python3", str(SCRIPT), str(path)], capture_output=True,
                          text=True)


def write_episodes(path, rows):
    path.write_text(HEADER + "".join(
        f"{model},{scenario},0,{progress},{cte},100,{collision},{goal},{truncated},0,500\n"
        for model, scenario, progress, cte, collision, goal, truncated in rows))


def test_seeds_pool_and_the_parts_add_up(tmp_path):
    # Config a, two seeds, 2 scenarios: a collision at 40 %, a time-out at 20 % on t-1 in both
    # seeds, a goal at 99 %. ref completes t-1.
    write_episodes(tmp_path / "episodes.csv", [
        ("a.seed_0", "t-0", 0.4, 10, 1, 0, 0),
        ("a.seed_0", "t-1", 0.2, 50, 0, 0, 1),
        ("a.seed_1", "t-0", 0.99, 20, 0, 1, 0),
        ("a.seed_1", "t-1", 0.2, 30, 0, 0, 1),
        ("ref", "t-0", 0.99, 20, 0, 1, 0),
        ("ref", "t-1", 0.99, 20, 0, 1, 0),
    ])
    result = breakdown(tmp_path / "episodes.csv")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    # progress (0.4 + 0.2 + 0.99 + 0.2) / 4 = 44.75 %; lost: collision 60/4 = 15 points,
    # time-outs 160/4 = 40 points, the rest 1/4 = 0.25 points.
    assert "| a | 2 | 44.8 | 15.00 (25.0, 40) | 40.00 (50.0, 20) | 0.25 (25.0) |" in lines
    assert "| ref | 1 | 99.0 | 0.00 (0.0, -) | 0.00 (0.0, -) | 1.00 (100.0) |" in lines
    # cte (10 + 50 + 20 + 30) / 4 = 27.5 m: collisions 2.5, time-outs 20, the rest 5; the one
    # scenario with time-outs times out in both seeds and ref completes it.
    assert "| a | 27.5 | 2.5 | 20.0 | 5.0 | 1 | 1 | 1 |" in lines


def test_refuses_a_file_without_the_columns_in_one_line(tmp_path):
    (tmp_path / "other.csv").write_text("model,progress\nx,0.5\n")
    result = breakdown(tmp_path / "other.csv")
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "other.csv: no column scenario" in result.stderr
    result = breakdown(tmp_path / "missing.csv")
    assert result.returncode == 2 and "missing.csv" in result.stderr

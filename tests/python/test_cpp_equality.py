"""Python gives what the programs give: a scenario file or training world stepped from Python
writes the trace `simulate` writes, byte for byte, and a policy run from Python scores the metrics
`evaluate` records."""

import csv
import importlib.util

import numpy as np
import pytest
import torch

import colav
from conftest import GOLDEN_DIR, SCENARIO_FILES, SOURCE_DIR, run_program

GOLDEN_CASES = sorted((GOLDEN_DIR / "visible").glob("*.scenario.yaml"))


def range_text(distance):
    """As env/trace.cpp prints a range: at most 4 decimals, trailing zeros stripped."""
    return ("%.4f" % distance).rstrip("0").rstrip(".")


def trace_row(step, state, reward=0.0, terminated=False, truncated=False):
    """One row of a `simulate` trace (env/trace.cpp) from Env.state() and the step's result."""
    numbers = [*state["vessel"], state["cross_track_error"], state["heading_error"],
               state["look_ahead_heading_error"], state["progress"], reward]
    flags = [terminated, truncated, state["collision"]]
    return ",".join([str(step)] + ["%.12g" % x for x in numbers] + [str(int(f)) for f in flags]
                    + [range_text(r) for r in state["ranges"]])


def python_trace(env, actions):
    """The rows of `simulate`'s trace of env's first episode under actions, from Python."""
    env.reset()
    rows = [trace_row(0, env.state())]
    for step, action in enumerate(actions, start=1):
        _, reward, terminated, truncated, _ = env.step(action)
        rows.append(trace_row(step, env.state(), reward, terminated, truncated))
        if terminated or truncated:
            break
    return rows


def read_actions(path):
    with open(path, encoding="utf-8") as file:
        return [[float(a0), float(a1)] for a0, a1 in list(csv.reader(file))[1:]]


def write_random_actions(path, seed):
    """300 random actions, mostly ahead, as an actions file at path."""
    rng = np.random.default_rng(seed)
    rows = ["%.6f,%.6f" % (a0, a1) for a0, a1 in rng.uniform(-0.2, 1.0, size=(300, 2))]
    path.write_text("a0,a1\n" + "\n".join(rows) + "\n")
    return path


def assert_same_trace_as_simulate(env, world_arguments, actions_file, tmp_path):
    """env's first episode under the actions of actions_file is the trace `simulate` writes for
    the world its world_arguments name (--scenario FILE or --training-seed S)."""
    trace_file = tmp_path / "trace.csv"
    run_program("simulate", *world_arguments, "--actions", actions_file, "--out", trace_file)
    expected = trace_file.read_text().splitlines()
    actual = python_trace(env, read_actions(actions_file))
    assert len(actual) == len(expected) - 1  # simulate also writes the header
    for row, (mine, theirs) in enumerate(zip(actual, expected[1:])):
        assert mine == theirs, f"row {row} differs"


def assert_same_scenario_trace_as_simulate(scenario_file, actions_file, tmp_path):
    assert_same_trace_as_simulate(colav.make(scenario=scenario_file),
                                  ["--scenario", scenario_file], actions_file, tmp_path)


@pytest.mark.skipif(not GOLDEN_CASES, reason=f"no golden cases in {GOLDEN_DIR}")
@pytest.mark.parametrize("scenario_file", GOLDEN_CASES, ids=lambda p: p.name.split(".")[0])
def test_golden_case_from_python_is_the_simulate_trace(scenario_file, tmp_path):
    actions_file = scenario_file.with_name(scenario_file.name.replace(".scenario.yaml",
                                                                      ".actions.csv"))
    assert_same_scenario_trace_as_simulate(scenario_file, actions_file, tmp_path)


@pytest.mark.parametrize("scenario_file", SCENARIO_FILES, ids=lambda p: p.stem)
def test_scenario_file_from_python_is_the_simulate_trace(scenario_file, tmp_path):
    actions_file = write_random_actions(tmp_path / "actions.csv", len(scenario_file.stem))
    assert_same_scenario_trace_as_simulate(scenario_file, actions_file, tmp_path)


def test_training_world_from_python_is_the_simulate_trace(tmp_path):
    """Without `world`, colav.make(seed=6) plays the paper's training worlds: its first episode is
    the training world `simulate --training-seed` builds for that episode's seed."""
    actions_file = write_random_actions(tmp_path / "actions.csv", 5)
    assert_same_trace_as_simulate(colav.make(seed=6),
                                  ["--training-seed", colav.training_episode_seed(6, 0, 0)],
                                  actions_file, tmp_path)


class TinyPolicy(torch.nn.Module):
    """A policy.pt as train_ppo writes one (forward: obs [B, observation_size] -> action [B, 2] in
    [-1, 1]), with fixed random weights and a bias towards full thrust."""

    def __init__(self, observation_size):
        super().__init__()
        torch.manual_seed(0)
        self.hidden = torch.nn.Linear(observation_size, 16)
        self.out = torch.nn.Linear(16, 2)
        with torch.no_grad():
            self.out.bias[0] = 2.0

    def forward(self, obs):
        return torch.tanh(self.out(torch.tanh(self.hidden(obs))))


# evaluate's sidecar of each policy, and the observation size it implies: the paper's observation,
# and one with two earlier scans 5 steps apart (env.scan_history).
POLICY_SETTINGS = {
    "current_scan": ("env:\n  closeness: log\n", 186),
    "scan_history": ("env:\n  closeness: log\n  scan_history: 2\n  scan_history_interval: 5\n",
                     546),
}


@pytest.fixture(scope="module", params=sorted(POLICY_SETTINGS))
def policy_file(request, tmp_path_factory):
    sidecar, observation_size = POLICY_SETTINGS[request.param]
    path = tmp_path_factory.mktemp("policy") / "policy.pt"
    torch.jit.script(TinyPolicy(observation_size)).save(str(path))
    (path.parent / "policy.pt.yaml").write_text(sidecar)
    return path


def run_policy_example():
    spec = importlib.util.spec_from_file_location(
        "run_policy", SOURCE_DIR / "python" / "examples" / "run_policy.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def evaluate_episodes(policy_file, out, *arguments):
    run_program("evaluate", "--policy", policy_file, "--trajectories", 0, "--threads", 2,
                "--out", out, *arguments)
    with open(out / "episodes.csv", encoding="utf-8") as file:
        return list(csv.DictReader(file))


def python_episodes(policy_file, scenarios):
    policy = colav.Policy(policy_file)
    assert policy.observation_settings["closeness"] == "log"
    envs = colav.make_vec(scenarios=scenarios, test_mode=True, **policy.observation_settings)
    assert envs.single_observation_space.shape == (policy.module.hidden.weight.shape[1],)
    return run_policy_example().run_episodes(policy, envs)


def assert_same_metrics(python, evaluate):
    assert len(python) == len(evaluate)
    columns = {"progress": "progress", "mean_abs_cte": "mean_cte", "steps": "steps",
               "collision": "collision", "goal_reached": "goal", "truncated": "truncated",
               "cumulative_reward": "reward", "path_length": "path_length"}
    for mine, theirs in zip(python, evaluate):
        for key, column in columns.items():
            assert float(mine[key]) == float(theirs[column]), f"{theirs['scenario']}: {key}"


def test_policy_from_python_scores_evaluate_metrics_on_test_scenarios(policy_file, tmp_path):
    evaluate = evaluate_episodes(policy_file, tmp_path / "eval", "--episodes", 6, "--seed", 3)
    assert [int(row["seed"]) for row in evaluate] == colav.evaluation_scenario_seeds(6, seed=3)
    assert_same_metrics(python_episodes(policy_file, colav.evaluation_scenarios(6, seed=3)),
                        evaluate)


def test_policy_from_python_scores_evaluate_metrics_on_scenario_files(policy_file, tmp_path):
    files = [arg for path in SCENARIO_FILES for arg in ("--scenario", path)]
    evaluate = evaluate_episodes(policy_file, tmp_path / "eval", *files)
    assert_same_metrics(python_episodes(policy_file, SCENARIO_FILES), evaluate)

"""Every example in python/examples/ runs (quickly, with small arguments)."""

import os
import subprocess
import sys

import pytest
import torch

from conftest import SCENARIO_FILES, SOURCE_DIR, RecurrentPolicyStandIn

EXAMPLES = SOURCE_DIR / "python" / "examples"


def run_example(name, *args):
    result = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, args)],
                            capture_output=True, text=True, env=dict(os.environ))
    assert result.returncode == 0, f"{name} failed:\n{result.stdout}\n{result.stderr}"
    return result.stdout


def test_every_example_is_tested():
    tested = {"random_agent.py", "run_policy.py", "scenario_file.py", "bench_python.py"}
    assert {path.name for path in EXAMPLES.glob("*.py")} == tested


def test_random_agent():
    assert "episodes ended" in run_example("random_agent.py", "--steps", 600, "--envs", 4)


@pytest.mark.parametrize("scenario_file", SCENARIO_FILES[:2], ids=lambda p: p.stem)
def test_scenario_file(scenario_file):
    assert "progress" in run_example("scenario_file.py", scenario_file)


def test_run_policy(tmp_path):
    policy = torch.jit.script(torch.nn.Sequential(torch.nn.Linear(186, 2), torch.nn.Tanh()))
    policy.save(str(tmp_path / "policy.pt"))
    output = run_example("run_policy.py", tmp_path / "policy.pt", "--episodes", 3)
    assert "over 3 episodes" in output and "collisions %" in output
    output = run_example("run_policy.py", tmp_path / "policy.pt", "--scenario", SCENARIO_FILES[0])
    assert "over 1 episodes (scenario files" in output


class CountingPolicy(RecurrentPolicyStandIn):
    """A recurrent policy: full surge, and full rudder for the first 5 steps of each episode,
    which only the state counts."""

    @torch.jit.export
    def step(self, obs, state):
        rudder = (state < 5).float()
        return torch.cat([torch.ones_like(rudder), rudder], 1), state + 1


def test_run_policy_steps_a_recurrent_policy_from_each_episodes_state(tmp_path):
    torch.jit.script(CountingPolicy()).save(str(tmp_path / "policy.pt"))
    output = run_example("run_policy.py", tmp_path / "policy.pt", "--episodes", 3)
    steps = float(output.split("duration (steps)")[1].split()[0])  # the mean over 3 episodes
    rudder = float(output.split("rudder ")[1].split()[0])
    # 5 steps at the limit in each episode: a state shared or not restarted would give others.
    assert abs(rudder - 100.0 * 5 / steps) < 0.05, output


class ConstantPolicy(torch.nn.Module):
    """Full surge, half rudder, whatever it sees; a training log_std as train_ppo's files have."""

    def __init__(self):
        super().__init__()
        self.log_std = torch.nn.Parameter(torch.log(torch.tensor([2.0, 0.5])))

    def forward(self, obs):
        return torch.tensor([[1.0, 0.5]]).expand(obs.shape[0], 2)


def test_run_policy_reports_actions_at_the_limits_and_the_training_std(tmp_path):
    torch.jit.script(ConstantPolicy()).save(str(tmp_path / "policy.pt"))
    output = run_example("run_policy.py", tmp_path / "policy.pt", "--episodes", 2)
    assert "actions at a limit %    surge 100.0, rudder 0.0" in output
    assert "training std            2, 0.5 (surge, rudder)" in output


class HistoryPolicy(torch.nn.Module):
    """A policy.pt trained with a scan history: it records its observation settings, as
    train_ppo's files do, and only takes observations of their size."""

    observation_settings: str

    def __init__(self):
        super().__init__()
        self.observation_settings = (
            "env:\n  closeness: log\n  scan_history: 3\n  scan_history_interval: 5\n")
        self.linear = torch.nn.Linear(6 + 180 * 4, 2)

    def forward(self, obs):
        return torch.tanh(self.linear(obs))


def test_run_policy_builds_the_env_of_the_recorded_observation_settings(tmp_path):
    torch.jit.script(HistoryPolicy()).save(str(tmp_path / "policy.pt"))
    output = run_example("run_policy.py", tmp_path / "policy.pt", "--episodes", 2)
    assert "'closeness': 'log', 'scan_history': 3, 'scan_history_interval': 5" in output


def test_bench_python(tmp_path):
    assert "random actions" in run_example("bench_python.py", "--seconds", 0.2, "--envs", 2)
    policy = torch.jit.script(torch.nn.Sequential(torch.nn.Linear(186, 2), torch.nn.Tanh()))
    policy.save(str(tmp_path / "policy.pt"))
    output = run_example("bench_python.py", "--seconds", 0.2, "--envs", 4, "--batch", 2,
                         "--policy", tmp_path / "policy.pt")
    assert "asynchronous batches of 2), policy actions:" in output and "steps/s" in output

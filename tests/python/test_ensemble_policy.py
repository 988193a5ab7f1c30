"""ensemble_policy (eval/policy_ensemble.h): one policy file acting with the mean of its members'
actions, memoryless and recurrent members side by side, loaded by Python's torch.jit and
colav.Policy, run by evaluate, and one-line refusals."""

import subprocess
from typing import Tuple

import numpy as np
import torch
from torch import Tensor

import colav
from conftest import BIN_DIR

PROGRAM = BIN_DIR / "ensemble_policy"
LOG_SETTINGS = "env:\n  closeness: log\n"
OBSERVATION_SIZE = 186


class Memoryless(torch.nn.Module):
    """tanh of a fixed linear map of the observation: a bounded action that depends on it."""

    def __init__(self, seed, settings=LOG_SETTINGS):
        super().__init__()
        generator = torch.Generator().manual_seed(seed)
        self.weight = torch.nn.Parameter(torch.randn(OBSERVATION_SIZE, 2, generator=generator))
        self.observation_settings: str = settings

    def forward(self, obs: Tensor) -> Tensor:
        return torch.tanh(obs @ self.weight)


class Recurrent(torch.nn.Module):
    """A memory of `size` values that sums the observation's first values; the action reads it."""

    def __init__(self, seed, size):
        super().__init__()
        generator = torch.Generator().manual_seed(seed)
        self.weight = torch.nn.Parameter(torch.randn(size, 2, generator=generator))
        self.recurrent_size: int = size
        self.observation_settings: str = LOG_SETTINGS

    @torch.jit.export
    def initial_state(self, batch: int) -> Tensor:
        return torch.zeros([batch, self.recurrent_size])

    @torch.jit.export
    def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:
        next_state = state + obs[:, :self.recurrent_size]
        return torch.tanh(next_state @ self.weight), next_state

    def forward(self, obs: Tensor) -> Tensor:
        assert False, "recurrent policy: call step(obs, state) starting from initial_state(B)"
        return obs


def save(module, path):
    torch.jit.script(module).save(str(path))
    return path


def ensemble(*args):
    return subprocess.run([str(PROGRAM), *map(str, args)],
                          capture_output=True, text=True)


def test_memoryless_members_average_their_actions(tmp_path):
    members = [save(Memoryless(seed), tmp_path / f"m{seed}.pt") for seed in (1, 2, 3)]
    result = ensemble("--out", tmp_path / "ensemble.pt", *members)
    assert result.returncode == 0, result.stderr
    loaded = torch.jit.load(str(tmp_path / "ensemble.pt"))
    obs = torch.rand(4, OBSERVATION_SIZE, generator=torch.Generator().manual_seed(4))
    expected = torch.stack([torch.jit.load(str(m))(obs) for m in members]).mean(0)
    assert torch.allclose(loaded(obs), expected)
    assert not hasattr(loaded, "recurrent_size")
    assert loaded.observation_settings == LOG_SETTINGS
    assert loaded.member_paths.splitlines() == [str(m) for m in members]


def test_recurrent_members_step_their_own_slices_of_the_state(tmp_path):
    plain = save(Memoryless(1), tmp_path / "plain.pt")
    small = save(Recurrent(2, 2), tmp_path / "small.pt")
    large = save(Recurrent(3, 3), tmp_path / "large.pt")
    result = ensemble("--out", tmp_path / "ensemble.pt", small, plain, large)
    assert result.returncode == 0, result.stderr
    loaded = torch.jit.load(str(tmp_path / "ensemble.pt"))
    assert loaded.recurrent_size == 5
    state = loaded.initial_state(3)
    assert torch.equal(state, torch.zeros(3, 5))
    members = [torch.jit.load(str(path)) for path in (small, plain, large)]
    small_state, large_state = torch.zeros(3, 2), torch.zeros(3, 3)
    draws = torch.Generator().manual_seed(5)
    for _ in range(3):  # the memories carry over: a misplaced slice shows by the second step
        obs = torch.rand(3, OBSERVATION_SIZE, generator=draws)
        action, state = loaded.step(obs, state)
        small_action, small_state = members[0].step(obs, small_state)
        large_action, large_state = members[2].step(obs, large_state)
        expected = torch.stack([members[1](obs), small_action, large_action]).mean(0)
        assert torch.allclose(action, expected)
        assert torch.equal(state, torch.cat([small_state, large_state], 1))


def test_evaluate_and_colav_run_a_recurrent_ensemble(tmp_path):
    members = [save(Memoryless(1), tmp_path / "plain.pt"), save(Recurrent(2, 2), tmp_path / "r.pt")]
    assert ensemble("--out", tmp_path / "ensemble.pt", *members).returncode == 0
    policy = colav.Policy(tmp_path / "ensemble.pt")
    assert policy.recurrent_size == 2 and policy.observation_settings == {"closeness": "log"}
    actions = policy.act(np.random.default_rng(0).random((3, OBSERVATION_SIZE)), np.ones(3, bool))
    assert actions.shape == (3, 2) and np.all(np.abs(actions) <= 1.0)
    result = subprocess.run([str(BIN_DIR / "evaluate"), "--policy", str(tmp_path / "ensemble.pt"),
                             "--episodes", "2", "--trajectories", "0", "--threads", "1",
                             "--out", str(tmp_path / "eval")], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "eval" / "episodes.csv").read_text().count("\n") == 3  # header + 2


def test_colav_policy_reads_the_stall_rules_count(tmp_path):
    members = [save(Recurrent(2, 2), tmp_path / "r.pt"), save(Memoryless(1), tmp_path / "a.pt"),
               save(Memoryless(2), tmp_path / "b.pt")]
    assert ensemble("--out", tmp_path / "plain.pt", *members).returncode == 0
    plain = colav.Policy(tmp_path / "plain.pt")
    plain.act(np.zeros((2, OBSERVATION_SIZE), np.float32))
    assert not plain.has_stall_rule and plain.stalls is None and plain.pace is None
    assert ensemble("--out", tmp_path / "ruled.pt", "--stall-pace", 0.1, "--stall-steps", 2,
                    *members).returncode == 0
    policy = colav.Policy(tmp_path / "ruled.pt")
    assert policy.has_stall_rule and policy.stalls is None and policy.pace is None
    # World 0 makes no way (surge 0), world 1 cruises at 1 m/s on course (heading error 0).
    obs = np.random.default_rng(0).random((2, OBSERVATION_SIZE)).astype(np.float32)
    obs[:, 0], obs[:, 4] = [0.0, 1.0], 0.0
    # The pace halves each step from 0.5 (2 steps' average) and stalls below 0.1 on the third
    # step, restarting at 0.5; the count stops at the reliefs' number, 2.
    counts, paces = [], []
    for _ in range(7):
        policy.act(obs)
        counts.append(policy.stalls.tolist())
        paces.append(policy.pace.tolist())
    assert counts == [[0, 0], [0, 0], [1, 0], [1, 0], [1, 0], [2, 0], [2, 0]]
    # World 1's average goes half way to 1 m/s each step.
    np.testing.assert_allclose(paces, [[0.25, 0.75], [0.125, 0.875], [0.5, 0.9375],
                                       [0.25, 0.96875], [0.125, 0.984375], [0.5, 0.9921875],
                                       [0.25, 0.99609375]])
    policy.act(obs, np.array([True, False]))
    assert policy.stalls.tolist() == [0, 0]


def test_bad_input_is_one_line_naming_it(tmp_path):
    log = save(Memoryless(1), tmp_path / "log.pt")
    linear = save(Memoryless(2, "env:\n  closeness: linear\n"), tmp_path / "linear.pt")
    (tmp_path / "garbage.pt").write_text("not a model")
    bare = Memoryless(3)
    del bare.observation_settings
    unrecorded = save(bare, tmp_path / "unrecorded.pt")
    cases = {
        (log, linear): "linear.pt: observation settings differ from those of",
        (log, tmp_path / "missing.pt"): "missing.pt: no such policy file",
        (log, tmp_path / "garbage.pt"): "garbage.pt: not a TorchScript policy",
        (log, unrecorded): "unrecorded.pt: no observation settings",
        (log,): "an ensemble needs at least two policies",
    }
    for members, message in cases.items():
        result = ensemble("--out", tmp_path / "out.pt", *members)
        assert result.returncode == 2, (members, result.stderr)
        assert len(result.stderr.splitlines()) == 1 and message in result.stderr, result.stderr
        assert not (tmp_path / "out.pt").exists()
    # The sidecar <policy>.yaml stands in for a record, as for the authors' agents.
    (tmp_path / "unrecorded.pt.yaml").write_text(LOG_SETTINGS)
    assert ensemble("--out", tmp_path / "out.pt", log, unrecorded).returncode == 0

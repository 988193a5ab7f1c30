"""colav.Policy: a policy.pt's observation settings, its deterministic actions, and a recurrent
policy's memory per world, restarted where an episode starts."""

import numpy as np
import pytest
import torch

import colav
from conftest import RecurrentPolicyStandIn


class CountingPolicy(RecurrentPolicyStandIn):
    """A recurrent policy whose action is the number of steps its memory has seen (surge) and the
    observation's first value (rudder)."""

    @torch.jit.export
    def step(self, obs, state):
        state = state + 1
        return torch.cat([state, obs[:, :1]], 1), state


class HistoryPolicy(torch.nn.Module):
    """A memoryless policy.pt that records its observation settings, as train_ppo's files do."""

    observation_settings: str

    def __init__(self):
        super().__init__()
        self.observation_settings = (
            "env:\n  closeness: log\n  scan_history: 3\n  scan_history_interval: 5\n")

    def forward(self, obs):
        return obs[:, :2] * 2


def save(module, path):
    torch.jit.script(module).save(str(path))
    return path


def observations(worlds):
    """obs [worlds, 186] whose first value is the world's index."""
    obs = np.zeros((worlds, colav.OBSERVATION_SIZE), dtype=np.float32)
    obs[:, 0] = np.arange(worlds)
    return obs


def test_reads_the_observation_settings_from_the_file_or_its_sidecar(tmp_path):
    policy = colav.Policy(save(HistoryPolicy(), tmp_path / "history.pt"))
    assert policy.observation_settings == {
        "closeness": "log", "scan_history": 3, "scan_history_interval": 5}
    assert policy.recurrent_size == 0
    # The authors' agents: a sidecar <policy>.yaml; without either, no settings.
    sidecar = save(CountingPolicy(), tmp_path / "authors.pt")
    assert colav.Policy(sidecar).observation_settings == {}
    (tmp_path / "authors.pt.yaml").write_text("env:\n  closeness: log\n")
    assert colav.Policy(sidecar).observation_settings == {"closeness": "log"}


def test_memoryless_actions_of_chosen_worlds(tmp_path):
    policy = colav.Policy(save(HistoryPolicy(), tmp_path / "policy.pt"))
    obs = observations(4)
    np.testing.assert_array_equal(policy.act(obs)[:, 0], [0, 2, 4, 6])
    np.testing.assert_array_equal(policy.act(obs, worlds=[3])[:, 0], [6])  # one row: a batch of 2
    np.testing.assert_array_equal(policy.act(obs, worlds=[2, 0])[:, 0], [4, 0])


class ConvPolicy(torch.nn.Module):
    """A memoryless policy with a circular convolution over the scan, as the trained ones have:
    LibTorch runs one row through it with other rounding than a batch's."""

    def __init__(self):
        super().__init__()
        self.conv = torch.nn.Conv1d(1, 3, 45, padding=22, padding_mode="circular")
        self.head = torch.nn.Linear(6 + 3 * 180, 2)

    def forward(self, obs):
        scans = self.conv(obs[:, 6:].unsqueeze(1)).flatten(1)
        return self.head(torch.cat([obs[:, :6], scans], 1))


def test_one_world_acts_as_evaluate_acts_it(tmp_path):
    """evaluate runs single rows as batches of two, and so does Policy.act."""
    torch.manual_seed(0)
    conv = torch.jit.script(ConvPolicy())
    policy = colav.Policy(save(conv, tmp_path / "conv.pt"))
    obs = np.random.default_rng(0).random((3, colav.OBSERVATION_SIZE), dtype=np.float32)
    with torch.no_grad():
        single = conv(torch.from_numpy(obs[[1]])).numpy()
        pair = conv(torch.from_numpy(obs[[1, 1]])).numpy()[:1]
    assert not np.array_equal(single, pair)  # else this test could not fail
    np.testing.assert_array_equal(policy.act(obs, worlds=[1]), pair)


def test_a_recurrent_policy_keeps_one_memory_per_world(tmp_path):
    policy = colav.Policy(save(CountingPolicy(), tmp_path / "policy.pt"))
    assert policy.recurrent_size == 1
    obs = observations(3)
    np.testing.assert_array_equal(policy.act(obs), [[1, 0], [1, 1], [1, 2]])
    # Only the worlds stepped advance their memories.
    np.testing.assert_array_equal(policy.act(obs, worlds=[2]), [[2, 2]])
    np.testing.assert_array_equal(policy.act(obs, worlds=[0, 2]), [[2, 0], [3, 2]])
    # World 0 starts an episode: its memory restarts from 0, the others go on.
    starts = np.array([True, False, False])
    np.testing.assert_array_equal(policy.act(obs, starts)[:, 0], [1, 2, 4])


class CountingFromTen(CountingPolicy):
    """CountingPolicy whose memory starts at 10, as an ensemble's stall rule starts its pace at
    0.5 m/s rather than 0."""

    @torch.jit.export
    def initial_state(self, batch: int):
        return torch.full((batch, 1), 10.0)


def test_an_episode_start_restarts_the_memory_from_the_initial_state(tmp_path):
    policy = colav.Policy(save(CountingFromTen(), tmp_path / "policy.pt"))
    obs = observations(2)
    np.testing.assert_array_equal(policy.act(obs)[:, 0], [11, 11])
    np.testing.assert_array_equal(policy.act(obs)[:, 0], [12, 12])
    np.testing.assert_array_equal(policy.act(obs, np.array([False, True]))[:, 0], [13, 11])


def test_refuses_what_it_cannot_run(tmp_path):
    with pytest.raises(ValueError, match="missing.pt: no such policy file"):
        colav.Policy(tmp_path / "missing.pt")
    policy = colav.Policy(save(CountingPolicy(), tmp_path / "policy.pt"))
    policy.act(observations(3))
    with pytest.raises(ValueError, match="4 worlds, but the memories are of 3"):
        policy.act(observations(4))
    with pytest.raises(ValueError, match=r"episode_starts of shape \(2,\), not \(3,\)"):
        policy.act(observations(3), [True, False])
    with pytest.raises(ValueError, match=r"obs of shape \(186,\), not \[worlds, observation\]"):
        policy.act(observations(1)[0])

"""A trained policy (train_ppo's policy.pt, or the authors' agents in shared/reference-agents/)
driven from Python: the observation settings it was trained with, and its deterministic actions,
stepping a recurrent policy's memory from each episode's start. Needs PyTorch (imported here only,
so the simulator does not)."""

import os
import re

import numpy as np

# The env keys that decide what an observation means (env/observation_settings.h), and which of
# them are whole numbers.
OBSERVATION_KEYS = ("closeness", "scan_history", "scan_history_interval")
_INTEGER_KEYS = ("scan_history", "scan_history_interval")
# An ensemble's stall rule keeps two columns last in the state: the pace average, then the number
# of stalls so far (eval/policy_ensemble.cpp, kStallColumns).
STALL_COLUMNS = 2


def _observation_settings(path, module):
    """The settings found where evaluate looks: the file's `observation_settings` record, else the
    sidecar file "<policy>.yaml"; both hold "env:\\n  closeness: linear|log" and, with a scan
    history, "scan_history: H" and "scan_history_interval: S". {} when neither exists."""
    text = getattr(module, "observation_settings", None)
    if text is None and os.path.exists(f"{path}.yaml"):
        with open(f"{path}.yaml", encoding="utf-8") as sidecar:
            text = sidecar.read()
    settings = {}
    for key in OBSERVATION_KEYS:
        match = re.search(rf"^\s*{key}:\s*(\S+)", text or "", re.MULTILINE)
        if match:
            value = match.group(1)
            settings[key] = int(value) if key in _INTEGER_KEYS else value
    return settings


def _has_stall_rule(module, recurrent_size):
    """Whether `module` is an ensemble_policy file with a stall rule: its state holds the
    members' states and, last, the rule's STALL_COLUMNS (eval/policy_ensemble.h)."""
    paths = getattr(module, "member_paths", None)
    if paths is None:
        return False
    members = [getattr(module, f"member_{k}") for k in range(len(paths.splitlines()))]
    members_size = sum(int(getattr(member, "recurrent_size", 0)) for member in members)
    return recurrent_size == members_size + STALL_COLUMNS


class Policy:
    """A policy.pt with its observation settings and, for a recurrent one, one memory per world.

        policy = colav.Policy("runs/best/policy.pt")
        envs = colav.make_vec(scenarios=colav.evaluation_scenarios(100), test_mode=True,
                              **policy.observation_settings)
        obs, _ = envs.reset()
        starts = np.ones(envs.num_envs, dtype=bool)
        while ...:
            obs, reward, terminated, truncated, info = envs.step(policy.act(obs, starts))
            starts = terminated | truncated   # make_vec resets a world within its last step

    Attributes: `module` (the TorchScript module), `observation_settings` ({key: value} for
    make_vec: closeness, and scan_history and scan_history_interval when recorded; the authors'
    agents use their sidecar <policy>.yaml), `recurrent_size` (0: memoryless),
    `has_stall_rule` (an ensemble_policy file with --stall-pace), then `stalls` and `pace` (how
    often each world's vessel has stalled in its episode, and its pace average).
    """

    def __init__(self, path):
        import torch

        path = str(path)
        if not os.path.isfile(path):
            raise ValueError(f"{path}: no such policy file")
        self._torch = torch
        self.module = torch.jit.load(path)
        self.observation_settings = _observation_settings(path, self.module)
        self.recurrent_size = int(getattr(self.module, "recurrent_size", 0))
        self.has_stall_rule = _has_stall_rule(self.module, self.recurrent_size)
        self._states = None

    @property
    def stalls(self):
        """For an ensemble with a stall rule (ensemble_policy --stall-pace): each world's number
        of stalls so far in its episode, as its last `act` steered by (float [N], the state's
        last column, eval/policy_ensemble.h). None for any other policy, or before any `act`."""
        return self._stall_column(-1)

    @property
    def pace(self):
        """For an ensemble with a stall rule: each world's pace average (m/s) after its last
        `act`, restarted at each stall (float [N], the state's last column but one). None for
        any other policy, or before any `act`."""
        return self._stall_column(-2)

    def _stall_column(self, column):
        """A copy of the states' `column` for an ensemble with a stall rule, else None."""
        if not self.has_stall_rule or self._states is None:
            return None
        return self._states[:, column].numpy().copy()

    def act(self, obs, episode_starts=None, worlds=None):
        """Deterministic actions float32 [len(worlds), 2] for the rows `worlds` of obs [N, n]
        (default: every row). A recurrent policy steps the memory of each of these worlds and
        keeps the state after; `episode_starts` (bool [N], as SB3's RecurrentPPO takes) marks the
        worlds whose observation starts an episode, whose memory restarts from the module's
        initial_state (zeros for train_ppo's memories; an ensemble's stall rule starts its pace at
        0.5 m/s). The memories are created so by the first call, for N worlds; a memoryless
        policy ignores both."""
        obs = np.asarray(obs, dtype=np.float32)
        if obs.ndim != 2:
            raise ValueError(f"Policy.act: obs of shape {obs.shape}, not [worlds, observation]")
        rows = np.arange(len(obs)) if worlds is None else np.asarray(worlds, dtype=np.int64)
        # The exported policies run batches of at least two rows (evaluate does the same).
        batch = rows if len(rows) > 1 else np.repeat(rows, 2)
        torch = self._torch
        with torch.no_grad():
            if self.recurrent_size == 0:
                return self.module(torch.from_numpy(obs[batch])).numpy()[: len(rows)]
            self._restart_memories(len(obs), episode_starts)
            actions, states = self.module.step(torch.from_numpy(obs[batch]), self._states[batch])
            self._states[rows] = states[: len(rows)]
            return actions.numpy()[: len(rows)]

    def _restart_memories(self, worlds, episode_starts):
        if self._states is None:
            self._states = self.module.initial_state(worlds)
        if len(self._states) != worlds:
            raise ValueError(f"Policy.act: {worlds} worlds, but the memories are of "
                             f"{len(self._states)} (the first call's); make a new Policy")
        if episode_starts is None:
            return
        starts = np.asarray(episode_starts, dtype=bool)
        if starts.shape != (worlds,):
            raise ValueError(f"Policy.act: episode_starts of shape {starts.shape}, not ({worlds},)")
        restarting = np.flatnonzero(starts)
        if len(restarting):
            self._states[restarting] = self.module.initial_state(len(restarting))

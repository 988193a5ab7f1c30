#!/usr/bin/python3
"""One policy file that acts with the mean of several trained policies' deterministic actions.

Agents trained from different seeds fail in different scenarios (README, "Ensembles of
seeds"); averaging their actions keeps what most of them do. The members may be memoryless or
recurrent (policy.recurrent_size), and of different recipes, but must share their observation
settings (recorded in the file, models/observation_settings_record.h, else in the sidecar
<policy>.yaml).

    /usr/bin/python3 scripts/ensemble_policy.py --out ensemble.pt POLICY.pt POLICY.pt...

The output is TorchScript with the interface of a trained policy.pt (models/policy_export.h), so
`evaluate`, `study` (as a reference agent) and colav.Policy run it: with only memoryless members,
forward(obs) -> action [B, 2]; with a recurrent member, recurrent_size (the members' state sizes
summed), initial_state(B) and step(obs, state) -> (action, next state), each recurrent member
stepping its own slice of the state. Attributes: observation_settings (the members'), member_paths
(their paths, one per line). Written through a temporary file, so an interrupted run leaves no
partial file. Bad input: one line naming the file, exit status 2.
"""

import argparse
import os
import sys
from typing import List, Tuple

import torch
from torch import Tensor

SETTINGS_ATTRIBUTE = "observation_settings"


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"ensemble_policy: error: {message}", file=sys.stderr)
    sys.exit(2)


class MemorylessEnsemble(torch.nn.Module):
    """The mean of the members' forward(obs)."""

    def __init__(self, members, settings, paths):
        super().__init__()
        self.members = torch.nn.ModuleList(members)
        self.observation_settings: str = settings
        self.member_paths: str = paths

    def forward(self, obs: Tensor) -> Tensor:
        actions: List[Tensor] = []
        for member in self.members:
            actions.append(member(obs))
        return torch.stack(actions).mean(0)


class RecurrentEnsemble(torch.nn.Module):
    """The mean of the memoryless members' forward(obs) and the recurrent members' step(obs,
    state); the state is the recurrent members' states side by side, in their order."""

    def __init__(self, memoryless, recurrent, settings, paths):
        super().__init__()
        self.memoryless = torch.nn.ModuleList(memoryless)
        self.recurrent = torch.nn.ModuleList(recurrent)
        self.state_sizes: List[int] = [int(member.recurrent_size) for member in recurrent]
        self.recurrent_size: int = sum(self.state_sizes)
        self.observation_settings: str = settings
        self.member_paths: str = paths

    @torch.jit.export
    def initial_state(self, batch: int) -> Tensor:
        return torch.zeros([batch, self.recurrent_size])

    @torch.jit.export
    def step(self, obs: Tensor, state: Tensor) -> Tuple[Tensor, Tensor]:
        assert state.dim() == 2 and state.size(0) == obs.size(0) and \
            state.size(1) == self.recurrent_size, \
            "policy: states [B, recurrent_size] expected (initial_state(B) at an episode start)"
        actions: List[Tensor] = []
        next_states: List[Tensor] = []
        for member in self.memoryless:
            actions.append(member(obs))
        start = 0
        index = 0
        for member in self.recurrent:
            size = self.state_sizes[index]
            action, next_state = member.step(obs, state[:, start:start + size])
            actions.append(action)
            next_states.append(next_state)
            start += size
            index += 1
        return torch.stack(actions).mean(0), torch.cat(next_states, 1)

    def forward(self, obs: Tensor) -> Tensor:
        assert False, "recurrent policy: call step(obs, state) starting from initial_state(B)"
        return obs


def load_member(path):
    """(module, observation settings text) of one policy file."""
    try:
        module = torch.jit.load(path)
    except (RuntimeError, ValueError, OSError) as error:
        fail(f"{path}: not a TorchScript policy ({str(error).splitlines()[0]})")
    if hasattr(module, SETTINGS_ATTRIBUTE):
        return module, str(getattr(module, SETTINGS_ATTRIBUTE))
    sidecar = path + ".yaml"
    try:
        with open(sidecar) as file:
            return module, file.read()
    except OSError:
        fail(f"{path}: no observation settings (neither recorded in the file nor in {sidecar})")


def build(paths):
    """The scripted ensemble of the policy files `paths`."""
    members, settings = [], None
    for path in paths:
        module, member_settings = load_member(path)
        if settings is not None and member_settings != settings:
            fail(f"{path}: observation settings differ from those of {paths[0]}")
        settings = member_settings
        members.append(module)
    memoryless, recurrent = [], []
    for member in members:
        (recurrent if int(getattr(member, "recurrent_size", 0)) > 0 else memoryless).append(member)
    listing = "\n".join(os.path.abspath(path) for path in paths)
    if recurrent:
        return torch.jit.script(RecurrentEnsemble(memoryless, recurrent, settings, listing))
    return torch.jit.script(MemorylessEnsemble(memoryless, settings, listing))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("policies", nargs="+", help="trained policy files (TorchScript)")
    parser.add_argument("--out", required=True, help="the ensemble's policy file")
    args = parser.parse_args()
    if len(args.policies) < 2:
        fail("an ensemble needs at least two policies")
    for path in args.policies:
        if not os.path.isfile(path):
            fail(f"{path}: no such file")
    if os.path.abspath(args.out) in map(os.path.abspath, args.policies):
        fail(f"--out {args.out}: is one of the members")
    ensemble = build(args.policies)
    temporary = args.out + ".partial"
    try:
        ensemble.save(temporary)
        os.replace(temporary, args.out)
    except (OSError, RuntimeError) as error:
        fail(f"--out {args.out}: {str(error).splitlines()[0]}")
    print(f"ensemble_policy: {args.out}: {len(args.policies)} members")


if __name__ == "__main__":
    main()

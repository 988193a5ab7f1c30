"""Writes a TorchScript policy that always goes full thrust ahead, and its sidecar (linear
closeness), for the end-to-end tests of evaluate.

usage: full_thrust_policy.py OUT.pt
"""
import sys

import torch


class FullThrust(torch.nn.Module):
    def forward(self, obs: torch.Tensor) -> torch.Tensor:
        return torch.tensor([1.0, 0.0]).expand(obs.shape[0], 2).contiguous()


torch.jit.script(FullThrust()).save(sys.argv[1])
with open(sys.argv[1] + ".yaml", "w") as sidecar:
    sidecar.write("env:\n  closeness: linear\n")

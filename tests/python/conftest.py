"""Shared fixtures and stand-ins of the Python tests. CTest (tests/CMakeLists.txt) sets
PYTHONPATH to the build's python folder and COLAV_BIN_DIR, COLAV_SOURCE_DIR, COLAV_GOLDEN_DIR."""

import os
import pathlib
import subprocess

import pytest
import torch

SOURCE_DIR = pathlib.Path(os.environ.get("COLAV_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
BIN_DIR = pathlib.Path(os.environ.get("COLAV_BIN_DIR", SOURCE_DIR / "build" / "bin"))
GOLDEN_DIR = pathlib.Path(os.environ.get("COLAV_GOLDEN_DIR",
                                          SOURCE_DIR.parent / "shared" / "golden"))
SCENARIO_FILES = sorted((SOURCE_DIR / "configs" / "scenarios").glob("*.yaml"))


def run_program(name, *args):
    """Runs build/bin/NAME with args; fails the test with its output if it fails."""
    result = subprocess.run([str(BIN_DIR / name), *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, f"{name} failed:\n{result.stdout}\n{result.stderr}"
    return result.stdout


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="module")
def deep_vae(tmp_path_factory):
    """A dataset and a DeepConvVAE encoder.pt as generate_dataset and train_vae write them (tiny
    data, one epoch): (scans.h5, encoder.pt)."""
    folder = tmp_path_factory.mktemp("vae")
    run_program("generate_dataset", "--out", folder / "data.h5", "--sim-scans", 200,
                "--synthetic-scans", 60)
    run_program("train_vae", "--data", folder / "data.h5", "--model", "deep", "--epochs", 1,
                "--seeds", 1, "--out", folder / "vae")
    return folder / "data.h5", folder / "vae" / "seed_0" / "encoder.pt"


class HeldAction(torch.nn.Module):
    """A policy that holds the same action (surge, rudder) whatever it sees."""

    def __init__(self, surge: float, rudder: float):
        super().__init__()
        self.action = torch.tensor([[surge, rudder]])

    def forward(self, obs):
        return self.action.expand(obs.shape[0], 2)


class RecurrentPolicyStandIn(torch.nn.Module):
    """What train_ppo exports for a recurrent policy, but `step`: recurrent_size (1),
    initial_state(B) (zeros) and a forward that refuses. Subclasses define step(obs, state) ->
    (action, next state)."""

    def __init__(self):
        super().__init__()
        self.recurrent_size = 1

    @torch.jit.export
    def initial_state(self, batch: int):
        return torch.zeros(batch, 1)

    def forward(self, obs):
        raise RuntimeError("recurrent policy: call step(obs, state)")

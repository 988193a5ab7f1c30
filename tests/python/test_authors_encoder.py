"""scripts/authors_encoder.py: an encoder.pt that computes the pre-trained perception of one of
the authors' agents, in train_vae's format, and one-line refusals of files that do not fit."""

import subprocess

import pytest
import torch

from conftest import SOURCE_DIR

AGENTS_DIR = SOURCE_DIR.parent / "shared" / "reference-agents"
SCRIPT = SOURCE_DIR / "scripts" / "authors_encoder.py"


@pytest.fixture
def deep_template(deep_vae):
    """A DeepConvVAE encoder.pt as train_vae writes one."""
    return deep_vae[1]


def convert(*args):
    return subprocess.run(["/usr/bin/python3", str(SCRIPT), *map(str, args)],
                          capture_output=True, text=True)


@pytest.mark.skipif(not (AGENTS_DIR / "deep_locked_3m.pt").exists(),
                    reason=f"no reference agents in {AGENTS_DIR}")
def test_the_encoder_computes_the_agents_perception(deep_template, tmp_path):
    agent_path = AGENTS_DIR / "deep_locked_3m.pt"
    result = convert(agent_path, deep_template, tmp_path / "encoder.pt")
    assert result.returncode == 0, result.stderr
    encoder = torch.jit.load(str(tmp_path / "encoder.pt"))
    agent = torch.jit.load(str(agent_path))
    obs = torch.rand(32, 186, generator=torch.Generator().manual_seed(0))
    # The agents put a ReLU after their head (extractor.head=reference in train_ppo).
    expected = agent.features(obs)[:, 6:]
    assert torch.equal(torch.relu(encoder(obs[:, 6:])), expected)
    assert encoder.architecture == "deep"
    assert encoder.observation_settings == torch.jit.load(str(deep_template)).observation_settings


def test_an_agent_without_the_encoders_parameters_is_refused(deep_template, tmp_path):
    agent = torch.jit.script(torch.nn.Linear(186, 2))
    agent.save(str(tmp_path / "agent.pt"))
    result = convert(tmp_path / "agent.pt", deep_template, tmp_path / "encoder.pt")
    assert result.returncode == 2 and len(result.stderr.splitlines()) == 1
    assert "agent.pt: no parameter c0w of shape (3, 1, 45)" in result.stderr
    assert not (tmp_path / "encoder.pt").exists()

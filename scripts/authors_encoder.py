#!/usr/bin/python3
"""Writes an encoder.pt (train_vae's format) whose convolutions are those of one of the paper
authors' agents (../shared/reference-agents/*.pt), to train our PPO on the authors' pre-trained
perception: does a gap to their agent come from the VAE or from the reinforcement learning?

The template is any encoder.pt of the same architecture written by train_vae: its structure,
attributes and observation settings are kept, its convolution weights replaced. fc_mu is the
agent's frozen head (random orthogonal in the authors' agents, reference-learning.md 6.2); train
with extractor.head=reference to put a ReLU after a re-drawn head, as their agents had.

    /usr/bin/python3 scripts/authors_encoder.py AGENT.pt TEMPLATE_encoder.pt OUT_encoder.pt
"""

import os
import sys

import torch

# The agent's parameter of each of our encoder's parameters.
AGENT_PARAMETERS = {
    "convs_0_weight": "c0w", "convs_0_bias": "c0b",
    "convs_1_weight": "c1w", "convs_1_bias": "c1b",
    "convs_2_weight": "c2w", "convs_2_bias": "c2b",
    "fc_mu_weight": "muw", "fc_mu_bias": "mub",
}


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"authors_encoder: error: {message}", file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        return torch.jit.load(path)
    except (RuntimeError, ValueError, OSError):
        fail(f"{path}: not a TorchScript file")


def main():
    if len(sys.argv) != 4:
        fail("usage: " + __doc__.strip().splitlines()[-1].strip())
    agent_path, template_path, out_path = sys.argv[1:]
    agent = dict(load(agent_path).named_parameters())
    encoder = load(template_path)
    with torch.no_grad():
        for ours, theirs in AGENT_PARAMETERS.items():
            target = getattr(encoder, ours, None)
            if target is None:
                fail(f"{template_path}: not an encoder.pt of train_vae (no {ours})")
            if theirs not in agent or agent[theirs].shape != target.shape:
                fail(f"{agent_path}: no parameter {theirs} of shape {tuple(target.shape)} "
                     f"for the template's {ours} ({template_path})")
            target.copy_(agent[theirs])
    temporary = out_path + ".tmp"  # written whole, then renamed: never half a file
    encoder.save(temporary)
    os.replace(temporary, out_path)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Writes a copy of a deep encoder.pt (train_vae's format) whose last convolution is rescaled so
that its convolutional features spread as much as those of another encoder (the mean over the 12
features of their standard deviation on the scans of a dataset, in the closeness the agents see):
is the authors' deep perception better for PPO only because its features are larger?

The features are what fc_mu receives; with train_ppo's extractor.head=reference (a re-drawn
orthogonal head, no bias, then a ReLU) rescaling them by k rescales the agent's perception by k.

    /usr/bin/python3 scripts/match_feature_spread.py REFERENCE_encoder.pt IN_encoder.pt \
        SCANS.h5 OUT_encoder.pt [--closeness log|linear]
"""

import argparse
import math
import os
import sys

import h5py
import torch

LAST_CONV = "convs_2"  # the DeepConvVAE's third and last convolution
RANGE_M = 150.0
SCANS_USED = 20000


def fail(message):
    """Bad input: one line on stderr, exit status 2."""
    print(f"match_feature_spread: error: {message}", file=sys.stderr)
    sys.exit(2)


def load_encoder(path):
    try:
        encoder = torch.jit.load(path)
    except (RuntimeError, ValueError, OSError):
        fail(f"{path}: not a TorchScript file")
    if getattr(encoder, "architecture", None) != "deep":
        fail(f"{path}: not a deep encoder.pt of train_vae")
    return encoder


def load_closeness(path, transform):
    try:
        with h5py.File(path, "r") as scans:
            ranges = torch.from_numpy(scans["ranges"][:SCANS_USED])
    except (OSError, KeyError):
        fail(f"{path}: not a dataset of generate_dataset (no 'ranges')")
    if transform == "log":
        return 1.0 - torch.log1p(ranges) / math.log(1.0 + RANGE_M)
    return 1.0 - ranges / RANGE_M


def feature_spread(encoder_path, closeness):
    """Mean standard deviation of the features fc_mu receives: the encoder with fc_mu made the
    identity computes them (a copy loaded for this, so no caller's encoder is changed)."""
    probe = load_encoder(encoder_path)
    with torch.no_grad():
        size = probe.fc_mu_weight.shape[1]
        probe.fc_mu_weight.copy_(torch.eye(size))
        probe.fc_mu_bias.zero_()
        return probe(closeness).std(0).mean().item()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reference")
    parser.add_argument("encoder")
    parser.add_argument("scans")
    parser.add_argument("out")
    parser.add_argument("--closeness", choices=["log", "linear"], default="log",
                        help="closeness transform of the scans (default: log, the paper recipe's)")
    args = parser.parse_args()
    encoder = load_encoder(args.encoder)
    closeness = load_closeness(args.scans, args.closeness)
    factor = feature_spread(args.reference, closeness) / feature_spread(args.encoder, closeness)
    with torch.no_grad():
        getattr(encoder, LAST_CONV + "_weight").mul_(factor)
        getattr(encoder, LAST_CONV + "_bias").mul_(factor)
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    temporary = args.out + ".tmp"  # written whole, then renamed: never half a file
    encoder.save(temporary)
    os.replace(temporary, args.out)
    print(f"{args.out}: last convolution x {factor:.4f}")


if __name__ == "__main__":
    main()

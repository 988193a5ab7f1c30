"""scripts/match_feature_spread.py: a deep encoder whose last convolution is rescaled to the
features' spread of another, and one-line refusals of files that do not fit."""

import subprocess

import pytest
import torch

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "match_feature_spread.py"


def match(*args):
    return subprocess.run(["/usr/bin/python3", str(SCRIPT), *map(str, args)],
                          capture_output=True, text=True)


def test_the_last_convolution_takes_the_reference_spread(deep_vae, tmp_path):
    scans, encoder_path = deep_vae
    # A reference whose features spread 2.5 times as much: the same encoder, last conv x 2.5.
    reference = torch.jit.load(str(encoder_path))
    with torch.no_grad():
        reference.convs_2_weight.mul_(2.5)
        reference.convs_2_bias.mul_(2.5)
    reference.save(str(tmp_path / "reference.pt"))
    result = match(tmp_path / "reference.pt", encoder_path, scans, tmp_path / "out.pt")
    assert result.returncode == 0, result.stderr
    assert "last convolution x 2.5000" in result.stdout
    out, original = torch.jit.load(str(tmp_path / "out.pt")), torch.jit.load(str(encoder_path))
    assert torch.allclose(out.convs_2_weight, 2.5 * original.convs_2_weight)
    assert torch.equal(out.convs_0_weight, original.convs_0_weight)
    assert torch.equal(out.fc_mu_weight, original.fc_mu_weight)
    assert out.observation_settings == original.observation_settings


def test_an_encoder_matched_to_itself_is_unchanged(deep_vae, tmp_path):
    scans, encoder_path = deep_vae
    result = match(encoder_path, encoder_path, scans, tmp_path / "out.pt", "--closeness", "linear")
    assert result.returncode == 0, result.stderr
    assert "last convolution x 1.0000" in result.stdout


@pytest.mark.parametrize("bad, message", [("encoder", "not a TorchScript file"),
                                          ("scans", "not a dataset of generate_dataset")])
def test_bad_input_is_refused_in_one_line(deep_vae, tmp_path, bad, message):
    scans, encoder_path = deep_vae
    junk = tmp_path / "junk"
    junk.write_text("not a file of ours\n")
    args = [encoder_path, junk if bad == "encoder" else encoder_path,
            junk if bad == "scans" else scans, tmp_path / "out.pt"]
    result = match(*args)
    assert result.returncode == 2 and len(result.stderr.splitlines()) == 1
    assert message in result.stderr
    assert not (tmp_path / "out.pt").exists()

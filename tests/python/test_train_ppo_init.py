"""train_ppo's policy.init: a run starts from a policy file's weights (at learning rate 0 it
ends with them, bit for bit, where its own initialisation differs), learns on from them, and
records the file in its configuration; with ppo.critic_warmup_steps its first updates train the
critic alone, and policy.init_keeps_log_std false replaces its log std."""

import subprocess

import pytest
import torch

from conftest import BIN_DIR, run_program

TINY = ["--steps", 128, "--envs", 2, "--set", "ppo.n_steps=64", "--set", "ppo.batch_size=64",
        "--set", "train.env_threads=1", "--set", "policy.recurrent_size=4"]


def weights(path):
    return {name: p.detach().clone() for name, p in torch.jit.load(str(path)).named_parameters()}


def same(a, b):
    return a.keys() == b.keys() and all(torch.equal(a[name], b[name]) for name in a)


@pytest.fixture(scope="module")
def start(tmp_path_factory):
    """A recurrent policy.pt of train_ppo (seed 0), barely trained."""
    folder = tmp_path_factory.mktemp("start")
    run_program("train_ppo", "--out", folder / "run", *TINY)
    return folder / "run" / "policy.pt"


def train(folder, *args):
    run_program("train_ppo", "--out", folder, "--seed", 1, *TINY, *args)
    return folder / "policy.pt"


def test_a_run_at_learning_rate_zero_ends_with_the_files_weights(start, tmp_path):
    frozen = ["--set", "ppo.learning_rate=0"]
    own = train(tmp_path / "own", *frozen)
    started = train(tmp_path / "started", *frozen, "--set", f"policy.init={start}")
    assert not same(weights(own), weights(start))  # its own initialisation is another
    assert same(weights(started), weights(start))
    assert "starting from the weights of" in (tmp_path / "started" / "train_ppo.log").read_text()
    assert f"init: \"{start}\"" in (tmp_path / "started" / "config.yaml").read_text()


def test_a_run_learns_on_from_the_files_weights(start, tmp_path):
    started = weights(train(tmp_path / "started", "--set", f"policy.init={start}"))
    assert not same(started, weights(start))
    # Every layer moved from the file's weights, a little (2 rollouts at Adam's 2e-4: at most
    # 0.002 here); another initialisation's first layer and memory differ by 0.6 to 0.9.
    for name in ("mlp_extractor_policy_net_0_weight", "recurrent_weight_hh", "action_net_weight"):
        moved = (started[name] - weights(start)[name]).abs().max()
        assert 0 < moved < 0.02, name


def test_a_critic_warmup_holds_the_actor_then_trains_it(start, tmp_path):
    """Three rollouts of 128 steps, the first a warm-up. The checkpoint at step 256 (written while
    the second rollout is collected, so after the first update only) keeps every parameter the
    actions read from the file, bit for bit, and has moved the critic's own; the later updates
    move the actor too."""
    warm = ["--steps", 384, "--set", f"policy.init={start}", "--set", "ppo.critic_warmup_steps=128",
            "--set", "train.checkpoint_interval=128"]
    final = weights(train(tmp_path / "warm", *warm))
    after_warmup = weights(tmp_path / "warm" / "checkpoints" / "policy_256.pt")
    initial = weights(start)
    critic = ("mlp_extractor_value_net", "value_net")
    for name in initial:
        if name.startswith(critic):
            assert not torch.equal(after_warmup[name], initial[name]), name
        else:
            assert torch.equal(after_warmup[name], initial[name]), name
    assert not torch.equal(final["action_net_weight"], initial["action_net_weight"])
    assert not torch.equal(final["recurrent_weight_hh"], initial["recurrent_weight_hh"])
    log = (tmp_path / "warm" / "train_ppo.log").read_text()
    assert "the critic trains alone, the actor held, until step 128" in log
    assert "step 256: the critic's warm-up is over" in log


def test_a_start_can_replace_the_files_log_std(start, tmp_path):
    """At learning rate 0: every weight is the file's but the log std, policy.log_std_init's."""
    started = weights(train(tmp_path / "narrow", "--set", "ppo.learning_rate=0", "--set",
                            f"policy.init={start}", "--set", "policy.init_keeps_log_std=false",
                            "--set", "policy.log_std_init=-1.5"))
    initial = weights(start)
    assert not torch.equal(initial["log_std"], torch.full((2,), -1.5))
    assert torch.equal(started["log_std"], torch.full((2,), -1.5))
    assert all(torch.equal(started[name], initial[name]) for name in initial if name != "log_std")
    log = (tmp_path / "narrow" / "train_ppo.log").read_text()
    assert "its log std replaced by -1.5 (policy.log_std_init)" in log


@pytest.mark.parametrize("setting, message", [
    ("ppo.critic_warmup_steps=128", "ppo.critic_warmup_steps = 128 covers the whole run"),
    ("policy.init_keeps_log_std=false", "policy.init_keeps_log_std = false needs a policy.init"),
])
def test_settings_that_cannot_hold_are_refused(setting, message, tmp_path):
    result = subprocess.run([str(BIN_DIR / "train_ppo"), "--out", str(tmp_path / "run"),
                             *map(str, TINY), "--set", setting], capture_output=True, text=True)
    assert result.returncode == 2
    assert message in result.stderr
    assert not (tmp_path / "run").exists()

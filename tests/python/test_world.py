"""The `world` keyword: train_ppo's world.* keys (without "world."), read and validated as
train_ppo reads them, make the training worlds other than the paper's; without it they are the
paper's (test_cpp_equality.py: the ones `simulate --training-seed` builds)."""

import functools
import re
import subprocess

import numpy as np
import pytest

import colav
from conftest import BIN_DIR

PAPER = {"num_moving": 17, "moving_displacement_sd": 500.0, "num_static": 11,
         "static_displacement_sd": 250.0, "path_bends": 0}
CIRCLES = {"num_static": 40, "num_moving": 0}  # crowded with circles, no vessels


def episode_scenarios(seed, num_envs, episode, world):
    """The scenario each world of make_vec(num_envs, seed, world=world) plays in `episode`."""
    return [colav.training_scenario(colav.training_episode_seed(seed, i, episode), world=world)
            for i in range(num_envs)]


def first_observations(scenarios):
    return np.array([colav.make(scenario=scenario).reset()[0] for scenario in scenarios])


@pytest.mark.parametrize("world, counts", [
    (None, (17, 11)),  # (moving vessels, circles): the paper's
    (CIRCLES, (0, 40)),
    ({"num_moving": 3, "num_static": 0, "moving_displacement_sd": 50}, (3, 0)),
])
def test_every_episode_is_the_training_scenario_of_the_world(world, counts):
    envs = colav.make_vec(3, seed=4, world=world, max_steps=2)
    single = colav.make(seed=4, world=world)  # world 0 of the batch
    obs, _ = envs.reset()
    single_obs, _ = single.reset()
    np.testing.assert_array_equal(colav.make_async(3, seed=4, world=world).reset()[0], obs)
    for episode in range(2):  # episode 1 after an auto-reset (vector) and a reset (single)
        scenarios = episode_scenarios(4, 3, episode, world)
        assert [(s.num_moving, s.num_static) for s in scenarios] == [counts] * 3
        np.testing.assert_array_equal(obs, first_observations(scenarios))
        np.testing.assert_array_equal(single_obs, obs[0])
        for _ in range(2):
            obs, *_ = envs.step(np.zeros((3, 2), dtype=np.float32))
        single_obs, _ = single.reset()


def test_another_world_gives_other_observations_than_the_paper_s():
    paper, _ = colav.make_vec(4, seed=9).reset()
    crowded, _ = colav.make_vec(4, seed=9, world=CIRCLES).reset()
    assert (paper != crowded).any(axis=1).all()


def test_world_settings_are_train_ppo_s_world_keys():
    help_text = subprocess.run([str(BIN_DIR / "train_ppo"), "--help"], capture_output=True,
                               text=True).stdout
    keys = {name: (default, doc) for name, default, doc in
            re.findall(r"^  world\.(\w+) = (\S+) \(.*?\) (.*)$", help_text, re.MULTILINE)}
    assert keys == {name: (str(default), doc)
                    for name, (default, doc) in colav.world_settings().items()}
    assert {name: default for name, (default, _) in colav.world_settings().items()} == PAPER


def test_resolved_world_is_an_attribute():
    assert colav.make_vec(2).world == PAPER and colav.make().world == PAPER
    assert colav.make_async(2).world == PAPER
    assert colav.make_vec(2, world=CIRCLES).world == {**PAPER, **CIRCLES}
    assert colav.make_async(2, world=CIRCLES).world == {**PAPER, **CIRCLES}
    numpy_values = {"num_static": np.int64(22), "static_displacement_sd": np.float32(125.0)}
    assert colav.make(world=numpy_values).world == {**PAPER, "num_static": 22,
                                                    "static_displacement_sd": 125.0}
    assert colav.make(scenario=colav.training_scenario(1)).world is None
    assert colav.make_vec(scenarios=[colav.training_scenario(1)]).world is None
    assert colav.make_async(scenarios=[colav.training_scenario(1)]).world is None


@functools.lru_cache(maxsize=None)  # one run of train_ppo per bad value, not one per make
def train_ppo_error(key, text):
    """train_ppo's one-line message for --set world.KEY=TEXT, without its program and origin."""
    result = subprocess.run([str(BIN_DIR / "train_ppo"), "--out", "never-written", "--set",
                             f"world.{key}={text}"], capture_output=True, text=True)
    assert result.returncode == 2
    return result.stderr.strip().split("--set: ", 1)[1]


@pytest.mark.parametrize("key, value, text", [
    ("num_statics", 3, "3"),  # unknown: did you mean 'world.num_static'?
    ("num_static", 201, "201"),
    ("num_moving", -1, "-1"),
    ("num_moving", 2.5, "2.5"),
    ("static_displacement_sd", float("nan"), "nan"),
    ("moving_displacement_sd", 5000.5, "5000.5"),
])
@pytest.mark.parametrize("make", [colav.make, colav.make_vec, colav.make_async,
                                  lambda world: colav.training_scenario(0, world=world)])
def test_bad_world_raises_value_error_with_train_ppo_s_message(make, key, value, text):
    with pytest.raises(colav.UserError) as error:
        make(world={key: value})
    assert isinstance(error.value, ValueError)
    assert f"'world.{key}'" in str(error.value)
    assert str(error.value).split(": ", 1)[1] == train_ppo_error(key, text)


def test_world_with_scenarios_is_refused():
    scenario = colav.training_scenario(1)
    with pytest.raises(ValueError, match="world"):
        colav.make(scenario=scenario, world={"num_static": 22})
    with pytest.raises(ValueError, match="world"):
        colav.make_vec(scenarios=[scenario], world={})
    with pytest.raises(ValueError, match="world"):
        colav.make_async(scenarios=[scenario], world={"num_moving": 3})


def test_world_must_be_a_dict():
    with pytest.raises(TypeError, match="world"):
        colav.make_vec(2, world=[("num_static", 22)])


# best_mixed's training worlds (studies/best_worlds.yaml): circles crowded in world.*, vessels in
# world2.*, half and half.
CROWDED_CIRCLES = {"static_displacement_sd": 125}
CROWDED_VESSELS = {"moving_displacement_sd": 250}


@pytest.mark.parametrize("num_envs, share, second", [(8, 0.5, 4), (8, 0.375, 3), (3, 0.5, 2),
                                                     (4, 0.1, 0), (2, 1.0, 2)])
def test_world2_takes_its_share_of_the_last_worlds_as_train_ppo_does(num_envs, share, second):
    # round(share * num_envs) worlds: 3 x 0.5 = 1.5 rounds up to 2, 4 x 0.1 = 0.4 down to 0.
    kinds = [CROWDED_CIRCLES] * (num_envs - second) + [CROWDED_VESSELS] * second
    for make in (colav.make_vec, colav.make_async):
        envs = make(num_envs, seed=5, world=CROWDED_CIRCLES, world2=CROWDED_VESSELS,
                    world2_share=share, max_steps=2)
        assert envs.world2 == {**PAPER, **CROWDED_VESSELS} and envs.world2_share == share
        obs, _ = envs.reset()
        for episode in range(2):
            scenarios = [colav.training_scenario(colav.training_episode_seed(5, i, episode),
                                                 world=kind) for i, kind in enumerate(kinds)]
            np.testing.assert_array_equal(obs, first_observations(scenarios))
            for _ in range(2):
                obs, *_ = envs.step(np.zeros((num_envs, 2), dtype=np.float32))


def test_without_world2_every_world_is_of_world():
    envs = colav.make_vec(2, world2_share=0.0, world=CIRCLES)
    assert envs.world2 == PAPER and envs.world2_share == 0.0
    alone, _ = colav.make_vec(4, seed=2, world=CIRCLES).reset()
    unused, _ = colav.make_vec(4, seed=2, world=CIRCLES, world2=CROWDED_VESSELS).reset()
    np.testing.assert_array_equal(alone, unused)  # no share: world2 plays nowhere


@pytest.mark.parametrize("share", [-0.1, 1.5, float("nan"), "0.5", True])
def test_a_bad_world2_share_is_refused(share):
    with pytest.raises(ValueError, match=r"world2_share: expected a number in \[0, 1\]"):
        colav.make_vec(2, world2_share=share)


def test_a_bad_world2_names_its_world2_key():
    with pytest.raises(ValueError, match="'world2.num_static'"):
        colav.make_vec(2, world2={"num_static": 201}, world2_share=0.5)
    with pytest.raises(TypeError, match="world2: expected a dict"):
        colav.make_async(2, world2=[("num_static", 22)], world2_share=0.5)


def test_world2_with_scenarios_is_refused():
    scenario = colav.training_scenario(1)
    with pytest.raises(ValueError, match="world2"):
        colav.make_vec(scenarios=[scenario], world2={"num_static": 3})
    with pytest.raises(ValueError, match="world2"):
        colav.make_async(scenarios=[scenario], world2_share=0.5)
    assert colav.make_vec(scenarios=[scenario]).world2 is None

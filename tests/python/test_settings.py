"""Every environment setting of the programs' configuration is a keyword, validated as the
programs validate env.* keys: a bad one raises ValueError naming the key."""

import math

import numpy as np
import pytest

import colav

# A valid value other than the default for each setting.
OTHER_VALUES = {
    "closeness": "log",
    "test_mode": True,
    "max_steps": 700,
    "goal_radius": 2.5,
    "goal_progress": 0.9,
    "min_cumulative_reward": -500.0,
    "scan_history": 2,
    "scan_history_interval": 3,
    "obstacle_list_refresh": 25,
}


def test_every_setting_of_the_schema_is_a_keyword():
    assert set(colav.env_settings()) == set(OTHER_VALUES)
    defaults = {name: default for name, (default, _doc) in colav.env_settings().items()}
    for make in (colav.make, colav.make_vec):
        assert make(**defaults).settings == defaults
        assert make(**OTHER_VALUES).settings == OTHER_VALUES
        assert make().settings == defaults


def test_numpy_values_are_accepted():
    envs = colav.make_vec(2, max_steps=np.int64(10), test_mode=np.bool_(True),
                          goal_radius=np.float32(3.0))
    assert envs.settings["max_steps"] == 10 and envs.settings["test_mode"] is True
    assert envs.settings["goal_radius"] == 3.0


def test_closeness_changes_the_observation():
    linear = colav.make(seed=0, scenario=colav.training_scenario(7))
    log = colav.make(seed=0, scenario=colav.training_scenario(7), closeness="log")
    obs_linear, obs_log = linear.reset()[0], log.reset()[0]
    ranges = linear.state()["ranges"]
    np.testing.assert_allclose(obs_linear[6:], 1 - ranges / 150, atol=1e-6)
    np.testing.assert_allclose(obs_log[6:], 1 - np.log1p(ranges) / math.log(151), atol=1e-6)
    assert ranges.min() < 150  # some ray sees an obstacle, so the two differ


def test_max_steps_truncates():
    envs = colav.make_vec(2, max_steps=3, test_mode=True)
    envs.reset()
    for _ in range(3):
        *_, truncated, info = envs.step(np.zeros((2, 2), dtype=np.float32))
    assert truncated.all() and list(info["episode_metrics"]["steps"]) == [3, 3]


@pytest.mark.parametrize("settings, key", [
    ({"max_steps": 0}, "env.max_steps"),
    ({"max_steps": 2.5}, "env.max_steps"),
    ({"goal_progress": 3.0}, "env.goal_progress"),
    ({"goal_radius": float("nan")}, "env.goal_radius"),
    ({"min_cumulative_reward": float("inf")}, "env.min_cumulative_reward"),
    ({"closeness": "cubic"}, "env.closeness"),
    ({"test_mode": "yes"}, "env.test_mode"),
    ({"scan_history": 16}, "'env.scan_history'"),
    ({"scan_history": -1}, "'env.scan_history'"),
    ({"scan_history_interval": 0}, "env.scan_history_interval"),
    ({"max_step": 10}, "env.max_step' (did you mean 'env.max_steps'?)"),
])
@pytest.mark.parametrize("make", [colav.make, colav.make_vec])
def test_bad_settings_raise_value_error_naming_the_key(make, settings, key):
    with pytest.raises(ValueError) as error:
        make(**settings)
    message = str(error.value)
    assert key in message and "\n" not in message
    assert isinstance(error.value, colav.UserError)


@pytest.mark.parametrize("arguments, name", [
    ({"num_envs": 0}, "num_envs"),
    ({"seed": -1}, "seed"),
    ({"num_threads": -2}, "num_threads"),
    ({"scenarios": []}, "num_envs"),
])
def test_bad_batch_arguments_raise_value_error_naming_them(arguments, name):
    with pytest.raises(ValueError, match=name):
        colav.make_vec(**arguments)


def test_reset_rejects_a_list_of_seeds():
    with pytest.raises(ValueError, match="seed"):
        colav.make_vec(2).reset(seed=[1, 2])


def test_bad_scenario_file_raises_value_error_naming_the_file(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: bad\nwaypoints: [[0, 0]]\n")
    with pytest.raises(ValueError, match="bad.yaml"):
        colav.make(scenario=bad)
    with pytest.raises(ValueError, match="missing.yaml"):
        colav.make_vec(scenarios=[tmp_path / "missing.yaml"])

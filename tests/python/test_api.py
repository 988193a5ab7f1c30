"""The rules of Gymnasium's env_checker, for colav.Env and colav.VectorEnv, and the batched
environment's own contract (autoreset, reused arrays, determinism)."""

import numpy as np
import pytest

import colav


def assert_observation(obs, space):
    assert isinstance(obs, np.ndarray) and obs.dtype == np.float32
    assert obs.shape == space.shape
    assert space.contains(obs)


@pytest.fixture(params=["single", "vector"])
def env(request):
    env = colav.make(seed=3) if request.param == "single" else colav.make_vec(4, seed=3)
    yield env
    env.close()


def test_spaces_have_gymnasium_attributes(env):
    for space in (env.observation_space, env.action_space):
        assert space.dtype == np.float32
        assert space.low.shape == space.shape and space.high.shape == space.shape
    assert env.observation_space.shape[-1] == colav.OBSERVATION_SIZE == 186
    assert env.action_space.shape[-1] == colav.ACTION_SIZE == 2
    assert np.all(env.action_space.low == -1.0) and np.all(env.action_space.high == 1.0)
    if colav.gymnasium is not None:
        assert isinstance(env.observation_space, colav.gymnasium.spaces.Box)
        gym = colav.gymnasium
        base = gym.Env if isinstance(env, colav.Env) else gym.vector.VectorEnv
        assert isinstance(env, base)


def test_reset_returns_observation_in_space_and_dict(env):
    result = env.reset(seed=1)
    assert isinstance(result, tuple) and len(result) == 2
    obs, info = result
    assert_observation(obs, env.observation_space)
    assert isinstance(info, dict)


def test_same_seed_same_observation_other_seed_other(env):
    first = env.reset(seed=5)[0].copy()
    env.step(env.action_space.sample())
    again = env.reset(seed=5)[0].copy()
    other = env.reset(seed=6)[0].copy()
    np.testing.assert_array_equal(first, again)
    assert not np.array_equal(first, other)
    assert not np.array_equal(env.reset()[0], other)  # no seed: the next episode


def test_step_returns_five_tuple_of_right_types(env):
    env.reset(seed=0)
    result = env.step(env.action_space.sample())
    assert isinstance(result, tuple) and len(result) == 5
    obs, reward, terminated, truncated, info = result
    assert_observation(obs, env.observation_space)
    assert isinstance(info, dict)
    if isinstance(env, colav.Env):
        assert isinstance(reward, float)
        assert isinstance(terminated, bool) and isinstance(truncated, bool)
    else:
        assert reward.dtype == np.float32 and reward.shape == (env.num_envs,)
        for flags in (terminated, truncated):
            assert flags.dtype == np.bool_ and flags.shape == (env.num_envs,)


def test_options_accepted_and_unknown_ones_rejected(env):
    obs, info = env.reset(seed=0, options={})
    assert_observation(obs, env.observation_space)
    env.reset(options=None)
    with pytest.raises(ValueError, match="colour"):
        env.reset(options={"colour": "red"})


def test_close_twice_is_safe_and_use_after_close_fails(env):
    env.reset(seed=0)
    env.close()
    env.close()
    with pytest.raises(RuntimeError, match="closed"):
        env.step(env.action_space.sample())


def test_render_has_no_modes_yet(env):
    assert env.render() is None
    assert env.render_mode is None


def test_single_env_refuses_step_after_episode_end():
    env = colav.make(max_steps=2)
    with pytest.raises(RuntimeError, match="reset"):
        env.step([1.0, 0.0])
    env.reset(seed=0)
    env.step([1.0, 0.0])
    *_, truncated, info = env.step([1.0, 0.0])
    assert truncated and info["episode_metrics"]["steps"] == 2
    with pytest.raises(RuntimeError, match="reset"):
        env.step([1.0, 0.0])


def test_single_env_state_gives_the_path_length_its_progress_is_a_share_of():
    env = colav.make(max_steps=50)
    env.reset(seed=1)
    length = env.state()["path_length"]
    assert 200.0 < length < 1000.0  # a training path: start and end 300 m apart, curved between
    done = False
    while not done:
        *_, terminated, truncated, info = env.step([1.0, 0.0])
        done = terminated or truncated
        assert env.state()["path_length"] == length
    metrics = info["episode_metrics"]
    assert metrics["path_length"] == length and metrics["progress"] == env.state()["progress"]


def test_vector_env_refuses_step_before_reset():
    with pytest.raises(RuntimeError, match="reset"):
        colav.make_vec(2).step(np.zeros((2, 2), dtype=np.float32))


def test_autoreset_hands_back_final_observation_and_metrics():
    envs = colav.make_vec(3, seed=2, max_steps=4)
    single = colav.make(seed=2, max_steps=4)  # world 0 of the batch
    envs.reset()
    single.reset()
    actions = np.tile(np.array([1.0, 0.5], dtype=np.float32), (3, 1))
    for t in range(1, 5):
        obs, reward, terminated, truncated, info = envs.step(actions)
        single_obs, *_ = single.step(actions[0])
        assert bool(truncated.all()) == (t == 4) and not terminated.any()
    assert info["_final_obs"].all() and info["_episode_metrics"].all()
    np.testing.assert_array_equal(info["episode_metrics"]["steps"], [4, 4, 4])
    np.testing.assert_array_equal(info["final_obs"][0], single_obs)
    np.testing.assert_array_equal(obs[0], single.reset()[0])  # the next episode's first obs
    _, _, _, _, info = envs.step(actions)
    assert info == {}


def test_vector_world_zero_is_the_single_env_of_the_same_seed():
    envs = colav.make_vec(2, seed=11)
    single = colav.make(seed=11)
    np.testing.assert_array_equal(envs.reset()[0][0], single.reset()[0])
    rng = np.random.default_rng(0)
    for _ in range(50):
        actions = rng.uniform(-1, 1, size=(2, 2)).astype(np.float32)
        obs, reward, *_ = envs.step(actions)
        single_obs, single_reward, *_ = single.step(actions[0])
        np.testing.assert_array_equal(obs[0], single_obs)
        assert reward[0] == np.float32(single_reward)


def test_returned_arrays_are_reused_every_other_step():
    envs = colav.make_vec(2, seed=0)
    envs.reset()
    actions = np.zeros((2, 2), dtype=np.float32)
    first = envs.step(actions)[0]
    kept = first.copy()
    second = envs.step(actions)[0]
    assert second is not first
    np.testing.assert_array_equal(first, kept)  # the next step left it alone
    assert envs.step(actions)[0] is first


def test_results_do_not_depend_on_thread_count_or_action_dtype():
    rng = np.random.default_rng(1)
    actions = rng.uniform(-1.2, 1.2, size=(300, 5, 2)).astype(np.float32)

    def run(num_threads, dtype):
        envs = colav.make_vec(5, seed=4, num_threads=num_threads, max_steps=120)
        envs.reset()
        history = []
        for action in actions:
            obs, reward, *_ = envs.step(action.astype(dtype))
            history.append(np.concatenate([obs.ravel(), reward]))
        return np.array(history)

    reference = run(1, np.float32)
    for num_threads, dtype in ((2, np.float32), (2, np.float64), (3, np.float32)):
        np.testing.assert_array_equal(run(num_threads, dtype), reference)


def test_bad_actions_raise_value_error():
    envs = colav.make_vec(2)
    envs.reset()
    with pytest.raises(ValueError, match=r"expected shape \(2, 2\), got \(4,\)"):
        envs.step(np.zeros(4, dtype=np.float32))
    with pytest.raises(ValueError, match="2 numbers"):
        single = colav.make()
        single.reset()
        single.step([1.0, 0.0, 0.0])

"""colav.make_async (EnvPool's asynchronous mode): shapes, env ids, each world playing the
synchronous environment's episodes under the same actions, and its errors."""

import numpy as np
import pytest

import colav

STEPS = 30


def action_of(world, step):
    """A deterministic action of a world on its step, sometimes outside [-1, 1] (clipped)."""
    thrust = 1.3 * np.sin(0.7 * world + 0.31 * step)
    yaw = 1.2 * np.cos(1.1 * world + 0.17 * step)
    return np.array([thrust, yaw], dtype=np.float32)


def snapshot(obs, reward, terminated, truncated, info, row):
    """What row `row` of a batch says about its world (copied: the arrays are reused)."""
    ended = bool(terminated[row] or truncated[row])
    final = info["final_obs"][row].copy() if ended else None
    ret = float(info["episode_metrics"]["cumulative_reward"][row]) if ended else None
    flags = bool(terminated[row]), bool(truncated[row])
    return obs[row].copy(), float(reward[row]), *flags, final, ret


def synchronous_run(num_envs, **settings):
    envs = colav.make_vec(num_envs, seed=3, **settings)
    obs, _ = envs.reset()
    runs = [[(obs[w].copy(), 0.0, False, False, None, None)] for w in range(num_envs)]
    for step in range(STEPS):
        actions = np.stack([action_of(w, step) for w in range(num_envs)])
        obs, reward, terminated, truncated, info = envs.step(actions)
        for w in range(num_envs):
            runs[w].append(snapshot(obs, reward, terminated, truncated, info, w))
    return runs


def asynchronous_run(num_envs, batch_size, **settings):
    envs = colav.make_async(num_envs, seed=3, batch_size=batch_size, num_threads=2, **settings)
    runs = [[] for _ in range(num_envs)]
    envs.async_reset()
    while min(len(run) for run in runs) <= STEPS:
        obs, reward, terminated, truncated, info = envs.recv()
        for row, world in enumerate(info["env_id"]):
            runs[world].append(snapshot(obs, reward, terminated, truncated, info, row))
        envs.send(np.stack([action_of(w, len(runs[w]) - 1) for w in info["env_id"]]),
                  info["env_id"])
    return [run[: STEPS + 1] for run in runs]


def assert_same_runs(actual, expected):
    for world, (mine, theirs) in enumerate(zip(actual, expected)):
        for t, (a, b) in enumerate(zip(mine, theirs)):
            where = f"world {world}, entry {t}"
            np.testing.assert_array_equal(a[0], b[0], err_msg=where)
            assert a[1:4] == b[1:4], where
            assert (a[4] is None) == (b[4] is None), where
            if a[4] is not None:
                np.testing.assert_array_equal(a[4], b[4], err_msg=where)
            assert a[5] == b[5], where


def test_shapes_types_and_env_ids():
    envs = colav.make_async(num_envs=6, batch_size=4, seed=1)
    assert (envs.num_envs, envs.batch_size) == (6, 4)
    assert envs.observation_space.shape == (4, colav.OBSERVATION_SIZE)
    assert envs.action_space.shape == (4, colav.ACTION_SIZE)
    obs, info = envs.reset()
    assert obs.dtype == np.float32 and obs.shape == (4, colav.OBSERVATION_SIZE)
    for _ in range(20):
        obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
        env_id = info["env_id"]
        assert env_id.dtype == np.int32 and env_id.shape == (4,)
        assert np.all(np.diff(env_id) > 0) and env_id.min() >= 0 and env_id.max() < 6
        assert obs.shape == (4, colav.OBSERVATION_SIZE) and reward.shape == (4,)
        assert reward.dtype == np.float32
        assert terminated.dtype == np.bool_ and truncated.shape == (4,)
    envs.close()


def test_each_world_plays_the_synchronous_episodes():
    expected = synchronous_run(5, max_steps=8)
    assert sum(entry[5] is not None for run in expected for entry in run) >= 10  # auto-resets
    assert_same_runs(asynchronous_run(5, 2, max_steps=8), expected)


def test_full_batch_is_the_synchronous_environment():
    sync = colav.make_vec(4, seed=2)
    pool = colav.make_async(4, seed=2, batch_size=4)
    np.testing.assert_array_equal(pool.reset()[0], sync.reset()[0])
    for step in range(15):
        actions = np.stack([action_of(w, step) for w in range(4)]).astype(np.float64)
        expected = sync.step(actions)
        actual = pool.step(actions)
        np.testing.assert_array_equal(actual[4]["env_id"], np.arange(4))
        for mine, theirs in zip(actual[:4], expected[:4]):
            np.testing.assert_array_equal(mine, theirs)


@pytest.mark.parametrize("batch_size", [0, -1, 9, 2.5, "4", True])
def test_bad_batch_size_is_a_value_error_naming_it(batch_size):
    with pytest.raises(ValueError, match="batch_size"):
        colav.make_async(num_envs=8, batch_size=batch_size)


def test_bad_sends_and_recvs():
    envs = colav.make_async(num_envs=4, batch_size=2, seed=0)
    for call in (lambda: envs.send(np.zeros((2, 2), np.float32), np.array([0, 1])), envs.recv):
        with pytest.raises(RuntimeError, match="before async_reset"):
            call()
    envs.async_reset()
    _, _, _, _, info = envs.recv()
    back = info["env_id"]
    stepping = np.setdiff1d(np.arange(4), back)
    with pytest.raises(ValueError, match="env_id: 4 is outside"):
        envs.send(np.zeros((1, 2)), np.array([4]))
    with pytest.raises(ValueError, match="has not come back"):
        envs.send(np.zeros((1, 2)), stepping[:1])
    with pytest.raises(ValueError, match=r"actions: expected shape \(2, 2\)"):
        envs.send(np.zeros((3, 2)), back)
    with pytest.raises(TypeError, match="env_id"):
        envs.send(np.zeros((2, 2)), np.array([0.0, 1.0]))
    envs.send(np.zeros((1, 2)), back[:1])  # the failed sends queued nothing: 3 worlds step
    envs.recv()
    with pytest.raises(RuntimeError, match="worlds stepping: 1, fewer than the batch of 2"):
        envs.recv()

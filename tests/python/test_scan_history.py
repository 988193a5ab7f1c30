"""Observations with a scan history (env.scan_history, env.scan_history_interval): their shape
and space, and their content checked against the scans of an environment without a history."""

import numpy as np

import colav

HISTORY, INTERVAL = 2, 3
SIZE = 6 + 180 * (1 + HISTORY)  # 546
NUM_ENVS, SEED, MAX_STEPS = 2, 5, 7  # episodes end (truncated) within the run below


def scans_of(obs):
    """The scans of observations [..., SIZE], newest first: [..., 1 + HISTORY, 180]."""
    return obs[..., 6:].reshape(*obs.shape[:-1], 1 + HISTORY, 180)


def test_spaces_have_the_size_of_the_history():
    envs = colav.make_vec(NUM_ENVS, seed=SEED, scan_history=HISTORY, scan_history_interval=INTERVAL)
    env = colav.make(seed=SEED, scan_history=HISTORY, scan_history_interval=INTERVAL)
    assert envs.observation_space.shape == (NUM_ENVS, SIZE)
    assert envs.single_observation_space.shape == env.observation_space.shape == (SIZE,)
    space = env.observation_space
    assert np.all(space.low[6:] == 0.0) and np.all(space.high[6:] == 1.0)
    np.testing.assert_array_equal(space.low[:6], colav.make().observation_space.low[:6])
    obs, _ = env.reset()
    assert obs.shape == (SIZE,) and space.contains(obs)
    assert space.contains(env.step([1.0, 0.3])[0])


def test_history_holds_the_scans_of_earlier_steps_of_the_episode():
    settings = dict(seed=SEED, max_steps=MAX_STEPS, test_mode=True)
    envs = colav.make_vec(NUM_ENVS, scan_history=HISTORY, scan_history_interval=INTERVAL,
                          **settings)
    plain = colav.make_vec(NUM_ENVS, **settings)  # the same worlds without a history
    obs, _ = envs.reset()
    plain_obs, _ = plain.reset()
    assert obs.shape == (NUM_ENVS, SIZE) and envs.observation_space.contains(obs)
    # Each world's current scans of its running episode, from the run without a history.
    episode_scans = [[scan.copy()] for scan in plain_obs[:, 6:]]

    def assert_history(observations, world):
        t = len(episode_scans[world]) - 1  # steps into the episode
        for k, scan in enumerate(scans_of(observations[world])):
            np.testing.assert_array_equal(scan, episode_scans[world][max(0, t - INTERVAL * k)])

    for world in range(NUM_ENVS):
        assert_history(obs, world)
    rng = np.random.default_rng(0)
    episodes_ended = 0
    for _ in range(MAX_STEPS + 4):
        actions = rng.uniform(-1, 1, size=(NUM_ENVS, 2)).astype(np.float32)
        obs, _, terminated, truncated, info = envs.step(actions)
        plain_obs, _, plain_terminated, plain_truncated, plain_info = plain.step(actions)
        assert obs.shape == (NUM_ENVS, SIZE) and envs.observation_space.contains(obs)
        np.testing.assert_array_equal(obs[:, :186], plain_obs)
        np.testing.assert_array_equal(terminated, plain_terminated)
        np.testing.assert_array_equal(truncated, plain_truncated)
        for world in range(NUM_ENVS):
            if terminated[world] or truncated[world]:
                final_obs = info["final_obs"]
                assert final_obs.shape == (NUM_ENVS, SIZE) and info["_final_obs"][world]
                assert envs.single_observation_space.contains(final_obs[world])
                np.testing.assert_array_equal(final_obs[world, :186],
                                              plain_info["final_obs"][world])
                episode_scans[world].append(plain_info["final_obs"][world, 6:].copy())
                assert_history(final_obs, world)
                episode_scans[world] = []  # obs holds the next episode's first observation
                episodes_ended += 1
            episode_scans[world].append(plain_obs[world, 6:].copy())
            assert_history(obs, world)
    assert episodes_ended >= NUM_ENVS

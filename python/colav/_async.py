"""colav.AsyncVectorEnv: EnvPool's asynchronous mode, a batch of worlds of which recv() returns
the first batch_size done while the others go on stepping."""

import numpy as np

from . import _colav
from ._envs import (_Closed, _check_options, _optional_seed, _resolve, _vector_worlds,
                    _whole_number, _worlds)
from ._spaces import action_space, observation_space


class AsyncVectorEnv:
    """num_envs worlds stepped on C++ threads, batch_size of them returned at a time (EnvPool's
    asynchronous mode, envpool.make(..., num_envs=N, batch_size=B)).

    AsyncVectorEnv(num_envs=8, seed=0, batch_size=None, scenarios=None, num_threads=0,
    world=None, world2=None, world2_share=0.0, **settings): the worlds of make_vec(num_envs, seed,
    scenarios=..., world=..., world2=..., world2_share=..., **settings), with its `settings`,
    `world`, `world2` and `world2_share` attributes; batch_size defaults to num_envs.
    num_threads (0: every core) counts the thread calling recv(), which steps worlds too while it
    waits.

        envs.async_reset()                                  # every world starts an episode
        obs, reward, terminated, truncated, info = envs.recv()
        envs.send(policy(obs), info["env_id"])              # or envs.step(actions, env_id)

    recv() waits for the first batch_size worlds that are done and returns their results, rows in
    increasing env id: obs float32 [B, observation_size], reward float32 [B], terminated and
    truncated bool [B], info {"env_id": int32 [B]}, plus "final_obs", "episode_metrics" and their
    masks where an episode ended (auto-reset on the same step, as make_vec). send(actions [k, 2],
    env_id [k]) queues the next step of worlds that came back from a recv; env_id defaults to the
    last recv's. step(actions, env_id=None) is send then recv; reset(seed=None) is async_reset
    then recv, returning (obs, info).

    Each world plays exactly the episodes it plays in make_vec with the same seed and the same
    actions; only which worlds a recv returns depends on timing. With batch_size == num_envs
    every recv returns every world in order, as make_vec does. The arrays recv returns are reused
    as make_vec's are: valid until the recv after next.
    """

    def __init__(self, num_envs=None, seed=0, *, batch_size=None, scenarios=None, num_threads=0,
                 world=None, world2=None, world2_share=0.0, **settings):
        resolved = _resolve(settings, "colav.AsyncVectorEnv")
        training_world, second_world, share = _vector_worlds(
            self, world, world2, world2_share, scenarios is not None, "colav.AsyncVectorEnv")
        self.settings = resolved.values
        threads = _whole_number("num_threads", num_threads, 0)
        count, loaded = _worlds(num_envs, scenarios)
        batch = count if batch_size is None else _whole_number("batch_size", batch_size, 1)
        if batch > count:
            raise ValueError(f"batch_size: {batch} is more than the {count} worlds (num_envs)")
        if loaded is None:
            self._core = _colav.AsyncVectorEnvironment(
                resolved, training_world, second_world, share, count, batch,
                _whole_number("seed", seed, 0), threads
            )
        else:
            self._core = _colav.AsyncVectorEnvironment(resolved, loaded, batch, threads)
        self.num_envs = count
        self.batch_size = batch
        self.single_observation_space = observation_space(self._core.observation_size)
        self.single_action_space = action_space()
        self.observation_space = observation_space(self._core.observation_size, batch)
        self.action_space = action_space(batch)
        self._started = False
        self._last_env_id = None
        self.closed = False

    def _require_started(self, call):
        if not self._started:
            raise RuntimeError(f"{call} before async_reset(): call async_reset() or reset() first")

    def async_reset(self, seed=None):
        """Queues a new episode in every world: the next ones, or with a seed episode 0 of that
        seed (one integer for all worlds). Steps already sent are played first; results not yet
        received are dropped."""
        self._core.async_reset(_optional_seed(seed))
        self._started = True

    def recv(self):
        self._require_started("recv()")
        return self._batch(self._core.recv())

    def send(self, actions, env_id=None):
        self._core.send(actions, self._env_ids(env_id, "send()"))

    def step(self, actions, env_id=None):
        """send(actions, env_id) then recv(), in one call into C++."""
        return self._batch(self._core.step(actions, self._env_ids(env_id, "step()")))

    def _env_ids(self, env_id, call):
        self._require_started(call)
        if env_id is not None:
            return np.asarray(env_id)
        if self._last_env_id is None:
            raise RuntimeError(f"{call} without env_id before the first recv()")
        return self._last_env_id

    def _batch(self, results):
        obs, reward, terminated, truncated, env_id, finished = results
        self._last_env_id = env_id
        info = self._core.finished_episodes() if finished else {}
        info["env_id"] = env_id
        return obs, reward, terminated, truncated, info

    def reset(self, *, seed=None, options=None):
        """async_reset(seed) then recv(): (obs, info) of the first batch_size worlds."""
        _check_options(options)
        self.async_reset(seed)
        obs, _, _, _, info = self.recv()
        return obs, info

    def close(self, **kwargs):
        self._core = _Closed()
        self.closed = True


def make_async(num_envs=None, seed=0, *, batch_size=None, scenarios=None, num_threads=0,
               world=None, world2=None, world2_share=0.0, **settings):
    """colav.AsyncVectorEnv(num_envs, seed, batch_size=..., scenarios=..., num_threads=...,
    world=..., world2=..., world2_share=..., **settings)."""
    return AsyncVectorEnv(num_envs, seed, batch_size=batch_size, scenarios=scenarios,
                          num_threads=num_threads, world=world, world2=world2,
                          world2_share=world2_share, **settings)

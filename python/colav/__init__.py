"""colav: the collision-avoidance simulator (C++, the same one the programs use) for Python.

    import colav
    envs = colav.make_vec(num_envs=8, seed=0, closeness="log")   # Gymnasium-style vector env
    obs, info = envs.reset()
    obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())

    env = colav.make(scenario="configs/scenarios/head-on.yaml")  # one world, Gymnasium Env

    envs = colav.make_vec(8, world={"num_static": 22})  # train_ppo's world.num_static=22

    envs = colav.make_async(num_envs=8, batch_size=4)  # EnvPool's asynchronous mode
    envs.async_reset()
    obs, reward, terminated, truncated, info = envs.recv()       # the first 4 worlds done
    envs.send(actions, info["env_id"])                           # their next step

    policy = colav.Policy("runs/best/policy.pt")   # a trained policy (needs PyTorch)
    envs = colav.make_vec(8, **policy.observation_settings)
    actions = policy.act(obs, episode_starts)      # a recurrent one keeps each world's memory

Observations are float32 [6 + 180*(1+scan_history)], [186] by default (OBSERVATION_SIZE): u, v,
r, cte/100, heading error, look-ahead heading error, then the closeness of rays 0-179 (README,
"Observation"). With scan_history=H, the 180 closeness values of the scans k*scan_history_interval
steps earlier follow for k = 1..H (the episode's first scan while there is none). Actions are
[thrust, yaw moment] in [-1, 1].
Bad settings, seeds or scenario files raise ValueError naming the key or file.
"""

from . import _colav
from ._async import AsyncVectorEnv, make_async
from ._envs import RENDER_SIZE, Env, VectorEnv, _resolve_world, make, make_vec
from ._policy import Policy
from ._spaces import ACTION_SIZE, OBSERVATION_SIZE, Box, gymnasium

UserError = _colav.UserError
Scenario = _colav.Scenario


def env_settings():
    """{keyword: (default, doc)} of every environment setting (the env.* keys of the programs)."""
    return _colav.setting_docs()


def world_settings():
    """{keyword: (default, doc)} of every training world setting (the world.* keys of train_ppo),
    the keys of the `world` dict of make, make_vec, make_async and training_scenario."""
    return _colav.world_setting_docs()


def load_scenario(path):
    """A scenario file (shared/spec/interfaces.md), validated."""
    return _colav.load_scenario_file(str(path))


def training_scenario(seed, world=None):
    """The training world of this seed: the paper's, as `simulate --training-seed` builds it, or
    with `world` (as make_vec's) that kind of training world."""
    return _colav.training_scenario(seed, _resolve_world(world, "colav.training_scenario"))


def training_episode_seed(seed, env_id, episode):
    """The seed of the training world that world env_id of make_vec(seed=seed) plays in its
    episode `episode` (0 first): training_scenario of it, with the same world, is that episode."""
    return _colav.training_episode_seed(seed, env_id, episode)


def evaluation_scenario_seeds(count, seed=0):
    """The seeds of evaluate's test scenarios 0 .. count-1 for master seed `seed` (the shared
    scenarios every model is evaluated on; evaluate runs them with test_mode=True)."""
    return [_colav.test_scenario_seed(seed, k) for k in range(count)]


def evaluation_scenarios(count=100, seed=0):
    """evaluate's test scenarios, for make_vec(scenarios=...)."""
    return [training_scenario(s) for s in evaluation_scenario_seeds(count, seed)]


__all__ = [
    "ACTION_SIZE", "OBSERVATION_SIZE", "AsyncVectorEnv", "Box", "Env", "Policy", "Scenario",
    "UserError", "VectorEnv", "env_settings", "gymnasium", "load_scenario", "make", "make_async",
    "make_vec", "evaluation_scenario_seeds", "evaluation_scenarios", "training_episode_seed",
    "training_scenario", "world_settings",
]

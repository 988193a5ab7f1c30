"""colav: the collision-avoidance simulator (C++, the same one the programs use) for Python.

    import colav
    envs = colav.make_vec(num_envs=8, seed=0, closeness="log")   # Gymnasium-style vector env
    obs, info = envs.reset()
    obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())

    env = colav.make(scenario="configs/scenarios/head-on.yaml")  # one world, Gymnasium Env

    envs = colav.make_async(num_envs=8, batch_size=4)  # EnvPool's asynchronous mode
    envs.async_reset()
    obs, reward, terminated, truncated, info = envs.recv()       # the first 4 worlds done
    envs.send(actions, info["env_id"])                           # their next step

Observations are float32 [6 + 180*(1+scan_history)], [186] by default (OBSERVATION_SIZE): u, v,
r, cte/100, heading error, look-ahead heading error, then the closeness of rays 0-179 (README,
"Observation"). With scan_history=H, the 180 closeness values of the scans k*scan_history_interval
steps earlier follow for k = 1..H (the episode's first scan while there is none). Actions are
[thrust, yaw moment] in [-1, 1].
Bad settings, seeds or scenario files raise ValueError naming the key or file.
"""

from . import _colav
from ._async import AsyncVectorEnv, make_async
from ._envs import RENDER_SIZE, Env, VectorEnv, make, make_vec
from ._spaces import ACTION_SIZE, OBSERVATION_SIZE, Box, gymnasium

UserError = _colav.UserError
Scenario = _colav.Scenario


def env_settings():
    """{keyword: (default, doc)} of every environment setting (the env.* keys of the programs)."""
    return _colav.setting_docs()


def load_scenario(path):
    """A scenario file (shared/spec/interfaces.md), validated."""
    return _colav.load_scenario_file(str(path))


def training_scenario(seed):
    """The paper's training world of this seed, as `simulate --training-seed` builds it."""
    return _colav.training_scenario(seed)


def evaluation_scenario_seeds(count, seed=0):
    """The seeds of evaluate's test scenarios 0 .. count-1 for master seed `seed` (the shared
    scenarios every model is evaluated on; evaluate runs them with test_mode=True)."""
    return [_colav.test_scenario_seed(seed, k) for k in range(count)]


def evaluation_scenarios(count=100, seed=0):
    """evaluate's test scenarios, for make_vec(scenarios=...)."""
    return [training_scenario(s) for s in evaluation_scenario_seeds(count, seed)]


__all__ = [
    "ACTION_SIZE", "OBSERVATION_SIZE", "AsyncVectorEnv", "Box", "Env", "Scenario", "UserError",
    "VectorEnv", "env_settings", "gymnasium", "load_scenario", "make", "make_async", "make_vec",
    "evaluation_scenario_seeds", "evaluation_scenarios", "training_scenario",
]

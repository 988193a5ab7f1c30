"""colav.Env (one world, Gymnasium Env) and colav.VectorEnv (a batch of worlds stepped by the C++
thread pool, Gymnasium VectorEnv). With Gymnasium installed they subclass its classes."""

import numbers
import os

import numpy as np

from . import _colav
from ._spaces import action_space, gymnasium, observation_space

_EnvBase = gymnasium.Env if gymnasium is not None else object
_VectorEnvBase = gymnasium.vector.VectorEnv if gymnasium is not None else object
# Autoreset as EnvPool does it (Gymnasium's "same-step" mode): see VectorEnv.
_autoreset_modes = getattr(gymnasium.vector, "AutoresetMode", None) if gymnasium else None
_SAME_STEP = _autoreset_modes.SAME_STEP if _autoreset_modes is not None else "SameStep"
RENDER_SIZE = 480  # pixels, the frames of `simulate --gif`


def _setting_text(value):
    """A keyword value as the text a config file would hold (the C++ side parses and checks it)."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Real) and not isinstance(value, numbers.Integral):
        return repr(float(value))
    return str(value)


def _setting_texts(settings):
    return {name: _setting_text(value) for name, value in settings.items()}


def _resolve(settings, origin):
    return _colav.resolve_settings(_setting_texts(settings), origin)


def _resolve_world(world, origin, keyword="world"):
    """The training world of the `world` (or `world2`) keyword ({world.* key without "world.":
    value}, as train_ppo reads its world.* or world2.* keys), the paper's without it."""
    if world is None:
        world = {}
    if not isinstance(world, dict):
        raise TypeError(f"{keyword}: expected a dict of world settings, got {world!r}")
    return _colav.resolve_world(_setting_texts(world), origin, keyword)


def _training_world(world, scenarios_given, origin):
    """The resolved training world, or None when the worlds replay scenarios instead. A `world`
    given with scenarios is an error: it would change nothing."""
    if not scenarios_given:
        return _resolve_world(world, origin)
    if world is not None:
        raise ValueError(f"{origin}: world sets the training worlds, which the scenarios "
                         "replace: give one or the other")
    return None


def _second_worlds(world2, world2_share, scenarios_given, origin):
    """(the resolved second kind of world, its share) of the world2 and world2_share keywords:
    the last round(world2_share * num_envs) worlds play world2, as train_ppo's world2.* keys and
    world2.share make them; (None, 0.0) when the worlds replay scenarios, where either is an
    error."""
    if (isinstance(world2_share, bool) or not isinstance(world2_share, numbers.Real)
            or not 0 <= world2_share <= 1):
        raise ValueError(f"world2_share: expected a number in [0, 1], got {world2_share!r}")
    if not scenarios_given:
        return _resolve_world(world2, origin, "world2"), float(world2_share)
    if world2 is not None or world2_share:
        raise ValueError(f"{origin}: world2 and world2_share set training worlds, which the "
                         "scenarios replace: give one or the other")
    return None, 0.0


def _vector_worlds(envs, world, world2, world2_share, scenarios_given, origin):
    """The vector environments' training worlds, resolved: sets envs.world, envs.world2 and
    envs.world2_share and returns (world, world2, share) for the C++ constructor."""
    training_world = _training_world(world, scenarios_given, origin)
    second_world, share = _second_worlds(world2, world2_share, scenarios_given, origin)
    envs.world = _values(training_world)
    envs.world2 = _values(second_world)
    envs.world2_share = share
    return training_world, second_world, share


def _scenario(scenario):
    """A Scenario from a scenario file path, or the Scenario itself."""
    if isinstance(scenario, _colav.Scenario):
        return scenario
    if isinstance(scenario, (str, os.PathLike)):
        return _colav.load_scenario_file(os.fspath(scenario))
    raise TypeError(f"scenario: expected a file path or a colav.Scenario, got {scenario!r}")


def _whole_number(name, value, minimum):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise ValueError(f"{name}: expected an integer >= {minimum}, got {value!r}")
    return int(value)


def _worlds(num_envs, scenarios):
    """(number of worlds, the loaded scenarios or None) of the vector environments' num_envs and
    scenarios arguments: num_envs training worlds (8 by default), or one per scenario."""
    if scenarios is None:
        return (8 if num_envs is None else _whole_number("num_envs", num_envs, 1)), None
    loaded = [_scenario(scenario) for scenario in scenarios]
    if not loaded or num_envs not in (None, len(loaded)):
        raise ValueError(
            f"num_envs: {num_envs} worlds for {len(loaded)} scenarios (give one or more "
            "scenarios and leave num_envs out)"
        )
    return len(loaded), loaded


def _values(resolved):
    return None if resolved is None else resolved.values


def _optional_seed(seed):
    return None if seed is None else _whole_number("seed", seed, 0)


def _check_options(options):
    """reset() takes Gymnasium's `options` argument; no option is defined yet."""
    if options is not None and not isinstance(options, dict):
        raise TypeError(f"options: expected a dict or None, got {options!r}")
    if options:
        raise ValueError(f"options: unknown option(s) {sorted(options)} (none is defined)")


class _Closed:
    """Stands in for the C++ environment after close(): any use is an error."""

    def __getattr__(self, name):
        raise RuntimeError("the environment is closed")


class Env(_EnvBase):
    """One world with the Gymnasium Env interface.

    Env(seed=0, scenario=None, render_mode=None, world=None, **settings): training worlds
    (episode k is the world of episode k of world 0 of make_vec(seed=seed, world=world)), or,
    with `scenario` (a scenario file path or a colav.Scenario), that scenario in every episode.
    `settings` are the env.* keys of the programs' configuration (colav.env_settings()), e.g.
    closeness="log", test_mode=True, max_steps=500. `world` holds train_ppo's world.* keys
    without "world." (colav.world_settings()), e.g. {"num_static": 22}: the training worlds are
    generated with them instead of the paper's. `settings` and `world` (None with a scenario) are
    also attributes, with every key's resolved value.

    Actions are used in double precision, as `simulate` uses them. step() returns
    (obs float32 [6 + 180*(1+scan_history)] ([186] by default), reward float, terminated bool,
    truncated bool, info); info is {} except on the last step of an episode: {"episode_metrics":
    {...}} (what evaluate records). state() gives the world behind the observation (the columns of
    a `simulate` trace).

    With render_mode="rgb_array", render() returns the scene now as a uint8 array
    [RENDER_SIZE, RENDER_SIZE, 3], drawn as `simulate --gif` draws its frames: the vessel (blue)
    in the middle of a 300 m wide view, its track, rays, path, obstacles.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}
    render_mode = None

    def __init__(self, seed=0, *, scenario=None, render_mode=None, world=None, **settings):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        resolved = _resolve(settings, "colav.Env")
        training_world = _training_world(world, scenario is not None, "colav.Env")
        self.settings = resolved.values
        self.world = _values(training_world)
        self.render_mode = render_mode
        self._core = _colav.SingleEnvironment(
            resolved, training_world if scenario is None else _scenario(scenario),
            _whole_number("seed", seed, 0), render=render_mode is not None,
        )
        self.observation_space = observation_space(self._core.observation_size)
        self.action_space = action_space()

    def reset(self, *, seed=None, options=None):
        """Starts the next episode, or with a seed episode 0 of that seed; returns (obs, {})."""
        _check_options(options)
        if gymnasium is not None:
            super().reset(seed=seed)  # seeds self.np_random, as Gymnasium expects
        return self._core.reset(_optional_seed(seed)), {}

    def step(self, action):
        obs, reward, terminated, truncated, metrics = self._core.step(action)
        info = {} if metrics is None else {"episode_metrics": metrics}
        return obs, reward, terminated, truncated, info

    def state(self):
        """{"vessel": [x, y, psi, u, v, r], "cross_track_error", "heading_error",
        "look_ahead_heading_error", "progress", "path_length" (m), "collision", "ranges": [180]
        (m)}."""
        return self._core.state()

    def render(self):
        """The scene as a uint8 array [RENDER_SIZE, RENDER_SIZE, 3] with render_mode="rgb_array";
        None without a render mode."""
        if self.render_mode is None:
            return None
        return self._core.render(RENDER_SIZE, RENDER_SIZE)

    def close(self):
        self._core = _Closed()


class VectorEnv(_VectorEnvBase):
    """A batch of worlds stepped together in C++ on a thread pool, with the GIL released.

    VectorEnv(num_envs=8, seed=0, scenarios=None, num_threads=0, world=None, world2=None,
    world2_share=0.0, **settings): num_envs training worlds (episode k of world i is generated
    from the seed, i and k alone, as colav.training_scenario(colav.training_episode_seed(seed, i,
    k), world=world)), or one world per entry of `scenarios` (scenario file paths or
    colav.Scenario objects, e.g. colav.training_scenario(s)) replaying it in every episode.
    num_threads 0 uses every core. `settings` and `world` (every world generated with it) as for
    colav.Env. A mix of two kinds of world, as train_ppo's world2.* keys and world2.share make
    it: the last round(world2_share * num_envs) worlds are generated with `world2` (a dict as
    `world`) instead, e.g. world={"static_displacement_sd": 125},
    world2={"moving_displacement_sd": 250}, world2_share=0.5 (the best_mixed recipe's worlds).

    step(actions [N, 2]) returns (obs float32 [N, 6 + 180*(1+scan_history)] ([N, 186] by
    default), reward float32 [N], terminated bool [N], truncated bool [N], info). float32 actions
    are read in place, other dtypes are converted.

    Autoreset (same step, as EnvPool): a world whose episode ends on a step is reset within that
    step. The returned obs row is already the first observation of its next episode, and
    terminated/truncated say the previous one ended; info then holds "final_obs" (shaped as obs:
    the last observation of the finished episode) and "episode_metrics" ({metric: [N]}), with the
    masks "_final_obs" and "_episode_metrics" marking the worlds concerned. Otherwise info is {}.

    The returned arrays belong to the environment and are not allocated per step: the next step
    writes to a second set, and the step after that overwrites them. Copy what you keep longer.
    """

    metadata = {"autoreset_mode": _SAME_STEP, "render_modes": []}
    render_mode = None

    def __init__(self, num_envs=None, seed=0, *, scenarios=None, num_threads=0, world=None,
                 world2=None, world2_share=0.0, **settings):
        resolved = _resolve(settings, "colav.VectorEnv")
        training_world, second_world, share = _vector_worlds(
            self, world, world2, world2_share, scenarios is not None, "colav.VectorEnv")
        self.settings = resolved.values
        threads = _whole_number("num_threads", num_threads, 0)
        count, loaded = _worlds(num_envs, scenarios)
        if loaded is None:
            self._core = _colav.VectorEnvironment(
                resolved, training_world, second_world, share, count,
                _whole_number("seed", seed, 0), threads
            )
        else:
            self._core = _colav.VectorEnvironment(resolved, loaded, threads)
        self.num_envs = self._core.num_envs
        self.single_observation_space = observation_space(self._core.observation_size)
        self.single_action_space = action_space()
        self.observation_space = observation_space(self._core.observation_size, self.num_envs)
        self.action_space = action_space(self.num_envs)
        self.closed = False

    def reset(self, *, seed=None, options=None):
        """New episodes everywhere: the next ones, or with a seed episode 0 of that seed (one
        integer for all worlds). Returns (obs, {})."""
        _check_options(options)
        if isinstance(seed, (list, tuple)):
            raise ValueError("seed: give one integer; it seeds every world")
        if gymnasium is not None:
            super().reset(seed=seed)  # seeds self.np_random, as Gymnasium expects
        return self._core.reset(_optional_seed(seed)), {}

    def step(self, actions):
        obs, reward, terminated, truncated, finished = self._core.step(actions)
        info = self._core.finished_episodes() if finished else {}
        return obs, reward, terminated, truncated, info

    def render(self):
        """No render modes yet: returns None."""
        return None

    def close(self, **kwargs):
        self._core = _Closed()
        self.closed = True


def make(seed=0, *, scenario=None, world=None, **settings):
    """colav.Env(seed, scenario=..., world=..., **settings)."""
    return Env(seed, scenario=scenario, world=world, **settings)


def make_vec(num_envs=None, seed=0, *, scenarios=None, num_threads=0, world=None, world2=None,
             world2_share=0.0, **settings):
    """colav.VectorEnv(num_envs, seed, scenarios=..., num_threads=..., world=..., world2=...,
    world2_share=..., **settings)."""
    return VectorEnv(num_envs, seed, scenarios=scenarios, num_threads=num_threads, world=world,
                     world2=world2, world2_share=world2_share, **settings)

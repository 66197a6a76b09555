"""crowdsim_bench: the crowdsim-bench simulator and benchmark from Python.

    import crowdsim_bench as cb
    env = cb.Env("suites/quick.yaml", row="orca")      # a suite row's worlds, humans, sensors
    obs, info = env.reset(seed=0)                       # seed = the suite's episode index
    obs, reward, terminated, truncated, info = env.step([0.5, 0.0])   # velocity, m/s, world frame

    cb.evaluate(my_policy, "suites/quick.yaml", row="orca", out="runs/mine")  # the CLI's outputs
    cb.run_suite("suites/quick.yaml")                   # the table as a list of dicts
    venv = cb.VectorEnv("suites/quick.yaml", row="orca", num_envs=16)  # batches, stepped in C++

Env follows the Gymnasium API (reset/step/action_space/observation_space); it subclasses
gymnasium.Env (and VectorEnv gymnasium.vector.VectorEnv) when gymnasium is installed, passes
gymnasium.utils.env_checker.check_env, and works the same without it. Episodes are those of
the suite: `reset(seed=k)` (or `options={"episode": k}`) is episode k of the row, exactly as
`crowdsim-bench run` simulates it, so a policy stepped from Python meets the same scenarios.
With gymnasium, importing the package registers ids such as "crowdsim_bench/Table1-v0" for
gymnasium.make (ENV_IDS; docs/gymnasium.md).
"""
from __future__ import annotations

import math
import os
import sys
from typing import Any, Callable, Sequence

try:
    import numpy as np

    from . import _core
except ImportError as _error:  # another interpreter than the build's (pyenv, conda, a venv)
    # The folder holding this package (build/python, or an install's dist-packages).
    _parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    # The .deb only recommends python3-numpy: said first when numpy is what is missing.
    _numpy = (
        f"crowdsim_bench needs numpy, which {sys.executable} cannot import: install it (Debian: "
        "apt install python3-numpy), or use the interpreter the package is built for. "
        if getattr(_error, "name", None) == "numpy"
        else ""
    )
    raise ImportError(
        f"{_numpy}crowdsim_bench cannot be imported by {sys.executable} (Python "
        f"{sys.version_info.major}.{sys.version_info.minor}): {_error}. The package is built for "
        "the interpreter the build found, Debian's /usr/bin/python3 unless the build was "
        f"configured with -DPython3_EXECUTABLE=...; run e.g. `PYTHONPATH={_parent} "
        "/usr/bin/python3 your_script.py`"
    ) from _error

__version__ = _core.__version__

try:  # optional: Debian 12 has no gymnasium package
    import gymnasium as _gym
    import gymnasium.vector  # noqa: F401  (VectorEnv's base, batch_space)
    from gymnasium import spaces as _spaces
except ImportError:  # pragma: no cover - depends on the machine
    _gym = None
    _spaces = None

# Info keys Gymnasium's wrappers and vector environments write themselves (RecordEpisodeStatistics:
# `episode`; same-step autoreset: `final_obs`, `final_info`; a vector info's masks: `_` + key):
# an info of Env or VectorEnv holding one made them fail (the suite's episode index is
# `episode_index`).
RESERVED_INFO_KEYS = frozenset(
    k for key in ("episode", "final_obs", "final_info") for k in (key, "_" + key))


class Box:
    """A box of real vectors (gymnasium.spaces.Box's contract, for machines without gymnasium)."""

    def __init__(self, low, high, shape, dtype=np.float64, seed=None):
        self.shape = tuple(shape)
        self.dtype = np.dtype(dtype)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)

    def sample(self):
        if self.dtype == np.bool_ or np.issubdtype(self.dtype, np.integer):
            # Whole values, both bounds included (uniform reals cast down never gave `high`,
            # and a bool box was all True).
            return self._rng.integers(self.low.astype(np.int64), self.high.astype(np.int64),
                                      endpoint=True).astype(self.dtype)
        low = np.where(np.isfinite(self.low), self.low, -1e3)
        high = np.where(np.isfinite(self.high), self.high, 1e3)
        return self._rng.uniform(low, high).astype(self.dtype)

    def contains(self, x) -> bool:
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all(x >= self.low) and np.all(x <= self.high))

    def __repr__(self):
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"


class Dict(dict):
    """A dict of spaces (gymnasium.spaces.Dict's contract, for machines without gymnasium)."""

    def sample(self):
        return {k: v.sample() for k, v in self.items()}

    def contains(self, x) -> bool:
        return isinstance(x, dict) and x.keys() == self.keys() and all(
            self[k].contains(x[k]) for k in self)


def _box(low, high, shape, dtype=np.float64):
    if _spaces is not None:
        return _spaces.Box(low=low, high=high, shape=shape, dtype=dtype)
    return Box(low, high, shape, dtype)


def _dict(spaces: dict):
    return _spaces.Dict(spaces) if _spaces is not None else Dict(spaces)


def _discrete_space(n: int):
    return _spaces.Discrete(n) if _spaces is not None else _DiscreteSpace(n)


def _batch_space(space, n: int):
    """`n` of a space side by side, as a vector environment's batch (gymnasium's batch_space:
    a Box gains a leading axis, a Discrete becomes a MultiDiscrete)."""
    if _spaces is not None:
        return _gym.vector.utils.batch_space(space, n)
    if isinstance(space, Dict):
        return Dict({k: _batch_space(v, n) for k, v in space.items()})
    if isinstance(space, _DiscreteSpace):
        return Box(0, space.n - 1, (n,), dtype=np.int64)
    return Box(np.broadcast_to(space.low, (n,) + space.shape),
               np.broadcast_to(space.high, (n,) + space.shape), (n,) + space.shape, space.dtype)


# Sensors whose readings' bounds this package knows (sensors/*/README.md).
_KNOWN_SENSORS = ("person", "lidar2d", "route")
# Slack on bounds that the core reaches through a rotation or a product (route's waypoint):
# rounding may pass them by an ulp or two.
_ROUNDING = 1e-9


def _last_time(time_limit: float, time_step: float) -> float:
    """The latest `time` an observation can hold: that of the step which times the episode out,
    the first k * time_step at or past time_limit - 1e-9 (the core's rule and arithmetic), which
    passes time_limit when the time step does not divide it."""
    k = max(1, math.ceil((time_limit - 1e-9) / time_step))
    while k > 1 and (k - 1) * time_step >= time_limit - 1e-9:
        k -= 1
    while k * time_step < time_limit - 1e-9:
        k += 1
    return k * time_step


def _observation_spaces(core, probe: dict) -> dict:
    """One observation's spaces by key, bounded where the suite row fixes the bounds: `time` by
    the timeout step, `lidar` by the range sensor's max_range, `route`'s waypoint by its
    lookahead (and its distance >= 0), `humans_mask` 0/1, the robot's heading by +-pi and
    radii and v_pref >= 0. Positions and velocities stay unbounded (a world declares no
    extent). `core`: a _core.Env of the row; `probe`: one of its observations (the keys and
    shapes of the other sensors' features)."""
    inf = np.inf
    sensors = list(core.sensor_params)  # [(plugin name, {parameter: value})], the row's order
    humans = core.humans
    robot_low = np.array([-inf] * 6 + [0.0, 0.0, -np.pi])  # radius, v_pref >= 0; heading
    robot_high = np.array([inf] * 8 + [np.pi])
    humans_low = np.full((humans, 5), -inf)
    humans_low[:, 4] = 0.0  # radius (0 in the padding rows)
    spaces = {
        "robot": _box(robot_low, robot_high, (9,)),
        "time": _box(0.0, _last_time(core.time_limit, core.time_step), ()),
        "humans": _box(humans_low, inf, (humans, 5)),
        "humans_mask": _box(0, 1, (humans,), dtype=np.bool_),
    }
    if "lidar" in probe:
        # The ranges of the first sensor giving any: a lidar2d's unless a sensor this package
        # does not know comes before it (it may give ranges of its own).
        max_range = inf
        for name, params in sensors:
            if name == "lidar2d":
                max_range = float(params["max_range"])
                break
            if name not in _KNOWN_SENSORS:
                break
        spaces["lidar"] = _box(0.0, max_range, np.shape(probe["lidar"]))
    for name, value in probe.items():  # other sensors' features under their name (route, ...)
        if name in spaces:
            continue
        shape = np.shape(value)
        params = next((p for n, p in sensors if n == name), None)
        if name == "route" and params is not None and shape == (3,):
            # Path distance (m) and the waypoint, at most `lookahead` from the robot.
            reach = float(params["lookahead"]) * (1.0 + _ROUNDING)
            spaces[name] = _box(np.array([0.0, -reach, -reach]), np.array([inf, reach, reach]),
                                shape)
        else:
            spaces[name] = _box(-inf, inf, shape)
    return spaces


def holonomic_actions(v_pref: float = 1.0, speeds: int = 5, rotations: int = 16,
                      stop: bool = True) -> np.ndarray:
    """CrowdNav's holonomic action set as velocities (n, 2): `speeds` exponentially spaced
    speeds up to v_pref times `rotations` directions, plus standing still (CrowdNav: 5 x 16 + 1)."""
    mags = [(math.exp((i + 1) / speeds) - 1) / (math.e - 1) * v_pref for i in range(speeds)]
    angles = np.linspace(0.0, 2 * math.pi, rotations, endpoint=False)
    acts = [(0.0, 0.0)] if stop else []
    acts += [(m * math.cos(a), m * math.sin(a)) for a in angles for m in mags]
    return np.asarray(acts, dtype=np.float64)


def unicycle_actions(v_pref: float = 1.0, time_step: float = 0.25, speeds: int = 5,
                     rotations: int = 16, stop: bool = True) -> np.ndarray:
    """CrowdNav's unicycle action set as commands (n, 2) = (linear m/s, angular rad/s): standing
    still, then `rotations` turns linspace(-pi/4, pi/4) per step (outer) times `speeds`
    exponentially spaced speeds up to v_pref (inner); a turn r is the angular speed r / time_step
    (CrowdNav: 5 x 16 + 1)."""
    mags = [(math.exp((i + 1) / speeds) - 1) / (math.e - 1) * v_pref for i in range(speeds)]
    turns = np.linspace(-math.pi / 4, math.pi / 4, rotations) if rotations > 1 else [0.0]
    acts = [(0.0, 0.0)] if stop else []
    acts += [(m, r / time_step) for r in turns for m in mags]
    return np.asarray(acts, dtype=np.float64)


def _action_set(core, discrete: bool):
    """The robot's actions and action space: velocities (vx, vy) for a holonomic robot, (linear,
    angular) commands for a unicycle or diff_drive one; with `discrete`, CrowdNav's 81 of them."""
    v = core.v_pref
    if core.kinematics == "holonomic":
        actions = holonomic_actions(v)
        space = _box(-v, v, (2,))
    else:
        actions = unicycle_actions(v, core.time_step)
        w = core.angular_speed_max
        space = _box(np.array([-v, -w]), np.array([v, w]), (2,))
    return actions, (_discrete_space(len(actions)) if discrete else space)


def _settings(set) -> list[str]:
    """`set=` as the core takes it: one "key.path=value" string or a sequence of them."""
    if isinstance(set, str):
        return [set]
    items = list(set)
    for item in items:
        if not isinstance(item, str):
            raise TypeError(f"set must be a 'key.path=value' string or a list of them "
                            f"(e.g. set=['humans.count=10']), got the entry {item!r}")
    return items


_MAX_EPISODE = 2**31 - 1


def _is_whole(value) -> bool:
    """An int or numpy integer, not a bool (True would pass for 1)."""
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def _episode_index(value, what: str) -> int:
    """A suite episode index (reset's seed or options['episode']): a whole number >= 0."""
    if not _is_whole(value):
        raise TypeError(f"{what} must be a whole number (the suite's episode index), got {value!r}")
    if not 0 <= int(value) <= _MAX_EPISODE:
        raise ValueError(f"{what} must be an episode index in [0, {_MAX_EPISODE}], got {value}")
    return int(value)


def _action_indices(actions, count: int, shape: tuple) -> np.ndarray:
    """Discrete actions: whole numbers in [0, count) of the given shape (no float truncation,
    no negative indexing from the end)."""
    a = np.asarray(actions)
    if a.shape == (1,) and shape == ():  # one index in a 1-element array, as some agents give
        a = a.reshape(())
    if a.dtype == np.bool_ or not np.issubdtype(a.dtype, np.integer):
        raise ValueError(f"discrete actions must be whole numbers in [0, {count - 1}] (indices "
                         f"into .actions), got {actions!r}")
    if a.shape != shape:
        raise ValueError(f"discrete actions must have shape {shape}, got shape {a.shape}")
    if a.size and (a.min() < 0 or a.max() >= count):
        raise ValueError(f"discrete actions must be in [0, {count - 1}] (indices into .actions), "
                         f"got {actions!r}")
    return a.astype(np.int64)


class _SeededWithoutGymnasium:
    """gymnasium.Env's and gymnasium.vector.VectorEnv's own part, for machines without
    gymnasium (Debian 12): `reset(seed=k)` seeds `np_random` (numpy's default generator, as
    Gymnasium's seeding makes it), and `unwrapped` is the environment itself."""

    _np_random = None

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        if seed is not None:
            self._np_random = np.random.default_rng(seed)

    @property
    def np_random(self) -> np.random.Generator:
        if self._np_random is None:  # unseeded: from fresh entropy, as Gymnasium's
            self._np_random = np.random.default_rng()
        return self._np_random

    @property
    def unwrapped(self):
        return self


def _python_int(seed):
    """A numpy integer seed as a Python int (Gymnasium's seeding takes only those)."""
    return int(seed) if isinstance(seed, np.integer) else seed


_Base = _gym.Env if _gym is not None else _SeededWithoutGymnasium


class _ClosedByWith:
    """A `with` block closes the environment at its end, as gymnasium.Env's does, also on
    machines without gymnasium (Debian 12): Env and VectorEnv."""

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        self.close()
        return False


class Env(_ClosedByWith, _Base):
    """One suite row's episodes, stepped from Python (Gymnasium API).

    Observation (dict of float64 arrays): `robot` (9,) = x, y, vx, vy, goal x, goal y, radius,
    v_pref, heading (world frame, m, m/s, rad); `humans` (H, 5) = x, y, vx, vy, radius of the
    people the person sensor sees, in the robot's frame (x towards the goal), padded to the row's
    human count with `humans_mask` (H,) marking real rows; `lidar` (beams,) ranges in m (only
    when the row has a range sensor); and under its name each sensor reporting other features
    (`route` (3,): path distance to the goal, waypoint x, y in the robot's frame); `time` ()
    in s. The observation space bounds what the row fixes: `time` by the timeout step, `lidar`
    by the sensor's max_range, `route`'s waypoint by its lookahead, `humans_mask` 0/1; positions
    and velocities are unbounded. Action: a velocity (vx, vy) in m/s, world frame, or with
    `discrete=True` an index into `actions` (CrowdNav's 81 holonomic actions). On a row whose
    robot is a unicycle or diff_drive (docs/kinematics.md), an action is a command (linear m/s,
    angular rad/s), `actions` CrowdNav's 81 unicycle commands, and `robot`'s heading the body's
    (the frame of `humans` and `lidar` turns with it). Reward: the harness's (success 1, collision -0.25, discomfort penalty). `terminated` on success or
    collision, `truncated` on timeout; `info["status"]` names the outcome and
    `info["episode_index"]` the suite's episode (never `episode`, which Gymnasium's
    RecordEpisodeStatistics writes: RESERVED_INFO_KEYS).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 4}

    def __init__(self, suite: str, row: str | int = 1, *, set: Sequence[str] = (),
                 discrete: bool = False, record: bool = False, render_mode: str | None = None):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode must be None or 'rgb_array', got {render_mode!r}")
        self._env = _core.Env(str(suite), row, _settings(set))
        self.render_mode = render_mode
        self._record = record or render_mode == "rgb_array"
        self.metadata = dict(self.metadata, render_fps=round(1.0 / self._env.time_step))
        self._episode = -1
        self._done = True
        self.discrete = discrete
        self.actions, self.action_space = _action_set(self._env, discrete)
        self.observation_space = _dict(_observation_spaces(self._env, self._env.reset(0, False)))

    # -- Gymnasium API -----------------------------------------------------------------------
    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Starts an episode of the row and returns (obs, info). `seed=k` (or
        `options={"episode": k}`, which wins) is the suite's episode k, the same scenario as
        episode k of `crowdsim-bench run`, not a random seed; without either, the episode after
        the last one (0 first). A world of frozen layouts reuses them in turn (random_rect's 100:
        episode k + 100 has episode k's layout), so train on another split (set=
        "world.split=train") than the one tested. `seed` also seeds `np_random` (Gymnasium's
        rule). info: `episode_index` (the suite's episode k), `layout` (the world's name)."""
        if options and "episode" in options:
            episode = _episode_index(options["episode"], 'options["episode"]')
        elif seed is not None:
            episode = _episode_index(seed, "seed")
        else:
            episode = self._episode + 1
            if episode > _MAX_EPISODE:
                raise ValueError(f"episode {self._episode} was the last episode index: call "
                                 f"reset(seed=k) with k in [0, {_MAX_EPISODE}]")
        super().reset(seed=_python_int(seed))  # seeds np_random (gymnasium.Env's or the stand-in)
        obs = self._env.reset(episode, self._record)
        self._episode = episode
        self._done = False
        return self._obs(obs), {"episode_index": episode, "layout": self._env.result()["layout"]}

    def step(self, action):
        """Moves the robot for one time step and returns (obs, reward, terminated, truncated,
        info). `action`: a velocity (vx, vy) in m/s, world frame (any array-like of two finite
        numbers), or with `discrete=True` an index into `actions`. `terminated` on success,
        collision or policy_error (a velocity above 10 x v_pref), `truncated` on timeout;
        info["status"] names the outcome and, at the episode's end, info also holds its metrics
        (those of `result()`, the episode index as `episode_index`). Stepping an ended episode
        is an error: call reset()."""
        if self._episode < 0:
            raise ValueError("step() before reset(): call reset() first (Gymnasium's order)")
        if self.discrete:
            velocity = self.actions[_action_indices(action, len(self.actions), ())]
        else:
            velocity = np.asarray(action, dtype=np.float64).reshape(-1)
            if velocity.shape != (2,) or not np.all(np.isfinite(velocity)):
                raise ValueError(f"action must be {self._action_form()}, got {action!r}")
        obs, reward, status, error = self._env.step(float(velocity[0]), float(velocity[1]))
        terminated = status in ("success", "collision_human", "collision_obstacle", "policy_error")
        truncated = status == "timeout"
        info = {"status": status}
        if error:
            info["error"] = error
        if terminated or truncated:
            result = self._env.result()
            result["episode_index"] = result.pop("episode")  # `episode` is Gymnasium's
            info.update(result)
        return self._obs(obs), float(reward), terminated, truncated, info

    def _action_form(self) -> str:
        return ("a finite velocity (vx, vy)" if self._env.kinematics == "holonomic" else
                "a finite command (linear m/s, angular rad/s) for this " + self._env.kinematics +
                " robot")

    @property
    def kinematics(self) -> str:
        """The robot's motion model: holonomic, unicycle or diff_drive (docs/kinematics.md)."""
        return self._env.kinematics

    def render(self):
        """With render_mode="rgb_array": the episode so far as an (height, width, 3) uint8
        array, drawn as the CLI's animation frames are (map, trails, discs, clock, key)."""
        if self.render_mode != "rgb_array":
            return None
        self._require_episode("render()")
        return self._env.render(1.0)

    def close(self):
        """Releases the episode and the suite row (a process holds at most 256 Env, VectorEnv
        and running evaluate() at once); the Env cannot be used afterwards."""
        self._env = _Closed("Env")

    # -- extras ------------------------------------------------------------------------------
    @property
    def episodes(self) -> int:
        """Episodes the suite runs per row (its `episodes:`)."""
        return self._env.episodes

    @property
    def time_step(self) -> float:
        return self._env.time_step

    def result(self) -> dict:
        """The current episode's metrics (status, time, path length, ...; `episode`: its index,
        as in episodes.csv)."""
        self._require_episode("result()")
        return self._env.result()

    def positions(self) -> np.ndarray:
        """Recorded positions (frames, 1 + humans, 2), robot first; needs `record=True`."""
        if not self._record:
            raise ValueError("positions() needs the episode recorded: Env(..., record=True) "
                             "(or render_mode='rgb_array')")
        self._require_episode("positions()")
        return self._env.positions()

    def _require_episode(self, what: str):
        if self._episode < 0:  # the constructor's probe episode is not the user's
            raise ValueError(f"{what} before reset(): no episode yet, call reset() first")

    @staticmethod
    def _obs(obs: dict) -> dict:
        obs["time"] = np.asarray(obs["time"], dtype=np.float64)
        return obs


class _Closed:
    """Stands in for the core object of a closed Env or VectorEnv: any use is a clear error."""

    def __init__(self, what: str):
        self._what = what

    def __getattr__(self, name):
        what = self.__dict__.get("_what", "environment")
        raise ValueError(f"this {what} was closed (close() released its suite row): "
                         f"make a new one")


class _DiscreteSpace:
    def __init__(self, n: int, seed=None):
        self.n = n
        self.shape = ()
        self.dtype = np.dtype(np.int64)
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)

    def sample(self) -> int:
        return int(self._rng.integers(self.n))

    def contains(self, x) -> bool:
        return _is_whole(x) and 0 <= int(x) < self.n

    def __repr__(self):
        return f"Discrete({self.n})"


def _out_folder(out) -> str:
    """evaluate's and run_suite's `out`: a folder as a str or os.PathLike (pathlib.Path), or
    None (or "") for the default folder under runs/."""
    if out is None:
        return ""
    try:
        return os.fspath(out)
    except TypeError:
        raise TypeError(f"out must be a folder path (a str or pathlib.Path), or None for the "
                        f"default folder under runs/; got {out!r}") from None


def _row_label(label, out: str) -> str:
    """evaluate's `label`: a row label as a suite's (not blank, no control characters) and,
    when it names the default folder runs/<suite name>.<label>, a folder name as a suite's
    `name` (a '/' made nested folders, '../' one outside runs/)."""
    if not isinstance(label, str):
        raise TypeError(f"label must be a str (the row's label in the tables), got {label!r}")
    if not label.strip() or any(ord(c) < 32 or ord(c) == 127 for c in label):
        raise ValueError(f"label must not be blank or contain control characters (line breaks, "
                         f"tabs), as a suite row's label; got {label!r}")
    if not out and not all(c.isascii() and (c.isalnum() or c in "_-.") for c in label):
        raise ValueError(f"label {label!r} names the default output folder runs/<suite name>."
                         f"<label>/: use only letters, digits, '_', '-', '.' in it, or give out=")
    return label


def _episode_count(episodes) -> int:
    """evaluate's and run_suite's `episodes`: None (or -1) for the suite's own count."""
    if episodes is None or (_is_whole(episodes) and episodes == -1):
        return -1
    if not _is_whole(episodes) or not 1 <= episodes <= _core.MAX_EPISODES:
        raise ValueError(f"episodes must be a whole number in [1, {_core.MAX_EPISODES}], or None "
                         f"for the suite's own count; got {episodes!r}")
    return int(episodes)


def evaluate(policy: Callable[[dict], Any], suite: str, row: str | int = 1, *,
             label: str = "python", out: str | os.PathLike | None = None,
             episodes: int | None = None, fresh: bool = True, set: Sequence[str] | str = (),
             progress: bool = False) -> list[dict]:
    """Runs one suite row with `policy(obs) -> (vx, vy)` as the robot (obs as in Env) and writes
    the CLI's outputs (table.md, table.csv, episodes.csv, manifest.json) to `out` (default
    runs/<suite name>.<label>/, beside the CLI's runs/<suite name>/). Returns the table rows as
    dicts. The policy is called once per step, episode after episode, with no reset: one that
    keeps state across steps (a recurrent network) starts an episode when obs["time"] == 0.
    A policy that raises ends that episode as policy_error with the message
    (episodes.csv's `error` column; a RuntimeWarning says how many). Ctrl-C (or a
    KeyboardInterrupt / SystemExit from the policy) stops the evaluation: the finished episodes
    stay in `out`, and the exception is raised again here. `label` names the row in the tables
    (and, without `out`, the folder: letters, digits, '_', '-', '.'). `episodes`: None for the
    suite's count. `fresh=True` plays every episode again, replacing the results of an earlier
    evaluation in `out` of the same row, label and suite settings; a folder holding anything
    else (a CLI run, another row or label, the suite or set= since changed) is refused: remove
    it or give another `out`. `fresh=False` resumes stored episodes: only safe when the
    policy has not changed since."""
    out = _out_folder(out)
    return _core.evaluate(policy, str(suite), row, _row_label(label, out), out,
                          _episode_count(episodes), fresh, _settings(set), progress)


def run_suite(suite: str, *, out: str | os.PathLike | None = None, jobs: int = 1,
              episodes: int | None = None, fresh: bool = False, set: Sequence[str] | str = (),
              progress: bool = False, dataframe: bool = False):
    """Runs a suite file as `crowdsim-bench run` does (results in `out`, default runs/<name>/);
    returns its table as a list of dicts (a pandas DataFrame with dataframe=True)."""
    if not _is_whole(jobs) or not 1 <= jobs <= _core.MAX_JOBS:
        raise ValueError(f"jobs must be a whole number in [1, {_core.MAX_JOBS}], got {jobs!r}")
    if dataframe:
        try:
            import pandas as pd  # before the run, not after hours of it
        except ModuleNotFoundError as e:
            raise ModuleNotFoundError(
                "run_suite(dataframe=True) needs pandas (apt install python3-pandas); "
                "without dataframe=True the table comes as a list of dicts") from e
    rows = _core.run_suite(str(suite), _out_folder(out), int(jobs), _episode_count(episodes),
                           fresh, _settings(set), progress)
    if dataframe:
        return pd.DataFrame(rows)
    return rows


def data_root() -> str:
    """The folder the package and the CLI find the project's data in (suites/, worlds/,
    results/models/): $CROWDSIM_DATA_DIR, else PREFIX/share/crowdsim-bench of an installed copy,
    else the source tree the build came from."""
    return _core.data_root()


from .vector import STATUS_NAMES, VectorEnv  # noqa: E402  (uses the helpers above)
from .registration import ENV_IDS, register_envs  # noqa: E402

register_envs()  # gymnasium.make("crowdsim_bench/Table1-v0"), ...; nothing without gymnasium

__all__ = ["Env", "VectorEnv", "STATUS_NAMES", "ENV_IDS", "RESERVED_INFO_KEYS", "evaluate",
           "run_suite", "holonomic_actions", "unicycle_actions", "data_root", "Box", "Dict", "__version__"]

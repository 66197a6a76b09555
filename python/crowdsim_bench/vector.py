"""VectorEnv: n copies of a suite row's episodes stepped together in C++."""
from __future__ import annotations

from typing import Sequence

import numpy as np

from . import _ClosedByWith, _core, _gym, _SeededWithoutGymnasium

STATUS_NAMES = tuple(_core.STATUS_NAMES)

if _gym is not None:
    _VectorBase = _gym.vector.VectorEnv
    # Gymnasium >= 1.1 names the mode with an enum; 1.0 knew next-step autoreset alone.
    _MODES = getattr(_gym.vector, "AutoresetMode", None)
    _NEXT_STEP = _MODES.NEXT_STEP if _MODES is not None else "next_step"
else:  # Debian 12: no gymnasium
    _VectorBase = _SeededWithoutGymnasium
    _NEXT_STEP = "next_step"


# The most sub-environments one VectorEnv makes: 4,096 take about 80 s and 260 MB to build.
MAX_NUM_ENVS = 4096


class VectorEnv(_ClosedByWith, _VectorBase):
    """`num_envs` environments of one suite row, stepped in C++ with numpy batches.

    Follows Gymnasium's vector API (a gymnasium.vector.VectorEnv when gymnasium is installed,
    so its vector wrappers take it): `reset(seed=k)` starts episodes k, k+1, ..., k+n-1 of the
    row (default 0) and seeds `np_random`; sub-environment i then plays episodes k+i, k+i+n,
    k+i+2n, ... whatever the thread count, so a batch run is reproducible. Observations are the
    Env's dict with a leading batch axis (`robot` (n, 9), `humans` (n, H, 5), `humans_mask`
    (n, H), `lidar` (n, beams), `time` (n,), other sensors' features under their name, e.g.
    `route` (n, 3)); `single_observation_space` is the Env's. `step(actions)` takes (n, 2)
    velocities (m/s, world frame) or, with `discrete=True`, (n,) indices into `actions`, and
    returns obs, reward (n,), terminated (n,), truncated (n,), info with `status` (n,) codes
    into STATUS_NAMES and `episode_index` (n,), each with its Gymnasium mask (`_status`,
    `_episode_index`: all True, one read-only array). Autoreset is Gymnasium's "next step" mode
    (`metadata["autoreset_mode"]`): the step after a sub-environment ended resets it, ignores
    its action and returns the new episode's first observation with reward 0. `threads` > 1
    steps the sub-environments on that many threads (the caller's included; the GIL is
    released while they run).
    """

    metadata = {"autoreset_mode": _NEXT_STEP}

    def __init__(self, suite: str, row: str | int = 1, num_envs: int = 16, *,
                 set: Sequence[str] | str = (), discrete: bool = False, threads: int = 1):
        from . import (_action_set, _batch_space, _dict, _is_whole, _observation_spaces,
                       _settings)
        for name, count in (("num_envs", num_envs), ("threads", threads)):
            if not _is_whole(count) or count < 1:  # 2.5 ran 2, threads=0 or -3 ran one
                raise ValueError(f"{name} must be a whole number >= 1, got {count!r}")
        if num_envs > MAX_NUM_ENVS:
            raise ValueError(
                f"num_envs must be at most {MAX_NUM_ENVS}, got {num_envs!r}: each environment "
                "holds its own plugins (about 20 ms to make and 64 kB); for more, run several "
                "VectorEnvs in separate processes")
        settings = _settings(set)
        self._env = _core.VectorEnv(str(suite), row, int(num_envs), settings, int(threads))
        self.num_envs = self._env.num_envs
        self.discrete = discrete
        probe = _core.Env(str(suite), row, settings)
        self.actions, self.single_action_space = _action_set(probe, discrete)
        self.action_space = _batch_space(self.single_action_space, self.num_envs)
        self.single_observation_space = _dict(_observation_spaces(probe, probe.reset(0, False)))
        self.observation_space = _batch_space(self.single_observation_space, self.num_envs)
        # The info keys' masks (every sub-environment has each key): one read-only array.
        self._everyone = np.ones(self.num_envs, dtype=np.bool_)
        self._everyone.flags.writeable = False

    @property
    def threads(self) -> int:
        return self._env.threads

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Starts episodes k, k+1, ..., k+n-1 of the row (k: `seed` or `options["episode"]`,
        default 0) and returns (obs, info) with info["episode_index"] (n,). `seed` also seeds
        `np_random`. Every sub-environment starts again: there is no `options["reset_mask"]`
        (they reset themselves on the step after their episode ended)."""
        from . import _MAX_EPISODE, _episode_index, _python_int
        if options and "reset_mask" in options:
            raise ValueError('options["reset_mask"] is not supported: VectorEnv resets a '
                             "sub-environment itself on the step after its episode ended "
                             '(metadata["autoreset_mode"]: next step); reset() starts them all')
        if options and "episode" in options:
            first = _episode_index(options["episode"], 'options["episode"]')
        else:
            first = _episode_index(seed, "seed") if seed is not None else 0
        if first > _MAX_EPISODE - (self.num_envs - 1):
            raise ValueError(f"the episodes {first}..{first + self.num_envs - 1} pass the last "
                             f"episode index {_MAX_EPISODE}")
        super().reset(seed=_python_int(seed))  # seeds np_random (Gymnasium's or the stand-in)
        obs = self._env.reset(first)
        episode = obs.pop("episode")
        return obs, {"episode_index": episode, "_episode_index": self._everyone}

    def step(self, actions):
        """Steps every sub-environment: `actions` (n, 2) velocities (m/s, world frame), or for a
        unicycle or diff_drive robot commands (linear m/s, angular rad/s), or with
        `discrete=True` (n,) indices into `actions`. Returns obs, reward (n,), terminated (n,),
        truncated (n,), info with `status` (n,) codes into STATUS_NAMES and `episode_index`
        (n,). A sub-environment that ended is reset on the next step, its action ignored."""
        if self.discrete:
            from . import _action_indices
            velocities = self.actions[_action_indices(actions, len(self.actions), (self.num_envs,))]
        else:
            velocities = np.asarray(actions, dtype=np.float64)
        if velocities.shape != (self.num_envs, 2):
            raise ValueError(f"actions must be {self.num_envs} finite velocities, shape "
                             f"({self.num_envs}, 2); got shape {np.shape(actions)}")
        if not np.all(np.isfinite(velocities)):
            bad = sorted({int(i) for i in np.nonzero(~np.isfinite(velocities))[0]})
            raise ValueError(f"actions must be finite velocities; not those of sub-environments "
                             f"{bad}")
        obs, reward, terminated, truncated, status, episode = self._env.step(velocities)
        # Gymnasium's vector info: each key beside its mask `_key`.
        return obs, reward, terminated, truncated, {
            "status": status, "_status": self._everyone,
            "episode_index": episode, "_episode_index": self._everyone}

    def close(self, **kwargs):
        """Releases the environments and the suite row; the VectorEnv cannot be used
        afterwards."""
        from . import _Closed
        self._env = _Closed("VectorEnv")
        self.closed = True

"""The PPO training file: YAML, one key per hyper-parameter, each checked by type and range.

    name: table1_lidar_person          # -> results/train/ppo_<name>/
    suite: ../baselines.yaml           # the row whose worlds, humans and sensors train the policy
    row: orca_rect3                    # (its robot policy is replaced by the learner)
    set: ["rows[orca_rect3].world.split=train"]   # --set overrides, as the CLI's
    total_steps: 20000000
    ...

Defaults cite their source in KEYS (docs/training.md, "PPO" has the table)."""
from __future__ import annotations

import difflib
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional, Sequence, Tuple


class PPOError(Exception):
    """Bad input (configuration, suite row, checkpoint): the message names the key or file;
    `python3 -m crowdsim_bench.ppo` prints it without a traceback and exits 2."""


@dataclass(frozen=True)
class Key:
    default: Any
    kind: str  # int, float, bool, str, row, choice, list
    low: Optional[float] = None
    high: Optional[float] = None
    low_open: bool = False  # (low, high] instead of [low, high]
    choices: Tuple[str, ...] = ()
    source: str = ""
    # Changes the course of a training: a resumed checkpoint must have the same value.
    fixed: bool = True


REQUIRED = object()

# Every key of the training file. Sources: "PPO paper" = Schulman et al. 2017, "Proximal Policy
# Optimization Algorithms", Table 3 (MuJoCo) and Table 5 (Atari); "baselines" = OpenAI
# baselines' ppo2 defaults; "ours" = chosen here (docs/training.md says why).
KEYS: Dict[str, Key] = {
    "name": Key("", "str", source="the file's name without .yaml"),
    "description": Key("", "str", source="free text", fixed=False),
    "base": Key("", "str", source="a training file whose keys this one takes, except name and "
                "description (relative to this file's folder); this file's keys replace them",
                fixed=False),
    "suite": Key(REQUIRED, "str", source="required; relative to this file's folder, else the "
                 "working folder"),
    "row": Key(REQUIRED, "row", source="required; a row label or 1-based index"),
    "set": Key([], "list", source="--set overrides of the suite (KEY.PATH=VALUE)"),
    "seed": Key(1, "int", 0, 2**31 - 1, source="ours"),
    "discrete": Key(False, "bool", source="ours: false = Gaussian velocity; true = CrowdNav's "
                    "81 holonomic actions"),
    "num_envs": Key(16, "int", 1, 4096, source="ours (PPO paper Atari: 8 actors)"),
    "threads": Key(1, "int", 1, 256, source="ours; results do not depend on it", fixed=False),
    "steps_per_rollout": Key(128, "int", 1, 100000, source="PPO paper Atari horizon T = 128"),
    "epochs": Key(4, "int", 1, 100, source="ours (PPO paper: 10 MuJoCo, 3 Atari)"),
    "minibatch_size": Key(512, "int", 1, 10**7, source="ours (PPO paper: 64 MuJoCo, 256 Atari)"),
    "learning_rate": Key(3e-4, "float", 0.0, 1.0, low_open=True,
                         source="PPO paper MuJoCo, Adam 3e-4"),
    "lr_schedule": Key("constant", "choice", choices=("constant", "linear"),
                       source="PPO paper MuJoCo: constant (Atari: linear to 0)"),
    "adam_epsilon": Key(1e-5, "float", 0.0, 1.0, low_open=True, source="baselines"),
    "clip": Key(0.2, "float", 0.0, 1.0, low_open=True, source="PPO paper, epsilon = 0.2"),
    "gamma": Key(0.99, "float", 0.0, 1.0, source="PPO paper"),
    "gae_lambda": Key(0.95, "float", 0.0, 1.0, source="PPO paper"),
    "entropy_coef": Key(0.0, "float", 0.0, 1.0, source="PPO paper MuJoCo c2 = 0 (Atari 0.01)"),
    "value_coef": Key(0.5, "float", 0.0, 100.0, source="baselines (PPO paper Atari c1 = 1)"),
    "max_grad_norm": Key(0.5, "float", 0.0, 1000.0, source="baselines; 0 = no clipping"),
    "normalize_advantages": Key(True, "bool", source="baselines (per minibatch)"),
    "total_steps": Key(20_000_000, "int", 1, 10**12,
                       source="ours (environment steps, all environments together)",
                       fixed=False),
    "progress_reward": Key(0.1, "float", 0.0, 10.0,
                           source="ours: shaping per metre gained towards the goal (along the "
                           "route when the row has one)"),
    "collision_penalty": Key(0.0, "float", 0.0, 100.0,
                             source="ours: subtracted from the reward of a collision, beside "
                             "the environment's -0.25"),
    "collision_penalty_warmup": Key(0, "int", 0, 10**12,
                                    source="ours: environment steps over which the collision "
                                    "penalty rises linearly from 0 (0: in full from the start)"),
    "wall_penalty": Key(0.0, "float", 0.0, 10.0,
                        source="ours: subtracted per step at contact with a wall the lidar sees, "
                        "falling linearly to 0 at wall_distance (as CrowdNav's discomfort "
                        "penalty near people)"),
    "wall_distance": Key(0.2, "float", 0.0, 5.0, low_open=True,
                         source="m; the robot's surface to the nearest lidar return below which "
                         "wall_penalty applies (CrowdNav's discomfort_dist, 0.2 m)"),
    "frame": Key("goal", "choice", choices=("goal", "route"),
                 source="ours: the frame of the policy's inputs and actions, x towards the goal "
                 "(CrowdNav's rotate()) or towards the route sensor's waypoint"),
    "hidden": Key(128, "int", 8, 4096, source="ours: width of the two trunk layers"),
    "init_log_std": Key(-0.5, "float", -10.0, 2.0, source="ours (continuous only)"),
    "checkpoint_interval": Key(20, "int", 1, 10**6,
                               source="ours: updates between checkpoints (the environments "
                               "start new episodes there)"),
}


def _range_text(key: Key) -> str:
    left = "(" if key.low_open else "["
    return f"{left}{key.low:g}, {key.high:g}]"


def _check(path: str, name: str, key: Key, value: Any) -> Any:
    where = f"{path}: {name}"
    if key.kind in ("int", "row"):
        if key.kind == "row" and isinstance(value, str):
            if not value.strip():
                raise PPOError(f"{where} must name a row (its label or 1-based index), got ''")
            return value
        if not isinstance(value, int) or isinstance(value, bool):
            what = "a row label or 1-based index" if key.kind == "row" else "a whole number"
            raise PPOError(f"{where} must be {what}, got {value!r}")
        if key.kind == "row":
            if value < 1:
                raise PPOError(f"{where} = {value} is out of range: rows are numbered from 1")
            return value
    elif key.kind == "float":
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            raise PPOError(f"{where} must be a number, got {value!r}")
        value = float(value)
        if value != value:
            raise PPOError(f"{where} must be a number, got NaN")
    elif key.kind == "bool":
        if not isinstance(value, bool):
            raise PPOError(f"{where} must be true or false, got {value!r}")
        return value
    elif key.kind == "str":
        if not isinstance(value, str):
            raise PPOError(f"{where} must be text, got {value!r}")
        return value
    elif key.kind == "choice":
        if value not in key.choices:
            raise PPOError(f"{where} must be one of {', '.join(key.choices)}; got {value!r}")
        return value
    elif key.kind == "list":
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise PPOError(f"{where} must be a list of 'key.path=value' texts, got {value!r}")
        for v in value:
            if "=" not in v:
                raise PPOError(f"{where}: {v!r} is not 'key.path=value'")
        return list(value)
    if key.low is not None:
        below = value <= key.low if key.low_open else value < key.low
        if below or value > key.high:
            raise PPOError(f"{where} = {value!r} is out of range {_range_text(key)}")
    return value


def parse(data: Any, path: str = "<config>") -> Dict[str, Any]:
    """A training file's mapping -> every key's value (defaults filled in); PPOError names the
    file and key of the first problem."""
    if not isinstance(data, dict):
        raise PPOError(f"{path}: a PPO training file is a YAML mapping of keys "
                       f"({', '.join(KEYS)}), got {type(data).__name__}")
    config: Dict[str, Any] = {}
    for name in data:
        if name not in KEYS:
            close = difflib.get_close_matches(str(name), list(KEYS), n=1)
            hint = f" (did you mean '{close[0]}'?)" if close else ""
            raise PPOError(f"{path}: unknown key '{name}'{hint}; the keys are: "
                           f"{', '.join(KEYS)}")
    for name, key in KEYS.items():
        if name in data and data[name] is not None:
            config[name] = _check(path, name, key, data[name])
        elif key.default is REQUIRED:
            raise PPOError(f"{path}: the key '{name}' is required ({key.source})")
        else:
            config[name] = list(key.default) if isinstance(key.default, list) else key.default
    batch = config["num_envs"] * config["steps_per_rollout"]
    if config["minibatch_size"] > batch:
        raise PPOError(f"{path}: minibatch_size = {config['minibatch_size']} is larger than a "
                       f"rollout (num_envs x steps_per_rollout = {batch})")
    if not config["name"]:
        config["name"] = os.path.splitext(os.path.basename(path))[0]
    return config


def load(path: str, overrides: Sequence[str] = ()) -> Dict[str, Any]:
    """Reads and checks a training file, each `key=value` of `overrides` (YAML values, as
    `train --set`) replacing the file's; `suite` becomes a path that exists (this file's folder
    first, then the working folder)."""
    try:
        import yaml
    except ImportError as e:  # pragma: no cover - Debian's python3-yaml
        raise PPOError("reading a PPO training file needs PyYAML (apt install python3-yaml)") from e
    data = _read_with_bases(path, yaml, [])
    for override in overrides:
        key, sep, text = override.partition("=")
        if not sep or not key:
            raise PPOError(f"--set {override}: write KEY=VALUE, e.g. --set total_steps=100000")
        if not isinstance(data, dict):
            break  # parse() names what the file is instead
        try:
            data[key.strip()] = yaml.safe_load(text)
        except yaml.YAMLError as e:
            raise PPOError(f"--set {override}: not a YAML value ({str(e).splitlines()[0]})") from None
    config = parse(data, path)
    config["suite"] = resolve_suite(config["suite"], path)
    return config


def _read_with_bases(path: str, yaml: Any, chain: List[str]) -> Any:
    """The file's mapping over its `base:` chain's (a key replaces the base's whole value, a
    list too); a base's suite is rewritten relative to this file's folder, the same file."""
    try:
        with open(path, encoding="utf-8") as f:
            data = yaml.safe_load(f)
    except OSError as e:
        via = f" (the base of {chain[-1]})" if chain else ""
        raise PPOError(f"{path}{via}: cannot read the training file ({e.strerror})") from None
    except yaml.YAMLError as e:
        raise PPOError(f"{path}: not valid YAML ({str(e).splitlines()[0]})") from None
    if not isinstance(data, dict) or not data.get("base"):
        return data
    base = data["base"]
    if not isinstance(base, str):
        raise PPOError(f"{path}: base must be the path of a training file, got {base!r}")
    base_path = os.path.normpath(os.path.join(os.path.dirname(path), base))
    chain = chain + [os.path.normpath(path)]
    if base_path in chain:
        raise PPOError(f"{path}: base: {base} leads back to itself "
                       f"({' -> '.join(chain + [base_path])})")
    inherited = _read_with_bases(base_path, yaml, chain)
    if not isinstance(inherited, dict):
        parse(inherited, base_path)  # names what the base is instead of a mapping
    merged = {k: v for k, v in inherited.items() if k not in ("name", "description", "base")}
    if isinstance(merged.get("suite"), str) and "suite" not in data:
        suite = resolve_suite(merged["suite"], base_path)
        merged["suite"] = suite if os.path.isabs(suite) else os.path.relpath(
            suite, os.path.dirname(os.path.abspath(path)))
    merged.update(data)
    return merged


def resolve_suite(suite: str, config_path: str) -> str:
    here = os.path.join(os.path.dirname(os.path.abspath(config_path)), suite)
    for candidate in (here, suite):
        if os.path.isfile(candidate):
            return os.path.relpath(candidate) if not os.path.isabs(suite) else candidate
    raise PPOError(f"{config_path}: suite: no file {here} (nor {suite} in the working folder)")


def resolved_text(config: Dict[str, Any], source: str) -> str:
    """Every key's value as a training file of its own (no base), the record of what trained."""
    import yaml
    keys = {k: config[k] for k in KEYS if k != "base"}
    return (f"# {source} with its base and any --seed / --set resolved: every key's value.\n"
            + yaml.safe_dump(keys, sort_keys=False, width=100))


def canonical(config: Dict[str, Any]) -> Dict[str, Any]:
    """The keys that decide a training's course (what a resumed checkpoint must match)."""
    return {k: config[k] for k, key in KEYS.items() if key.fixed and k not in ("suite",)}

"""PPO training over crowdsim_bench.VectorEnv: rollouts, GAE, clipped-surrogate updates,
checkpoints, the learning curve and the TorchScript export."""
from __future__ import annotations

import collections
import ctypes
import csv
import json
import math
import os
import sys
import time
from typing import Any, Dict, List, Optional, TextIO

import numpy as np
import torch

from .. import STATUS_NAMES, VectorEnv
from . import config as config_module
from .config import PPOError
from .curve import write_svg
from .model import ActorCritic, ExportedPolicy

CHECKPOINT_FORMAT = "crowdsim_bench.ppo checkpoint"
CHECKPOINT_VERSION = 1
# Observation keys the encoder takes; any other sensor's features are refused (named).
KNOWN_KEYS = ("robot", "humans", "humans_mask", "lidar", "time", "route")
CURVE_COLUMNS = ["update", "steps", "episodes", "seconds", "steps_per_s", "collect_seconds",
                 "update_seconds", "mean_return",
                 "success", "collision", "timeout", "policy_loss", "value_loss", "entropy",
                 "approx_kl", "clip_fraction", "learning_rate"]
# Episodes the progress line's and the curve's rates are over.
WINDOW = 200


def atomic_write(path: str, write) -> None:
    """Writes `path` through a temporary file beside it and a rename: a crash or Ctrl-C leaves
    the old file or the new one, never half of one. `write(tmp_path)` writes the file."""
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def one_thread() -> None:
    """Keeps the arithmetic on the calling thread: torch's intra-op pool and OpenBLAS's own
    (Debian's torch multiplies through the pthread OpenBLAS, whose worker spins beside the main
    thread: a 1-thread training used two cores). The results do not depend on it."""
    torch.set_num_threads(1)
    try:
        with open("/proc/self/maps") as f:
            libraries = {line.split()[-1] for line in f if "openblas" in line}
    except OSError:
        return
    for path in libraries:
        try:
            ctypes.CDLL(path).openblas_set_num_threads(1)
        except (OSError, AttributeError):
            pass


def make_env(config: Dict[str, Any], num_envs: Optional[int] = None) -> VectorEnv:
    try:
        return VectorEnv(config["suite"], row=config["row"],
                         num_envs=num_envs or config["num_envs"], set=config["set"],
                         threads=config["threads"])
    except (ValueError, RuntimeError, TypeError, KeyError, OSError) as e:
        message = e.args[0] if isinstance(e, KeyError) and e.args else e
        raise PPOError(f"{config['suite']}, row {config['row']!r}: {message}") from None


def observation_layout(env: VectorEnv, where: str) -> Dict[str, Any]:
    """What the encoder needs to know of the row's observation; PPOError for one it cannot
    take (a sensor's features it does not know, a route of another shape)."""
    space = env.single_observation_space
    keys = list(space.keys())
    unknown = [k for k in keys if k not in KNOWN_KEYS]
    if unknown:
        raise PPOError(f"{where}: the row's observation has {', '.join(repr(k) for k in unknown)}, "
                       f"which the PPO encoder cannot take (it reads {', '.join(KNOWN_KEYS)}): "
                       "remove that sensor from the row or choose another row")
    for k in ("robot", "humans", "humans_mask", "time"):
        if k not in keys:
            raise PPOError(f"{where}: the row's observation has no {k!r}")
    if "route" in keys and tuple(space["route"].shape) != (3,):
        raise PPOError(f"{where}: the row's `route` has shape {tuple(space['route'].shape)}; the "
                       "PPO encoder takes the route sensor's (3,)")
    beams = int(space["lidar"].shape[0]) if "lidar" in keys else 0
    max_range = float(np.max(space["lidar"].high)) if beams else 0.0
    if not math.isfinite(max_range):
        max_range = 5.0
    time_limit = float(np.max(space["time"].high))
    return {"beams": beams, "max_range": max_range, "uses_route": "route" in keys,
            "time_limit": time_limit if math.isfinite(time_limit) else 0.0,
            "humans": int(space["humans"].shape[0])}


def build_model(config: Dict[str, Any], layout: Dict[str, Any]) -> ActorCritic:
    return ActorCritic(layout["beams"], layout["max_range"], layout["uses_route"],
                       layout["time_limit"], config["discrete"], hidden=config["hidden"],
                       init_log_std=config["init_log_std"], frame=config["frame"])


def tensors(obs: Dict[str, np.ndarray]) -> Dict[str, torch.Tensor]:
    return {k: torch.from_numpy(np.asarray(v)) for k, v in obs.items()}


def potential(obs: Dict[str, np.ndarray]) -> np.ndarray:
    """Distance to go: along the route when the row has one, else straight to the goal."""
    if "route" in obs:
        return np.asarray(obs["route"])[:, 0].copy()
    robot = obs["robot"]
    return np.hypot(robot[:, 4] - robot[:, 0], robot[:, 5] - robot[:, 1])


def wall_penalty(obs: Dict[str, np.ndarray], penalty: float, distance: float) -> np.ndarray:
    """Per environment: `penalty` at contact with what the lidar sees, falling linearly to 0
    where the robot's surface is `distance` from the nearest return."""
    gap = np.asarray(obs["lidar"]).min(axis=1) - np.asarray(obs["robot"])[:, 6]
    return penalty * np.clip(1.0 - gap / distance, 0.0, 1.0)


def export(model: ActorCritic, path: str) -> None:
    """The greedy policy as a TorchScript module for the `torchscript` plugin, written
    atomically."""
    scripted = torch.jit.script(ExportedPolicy(model).eval())
    atomic_write(path, lambda tmp: scripted.save(tmp))


def plugin_row(layout: Dict[str, Any], weights: str) -> str:
    sensors = "lidar+person" if layout["beams"] else "person"
    params = f"sensors: {sensors}, humans: {layout['humans']}"
    if layout["beams"]:
        params += f", lidar_beams: {layout['beams']}"
    if layout["uses_route"]:
        params += ", route: true"
    return f"{{label: ppo, policy: torchscript, weights: {weights}, params: {{{params}}}}}"


def _format_duration(seconds: float) -> str:
    seconds = int(max(0, seconds))
    h, rest = divmod(seconds, 3600)
    m, s = divmod(rest, 60)
    return f"{h}h{m:02d}m" if h else f"{m}m{s:02d}s"


class Trainer:
    """One training into `out`. `train()` runs it to `total_steps` (or `stop_after` updates,
    as an interruption would, for tests)."""

    def __init__(self, config: Dict[str, Any], out: str, resume: bool = False,
                 log: TextIO = sys.stderr, quiet: bool = False):
        self.config = config
        self.out = out
        self.log = log
        self.quiet = quiet
        self.checkpoint_path = os.path.join(out, "checkpoint.pt")
        self.curve_path = os.path.join(out, "learning_curve.csv")
        one_thread()
        if os.path.exists(self.checkpoint_path) and not resume:
            raise PPOError(f"{out}: holds a training already (checkpoint.pt): --resume continues "
                           "it, --out names another folder")
        checkpoint = self._read_checkpoint() if resume and os.path.exists(
            self.checkpoint_path) else None
        if resume and checkpoint is None:
            self._say(f"{out}: no checkpoint to resume; starting the training")
        self.env = make_env(config)
        where = f"{config['suite']}, row {config['row']!r}"
        self.layout = observation_layout(self.env, where)
        if config["frame"] == "route" and not self.layout["uses_route"]:
            raise PPOError(f"{where}: frame: route needs the route sensor in the row's sensors "
                           "(e.g. suites/table2_route.yaml's rows); frame: goal does without")
        if config["wall_penalty"] and not self.layout["beams"]:
            raise PPOError(f"{where}: wall_penalty needs a lidar in the row's sensors (it reads "
                           "the nearest return); set wall_penalty: 0 or add the lidar")
        torch.manual_seed(config["seed"])
        self.model = build_model(config, self.layout)
        self.optimizer = torch.optim.Adam(self.model.parameters(), lr=config["learning_rate"],
                                          eps=config["adam_epsilon"])
        self.batch = config["num_envs"] * config["steps_per_rollout"]
        # By status code (STATUS_NAMES): 1.0 for the collisions.
        self._collision = np.array([float(n.startswith("collision")) for n in STATUS_NAMES])
        self.total_updates = max(1, math.ceil(config["total_steps"] / self.batch))
        self.update = 0
        self.steps = 0
        self.episodes = 0
        self.next_episode = 0
        self.outcomes: collections.deque = collections.deque(maxlen=WINDOW)
        self.returns: collections.deque = collections.deque(maxlen=WINDOW)
        self.seconds = 0.0
        if checkpoint is not None:
            self._restore(checkpoint)
        os.makedirs(out, exist_ok=True)
        self._trim_curve()

    # -- checkpoints -------------------------------------------------------------------------
    def _read_checkpoint(self) -> Dict[str, Any]:
        path = self.checkpoint_path
        try:
            state = torch.load(path, map_location="cpu")
        except Exception as e:  # a damaged zip, a pickle of something else, ...
            first = (str(e).strip().splitlines() or [type(e).__name__])[0]
            raise PPOError(f"{path}: not a readable checkpoint ({first}); remove it (or the "
                           "folder) to train again") from None
        if not isinstance(state, dict) or state.get("format") != CHECKPOINT_FORMAT:
            raise PPOError(f"{path}: not a crowdsim_bench.ppo checkpoint (no '{CHECKPOINT_FORMAT}' "
                           "format tag); --out names another folder")
        if state.get("version") != CHECKPOINT_VERSION:
            raise PPOError(f"{path}: checkpoint version {state.get('version')!r}, this trainer "
                           f"reads version {CHECKPOINT_VERSION}")
        mine = config_module.canonical(self.config)
        # A key the checkpoint does not name came after it: it trained with the default.
        theirs = {k: config_module.KEYS[k].default for k in mine}
        theirs.update(state.get("config", {}))
        differ = sorted(k for k in set(mine) | set(theirs) if mine.get(k) != theirs.get(k))
        if differ:
            detail = "; ".join(f"{k}: {theirs.get(k)!r} there, {mine.get(k)!r} here" for k in differ)
            raise PPOError(f"{path}: the checkpoint was trained with another configuration "
                           f"({detail}); only total_steps, threads and description may change "
                           "on --resume")
        return state

    def _restore(self, state: Dict[str, Any]) -> None:
        try:
            self.model.load_state_dict(state["model"])
            self.optimizer.load_state_dict(state["optimizer"])
            torch.set_rng_state(state["torch_rng"])
        except (KeyError, RuntimeError, ValueError, TypeError) as e:
            raise PPOError(f"{self.checkpoint_path}: the checkpoint does not fit this "
                           f"configuration's network ({str(e).splitlines()[0]})") from None
        self.update = state["update"]
        self.steps = state["steps"]
        self.episodes = state["episodes"]
        self.next_episode = state["next_episode"]
        self.outcomes.extend(state["outcomes"])
        self.returns.extend(state["returns"])
        self.seconds = state["seconds"]

    def _write_checkpoint(self) -> None:
        state = {
            "format": CHECKPOINT_FORMAT, "version": CHECKPOINT_VERSION,
            "config": config_module.canonical(self.config),
            "model": self.model.state_dict(), "optimizer": self.optimizer.state_dict(),
            "torch_rng": torch.get_rng_state(), "update": self.update, "steps": self.steps,
            "episodes": self.episodes, "next_episode": self.next_episode,
            "outcomes": list(self.outcomes), "returns": list(self.returns),
            "seconds": self.seconds, "layout": self.layout,
        }
        atomic_write(self.checkpoint_path, lambda tmp: torch.save(state, tmp))
        export(self.model, os.path.join(self.out, "policy.pt"))
        rows = self._curve_rows()
        if rows:
            atomic_write(os.path.join(self.out, "learning_curve.svg"),
                         lambda tmp: write_svg(rows, tmp, self.config["name"]))

    def _trim_curve(self) -> None:
        """The curve as of the checkpoint: rows after it (a run interrupted later) dropped."""
        rows = [r for r in self._curve_rows() if int(r["update"]) <= self.update]

        def write(tmp):
            with open(tmp, "w", newline="") as f:
                w = csv.DictWriter(f, CURVE_COLUMNS)
                w.writeheader()
                w.writerows(rows)
        atomic_write(self.curve_path, write)

    def _curve_rows(self) -> List[Dict[str, str]]:
        if not os.path.exists(self.curve_path):
            return []
        with open(self.curve_path, newline="") as f:
            return list(csv.DictReader(f))

    # -- training ----------------------------------------------------------------------------
    def _say(self, text: str) -> None:
        if not self.quiet:
            print(text, file=self.log, flush=True)

    def _distribution(self, out: torch.Tensor):
        if self.config["discrete"]:
            return torch.distributions.Categorical(logits=out)
        return torch.distributions.Normal(out, self.model.log_std.exp().expand_as(out))

    def _log_prob(self, dist, action):
        lp = dist.log_prob(action)
        return lp if self.config["discrete"] else lp.sum(-1)

    def _entropy(self, dist):
        e = dist.entropy()
        return e if self.config["discrete"] else e.sum(-1)

    def _collision_penalty(self) -> float:
        """The collision penalty of the coming rollout: its full value, or a share of it
        rising linearly with the steps trained over `collision_penalty_warmup`."""
        c = self.config
        warmup = c["collision_penalty_warmup"]
        if not warmup:
            return c["collision_penalty"]
        return c["collision_penalty"] * min(1.0, self.steps / warmup)

    def _rollout(self, obs, ended, episode_return):
        c = self.config
        n, horizon = c["num_envs"], c["steps_per_rollout"]
        stored: List[Dict[str, torch.Tensor]] = []
        actions, log_probs, values, rewards, dones, valids = [], [], [], [], [], []
        phi = potential(obs)
        penalty = self._collision_penalty()
        for _ in range(horizon):
            t_obs = tensors(obs)
            with torch.no_grad():
                out, value = self.model(t_obs)
                dist = self._distribution(out)
                action = dist.sample()
                log_prob = self._log_prob(dist, action)
                velocity = self.model.to_world(self.model.local_velocity(action, t_obs["robot"]),
                                               t_obs).numpy()
            obs, reward, terminated, truncated, info = self.env.step(velocity)
            done = terminated | truncated
            valid = ~ended  # a step right after an episode's end only resets that environment
            new_phi = potential(obs)
            shaped = reward + c["progress_reward"] * (phi - new_phi)
            if penalty:
                shaped = shaped - penalty * self._collision[info["status"]]
            if c["wall_penalty"]:
                shaped = shaped - wall_penalty(obs, c["wall_penalty"], c["wall_distance"])
            shaped = np.where(valid, shaped, 0.0)
            phi = new_phi
            episode_return += np.where(valid, reward, 0.0)
            for i in np.nonzero(done & valid)[0]:
                self.outcomes.append(STATUS_NAMES[int(info["status"][i])])
                self.returns.append(float(episode_return[i]))
                episode_return[i] = 0.0
                self.episodes += 1
            self.next_episode = max(self.next_episode, int(info["episode_index"].max()) + 1)
            stored.append(t_obs)
            actions.append(action)
            log_probs.append(log_prob)
            values.append(value)
            rewards.append(torch.from_numpy(shaped).float())
            dones.append(torch.from_numpy(done.astype(np.float32)))
            valids.append(torch.from_numpy(valid.copy()))
            ended = done
        with torch.no_grad():
            last_value = self.model(tensors(obs))[1] * torch.from_numpy(~ended).float()
        self.steps += n * horizon
        batch = {k: torch.stack([s[k] for s in stored]) for k in stored[0]}
        return (obs, ended, episode_return, batch, torch.stack(actions), torch.stack(log_probs),
                torch.stack(values), torch.stack(rewards), torch.stack(dones),
                torch.stack(valids), last_value)

    def _advantages(self, values, rewards, dones, last_value):
        c = self.config
        horizon = rewards.size(0)
        advantages = torch.zeros_like(rewards)
        running = torch.zeros_like(last_value)
        for t in reversed(range(horizon)):
            next_value = last_value if t == horizon - 1 else values[t + 1]
            alive = 1.0 - dones[t]
            delta = rewards[t] + c["gamma"] * next_value * alive - values[t]
            running = delta + c["gamma"] * c["gae_lambda"] * alive * running
            advantages[t] = running
        return advantages, advantages + values

    def _optimize(self, batch, actions, log_probs, advantages, returns, valids):
        c = self.config
        flat = valids.reshape(-1).nonzero().squeeze(1)
        def take(x):
            return x.reshape((-1,) + tuple(x.shape[2:]))[flat]
        obs = {k: take(v) for k, v in batch.items()}
        actions, old_log_probs = take(actions), take(log_probs)
        advantages, returns = take(advantages), take(returns)
        count = flat.numel()
        stats = collections.defaultdict(float)
        steps = 0
        for _ in range(c["epochs"]):
            order = torch.randperm(count)
            for start in range(0, count, c["minibatch_size"]):
                idx = order[start:start + c["minibatch_size"]]
                if idx.numel() < 2:
                    continue
                out, value = self.model({k: v[idx] for k, v in obs.items()})
                dist = self._distribution(out)
                log_prob = self._log_prob(dist, actions[idx])
                adv = advantages[idx]
                if c["normalize_advantages"]:
                    adv = (adv - adv.mean()) / (adv.std() + 1e-8)
                ratio = torch.exp(log_prob - old_log_probs[idx])
                policy_loss = -torch.min(ratio * adv, torch.clamp(
                    ratio, 1.0 - c["clip"], 1.0 + c["clip"]) * adv).mean()
                value_loss = 0.5 * (returns[idx] - value).pow(2).mean()
                entropy = self._entropy(dist).mean()
                loss = policy_loss + c["value_coef"] * value_loss - c["entropy_coef"] * entropy
                self.optimizer.zero_grad()
                loss.backward()
                if c["max_grad_norm"] > 0:
                    torch.nn.utils.clip_grad_norm_(self.model.parameters(), c["max_grad_norm"])
                self.optimizer.step()
                with torch.no_grad():
                    stats["policy_loss"] += float(policy_loss)
                    stats["value_loss"] += float(value_loss)
                    stats["entropy"] += float(entropy)
                    stats["approx_kl"] += float((old_log_probs[idx] - log_prob).mean())
                    stats["clip_fraction"] += float(((ratio - 1.0).abs() > c["clip"]).float().mean())
                steps += 1
        return {k: v / max(1, steps) for k, v in stats.items()}

    def _rates(self) -> Dict[str, float]:
        n = len(self.outcomes)
        if not n:
            return {"success": float("nan"), "collision": float("nan"), "timeout": float("nan"),
                    "mean_return": float("nan")}
        return {
            "success": sum(o == "success" for o in self.outcomes) / n,
            "collision": sum(o.startswith("collision") for o in self.outcomes) / n,
            "timeout": sum(o == "timeout" for o in self.outcomes) / n,
            "mean_return": sum(self.returns) / len(self.returns),
        }

    def train(self, stop_after: Optional[int] = None) -> Dict[str, Any]:
        """Runs the training to total_steps; returns the summary. `stop_after`: stop once this
        many updates are done, as Ctrl-C would at that point (tests)."""
        c = self.config
        if self.update >= self.total_updates:
            self._say(f"{self.out}: already trained to update {self.update} "
                      f"({self.steps:,} steps); raise total_steps to go on")
            return self._finish(0.0, 0)
        self._say(f"crowdsim_bench.ppo: {c['name']}, seed {c['seed']}, {c['suite']} row "
                  f"{c['row']!r}, {c['num_envs']} environments x {c['steps_per_rollout']} steps "
                  f"per update, {self.total_updates} updates -> {self.out}"
                  + (f" (resuming at update {self.update})" if self.update else ""))
        started = time.monotonic()
        last_print = 0.0
        updates_this_run = 0
        curve = open(self.curve_path, "a", newline="")
        writer = csv.DictWriter(curve, CURVE_COLUMNS)
        obs = ended = episode_return = None
        try:
            while self.update < self.total_updates:
                if stop_after is not None and self.update >= stop_after:
                    raise KeyboardInterrupt
                if self.update % c["checkpoint_interval"] == 0 or obs is None:
                    # A segment starts: every environment starts a new episode, so a resumed
                    # training continues exactly as an uninterrupted one.
                    obs, _ = self.env.reset(seed=self.next_episode)
                    ended = np.zeros(c["num_envs"], dtype=bool)
                    episode_return = np.zeros(c["num_envs"])
                    self.next_episode += c["num_envs"]
                tick = time.monotonic()
                lr = c["learning_rate"]
                if c["lr_schedule"] == "linear":
                    lr *= 1.0 - self.update / self.total_updates
                for group in self.optimizer.param_groups:
                    group["lr"] = lr
                (obs, ended, episode_return, batch, actions, log_probs, values, rewards, dones,
                 valids, last_value) = self._rollout(obs, ended, episode_return)
                collected = time.monotonic()
                advantages, returns = self._advantages(values, rewards, dones, last_value)
                stats = self._optimize(batch, actions, log_probs, advantages, returns, valids)
                self.update += 1
                updates_this_run += 1
                now = time.monotonic()
                self.seconds += now - tick
                elapsed = time.monotonic() - started
                rate = updates_this_run * self.batch / max(elapsed, 1e-9)
                rates = self._rates()
                writer.writerow({"update": self.update, "steps": self.steps,
                                 "episodes": self.episodes, "seconds": f"{self.seconds:.1f}",
                                 "steps_per_s": f"{rate:.0f}", "learning_rate": f"{lr:.3g}",
                                 "collect_seconds": f"{collected - tick:.3f}",
                                 "update_seconds": f"{now - collected:.3f}",
                                 **{k: f"{v:.4f}" for k, v in rates.items()},
                                 **{k: f"{v:.5f}" for k, v in stats.items()}})
                curve.flush()
                at_checkpoint = (self.update % c["checkpoint_interval"] == 0
                                 or self.update == self.total_updates)
                if at_checkpoint:
                    self._write_checkpoint()
                if time.monotonic() - last_print >= 10.0 or at_checkpoint and \
                        self.update == self.total_updates or updates_this_run == 1:
                    last_print = time.monotonic()
                    eta = (self.total_updates - self.update) * elapsed / updates_this_run
                    self._say(f"update {self.update}/{self.total_updates}  steps {self.steps:,}  "
                              f"{rate:,.0f} steps/s  return {rates['mean_return']:.3f}  success "
                              f"{rates['success']:.3f} collision {rates['collision']:.3f} timeout "
                              f"{rates['timeout']:.3f} (last {len(self.outcomes)} episodes)  "
                              f"kl {stats.get('approx_kl', 0.0):.4f}  ETA {_format_duration(eta)}")
        except KeyboardInterrupt:
            done = self.update - self.update % c["checkpoint_interval"]
            self._say(f"interrupted at update {self.update}: the checkpoint holds update "
                      f"{max(done, 0)}; --resume continues from there")
            raise
        finally:
            curve.close()
        return self._finish(time.monotonic() - started, updates_this_run)

    def _finish(self, elapsed: float, updates: int) -> Dict[str, Any]:
        summary = {
            "name": self.config["name"], "seed": self.config["seed"], "update": self.update,
            "steps": self.steps, "episodes": self.episodes, "seconds_total": round(self.seconds, 1),
            "seconds_this_run": round(elapsed, 1),
            "steps_per_s_this_run": round(updates * self.batch / elapsed) if elapsed else None,
            "last_episodes": {k: round(v, 4) for k, v in self._rates().items()},
            "torch": torch.__version__, "layout": self.layout,
            "plugin_row": plugin_row(self.layout, os.path.join(self.out, "policy.pt")),
        }
        def write(tmp):
            with open(tmp, "w") as f:
                f.write(json.dumps(summary, indent=2) + "\n")
        atomic_write(os.path.join(self.out, "summary.json"), write)
        self._say(f"done: {self.steps:,} steps, {self.episodes} episodes, success of the last "
                  f"{len(self.outcomes)} {summary['last_episodes'].get('success', float('nan')):.3f}"
                  f" -> {os.path.join(self.out, 'policy.pt')}")
        self._say(f"as a suite row: {summary['plugin_row']}")
        return summary

    def close(self) -> None:
        self.env.close()

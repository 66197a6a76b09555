"""The PPO actor-critic: an observation encoder (robot state, lidar, the people seen pooled by
attention as SARL does, the route when the row has one) with a policy head and a value head, and
the TorchScript module exported for the `torchscript` policy plugin.

Everything is computed in the goal frame: x from the robot towards its goal, as the `humans`
rows of the observation already are; or, with `frame: route`, in the route frame: x towards
the route sensor's waypoint (the goal frame in open space). The policy's actions are velocities
in that frame, turned into world-frame velocities (what `VectorEnv.step` and the plugin take)
by `to_world`.
"""
from __future__ import annotations

import math
from typing import Dict, List, Tuple

import torch
from torch import Tensor, nn

# Scales that bring the inputs near [-1, 1]: metres to goal and along the route.
DISTANCE_SCALE = 0.1
# Per-person features (goal frame): x, y, vx, vy, radius, distance, gap (distance minus both
# radii), and a 1 for a real row.
HUMAN_FEATURES = 8
# Robot features: distance to goal, v_pref, radius, velocity (2, goal frame), heading relative
# to the goal direction (cos, sin), elapsed fraction of the time limit.
ROBOT_FEATURES = 8
ROUTE_FEATURES = 3
# Route frame: path distance, waypoint distance, the goal's direction in the frame (cos, sin).
ROUTE_FRAME_FEATURES = 4


def holonomic_velocities(speeds: int = 5, rotations: int = 16) -> Tensor:
    """CrowdNav's 81 holonomic actions as unit velocities (multiply by v_pref): stop, then
    `rotations` directions x `speeds` speeds (direction the outer loop), as
    crowdsim_bench.holonomic_actions; here in the goal frame (direction 0 = towards the goal)."""
    acts: List[Tuple[float, float]] = [(0.0, 0.0)]
    for k in range(rotations):
        a = 2.0 * math.pi * k / rotations
        for i in range(speeds):
            m = (math.exp((i + 1) / speeds) - 1.0) / (math.e - 1.0)
            acts.append((m * math.cos(a), m * math.sin(a)))
    return torch.tensor(acts, dtype=torch.float32)


def _mlp(sizes: List[int], last_activation: bool) -> nn.Sequential:
    layers: List[nn.Module] = []
    for i in range(len(sizes) - 1):
        layers.append(nn.Linear(sizes[i], sizes[i + 1]))
        if i + 2 < len(sizes) or last_activation:
            layers.append(nn.ReLU())
    return nn.Sequential(*layers)


class ActorCritic(nn.Module):
    """Observation dict (batched: robot (B, 9), humans (B, H, 5), humans_mask (B, H), lidar
    (B, beams), route (B, 3), time (B,)) -> policy output and value.

    Continuous: the output is the mean of a Gaussian over the goal-frame velocity (a
    state-independent log standard deviation beside it); discrete: 81 logits over CrowdNav's
    holonomic actions in the goal frame. Scriptable (torch.jit.script) as it is."""

    def __init__(self, beams: int, max_range: float, uses_route: bool, time_limit: float,
                 discrete: bool, hidden: int = 128, human_embedding: int = 64,
                 init_log_std: float = -0.5, frame: str = "goal"):
        super().__init__()
        if frame == "route" and not uses_route:
            raise ValueError("frame: route needs the route sensor in the row's observation")
        self.route_frame = frame == "route"
        self.uses_lidar = beams > 0
        self.beams = beams
        self.uses_route = uses_route
        self.discrete = discrete
        self.lidar_scale = 1.0 / max_range if max_range > 0 else 1.0
        self.time_scale = 1.0 / time_limit if time_limit > 0 else 0.0
        self.distance_scale = DISTANCE_SCALE
        lidar_out = 32 if self.uses_lidar else 0
        # Present whatever the configuration (TorchScript compiles every branch); unused ones
        # are never called.
        self.lidar = _mlp([max(beams, 1), 64, 32], True)
        # SARL's attention: embed each (robot, person) pair, score it against the mean embedding
        # of the people seen, pool a second embedding by the normalized scores.
        self.pair = _mlp([ROBOT_FEATURES + HUMAN_FEATURES, human_embedding, human_embedding], True)
        self.pair_value = _mlp([human_embedding, 32], True)
        self.attention = _mlp([2 * human_embedding, 64, 1], False)
        route_in = ROUTE_FRAME_FEATURES if self.route_frame else ROUTE_FEATURES
        trunk_in = ROBOT_FEATURES + lidar_out + 32 + (route_in if uses_route else 0)
        self.trunk = nn.Sequential(nn.Linear(trunk_in, hidden), nn.Tanh(),
                                   nn.Linear(hidden, hidden), nn.Tanh())
        outputs = 81 if discrete else 2
        self.policy_head = nn.Linear(hidden, outputs)
        self.value_head = nn.Linear(hidden, 1)
        self.log_std = nn.Parameter(torch.full((2,), float(init_log_std)))
        self.register_buffer("action_set", holonomic_velocities())
        for module in self.modules():
            if isinstance(module, nn.Linear):
                nn.init.orthogonal_(module.weight, math.sqrt(2.0))
                nn.init.zeros_(module.bias)
        # Small initial policy outputs (near-uniform logits, means near 0), a unit-gain value.
        nn.init.orthogonal_(self.policy_head.weight, 0.01)
        nn.init.orthogonal_(self.value_head.weight, 1.0)

    def route_turn(self, obs: Dict[str, Tensor]) -> Tensor:
        """The waypoint's bearing in the sensor frame (the heading's; holonomic: the goal
        frame), the turn from it to the route frame: 0 where the waypoint is the robot itself."""
        route = obs["route"].float()
        wx, wy = route[:, 1], route[:, 2]
        away = wx * wx + wy * wy > 1e-12
        return torch.where(away, torch.atan2(wy, wx), torch.zeros_like(wx))

    def frame(self, obs: Dict[str, Tensor]) -> Tuple[Tensor, Tensor, Tensor, Tensor]:
        """The policy frame's x axis in the world (angle, cos, sin) and the distance to the
        goal: the goal frame, or the heading turned towards the waypoint (frame: route)."""
        robot = obs["robot"].float()
        dx = robot[:, 4] - robot[:, 0]
        dy = robot[:, 5] - robot[:, 1]
        dist = torch.sqrt(dx * dx + dy * dy)
        if self.route_frame:
            theta = robot[:, 8] + self.route_turn(obs)
        else:
            theta = torch.atan2(dy, dx)
        return theta, torch.cos(theta), torch.sin(theta), dist

    def encode(self, obs: Dict[str, Tensor]) -> Tensor:
        robot = obs["robot"].float()
        theta, c, s, dist = self.frame(obs)
        vx, vy = robot[:, 2], robot[:, 3]
        rel = robot[:, 8] - theta
        self_state = torch.stack([
            dist * self.distance_scale, robot[:, 7], robot[:, 6], c * vx + s * vy, -s * vx + c * vy,
            torch.cos(rel), torch.sin(rel), obs["time"].float().reshape(-1) * self.time_scale], 1)
        parts = [self_state]
        if self.uses_lidar:
            lidar = obs["lidar"].float()
            if lidar.size(1) != self.beams:
                raise RuntimeError("crowdsim_bench.ppo: the lidar has another beam count than "
                                   "the model was trained with")
            parts.append(self.lidar(torch.clamp(lidar * self.lidar_scale, 0.0, 1.0)))
        humans = obs["humans"].float()
        if self.route_frame:
            humans = self._turned(humans, obs)
        parts.append(self._people(self_state, humans, obs["humans_mask"], robot))
        if self.uses_route:
            if "route" not in obs:
                raise RuntimeError("crowdsim_bench.ppo: the model reads the route sensor, but the "
                                   "observation has no `route` (give the row the route sensor, "
                                   "and the torchscript plugin `route: true`)")
            route = obs["route"].float()
            if self.route_frame:
                goal = torch.atan2(robot[:, 5] - robot[:, 1], robot[:, 4] - robot[:, 0])
                bearing = goal - theta
                waypoint = torch.sqrt(route[:, 1] * route[:, 1] + route[:, 2] * route[:, 2])
                parts.append(torch.stack([route[:, 0] * self.distance_scale, waypoint,
                                          torch.cos(bearing), torch.sin(bearing)], 1))
            else:
                parts.append(torch.stack([route[:, 0] * self.distance_scale, route[:, 1],
                                          route[:, 2]], 1))
        return self.trunk(torch.cat(parts, 1))

    def _turned(self, humans: Tensor, obs: Dict[str, Tensor]) -> Tensor:
        """The people's rows (sensor frame) in the route frame: positions and velocities turned
        back by the waypoint's bearing."""
        turn = self.route_turn(obs).unsqueeze(1)
        tc, ts = torch.cos(turn), torch.sin(turn)
        x, y, vx, vy = humans[:, :, 0], humans[:, :, 1], humans[:, :, 2], humans[:, :, 3]
        return torch.cat([torch.stack([tc * x + ts * y, -ts * x + tc * y,
                                       tc * vx + ts * vy, -ts * vx + tc * vy], 2),
                          humans[:, :, 4:]], 2)

    def _people(self, self_state: Tensor, humans: Tensor, mask: Tensor, robot: Tensor) -> Tensor:
        b = humans.size(0)
        if humans.size(1) == 0:
            return torch.zeros(b, 32, dtype=self_state.dtype)
        x, y = humans[:, :, 0], humans[:, :, 1]
        d = torch.sqrt(x * x + y * y)
        m = mask.to(self_state.dtype)
        gap = d - humans[:, :, 4] - robot[:, 6].unsqueeze(1)
        rows = torch.stack([x, y, humans[:, :, 2], humans[:, :, 3], humans[:, :, 4], d, gap, m], 2)
        rows = torch.cat([self_state.unsqueeze(1).expand(-1, rows.size(1), -1), rows], 2)
        e = self.pair(rows)  # (B, H, E)
        seen = m.sum(1, keepdim=True)  # (B, 1)
        mean = (e * m.unsqueeze(2)).sum(1) / seen.clamp_min(1.0)
        scores = self.attention(torch.cat([e, mean.unsqueeze(1).expand_as(e)], 2)).squeeze(2)
        scores = scores.masked_fill(mask.logical_not(), -1e9)
        w = torch.softmax(scores, 1) * m  # nobody seen: all zero
        return (w.unsqueeze(2) * self.pair_value(e)).sum(1)

    def forward(self, obs: Dict[str, Tensor]) -> Tuple[Tensor, Tensor]:
        h = self.encode(obs)
        return self.policy_head(h), self.value_head(h).squeeze(1)

    def to_world(self, local: Tensor, obs: Dict[str, Tensor]) -> Tensor:
        """Policy-frame velocities (B, 2) -> world-frame velocities (B, 2), float64."""
        _, c, s, _ = self.frame(obs)
        vx = c * local[:, 0] - s * local[:, 1]
        vy = s * local[:, 0] + c * local[:, 1]
        return torch.stack([vx, vy], 1).double()

    def local_velocity(self, action: Tensor, robot: Tensor) -> Tensor:
        """The goal-frame velocity an action stands for: a discrete index (B,) into the
        holonomic set scaled by v_pref, or a Gaussian sample (B, 2) shortened to v_pref."""
        v_pref = robot[:, 7].float().unsqueeze(1)
        if self.discrete:
            return self.action_set[action.long()] * v_pref
        norm = torch.sqrt((action * action).sum(1, keepdim=True))
        return action * torch.clamp(v_pref / norm.clamp_min(1e-9), max=1.0)

    def greedy(self, obs: Dict[str, Tensor]) -> Tensor:
        """The deterministic action (the most likely one) as world-frame velocities (B, 2)."""
        out, _ = self.forward(obs)
        if self.discrete:
            action = torch.argmax(out, 1)
        else:
            action = out
        return self.to_world(self.local_velocity(action, obs["robot"]), obs)


class ExportedPolicy(nn.Module):
    """The greedy policy on one observation as the `torchscript` plugin gives it (robot (9,),
    humans (H, 5), humans_mask (H,), lidar (beams,), time (), float64) -> (vx, vy) float64,
    world frame: the plugin's default `output: velocity`."""

    def __init__(self, model: ActorCritic):
        super().__init__()
        self.model = model

    def forward(self, obs: Dict[str, Tensor]) -> Tensor:
        batched: Dict[str, Tensor] = {}
        for key, value in obs.items():
            batched[key] = value.unsqueeze(0)
        return self.model.greedy(batched).reshape(2)

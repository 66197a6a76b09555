#!/usr/bin/env python3
"""A policy network trained in Python with PyTorch on crowdsim_bench.VectorEnv, end to end:
advantage actor-critic over 16 environments stepped in C++, then a test on the suite's own
episodes with evaluate(), and the policy saved as TorchScript for `crowdsim-bench run`.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/train_policy_torch.py [UPDATES] [OUT.pt]

Needs python3-torch (Debian). The default 1000 updates (16 x 32 steps each, ~15k episodes)
take about 30 s on one core, in the 1-obstacle train layouts with the quick suite's 5 ORCA humans
(lidar + person sensor); the test uses the suite's own (test) layouts. A short example of the
loop, not a tuned learner: measured once here (2026-11-26), the sampled policy's success rose
from 0 to 0.14 and the greedy policy reached 0.13 on the test episodes (collisions are the
rest). Before it trained in the test layouts themselves (episodes 1000+ of the suite, whose
layouts repeat every 100 episodes) and reached ~0.2-0.3 there. The features, the action set (CrowdNav's 81 in the
robot's frame) and the reward shaping (progress towards the goal) are the example's choices.
"""
import os
import sys
from typing import Dict, Tuple

import numpy as np
import torch
from torch import nn

import crowdsim_bench as cb

SUITE, ROW = "suites/quick.yaml", "orca"  # the row gives worlds, humans and sensors
# Training in the 1-obstacle *train* layouts: the suite's episodes (any index, 1000 as 0)
# cycle through its 100 test layouts, which the test below uses.
TRAIN_SET = "world.split=train"
ENVS, STEPS, GAMMA = 16, 32, 0.95


def robot_frame_actions(v_pref=1.0):
    """Velocities in the robot's frame (x towards the goal): CrowdNav's 81 holonomic actions."""
    return torch.tensor(cb.holonomic_actions(v_pref), dtype=torch.float32)


class Policy(nn.Module):
    """Observation dict (Env's layout, batched or not) -> action logits and state value."""

    def __init__(self, humans: int, beams: int):
        super().__init__()
        self.register_buffer("actions", robot_frame_actions())
        size = 3 + humans * 5 + beams
        self.body = nn.Sequential(nn.Linear(size, 128), nn.Tanh(), nn.Linear(128, 128), nn.Tanh())
        self.logits = nn.Linear(128, self.actions.shape[0])
        self.value = nn.Linear(128, 1)

    def features(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        robot = obs["robot"].float().reshape(-1, 9)
        heading = robot[:, 8]
        goal = robot[:, 4:6] - robot[:, 0:2]
        c, s = torch.cos(heading), torch.sin(heading)
        v_local = torch.stack([c * robot[:, 2] + s * robot[:, 3], -s * robot[:, 2] + c * robot[:, 3]], 1)
        humans = obs["humans"].float().reshape(robot.shape[0], -1)
        lidar = obs["lidar"].float().reshape(robot.shape[0], -1) / 5.0
        return torch.cat([torch.sqrt((goal * goal).sum(1, keepdim=True)) / 10.0, v_local, humans / 5.0, lidar], 1)

    def forward(self, obs: Dict[str, torch.Tensor]) -> Tuple[torch.Tensor, torch.Tensor]:
        h = self.body(self.features(obs))
        return self.logits(h), self.value(h).squeeze(1)

    def to_world(self, index: torch.Tensor, robot: torch.Tensor) -> torch.Tensor:
        """Chosen robot-frame actions as world-frame velocities."""
        local = self.actions[index]
        heading = robot.float().reshape(-1, 9)[:, 8]
        c, s = torch.cos(heading), torch.sin(heading)
        return torch.stack([c * local[:, 0] - s * local[:, 1], s * local[:, 0] + c * local[:, 1]], 1)


class Greedy(nn.Module):
    """The trained policy for `crowdsim-bench run` (policy: torchscript, output: velocity):
    the most likely action, as a world-frame velocity."""

    def __init__(self, policy: Policy):
        super().__init__()
        self.policy = policy

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        logits, _ = self.policy(obs)
        return self.policy.to_world(logits.argmax(1), obs["robot"]).reshape(2).double()


def tensors(obs):
    return {k: torch.from_numpy(np.asarray(v)) for k, v in obs.items()}


def progress(obs_before, obs_after):
    """Shaping: metres gained towards the goal this step (the harness's reward is sparse)."""
    def dist(o):
        return np.linalg.norm(o["robot"][:, 4:6] - o["robot"][:, 0:2], axis=1)
    return dist(obs_before) - dist(obs_after)


def train(updates: int) -> Policy:
    torch.manual_seed(0)
    env = cb.VectorEnv(SUITE, row=ROW, num_envs=ENVS, set=TRAIN_SET)
    policy = Policy(env._env.humans, env._env.beams)
    optimizer = torch.optim.Adam(policy.parameters(), lr=1e-3)
    obs, _ = env.reset(seed=0)
    ended = np.zeros(ENVS, dtype=bool)
    outcomes = []
    for update in range(1, updates + 1):
        log_probs, values, rewards, alive, entropies = [], [], [], [], []
        for _ in range(STEPS):
            logits, value = policy(tensors(obs))
            dist = torch.distributions.Categorical(logits=logits)
            index = dist.sample()
            velocity = policy.to_world(index, torch.from_numpy(obs["robot"])).detach().double().numpy()
            new_obs, reward, terminated, truncated, info = env.step(velocity)
            shaped = reward + 0.1 * progress(obs, new_obs) * ~ended
            # A step right after an episode ended only resets that environment: no learning signal.
            mask = torch.from_numpy(~ended).float()
            log_probs.append(dist.log_prob(index) * mask)
            entropies.append(dist.entropy() * mask)
            values.append(value * mask)
            rewards.append(torch.from_numpy(shaped).float() * mask)
            done = terminated | truncated
            alive.append(torch.from_numpy(~done).float())
            outcomes += [cb.STATUS_NAMES[s] for s in info["status"][done]]
            ended, obs = done, new_obs
        with torch.no_grad():
            ret = policy(tensors(obs))[1] * torch.from_numpy(~ended).float()
        returns = []
        for r, a in zip(reversed(rewards), reversed(alive)):
            ret = r + GAMMA * a * ret
            returns.append(ret)
        returns = torch.stack(returns[::-1])
        values, log_probs = torch.stack(values), torch.stack(log_probs)
        advantage = returns - values
        loss = (-(log_probs * advantage.detach()).mean() + 0.5 * advantage.pow(2).mean()
                - 0.01 * torch.stack(entropies).mean())
        optimizer.zero_grad()
        loss.backward()
        nn.utils.clip_grad_norm_(policy.parameters(), 1.0)
        optimizer.step()
        if update % 25 == 0:
            recent = outcomes[-200:]
            rate = sum(o == "success" for o in recent) / max(1, len(recent))
            print(f"update {update:4d}: {len(outcomes)} episodes, success of the last "
                  f"{len(recent)} {rate:.2f}", flush=True)
    return policy


def main():
    updates = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    out = sys.argv[2] if len(sys.argv) > 2 else "runs/a2c_policy.pt"
    torch.set_num_threads(1)
    policy = train(updates)
    greedy = Greedy(policy).eval()

    def act(obs):
        with torch.no_grad():
            return greedy(tensors(obs)).numpy()

    rows = cb.evaluate(act, SUITE, row=ROW, label="a2c_example", out="runs/a2c_example", episodes=100)
    r = rows[0]
    print(f"test (episodes 0-99, greedy): success {r['success']:.2f}, collision "
          f"{r['collision']:.2f}, timeout {r['timeout']:.2f} -> runs/a2c_example/table.md")
    torch.jit.script(greedy).save(out)
    # The row's sensors give the module its inputs: lidar and people, as the Env it trained on.
    print(f"TorchScript policy: {out}; as a row of a suite with {SUITE}'s worlds and sensors:\n"
          f"  - {{label: a2c, policy: torchscript, weights: {os.path.abspath(out)}, "
          f"params: {{sensors: lidar+person}}}}")


if __name__ == "__main__":
    main()

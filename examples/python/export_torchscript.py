#!/usr/bin/env python3
"""A PyTorch policy as a drop-in for `crowdsim-bench run`: scripts a module with the
TorchScript policy interface, saves it, and writes a suite that runs it beside `linear`.

    /usr/bin/python3 examples/python/export_torchscript.py [OUT_DIR]      # default runs/torchscript_example
    build/bin/crowdsim-bench run OUT_DIR/suite.yaml --out OUT_DIR/results

Needs python3-torch (Debian), not the crowdsim_bench package. The interface (plugins/policies/torchscript):
forward(obs: Dict[str, Tensor]) -> Tensor, obs with the layout of crowdsim_bench.Env's
observations as float64 tensors (`robot` (9,), `humans` (H, 5), `humans_mask` (H,) bool,
`lidar` (beams,) when the row has a lidar, `time` ()), returning (vx, vy) in m/s, world frame
(or, with `output: action`, an index or 81 scores over CrowdNav's holonomic actions). Any
trained nn.Module works the same way when wrapped like this one: convert the dict to its
inputs, return the velocity.
"""
import os
import sys
from typing import Dict

import torch


class SlowNearPeople(torch.nn.Module):
    """Straight to the goal at v_pref (the last step shortened, as `linear`), slowed to 30% when
    a person is within 1.5 m of the robot's centre."""

    def __init__(self, time_step: float = 0.25):
        super().__init__()
        self.time_step = time_step

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        robot, humans, mask = obs["robot"], obs["humans"], obs["humans_mask"]
        to_goal = robot[4:6] - robot[0:2]
        dist = torch.sqrt(to_goal[0] * to_goal[0] + to_goal[1] * to_goal[1])
        if float(dist) < 1e-9:
            return torch.zeros(2, dtype=torch.float64)
        speed = robot[7]
        if bool(mask.any()):
            seen = humans[mask]
            if float(torch.sqrt(seen[:, 0] ** 2 + seen[:, 1] ** 2).min()) < 1.5:
                speed = speed * 0.3
        return to_goal / dist * torch.minimum(speed, dist / self.time_step)


SUITE = """# Written by examples/python/export_torchscript.py: the quick suite's conditions with the
# exported module as a robot policy beside the `linear` baseline.
name: torchscript_example
episodes: 100
seed: 2026
world: {{source: random_rect, obstacles: 1, split: test}}
humans: {{count: 5, policy: orca}}
robot:
  sensors: [person, {{type: lidar2d, beams: 45, fov_deg: 180, max_range: 5}}]
rows:
  - {{label: linear, policy: linear}}
  - {{label: {label}, policy: torchscript, weights: {weights}, params: {{sensors: person, humans: 5}}}}
"""


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "runs/torchscript_example"
    os.makedirs(out, exist_ok=True)
    weights = os.path.join(out, "slow_near_people.pt")
    torch.jit.script(SlowNearPeople().eval()).save(weights)
    suite = os.path.join(out, "suite.yaml")
    with open(suite, "w") as f:  # weights relative to the suite's folder
        f.write(SUITE.format(label="slow_near_people", weights="slow_near_people.pt"))
    print(f"TorchScript policy: {weights}\nsuite: {suite} "
          f"(run: build/bin/crowdsim-bench run {suite} --out {os.path.join(out, 'results')})")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Benchmarks a hand-written Python policy on a suite row, with the CLI's outputs and metrics.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/evaluate_policy.py   # -> runs/python_demo/

The policy walks to the goal and sidesteps the nearest person it sees ahead (a toy rule: the
point is that it meets exactly the scenarios and metrics of the built-in policies).
"""
import numpy as np

import crowdsim_bench as cb


def sidestep(obs):
    robot = obs["robot"]
    to_goal = robot[4:6] - robot[0:2]
    dist = np.linalg.norm(to_goal)
    if dist < 1e-9:
        return np.zeros(2)
    heading = to_goal / dist
    velocity = heading * min(robot[7], dist / 0.25)
    seen = obs["humans"][obs["humans_mask"]]
    ahead = seen[(seen[:, 0] > 0) & (np.hypot(seen[:, 0], seen[:, 1]) < 1.5)]
    if len(ahead):  # humans are in the robot's frame: x towards the goal, y to its left
        side = -1.0 if ahead[np.argmin(ahead[:, 0]), 1] > 0 else 1.0
        left = np.array([-heading[1], heading[0]])
        velocity = 0.6 * velocity + 0.6 * side * left
    return velocity


rows = cb.evaluate(sidestep, "suites/quick.yaml", row="linear", label="sidestep",
                   out="runs/python_demo", progress=True)
for r in rows:
    print(f"{r['label']}: success {r['success']:.3f}, collision {r['collision']:.3f}, "
          f"timeout {r['timeout']:.3f} over {r['episodes']} episodes")
print(open("runs/python_demo/table.md").read().split("\n\n")[0])

"""Whole episodes of CrowdNav's own env, timed: circle crossing of radius 4, 5 ORCA humans, the
ORCA robot invisible to them (safety space 0), as CrowdNav's crowd_nav/test.py runs
`--policy orca` on its 500 test cases, i.e. the task of suites/crowdnav_orca.yaml's row orca.

    PYTHONPATH=<rvo2 module>:<CrowdNav checkout>:stubs python3 run_crowdnav.py CROWDNAV_DIR [EPISODES]

Prints CPU time per episode and per step and the outcomes (CrowdNav publishes 0.43 success).
"""
import configparser
import os
import sys
import time

from crowd_sim.envs.crowd_sim import CrowdSim
from crowd_sim.envs.policy.orca import ORCA
from crowd_sim.envs.utils.robot import Robot

crowdnav_dir = sys.argv[1]
episodes = int(sys.argv[2]) if len(sys.argv) > 2 else 500
config = configparser.RawConfigParser()
config.read(os.path.join(crowdnav_dir, "crowd_nav", "configs", "env.config"))
env = CrowdSim()
env.configure(config)
robot = Robot(config, "robot")
robot.set_policy(ORCA())
robot.policy.safety_space = 0
env.set_robot(robot)
outcomes = {}
steps = 0
t0 = time.process_time()
for k in range(episodes):
    ob = env.reset("test", k)
    done = False
    while not done:
        ob, _, done, info = env.step(robot.act(ob))
        steps += 1
    name = type(info).__name__
    outcomes[name] = outcomes.get(name, 0) + 1
cpu = time.process_time() - t0
print(f"CrowdNav env: {episodes} episodes, {steps} steps, CPU {cpu:.3f} s: "
      f"{1e6 * cpu / episodes:.0f} us per episode, {1e6 * cpu / steps:.1f} us per step; "
      f"outcomes {outcomes}")

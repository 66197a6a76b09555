#!/usr/bin/env python3
"""A random agent in a suite row's episodes, through the Gymnasium API of crowdsim_bench.Env.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/random_agent.py [suites/quick.yaml] [row]
"""
import sys
from collections import Counter

import crowdsim_bench as cb

suite = sys.argv[1] if len(sys.argv) > 1 else "suites/quick.yaml"
row = sys.argv[2] if len(sys.argv) > 2 else "orca"
env = cb.Env(suite, row=row, discrete=True)  # CrowdNav's 81 holonomic actions
env.action_space.seed(0)
outcomes = Counter()
for episode in range(20):
    obs, info = env.reset(seed=episode)
    ret, done = 0.0, False
    while not done:
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        ret += reward
        done = terminated or truncated
    outcomes[info["status"]] += 1
    print(f"episode {episode:2d} {info['layout']:>16}: {info['status']:<18} "
          f"after {info['time']:5.2f} s, return {ret:+.3f}")
print(dict(outcomes))

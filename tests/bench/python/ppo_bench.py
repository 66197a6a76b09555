"""PPO throughput (issue 49): environment steps per second of crowdsim_bench.ppo's training,
collection (the policy's forward pass and VectorEnv) and update (the clipped-surrogate epochs)
together and apart, for the training files of suites/ppo/ with VectorEnv on 1 and on 2 threads.

Run from the source root with the build's python/ folder on PYTHONPATH, on a quiet machine:

    PYTHONPATH=build/python /usr/bin/python3 tests/bench/python/ppo_bench.py [--updates N]
        [--set KEY=VALUE ...] [FILE...]

Each measurement trains a fresh model for a warm-up update and then N updates (default 12) into a
scratch folder; the figures are the best of 3 such runs (a 2-core VM drifts by +-25%).
"""
import argparse
import io
import os
import sys
import tempfile
import time

from crowdsim_bench.ppo import config as ppo_config
from crowdsim_bench.ppo.trainer import Trainer

FILES = ["suites/ppo/table1.yaml", "suites/ppo/table1_route.yaml"]


def measure(path, threads, updates, overrides=()):
    """(steps/s overall, collection steps/s, update steps/s) of one run."""
    config = ppo_config.load(path, list(overrides) + [f"threads={threads}",
                                                      "checkpoint_interval=1000000"])
    batch = config["num_envs"] * config["steps_per_rollout"]
    config["total_steps"] = batch * (updates + 1)
    with tempfile.TemporaryDirectory() as out:
        trainer = Trainer(config, os.path.join(out, "run"), log=io.StringIO(), quiet=True)
        try:
            trainer.train(stop_after=1)  # warm-up: the first rollout's episodes and allocations
        except KeyboardInterrupt:
            pass
        start = time.perf_counter()
        trainer.train()
        seconds = time.perf_counter() - start
        collect = update = 0.0
        with open(trainer.curve_path) as f:
            rows = f.read().splitlines()
        header = rows[0].split(",")
        for line in rows[2:]:  # the update after the warm-up on
            values = dict(zip(header, line.split(",")))
            collect += float(values["collect_seconds"])
            update += float(values["update_seconds"])
        trainer.close()
    steps = batch * updates
    return steps / seconds, steps / collect, steps / update


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", default=FILES)
    parser.add_argument("--updates", type=int, default=12)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a key of the training files for every measurement, as train --set")
    parser.add_argument("--threads", type=int, action="append", help="default: 1 and 2")
    args = parser.parse_args()
    print(f"{'training file':32} {'threads':>7} {'steps/s':>9} {'collect/s':>10} {'update/s':>9}")
    for path in args.files:
        for threads in args.threads or (1, 2):
            runs = [measure(path, threads, args.updates, args.set) for _ in range(args.repeats)]
            best = max(runs, key=lambda r: r[0])
            print(f"{path:32} {threads:7d} {best[0]:9.0f} {best[1]:10.0f} {best[2]:9.0f}")
            sys.stdout.flush()


if __name__ == "__main__":
    main()

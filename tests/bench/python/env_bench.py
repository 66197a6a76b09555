"""Benchmarks of the Python package (run from the source root with the build's python/ folder
on PYTHONPATH; `make bench` runs it): what Env.step() costs over the C++ step it wraps, and
VectorEnv's steps per second on one core.

The C++ step is timed on the same episodes, stepped in C++ exactly as Env steps them (the
robot stands still: velocity (0, 0)), and the Python side steps those episodes with the same
velocity: same simulation, so the difference per step is what the Python layer adds (the
observation's numpy arrays, the call, the wrapper).
"""
import sys
import time

import numpy as np

import crowdsim_bench as cb

QUICK = "suites/quick.yaml"
STILL = ["rows[linear].params.speed_factor=0"]


def best_of(repeats, fn):
    return min(fn() for _ in range(repeats))


def cpp_seconds_per_step(episodes):
    def once():
        steps, seconds = cb._core._time_fixed_velocity_steps(QUICK, "linear", STILL, episodes, 0.0, 0.0)
        return seconds / steps
    return best_of(3, once)


def python_seconds_per_step(episodes, raw):
    env = cb.Env(QUICK, row="linear", set=STILL)
    zero = np.zeros(2)

    def once():
        steps = 0
        t0 = time.perf_counter()
        for k in range(episodes):
            env.reset(seed=k)
            if raw:  # the C++ binding alone, without the Gymnasium wrapper
                core = env._env
                while True:
                    steps += 1
                    _, _, status, _ = core.step(0.0, 0.0)
                    if status != "running":
                        break
            else:
                while True:
                    steps += 1
                    _, _, terminated, truncated, _ = env.step(zero)
                    if terminated or truncated:
                        break
        return (time.perf_counter() - t0) / steps
    return best_of(3, once)


def vector_steps_per_second(num_envs, threads, still=False, batches=400):
    venv = cb.VectorEnv(QUICK, row="orca", num_envs=num_envs, threads=threads,
                        set=["world.obstacles=3"])
    venv.reset(seed=0)
    rng = np.random.default_rng(0)
    actions = [rng.uniform(-0.7, 0.7, (num_envs, 2)) * (0.0 if still else 1.0) for _ in range(16)]

    def once():
        t0 = time.perf_counter()
        for b in range(batches):
            venv.step(actions[b % 16])
        return (time.perf_counter() - t0) / (batches * num_envs)
    return 1.0 / best_of(3, once)


def main():
    episodes = int(sys.argv[1]) if len(sys.argv) > 1 else 30
    cpp = cpp_seconds_per_step(episodes)
    raw = python_seconds_per_step(episodes, raw=True)
    full = python_seconds_per_step(episodes, raw=False)
    print("Env.step on the quick suite's episodes (5 ORCA humans, 1 obstacle, lidar 45 + person)")
    print(f"  C++ step                   {cpp * 1e6:8.2f} us")
    print(f"  _core.Env.step             {raw * 1e6:8.2f} us  (+{(raw - cpp) * 1e6:.2f} us)")
    print(f"  Env.step (Gymnasium API)   {full * 1e6:8.2f} us  (+{(full - cpp) * 1e6:.2f} us over C++)")
    print("VectorEnv, 3 obstacles, 5 ORCA humans, lidar 45 + person")
    for still in (False, True):
        for n, threads in ((1, 1), (16, 1), (16, 2)):
            rate = vector_steps_per_second(n, threads, still)
            what = "standing still" if still else "random velocities (short episodes)"
            print(f"  VectorEnv({n:2d}) threads {threads}  {rate:10.0f} steps/s  {what}")


if __name__ == "__main__":
    main()

"""Gymnasium ids for suite rows: `gymnasium.make("crowdsim_bench/Table1-v0")` is
`crowdsim_bench.Env(<data root>/suites/baselines.yaml, row="orca_rect1")`, and
`gymnasium.make_vec(id, num_envs=n)` the C++ VectorEnv of the same row. Registered when the
package is imported and gymnasium is importable (docs/gymnasium.md)."""
from __future__ import annotations

import os

from . import _gym, data_root

# id -> (suite file under the data root, row). A row's robot policy is replaced by the Python
# agent: what an id fixes is the row's world, humans, sensors and episodes. The rows are the
# baselines' (no trained weights to load, so an install without its models has them too) in the
# paper's test conditions: Table 1's 1-obstacle test layouts and Table 2's floor plans, each
# with 5 ORCA humans, person + lidar sensors and the suites' 500 episodes (seed 2026).
ENV_IDS = {
    "crowdsim_bench/Quick-v0": ("suites/quick.yaml", "orca"),
    "crowdsim_bench/Table1-v0": ("suites/baselines.yaml", "orca_rect1"),
    "crowdsim_bench/Table1ThreeObstacles-v0": ("suites/baselines.yaml", "orca_rect3"),
    "crowdsim_bench/FloorPlanEasy-v0": ("suites/gibson_baselines.yaml", "orca_easy"),
    "crowdsim_bench/FloorPlanMedium-v0": ("suites/gibson_baselines.yaml", "orca_medium"),
    "crowdsim_bench/FloorPlanHard-v0": ("suites/gibson_baselines.yaml", "orca_hard"),
    "crowdsim_bench/CrowdNav-v0": ("suites/crowdnav_orca.yaml", "orca"),
}


def register_envs() -> None:
    """Registers ENV_IDS with gymnasium (nothing without it), suites by their path under the
    data root (data_root(): found from any working folder). An id already registered is kept."""
    if _gym is None:
        return
    root = data_root()
    for env_id, (suite, row) in ENV_IDS.items():
        if env_id in _gym.registry:
            continue
        _gym.register(env_id, entry_point="crowdsim_bench:Env",
                      vector_entry_point="crowdsim_bench:VectorEnv",
                      kwargs={"suite": os.path.join(root, suite), "row": row})

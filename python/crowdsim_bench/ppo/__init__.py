"""crowdsim_bench.ppo: a PPO baseline (clipped surrogate, GAE; Schulman et al. 2017) trained on
crowdsim_bench.VectorEnv and exported as TorchScript for the `torchscript` policy plugin.

    python3 -m crowdsim_bench.ppo train suites/ppo/table1.yaml [--resume] [--seed N] [--out DIR]
    python3 -m crowdsim_bench.ppo evaluate results/train/ppo_table1/policy.pt SUITE ROW

Needs python3-torch and python3-yaml (Debian). docs/training.md ("PPO") lists every key of the
training file with its default and source.
"""
from .config import KEYS, PPOError, load, parse  # noqa: F401
from .model import ActorCritic, ExportedPolicy  # noqa: F401
from .trainer import Trainer, export  # noqa: F401

__all__ = ["KEYS", "PPOError", "load", "parse", "ActorCritic", "ExportedPolicy", "Trainer",
           "export"]

"""python3 -m crowdsim_bench.ppo train CONFIG.yaml [--resume] [--seed N] [--out DIR]
python3 -m crowdsim_bench.ppo evaluate POLICY.pt SUITE ROW [--episodes N] [--out DIR]

Bad input (a key misspelt or out of range, a row the encoder cannot take, a damaged or foreign
checkpoint) is one line naming the key or file, exit status 2; Ctrl-C exits 130 with the last
checkpoint kept."""
from __future__ import annotations

import argparse
import os
import sys
from typing import List, Optional


def _train(args) -> int:
    from .config import load, resolved_text
    from .trainer import Trainer
    config = load(args.config, args.set or [])
    if args.seed is not None:
        if not 0 <= args.seed <= 2**31 - 1:
            from .config import PPOError
            raise PPOError(f"--seed {args.seed} is out of range [0, 2147483647]")
        config["seed"] = args.seed
    out = args.out or os.path.join(
        "results", "train", f"ppo_{config['name']}"
        + (f"_seed{args.seed}" if args.seed is not None else ""))
    trainer = Trainer(config, out, resume=args.resume)
    with open(os.path.join(out, "training.yaml"), "w", encoding="utf-8") as f:
        f.write(resolved_text(config, args.config))
    try:
        trainer.train()
    finally:
        trainer.close()
    return 0


def _evaluate(args) -> int:
    import numpy as np
    import torch

    import crowdsim_bench as cb

    from .config import PPOError
    torch.set_num_threads(1)
    try:
        module = torch.jit.load(args.policy, map_location="cpu")
    except (RuntimeError, ValueError) as e:
        first = (str(e).strip().splitlines() or [type(e).__name__])[0]
        raise PPOError(f"{args.policy}: not a TorchScript policy ({first})") from None

    def act(obs):
        with torch.no_grad():
            return module({k: torch.from_numpy(np.asarray(v)) for k, v in obs.items()}).numpy()

    try:
        rows = cb.evaluate(act, args.suite, row=args.row, label=args.label, out=args.out,
                           episodes=args.episodes, progress=True)
    except (ValueError, RuntimeError) as e:
        raise PPOError(f"{args.suite}, row {args.row!r}: {e}") from None
    for r in rows:
        print(f"{r.get('label', args.label)}: success {r['success']:.3f}, collision "
              f"{r['collision']:.3f}, timeout {r['timeout']:.3f}")
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m crowdsim_bench.ppo",
                                     description="PPO baseline for crowdsim-bench")
    sub = parser.add_subparsers(dest="command", required=True)
    train = sub.add_parser("train", help="train a policy from a PPO training file (YAML)")
    train.add_argument("config", help="training file, e.g. suites/ppo/table1.yaml")
    train.add_argument("--resume", action="store_true",
                       help="continue the training in the output folder from its checkpoint")
    train.add_argument("--seed", type=int, help="another seed (default folder gets _seed<N>)")
    train.add_argument("--out", help="output folder (default results/train/ppo_<name>)")
    train.add_argument("--set", action="append", metavar="KEY=VALUE",
                       help="replace a key of the file (repeatable), e.g. --set total_steps=1000000")
    evaluate = sub.add_parser("evaluate", help="test an exported policy.pt on a suite row "
                              "through crowdsim_bench.evaluate (rows with the route sensor too)")
    evaluate.add_argument("policy", help="policy.pt written by train")
    evaluate.add_argument("suite")
    evaluate.add_argument("row")
    evaluate.add_argument("--episodes", type=int, default=None)
    evaluate.add_argument("--label", default="ppo")
    evaluate.add_argument("--out", default=None)
    args = parser.parse_args(argv)
    from .config import PPOError
    try:
        return _train(args) if args.command == "train" else _evaluate(args)
    except PPOError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130


if __name__ == "__main__":
    sys.exit(main())

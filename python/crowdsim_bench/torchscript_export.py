"""Exports a cadrl or sarl weights file of `crowdsim-bench train` as a TorchScript value network
for the `torchscript` policy plugin's `output: values` mode.

    PYTHONPATH=build/python /usr/bin/python3 -m crowdsim_bench.torchscript_export results/models/sarl_pp_lidar_person_rect1/weights.pt sarl.ts.pt

The module takes the stacked lookahead observations of the plugin (robot (A, 9), humans
(A, H, 5), humans_mask (A, H), lidar (A, beams): observation_tensors.h) and returns V(s') of
each (A,). It builds the state the C++ networks see (plugins/lib/value_rl/src/state_encoding.cc:
self state in the robot's frame, lidar ranges / max_range capped at 1, one row per person seen
and a stand-in 10 m behind the robot when nobody is) and runs the same layers with the file's
weights (plugins/lib/value_rl/src/value_network.cc), so the plugin with this module decides as
the built-in policy does: tests/python/test_torchscript_export.py runs both on the same
episodes. It also writes the row's params to use (the action set and sensors of the model).

Needs python3-torch (Debian) and, to read the lidar's max_range from the training.yaml next to
the weights, python3-yaml; --lidar-max-range sets it otherwise.
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path
from typing import Dict, List, Optional

import torch
from torch import Tensor

# value_rl's constants (state_encoding.h): a person model seeing nobody gets one stand-in
# human this far behind the robot, standing still.
ABSENT_HUMAN_DISTANCE = 10.0


def _mlp(width: int, dims: List[int], last_relu: bool) -> torch.nn.Sequential:
    """value_rl's Mlp(): Linear layers with a ReLU after each but the last (same indices, so
    the weights file's parameter names load as they are)."""
    layers: List[torch.nn.Module] = []
    for i, d in enumerate(dims):
        layers.append(torch.nn.Linear(width, d))
        if i + 1 < len(dims) or last_relu:
            layers.append(torch.nn.ReLU())
        width = d
    return torch.nn.Sequential(*layers)


class JoinedMlp(torch.nn.Module):
    """value_rl's ForwardJoined: an MLP over rows that join a per-state part (B, S) and a
    per-row part (B, N, R), with the first layer's weight split into the state's and the rows'
    columns as there, so the arithmetic is the C++ one. `state_first`: the state's columns
    come first in the joined row."""

    def __init__(self, state_width: int, row_width: int, dims: List[int], last_relu: bool,
                 state_first: bool):
        super().__init__()
        self.first = torch.nn.Linear(state_width + row_width, dims[0])
        rest = _mlp(dims[0], dims[1:], last_relu) if len(dims) > 1 else torch.nn.Sequential()
        self.rest = torch.nn.Sequential(torch.nn.ReLU(), *rest) if len(dims) > 1 or last_relu \
            else torch.nn.Sequential()
        self.state_width = state_width
        self.row_width = row_width
        self.state_first = state_first

    def forward(self, state: Tensor, rows: Tensor) -> Tensor:
        w = self.first.weight
        state_at = 0 if self.state_first else self.row_width
        rows_at = self.state_width if self.state_first else 0
        x = torch.nn.functional.linear(rows, w.narrow(1, rows_at, self.row_width)) + \
            torch.nn.functional.linear(state, w.narrow(1, state_at, self.state_width),
                                       self.first.bias).unsqueeze(1)
        return self.rest(x)


def _joined_names(state: Dict[str, Tensor], prefixes: List[str]) -> Dict[str, Tensor]:
    """The weights file's names (`mlp1.0.weight`, `mlp1.2.bias`) as JoinedMlp's
    (`mlp1.first.weight`, `mlp1.rest.1.bias`) for the joined MLPs."""
    renamed: Dict[str, Tensor] = {}
    for name, tensor in state.items():
        prefix, _, rest = name.partition(".")
        if prefix in prefixes:
            index, _, field = rest.partition(".")
            name = f"{prefix}.first.{field}" if index == "0" else f"{prefix}.rest.{int(index) - 1}.{field}"
        renamed[name] = tensor
    return renamed


class ValueNetworkModule(torch.nn.Module):
    """CADRL or SARL (with or without lidar / humans) on the plugin's observation dict."""

    def __init__(self, model: str, sensors: str, lidar_beams: int, lidar_hidden: int,
                 lidar_features: int, lidar_max_range: float):
        super().__init__()
        self.is_sarl = model == "sarl"
        self.uses_lidar = sensors != "person"
        self.uses_humans = sensors != "lidar"
        self.lidar_scale = 1.0 / lidar_max_range if lidar_max_range > 0 else 1.0
        self.absent_distance = ABSENT_HUMAN_DISTANCE
        self_dim = 6
        if self.uses_lidar:
            self.lidar = _mlp(lidar_beams, [lidar_hidden, lidar_features], True)
            self_dim += lidar_features
        else:
            self.lidar = torch.nn.Sequential()
        # Unused parts stay empty (TorchScript needs every attribute in both branches).
        self.mlp = JoinedMlp(1, 1, [1], False, True)
        self.mlp_plain = torch.nn.Sequential()
        self.mlp1 = JoinedMlp(1, 1, [1], False, True)
        self.mlp2 = torch.nn.Sequential()
        self.attention = JoinedMlp(1, 1, [1], False, False)
        self.mlp3 = torch.nn.Sequential()
        if self.is_sarl:
            if self.uses_humans:
                self.mlp1 = JoinedMlp(6, 7, [150, 100], True, True)
                self.mlp2 = _mlp(100, [100, 50], False)
                self.attention = JoinedMlp(100, 100, [100, 100, 1], False, False)
            self.mlp3 = _mlp(self_dim + (50 if self.uses_humans else 0), [150, 100, 100, 1], False)
        elif self.uses_humans:
            self.mlp = JoinedMlp(self_dim, 7, [150, 100, 100, 1], False, True)
        else:
            self.mlp_plain = _mlp(self_dim, [150, 100, 100, 1], False)
        # The parts this configuration uses (what the weights file must fill).
        self.used: List[str] = (["lidar"] if self.uses_lidar else []) + (
            (["mlp1", "mlp2", "attention", "mlp3"] if self.uses_humans else ["mlp3"]) if self.is_sarl
            else (["mlp"] if self.uses_humans else ["mlp_plain"]))

    def _self_state(self, robot: Tensor) -> Tensor:
        # state_encoding.cc AppendSelf, in float64 and then float32 as there.
        px, py, vx, vy = robot[:, 0], robot[:, 1], robot[:, 2], robot[:, 3]
        gx, gy, radius, v_pref, heading = robot[:, 4], robot[:, 5], robot[:, 6], robot[:, 7], robot[:, 8]
        c = torch.cos(heading)
        s = torch.sin(heading)
        dx = gx - px
        dy = gy - py
        dg = torch.sqrt(dx * dx + dy * dy)
        local_vx = vx * c + vy * s
        local_vy = vy * c - vx * s
        return torch.stack([dg, v_pref, torch.zeros_like(dg), radius, local_vx, local_vy], 1).float()

    def _human_rows(self, robot: Tensor, humans: Tensor, mask: Tensor):
        # state_encoding.cc AppendHuman; a state without anybody seen gets the stand-in row.
        if humans.size(1) == 0:  # `humans: 0` and nobody seen: room for the stand-in
            humans = torch.zeros(humans.size(0), 1, 5, dtype=humans.dtype)
            mask = torch.zeros(mask.size(0), 1, dtype=torch.bool)
        radius = robot[:, 6].unsqueeze(1).expand(-1, humans.size(1))
        nobody = mask.logical_not().all(1)
        stand_in = torch.zeros_like(humans[:, 0, :])
        stand_in[:, 0] = -self.absent_distance
        stand_in[:, 4] = robot[:, 6]
        first = torch.where(nobody.unsqueeze(1), stand_in, humans[:, 0, :])
        humans = torch.cat([first.unsqueeze(1), humans[:, 1:, :]], 1)
        mask = torch.cat([(mask[:, 0] | nobody).unsqueeze(1), mask[:, 1:]], 1)
        x, y = humans[:, :, 0], humans[:, :, 1]
        rows = torch.stack([x, y, humans[:, :, 2], humans[:, :, 3], humans[:, :, 4],
                            torch.sqrt(x * x + y * y), radius + humans[:, :, 4]], 2).float()
        return rows, mask

    def forward(self, obs: Dict[str, Tensor]) -> Tensor:
        robot = obs["robot"]
        plain = self._self_state(robot)
        joint = plain
        if self.uses_lidar:
            scaled = torch.clamp(obs["lidar"] * self.lidar_scale, max=1.0).float()
            joint = torch.cat([plain, self.lidar(scaled)], 1)
        if self.uses_humans:
            rows, mask = self._human_rows(robot, obs["humans"], obs["humans_mask"])
            if self.is_sarl:
                e = self.mlp1(plain, rows)
                h = self.mlp2(e)
                m = mask.float().unsqueeze(2)
                mean = (e * m).sum(1) / m.sum(1).clamp_min(1.0)
                scores = self.attention(mean, e).squeeze(2)
                w = torch.exp(scores) * scores.ne(0).float() * m.squeeze(2)
                w = w / w.sum(1, keepdim=True)
                joint = torch.cat([joint, (w.unsqueeze(2) * h).sum(1)], 1)
                values = self.mlp3(joint).squeeze(1)
            else:
                v = self.mlp(joint, rows).squeeze(2)
                v = v.masked_fill(mask.logical_not(), float("inf"))
                values = torch.min(v, 1)[0]
        elif self.is_sarl:
            values = self.mlp3(joint).squeeze(1)
        else:
            values = self.mlp_plain(joint).squeeze(1)
        return values


def _training_setting(weights: Path, plugin: str, key: str) -> Optional[str]:
    """`key` of `plugin` in the training.yaml beside the weights: its canonical lines name each
    plugin with its parameters, e.g. `lidar2d{beams=45;fov_deg=180;max_range=5;...}`."""
    training = weights.parent / "training.yaml"
    if not training.is_file():
        return None
    match = re.search(plugin + r"\{[^}]*\b" + key + r"=([^;}]*)", training.read_text())
    return match.group(1) if match else None


def export(weights: Path, out: Path, lidar_max_range: Optional[float] = None) -> Dict[str, object]:
    """Writes the TorchScript module of `weights` to `out`; returns the row params to use."""
    if not weights.is_file():
        raise SystemExit(f"{weights}: no such file (cadrl/sarl weights are written by "
                         "`crowdsim-bench train`, e.g. results/train/<name>/weights.pt)")
    try:
        archive = torch.jit.load(str(weights), map_location="cpu")
    except RuntimeError as e:
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise SystemExit(f"{weights}: not a TorchScript archive ({first}); give the weights.pt "
                         "of `crowdsim-bench train`") from None
    if not hasattr(archive, "crowdsim_model"):
        raise SystemExit(f"{weights}: a TorchScript module, but not cadrl/sarl weights of "
                         "`crowdsim-bench train` (no crowdsim_model attribute); a module already "
                         "exported runs as it is: {policy: torchscript, weights: " + str(weights) +
                         "}")
    model = str(archive.crowdsim_model)
    sensors = str(archive.crowdsim_sensors)
    beams = int(archive.crowdsim_lidar_beams)
    if sensors.endswith("+route"):
        raise SystemExit(f"{weights}: a {sensors} model; the torchscript plugin has no route input "
                         "yet, so models that read the route sensor cannot be exported")
    state = {name: p.detach().clone() for name, p in archive.named_parameters()}
    hidden, features = 64, 32
    if "lidar.0.weight" in state:
        hidden = state["lidar.0.weight"].shape[0]
        features = state["lidar.2.weight"].shape[0]
    if sensors != "person" and lidar_max_range is None:
        found = _training_setting(weights, "lidar2d", "max_range")
        lidar_max_range = float(found) if found else None
        if lidar_max_range is None:
            raise SystemExit(f"{weights}: a lidar model, but no training.yaml beside it to read the "
                             "lidar's max_range from; give --lidar-max-range")
    net = ValueNetworkModule(model, sensors, beams, hidden, features, lidar_max_range or 0.0)
    if net.uses_humans:
        state = _joined_names(state, ["mlp1", "attention"] if net.is_sarl else ["mlp"])
    elif not net.is_sarl:
        state = {name.replace("mlp.", "mlp_plain.", 1) if name.startswith("mlp.") else name: t
                 for name, t in state.items()}
    missing, unexpected = net.load_state_dict(state, strict=False)
    missing = [name for name in missing if name.split(".")[0] in net.used]
    if missing or unexpected:
        raise SystemExit(f"{weights}: parameters do not fit a {model} network with sensors "
                         f"{sensors}: missing {missing}, unexpected {unexpected}")
    scripted = torch.jit.script(net.eval())
    try:  # a folder not there yet is made, as `crowdsim-bench run --out` does
        Path(out).parent.mkdir(parents=True, exist_ok=True)
        scripted.save(str(out))
    except (OSError, RuntimeError) as e:  # torch reports a file it cannot write as RuntimeError
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise SystemExit(f"{out}: cannot write the exported module ({first})") from None
    # The action set: from training.yaml when it is there, else cadrl's and sarl's default.
    action_set = {"speed_samples": 2, "rotation_samples": 8, "stop_action": False}
    for key, default in list(action_set.items()):
        found = _training_setting(weights, model, key)
        if found is not None:
            action_set[key] = found == "true" if isinstance(default, bool) else int(found)
    count = action_set["speed_samples"] * action_set["rotation_samples"] + int(action_set["stop_action"])
    if count != int(archive.crowdsim_actions):
        raise SystemExit(f"{weights}: the model has {int(archive.crowdsim_actions)} actions but the "
                         f"action set {action_set} has {count}; put its training.yaml beside it")
    params: Dict[str, object] = {"output": "values", "sensors": sensors, **action_set}
    if beams:
        params["lidar_beams"] = beams
    return params


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("weights", type=Path, help="cadrl/sarl weights (.pt of crowdsim-bench train)")
    parser.add_argument("out", type=Path, help="TorchScript file to write")
    parser.add_argument("--lidar-max-range", type=float, default=None,
                        help="m; default: from training.yaml beside the weights")
    args = parser.parse_args(argv)
    params = export(args.weights, args.out, args.lidar_max_range)
    flow = ", ".join(f"{k}: {str(v).lower() if isinstance(v, bool) else v}" for k, v in params.items())
    print(f"wrote {args.out}; row: {{policy: torchscript, weights: {args.out}, params: {{{flow}}}}}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

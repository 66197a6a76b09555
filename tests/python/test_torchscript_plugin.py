"""The `torchscript` policy plugin: tiny modules scripted and saved here with python3-torch run
as suite rows of suites/quick.yaml through the CLI. A module with the `linear` rule plays the
`linear` row's episodes; `action` mode picks CrowdNav's holonomic actions by index or by
scores; a module reading every observation key decides as the same module called from Python
through crowdsim_bench.evaluate() (same layout); wrong files are errors naming file and fix.
Run by ctest (torchscript_plugin) from the source root with CROWDSIM_BENCH naming the CLI;
exits 77 (ctest: skipped) without python3-torch."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

try:
    import torch
except ImportError:
    print("torchscript_plugin: python3-torch is not installed (apt-get install python3-torch); skipped")
    sys.exit(77)

from typing import Dict

import numpy as np

CLI = os.environ.get("CROWDSIM_BENCH", "build/bin/crowdsim-bench")
QUICK = "suites/quick.yaml"
EPISODES = 12
# The outcome columns of episodes.csv (all but the row label and the decision time).
COMPARED = ["episode", "seed", "layout", "status", "time", "steps", "danger_steps",
            "path_length", "min_human_distance", "discounted_return", "humans_at_goal", "error"]


class StraightToGoal(torch.nn.Module):
    """The `linear` plugin's rule: v_pref towards the goal, the last step shortened to reach it
    (the suite's time step is 0.25 s)."""

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        r = obs["robot"]
        d = r[4:6] - r[0:2]
        dist = torch.sqrt(d[0] * d[0] + d[1] * d[1])
        if float(dist) < 1e-9:
            return torch.zeros(2, dtype=torch.float64)
        return d / dist * torch.minimum(r[7], dist / 0.25)


class ConstantVelocity(torch.nn.Module):
    """v_pref along the world's +x axis: holonomic action 5 (direction 0, fastest speed)."""

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return torch.stack([obs["robot"][7], torch.zeros((), dtype=torch.float64)])


class ConstantIndex(torch.nn.Module):
    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return torch.tensor(5)


def goal_scores(obs: Dict[str, torch.Tensor]) -> torch.Tensor:
    """Scores of the 81 holonomic actions (stop, then 16 directions x 5 speeds): minus the
    squared distance to the velocity straight to the goal at v_pref."""
    r = obs["robot"]
    d = r[4:6] - r[0:2]
    want = d / torch.sqrt(d[0] * d[0] + d[1] * d[1]) * r[7]
    speeds = (torch.exp(torch.arange(1, 6, dtype=torch.float64) / 5) - 1) / (torch.e - 1) * r[7]
    angles = torch.arange(16, dtype=torch.float64) * (2 * torch.pi / 16)
    vx = (torch.cos(angles)[:, None] * speeds[None, :]).reshape(-1)
    vy = (torch.sin(angles)[:, None] * speeds[None, :]).reshape(-1)
    vx = torch.cat([torch.zeros(1, dtype=torch.float64), vx])
    vy = torch.cat([torch.zeros(1, dtype=torch.float64), vy])
    return -((vx - want[0]) ** 2 + (vy - want[1]) ** 2)


class GoalScores(torch.nn.Module):
    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return goal_scores(obs).float()


class GoalIndex(torch.nn.Module):
    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return torch.argmax(goal_scores(obs))


class Cautious(torch.nn.Module):
    """Reads every key: slows down near the closest seen human and the closest lidar return,
    and checks the layout (shapes, dtypes, padding) on every call."""

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        r, h, m, lidar = obs["robot"], obs["humans"], obs["humans_mask"], obs["lidar"]
        if r.shape != (9,) or h.shape != (5, 5) or m.dtype != torch.bool or lidar.shape != (45,):
            raise RuntimeError("unexpected observation layout")
        if obs["time"].dim() != 0 or h.dtype != torch.float64:
            raise RuntimeError("unexpected time or dtype")
        near = torch.tensor(10.0, dtype=torch.float64)
        if bool(m.any()):
            seen = h[m]
            near = torch.sqrt(seen[:, 0] ** 2 + seen[:, 1] ** 2).min() - seen[:, 4].min()
        factor = torch.clamp(torch.minimum(near, lidar.min()) / 2.0, 0.2, 1.0)
        d = r[4:6] - r[0:2]
        dist = torch.sqrt(d[0] * d[0] + d[1] * d[1])
        if float(dist) < 1e-9:
            return torch.zeros(2, dtype=torch.float64)
        return d / dist * torch.minimum(r[7] * factor, dist / 0.25) + 0.01 * obs["time"]


class TurnThenGo(torch.nn.Module):
    """`command` mode on a unicycle robot: turn towards the goal (at most pi rad/s), and go at
    v_pref once within 45 degrees of it."""
    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        r = obs["robot"]
        d = r[4:6] - r[0:2]
        error = torch.atan2(d[1], d[0]) - r[8]
        error = torch.atan2(torch.sin(error), torch.cos(error))
        angular = torch.clamp(error / 0.25, -torch.pi, torch.pi)
        linear = r[7] if float(torch.abs(error)) < torch.pi / 4 else torch.zeros((), dtype=torch.float64)
        return torch.stack([linear, angular])


class WrongSignature(torch.nn.Module):
    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return x


class ThreeNumbers(torch.nn.Module):
    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return torch.zeros(3)


class NearerToGoalIsBetter(torch.nn.Module):
    """`values` mode: V(s') = minus the distance to the goal of each stacked lookahead state,
    with every key's batch size checked against the robot's."""

    def forward(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        r = obs["robot"]
        a = r.size(0)
        if obs["humans"].size(0) != a or obs["humans_mask"].size(0) != a or obs["time"].size(0) != a:
            raise RuntimeError("batch sizes differ")
        d = r[:, 4:6] - r[:, 0:2]
        return -torch.sqrt((d * d).sum(1)).float()


class NoForward(torch.nn.Module):
    @torch.jit.export
    def act(self, obs: Dict[str, torch.Tensor]) -> torch.Tensor:
        return obs["robot"][0:2]


def save(module, path):
    torch.jit.script(module).save(path)
    return path


def quick_with_rows(folder, rows):
    """suites/quick.yaml with `rows` (YAML flow maps) in place of its own."""
    with open(QUICK) as f:
        head = f.read().split("\nrows:")[0]
    path = os.path.join(folder, "suite.yaml")
    with open(path, "w") as f:
        f.write(head + "\nrows:\n" + "".join(f"  - {row}\n" for row in rows))
    return path


def run(suite, out, episodes=EPISODES):
    p = subprocess.run([CLI, "run", suite, "--episodes", str(episodes), "--out", out, "--jobs", "2"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError(f"crowdsim-bench run failed ({p.returncode}):\n{p.stdout}\n{p.stderr}")
    return episodes_by_row(os.path.join(out, "episodes.csv"))


def episodes_by_row(path):
    rows = {}
    with open(path, newline="") as f:
        for e in csv.DictReader(f):
            rows.setdefault(e["row"], {})[int(e["episode"])] = [e[c] for c in COMPARED]
    return rows


class TorchScriptPlugin(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def test_velocity_module_plays_the_linear_rows_episodes(self):
        pt = save(StraightToGoal(), self.path("straight.pt"))
        suite = quick_with_rows(self.dir, [
            "{label: linear, policy: linear}",
            f"{{label: ts, policy: torchscript, weights: {pt}}}",
        ])
        got = run(suite, self.path("out"))
        self.assertEqual(len(got["ts"]), EPISODES)
        self.assertEqual(got["ts"], got["linear"])
        statuses = {e[3] for e in got["ts"].values()}
        self.assertTrue(statuses & {"success", "collision_human", "collision_obstacle"}, statuses)

    def test_action_mode_takes_an_index_or_the_argmax_of_81_scores(self):
        rows = [
            f"{{label: velocity, policy: torchscript, weights: {save(ConstantVelocity(), self.path('v.pt'))}}}",
            f"{{label: index5, policy: torchscript, weights: {save(ConstantIndex(), self.path('i.pt'))}, params: {{output: action}}}}",
            f"{{label: goal_index, policy: torchscript, weights: {save(GoalIndex(), self.path('gi.pt'))}, params: {{output: action}}}}",
            f"{{label: goal_scores, policy: torchscript, weights: {save(GoalScores(), self.path('gs.pt'))}, params: {{output: action}}}}",
        ]
        got = run(quick_with_rows(self.dir, rows), self.path("out"))
        # Action 5 is v_pref along +x: the velocity module's episodes.
        self.assertEqual(got["index5"], got["velocity"])
        # Index and scores of the same choice: the same episodes, which do move.
        self.assertEqual(got["goal_index"], got["goal_scores"])
        self.assertNotEqual(got["goal_index"], got["velocity"])
        self.assertTrue(all(float(e[7]) > 0 for e in got["goal_index"].values()))

    def test_values_mode_acts_on_the_best_lookahead_value(self):
        pt = save(NearerToGoalIsBetter(), self.path("values.pt"))
        got = run(quick_with_rows(self.dir, [
            f"{{label: values, policy: torchscript, weights: {pt}, params: {{output: values}}}}",
        ]), self.path("out"))
        statuses = [e[3] for e in got["values"].values()]
        self.assertNotIn("policy_error", statuses)
        self.assertIn("success", statuses)
        self.assertTrue(all(float(e[7]) > 0 for e in got["values"].values()))

    def test_the_output_names_the_form_a_unicycle_robot_takes(self):
        command = save(TurnThenGo(), self.path("turn.pt"))
        velocity = save(StraightToGoal(), self.path("straight.pt"))
        got = run(quick_with_rows(self.dir, [
            f"{{label: command, policy: torchscript, weights: {command}, "
            "params: {output: command}, kinematics: unicycle}",
            f"{{label: tracked, policy: torchscript, weights: {velocity}, "
            "kinematics: {model: unicycle, track_velocity: true}}",
            "{label: linear, policy: linear, kinematics: unicycle}",
        ]), self.path("out"))
        statuses = [e[3] for e in got["command"].values()]
        self.assertNotIn("policy_error", statuses)
        self.assertIn("success", statuses)
        # A tracked velocity module is the linear plugin on the same body, episode for episode.
        self.assertEqual(got["tracked"], got["linear"])
        # Velocities without tracking, and commands for a holonomic robot, are refused before
        # any episode.
        refused = subprocess.run([CLI, "run", quick_with_rows(self.dir, [
            f"{{label: v, policy: torchscript, weights: {velocity}, kinematics: unicycle}}"]),
            "--out", self.path("refused")], capture_output=True, text=True)
        self.assertEqual(refused.returncode, 2, refused.stdout + refused.stderr)
        self.assertIn("cannot drive a unicycle robot: add `track_velocity: true`", refused.stderr)
        holonomic = subprocess.run([CLI, "run", quick_with_rows(self.dir, [
            f"{{label: h, policy: torchscript, weights: {command}, params: {{output: command}}}}"]),
            "--out", self.path("holonomic")], capture_output=True, text=True)
        self.assertEqual(holonomic.returncode, 2, holonomic.stdout + holonomic.stderr)
        self.assertIn("output: command returns (linear, angular) commands, which a holonomic "
                      "robot does not take", holonomic.stderr)

    def test_values_mode_refuses_a_module_without_one_value_per_action(self):
        pt = save(ConstantIndex(), self.path("i.pt"))
        err = self.validate_error(
            f"{{label: ts, policy: torchscript, weights: {pt}, params: {{output: values, "
            "speed_samples: 2, rotation_samples: 8, stop_action: false}}")
        self.assertIn("output: values expects 16 floating-point values", err)

    def test_observation_layout_equals_the_python_envs(self):
        try:
            import crowdsim_bench as cb
        except ImportError:
            self.skipTest("the Python package crowdsim_bench is not built or not on PYTHONPATH")
        module = Cautious()
        pt = save(module, self.path("cautious.pt"))
        scripted = torch.jit.load(pt)
        suite = quick_with_rows(self.dir, [
            f"{{label: ts, policy: torchscript, weights: {pt}, params: {{sensors: lidar+person}}}}",
        ])
        got = run(suite, self.path("cli"), episodes=6)

        def policy(obs):
            tensors = {k: torch.from_numpy(np.asarray(v)) for k, v in obs.items()}
            return scripted(tensors).numpy()

        cb.evaluate(policy, suite, row="ts", label="ts", out=self.path("py"), episodes=6)
        from_python = episodes_by_row(os.path.join(self.path("py"), "episodes.csv"))
        self.assertEqual(got["ts"], from_python["ts"])
        self.assertTrue(all(e[3] != "policy_error" for e in got["ts"].values()), got["ts"])

    def validate_error(self, row):
        suite = quick_with_rows(self.dir, [row])
        p = subprocess.run([CLI, "validate", suite], capture_output=True, text=True)
        self.assertNotEqual(p.returncode, 0, p.stdout)
        return p.stdout + p.stderr

    def test_wrong_files_are_errors_naming_the_file_and_the_fix(self):
        missing = self.path("missing.pt")
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {missing}}}")
        self.assertIn(f"weights file '{missing}' does not exist", msg)
        self.assertIn("torch.jit.script(model).save(path)", msg)

        msg = self.validate_error("{label: ts, policy: torchscript}")
        self.assertIn("parameter 'weights' is empty", msg)

        state = self.path("state.pt")
        torch.save({"w": torch.zeros(2)}, state)
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {state}}}")
        self.assertIn(f"'{state}' is not a TorchScript module", msg)

        damaged = save(StraightToGoal(), self.path("damaged.pt"))
        with open(damaged, "r+b") as f:
            f.truncate(os.path.getsize(damaged) // 2)
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {damaged}}}")
        self.assertIn(f"'{damaged}'", msg)

        pt = save(NoForward(), self.path("noforward.pt"))
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {pt}}}")
        self.assertIn(f"'{pt}' has no forward method", msg)

        pt = save(WrongSignature(), self.path("signature.pt"))
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {pt}}}")
        self.assertIn("expected forward(self, obs: Dict[str, Tensor]) -> Tensor", msg)

        pt = save(ThreeNumbers(), self.path("three.pt"))
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {pt}}}")
        self.assertIn("returned a tensor of shape [3] and dtype Float", msg)
        self.assertIn("output: velocity expects 2 floating-point numbers", msg)

        pt = save(StraightToGoal(), self.path("velocity.pt"))
        msg = self.validate_error(
            f"{{label: ts, policy: torchscript, weights: {pt}, params: {{output: action}}}}")
        self.assertIn("returned a tensor of shape [2] and dtype Double", msg)
        self.assertIn("output: action expects one integer index in [0, 81) or 81", msg)

    def test_a_missing_sensor_is_refused_and_lidar_beams_must_match(self):
        pt = save(StraightToGoal(), self.path("straight.pt"))
        suite = quick_with_rows(self.dir, [
            f"{{label: ts, policy: torchscript, weights: {pt}, params: {{sensors: lidar}}, sensors: [person]}}",
        ])
        p = subprocess.run([CLI, "validate", suite], capture_output=True, text=True)
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("lidar2d", p.stdout + p.stderr)

        # A module that reads the lidar on a row whose params leave it out (sensors: person).
        cautious = save(Cautious(), self.path("cautious.pt"))
        msg = self.validate_error(f"{{label: ts, policy: torchscript, weights: {cautious}}}")
        self.assertIn("KeyError: lidar", msg)
        self.assertIn("The observation has the keys robot, time, humans, humans_mask "
                      "(params.sensors: person); a module that reads lidar needs sensors: lidar "
                      "or lidar+person", msg)

        suite = quick_with_rows(self.dir, [
            f"{{label: ts, policy: torchscript, weights: {pt}, params: {{sensors: lidar+person, lidar_beams: 30}}}}",
        ])
        # run plays the first step before any episode, as validate does: refused (exit 2, no
        # folder), where it ran a table of policy errors and exited 0.
        p = subprocess.run([CLI, "run", suite, "--episodes", "2", "--quiet", "--out",
                            self.path("beams")], capture_output=True, text=True)
        self.assertEqual(p.returncode, 2, p.stdout + p.stderr)
        self.assertIn("row 'ts' (rows[0]): the first step of episode 0 fails: the robot's "
                      "policy failed: torchscript: the lidar2d sensor has 45 beams but parameter "
                      "lidar_beams is 30; set lidar_beams: 45", p.stderr)
        self.assertFalse(os.path.exists(self.path("beams")))

    def test_the_example_script_writes_a_runnable_suite(self):
        p = subprocess.run([sys.executable, "examples/python/export_torchscript.py", self.dir],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        got = run(os.path.join(self.dir, "suite.yaml"), self.path("results"), episodes=4)
        self.assertEqual(len(got["slow_near_people"]), 4)
        self.assertTrue(all(e[3] != "policy_error" for e in got["slow_near_people"].values()))


if __name__ == "__main__":
    unittest.main(verbosity=2)

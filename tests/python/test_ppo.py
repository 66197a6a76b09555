"""crowdsim_bench.ppo, the PPO baseline: the training file's errors name key, value and range;
a tiny training is seeded (same seed, same weights) and resumable (interrupted + resumed = the
uninterrupted run, weights and curve); a damaged, foreign or other-configuration checkpoint is
refused naming the file; the exported TorchScript module takes the plugin's observation and
returns (vx, vy); run by the `torchscript` plugin (when CROWDSIM_BENCH names a CLI with it) it
plays the same episodes as the Python policy through crowdsim_bench.evaluate().

Run from the source root with the package on PYTHONPATH (ctest python_ppo). Skipped, saying
so, without python3-torch or python3-yaml. Tiny runs on one thread: ~15-30 s in all."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

try:
    import torch
    import yaml  # noqa: F401  (the training file)
except ImportError as e:
    torch = None
    _MISSING = f"python3-torch and python3-yaml are needed ({e}); skipped"

if torch is not None:
    import crowdsim_bench as cb
    from crowdsim_bench import ppo
    from crowdsim_bench.ppo.config import PPOError, canonical, load, parse, resolved_text
    from crowdsim_bench.ppo.trainer import Trainer, observation_layout
    torch.set_num_threads(1)

QUICK = "suites/quick.yaml"
# A tiny training: 4 environments x 16 steps, 6 updates, a checkpoint every 2.
TINY = {"suite": QUICK, "row": "orca", "set": ["world.split=train"], "num_envs": 4,
        "steps_per_rollout": 16, "epochs": 2, "minibatch_size": 32, "total_steps": 6 * 64,
        "checkpoint_interval": 2, "hidden": 32, "seed": 7}
CLI = os.environ.get("CROWDSIM_BENCH", "")


def tiny(**changes):
    data = dict(TINY, **changes)
    return parse(data, "tiny.yaml")


def course(config):
    """What decides a training and what it was run for (canonical keys and total_steps)."""
    return dict(canonical(config), total_steps=config["total_steps"])


def weights(trainer):
    return {k: v.clone() for k, v in trainer.model.state_dict().items()}


def train(config, out, stop_after=None, resume=False):
    trainer = Trainer(config, out, resume=resume, quiet=True)
    try:
        trainer.train(stop_after=stop_after)
    finally:
        trainer.close()
    return trainer


def curve(out):
    with open(os.path.join(out, "learning_curve.csv"), newline="") as f:
        return [{k: v for k, v in r.items() if k not in ("seconds", "steps_per_s", "collect_seconds", "update_seconds")}
                for r in csv.DictReader(f)]


@unittest.skipIf(torch is None, _MISSING if torch is None else "")
class Config(unittest.TestCase):
    def assertError(self, data, *parts):
        with self.assertRaises(PPOError) as c:
            parse(data, "bad.yaml")
        for part in parts:
            self.assertIn(part, str(c.exception))

    def test_a_misspelt_key_is_named_with_the_valid_keys(self):
        self.assertError(dict(TINY, lerning_rate=0.1), "bad.yaml", "'lerning_rate'",
                         "did you mean 'learning_rate'", "gae_lambda")

    def test_values_out_of_range_name_key_value_and_range(self):
        self.assertError(dict(TINY, clip=1.5), "clip = 1.5", "(0, 1]")
        self.assertError(dict(TINY, gamma=-0.1), "gamma = -0.1", "[0, 1]")
        self.assertError(dict(TINY, num_envs=0), "num_envs = 0", "[1, 4096]")
        self.assertError(dict(TINY, learning_rate=0), "learning_rate = 0.0", "(0, 1]")
        self.assertError(dict(TINY, epochs=2.5), "epochs must be a whole number")
        self.assertError(dict(TINY, discrete="yes"), "discrete must be true or false")
        self.assertError(dict(TINY, lr_schedule="cosine"), "lr_schedule", "constant, linear")
        self.assertError(dict(TINY, minibatch_size=1000), "minibatch_size = 1000",
                         "num_envs x steps_per_rollout = 64")
        self.assertError({"row": "orca"}, "'suite' is required")
        self.assertError([1, 2], "a YAML mapping")

    def test_committed_models_match_their_training_files(self):
        # results/models/ppo_NAME[_seedN]/training.yaml is the file it trained from (with
        # --seed N, its base resolved): every key that steers a training is as suites/ppo/NAME.yaml
        # gives it now (a changed file would no longer describe the committed model).
        import glob
        import json
        folders = sorted(glob.glob("results/models/ppo_*"))
        self.assertTrue(folders)
        for folder in folders:
            with open(os.path.join(folder, "summary.json")) as f:
                summary = json.load(f)
            with open(os.path.join(folder, "training.yaml")) as f:
                text = f.read()
            trained = parse(yaml.safe_load(text), folder)
            shipped = load(os.path.join("suites/ppo", summary["name"] + ".yaml"))
            self.assertEqual(dict(course(trained), seed=0), dict(course(shipped), seed=0), folder)
            _, reseeded, seed = os.path.basename(folder).rpartition("_seed")
            want = int(seed) if reseeded else shipped["seed"]
            self.assertEqual(summary["seed"], want, folder)
            # The trainer's record holds the seed it trained with; a copy of the file, the file's.
            recorded = "resolved: every key's value" in text.splitlines()[0]
            self.assertEqual(trained["seed"], want if recorded else shipped["seed"], folder)
            self.assertGreaterEqual(summary["steps"], trained["total_steps"], folder)
            self.assertTrue(os.path.isfile(os.path.join(folder, "policy.pt")), folder)

    def test_defaults_are_filled_in(self):
        c = parse({"suite": QUICK, "row": "orca"}, "suites/ppo/x.yaml")
        self.assertEqual((c["clip"], c["gamma"], c["gae_lambda"], c["learning_rate"]),
                         (0.2, 0.99, 0.95, 3e-4))
        self.assertEqual(c["name"], "x")
        self.assertEqual(set(c), set(ppo.KEYS))

    def test_the_command_line_says_one_line_and_exits_2(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.yaml")
            with open(path, "w") as f:
                f.write("suite: suites/quick.yaml\nrow: orca\nclip: 3\n")
            p = subprocess.run([sys.executable, "-m", "crowdsim_bench.ppo", "train", path,
                                "--out", os.path.join(d, "out")], capture_output=True, text=True)
        self.assertEqual(p.returncode, 2, p.stderr)
        self.assertNotIn("Traceback", p.stderr)
        self.assertIn("clip = 3.0 is out of range (0, 1]", p.stderr)

    def test_set_replaces_a_key_of_the_file_for_one_run(self):
        from crowdsim_bench.ppo.config import load
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "t.yaml")
            with open(path, "w") as f:
                f.write(f"suite: {os.path.abspath(QUICK)}\nrow: orca\ntotal_steps: 5000\n")
            self.assertEqual(load(path, ["total_steps=64", "discrete=true"])["total_steps"], 64)
            self.assertTrue(load(path, ["discrete=true"])["discrete"])
            with self.assertRaises(PPOError) as c:
                load(path, ["total_steps"])
            self.assertIn("write KEY=VALUE", str(c.exception))
            with self.assertRaises(PPOError) as c:
                load(path, ["total_step=64"])
            self.assertIn("did you mean", str(c.exception))
            with self.assertRaises(PPOError) as c:
                load(path, ["clip=3"])
            self.assertIn("clip = 3.0 is out of range", str(c.exception))

    def test_a_base_lends_its_keys_and_the_file_replaces_them(self):
        with tempfile.TemporaryDirectory() as d:
            os.makedirs(os.path.join(d, "sub"))
            with open(os.path.join(d, "base.yaml"), "w") as f:
                # The base's suite relative to the base's folder, not the extending file's.
                suite = os.path.relpath(os.path.abspath(QUICK), d)
                f.write(f"name: b\ndescription: the base\nsuite: {suite}\n"
                        "row: orca\nclip: 0.1\ngamma: 0.9\nset: [world.split=train]\n")
            path = os.path.join(d, "sub", "child.yaml")
            with open(path, "w") as f:
                f.write("base: ../base.yaml\ngamma: 0.95\n")
            c = load(path)
            self.assertEqual((c["clip"], c["gamma"], c["row"], c["set"]),
                             (0.1, 0.95, "orca", ["world.split=train"]))
            self.assertEqual((c["name"], c["description"]), ("child", ""))
            self.assertEqual(os.path.abspath(c["suite"]), os.path.abspath(QUICK))
            # The record of a training is a file of its own with the same values.
            again = parse(yaml.safe_load(resolved_text(c, path)), "training.yaml")
            self.assertEqual(again, dict(c, base=""))

    def test_a_missing_or_circular_base_is_named(self):
        with tempfile.TemporaryDirectory() as d:
            a, b = os.path.join(d, "a.yaml"), os.path.join(d, "b.yaml")
            with open(a, "w") as f:
                f.write("base: b.yaml\n")
            with self.assertRaises(PPOError) as c:
                load(a)
            self.assertIn(f"{b} (the base of {a}): cannot read", str(c.exception))
            with open(b, "w") as f:
                f.write("base: a.yaml\nrow: orca\n")
            with self.assertRaises(PPOError) as c:
                load(a)
            self.assertIn(f"leads back to itself ({a} -> {b} -> {a})", str(c.exception))

    def test_a_row_whose_observation_the_encoder_cannot_take(self):
        class Space:
            def __init__(self, shape):
                self.shape, self.high = shape, np.full(shape, 5.0)

        class FakeEnv:
            single_observation_space = {"robot": Space((9,)), "humans": Space((5, 5)),
                                        "humans_mask": Space((5,)), "time": Space(()),
                                        "sonar": Space((8,))}
        with self.assertRaises(PPOError) as c:
            observation_layout(FakeEnv(), "suite.yaml, row 'x'")
        self.assertIn("'sonar'", str(c.exception))
        self.assertIn("suite.yaml, row 'x'", str(c.exception))

    def test_the_route_frame_needs_the_route_sensor(self):
        with tempfile.TemporaryDirectory() as d, self.assertRaises(PPOError) as c:
            Trainer(tiny(frame="route"), os.path.join(d, "out"), quiet=True)
        self.assertIn("row 'orca': frame: route needs the route sensor", str(c.exception))

    def test_the_wall_penalty_needs_a_lidar(self):
        sensors = "robot.sensors=[person]"
        with tempfile.TemporaryDirectory() as d, self.assertRaises(PPOError) as c:
            Trainer(tiny(wall_penalty=0.1, set=TINY["set"] + [sensors]), os.path.join(d, "out"),
                    quiet=True)
        self.assertIn("wall_penalty needs a lidar", str(c.exception))

    def test_the_wall_penalty_falls_linearly_to_zero_at_its_distance(self):
        from crowdsim_bench.ppo.trainer import wall_penalty
        # Radius 0.3: surfaces 0 (touching), 0.1, 0.3 and 1.0 m from the nearest return.
        lidar = np.array([[5.0, 0.3, 4.0], [0.4, 5.0, 5.0], [0.6, 0.7, 5.0], [1.3, 5.0, 2.0]])
        robot = np.zeros((4, 9))
        robot[:, 6] = 0.3
        got = wall_penalty({"lidar": lidar, "robot": robot}, 0.06, 0.3)
        np.testing.assert_allclose(got, [0.06, 0.04, 0.0, 0.0], atol=1e-12)

    def test_an_unknown_row_is_named(self):
        with tempfile.TemporaryDirectory() as d, self.assertRaises(PPOError) as c:
            Trainer(tiny(row="no_such_row"), os.path.join(d, "out"), quiet=True)
        self.assertIn("no_such_row", str(c.exception))


@unittest.skipIf(torch is None, _MISSING if torch is None else "")
class Frames(unittest.TestCase):
    def test_the_route_frame_turns_actions_and_people_towards_the_waypoint(self):
        from crowdsim_bench.ppo.model import ActorCritic
        # The robot at the origin, its goal 10 m along x (heading 0), the waypoint 2 m to its
        # left; one person at (1, 1).
        obs = {"robot": torch.tensor([[0.0, 0, 0, 0, 10, 0, 0.3, 1.0, 0]]),
               "humans": torch.tensor([[[1.0, 1, 0.5, 0, 0.3]]]),
               "humans_mask": torch.tensor([[True]]), "time": torch.tensor([0.0]),
               "route": torch.tensor([[12.0, 0, 2]])}
        for frame, want in (("goal", (1.0, 0.0)), ("route", (0.0, 1.0))):
            model = ActorCritic(0, 5.0, True, 25.0, False, hidden=16, frame=frame)
            with torch.no_grad():
                model.policy_head.weight.zero_()
                model.policy_head.bias.copy_(torch.tensor([1.0, 0.0]))  # "straight ahead"
                got = model.greedy(obs)[0]
            self.assertTrue(torch.allclose(got, torch.tensor(want, dtype=torch.float64),
                                           atol=1e-6), (frame, got))
        # x along the waypoint (world +y): the person at (1, 1) lies 1 m ahead, 1 m right; its
        # velocity (0.5, 0) points right.
        turned = model._turned(obs["humans"], obs)[0, 0]
        self.assertTrue(torch.allclose(turned, torch.tensor([1.0, -1, 0, -0.5, 0.3]), atol=1e-6),
                        turned)


@unittest.skipIf(torch is None, _MISSING if torch is None else "")
class Training(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def out(self, name):
        return os.path.join(self.tmp.name, name)

    def test_same_seed_same_weights_and_resume_continues_exactly(self):
        a = weights(train(tiny(), self.out("a")))
        b = weights(train(tiny(), self.out("b")))
        for k in a:
            self.assertTrue(torch.equal(a[k], b[k]), k)
        other = weights(train(tiny(seed=8), self.out("other")))
        self.assertFalse(all(torch.equal(a[k], other[k]) for k in a))
        # Interrupted after update 3 (checkpoint of update 2), then resumed to the end.
        with self.assertRaises(KeyboardInterrupt):
            train(tiny(), self.out("r"), stop_after=3)
        resumed = weights(train(tiny(), self.out("r"), resume=True))
        for k in a:
            self.assertTrue(torch.equal(a[k], resumed[k]), k)
        self.assertEqual(curve(self.out("r")), curve(self.out("a")))
        for name in ("policy.pt", "checkpoint.pt", "learning_curve.svg", "summary.json"):
            self.assertTrue(os.path.isfile(os.path.join(self.out("r"), name)), name)
        self.assertEqual([f for f in os.listdir(self.out("r")) if ".tmp" in f], [])

    def test_the_command_line_records_every_key_it_trained_with(self):
        path = self.out("tiny.yaml")
        with open(path, "w") as f:
            yaml.safe_dump(dict(TINY, suite=os.path.abspath(QUICK), total_steps=64), f)
        out = self.out("cli")
        p = subprocess.run([sys.executable, "-m", "crowdsim_bench.ppo", "train", path, "--seed",
                            "9", "--set", "clip=0.3", "--out", out], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)
        with open(os.path.join(out, "training.yaml")) as f:
            recorded = parse(yaml.safe_load(f), "training.yaml")
        self.assertEqual(recorded, dict(load(path, ["clip=0.3"]), seed=9))

    def test_the_collision_penalty_rises_over_its_warmup(self):
        trainer = Trainer(tiny(collision_penalty=2.0, collision_penalty_warmup=1000),
                          self.out("w"), quiet=True)
        try:
            seen = []
            for steps in (0, 250, 1000, 5000):
                trainer.steps = steps
                seen.append(trainer._collision_penalty())
        finally:
            trainer.close()
        self.assertEqual(seen, [0.0, 0.5, 2.0, 2.0])
        full = Trainer(tiny(collision_penalty=2.0), self.out("f"), quiet=True)
        full.close()
        self.assertEqual(full._collision_penalty(), 2.0)

    def test_checkpoints_that_cannot_be_resumed_are_refused_naming_the_file(self):
        out = self.out("c")
        train(tiny(total_steps=2 * 64), out)
        with self.assertRaises(PPOError) as c:
            Trainer(tiny(), out, quiet=True)  # without --resume
        self.assertIn("--resume", str(c.exception))
        with self.assertRaises(PPOError) as c:
            Trainer(tiny(learning_rate=0.01), out, resume=True, quiet=True)
        self.assertIn("learning_rate: 0.0003 there, 0.01 here", str(c.exception))
        checkpoint = os.path.join(out, "checkpoint.pt")
        # A key added after the checkpoint was written: it trained with that key's default.
        state = torch.load(checkpoint)
        del state["config"]["collision_penalty"]
        torch.save(state, checkpoint)
        Trainer(tiny(), out, resume=True, quiet=True).close()
        with self.assertRaises(PPOError) as c:
            Trainer(tiny(collision_penalty=0.5), out, resume=True, quiet=True)
        self.assertIn("collision_penalty: 0.0 there, 0.5 here", str(c.exception))
        torch.save({"model": {}}, checkpoint)
        with self.assertRaises(PPOError) as c:
            Trainer(tiny(), out, resume=True, quiet=True)
        self.assertIn(checkpoint, str(c.exception))
        self.assertIn("not a crowdsim_bench.ppo checkpoint", str(c.exception))
        with open(checkpoint, "wb") as f:
            f.write(b"PK\x03\x04 not really a zip")
        with self.assertRaises(PPOError) as c:
            Trainer(tiny(), out, resume=True, quiet=True)
        self.assertIn("not a readable checkpoint", str(c.exception))

    def test_exported_module_takes_one_observation_and_acts_as_the_python_policy(self):
        env = cb.Env(QUICK, row="orca")
        for discrete in (False, True):
            out = self.out(f"e{discrete}")
            trainer = train(tiny(discrete=discrete, total_steps=64, checkpoint_interval=1), out)
            module = torch.jit.load(os.path.join(out, "policy.pt"))
            for episode in range(3):
                obs, _ = env.reset(seed=episode)
                for _ in range(5):
                    t = {k: torch.from_numpy(np.asarray(v)) for k, v in obs.items()}
                    with torch.no_grad():
                        got = module(t)
                    self.assertEqual(tuple(got.shape), (2,))
                    self.assertEqual(got.dtype, torch.float64)
                    with torch.no_grad():
                        want = trainer.model.greedy({k: v.unsqueeze(0) for k, v in t.items()})[0]
                    self.assertTrue(torch.equal(got, want), (got, want))
                    self.assertLessEqual(float(got.norm()), obs["robot"][7] + 1e-6)
                    obs, _, terminated, truncated, _ = env.step(got.numpy())
                    if terminated or truncated:
                        break

    @unittest.skipUnless(CLI and os.path.exists(os.path.join(
        os.path.dirname(os.path.dirname(os.path.abspath(CLI or "."))), "plugins",
        "crowdsim_torchscript.so")), "CROWDSIM_BENCH names no CLI with the torchscript plugin")
    def test_the_plugin_plays_the_python_policys_episodes(self):
        # With the route sensor too: the model reads `route`, which the plugin passes when
        # `route: true`.
        sensors = "[person, {type: lidar2d, beams: 45, fov_deg: 180, max_range: 5}"
        for route, frame in ((False, "goal"), (True, "goal"), (True, "route")):
            name = ("r" if route else "p") + frame
            out = self.out(name)
            changes = {"total_steps": 64, "checkpoint_interval": 1, "frame": frame}
            if route:
                changes["set"] = TINY["set"] + [f"robot.sensors={sensors}, route]"]
            trainer = train(tiny(**changes), out)
            self.assertEqual(trainer.layout["uses_route"], route)
            policy = os.path.join(out, "policy.pt")
            with open(QUICK) as f:
                head = f.read().split("\nrows:")[0]
            if route:
                head = head.replace(f"sensors: {sensors}]", f"sensors: {sensors}, route]")
            suite = self.out(f"{name}_suite.yaml")
            with open(suite, "w") as f:
                f.write(head + "\nrows:\n  - {label: ppo, policy: torchscript, weights: " + policy +
                        ", params: {sensors: lidar+person" + (", route: true" if route else "") +
                        "}}\n")
            p = subprocess.run([CLI, "run", suite, "--episodes", "4", "--jobs", "1", "--out",
                                self.out(f"{name}_cli")], capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stdout + p.stderr)

            def act(obs):
                with torch.no_grad():
                    t = {k: torch.from_numpy(np.asarray(v)).unsqueeze(0) for k, v in obs.items()}
                    return trainer.model.greedy(t)[0].numpy()
            cb.evaluate(act, suite, row="ppo", label="ppo", out=self.out(f"{name}_py"), episodes=4)

            def episodes(folder):
                with open(os.path.join(folder, "episodes.csv"), newline="") as f:
                    return [(e["episode"], e["status"], e["steps"], e["path_length"])
                            for e in csv.DictReader(f)]
            self.assertEqual(sorted(episodes(self.out(f"{name}_cli"))),
                             sorted(episodes(self.out(f"{name}_py"))), route)


if __name__ == "__main__":
    unittest.main()

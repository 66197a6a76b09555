"""The Python package: the Gymnasium contract of Env, episodes equal to the CLI's, evaluate()
writing the CLI's outputs, run_suite(). Run by ctest (python_package) with the build's
python/ folder on PYTHONPATH, from the source root."""
import csv
import math
import os
import pathlib
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

import crowdsim_bench as cb

QUICK = "suites/quick.yaml"


def straight_to_goal(obs, time_step=0.25):
    """The `linear` plugin's rule (speed v_pref, last step shortened), in Python."""
    r = obs["robot"]
    to_goal = r[4:6] - r[0:2]
    dist = math.sqrt(to_goal[0] * to_goal[0] + to_goal[1] * to_goal[1])
    if dist < 1e-9:
        return np.zeros(2)
    speed = min(r[7], dist / time_step)
    return to_goal / dist * speed


def committed_episodes(row):
    with open("results/quick/episodes.csv", newline="") as f:
        return {int(e["episode"]): e for e in csv.DictReader(f) if e["row"] == row}


class EnvContract(unittest.TestCase):
    def setUp(self):
        self.env = cb.Env(QUICK, row="orca")

    def test_spaces_reset_and_step_follow_gymnasium(self):
        obs, info = self.env.reset(seed=3)
        self.assertIsInstance(info, dict)
        self.assertEqual(set(obs), set(self.env.observation_space.keys()))
        self.assertTrue(self.env.observation_space.contains(obs))
        self.assertEqual(obs["robot"].dtype, np.float64)
        self.assertEqual(obs["humans"].shape, (5, 5))
        self.assertEqual(obs["humans_mask"].dtype, np.bool_)
        self.assertEqual(obs["lidar"].shape, (45,))
        self.assertEqual(self.env.action_space.shape, (2,))
        action = self.env.action_space.sample()
        self.assertTrue(self.env.action_space.contains(action))
        out = self.env.step(action)
        self.assertEqual(len(out), 5)
        obs2, reward, terminated, truncated, info = out
        self.assertIsInstance(reward, float)
        self.assertIsInstance(terminated, bool)
        self.assertIsInstance(truncated, bool)
        self.assertIn("status", info)
        self.assertAlmostEqual(float(obs2["time"]), 0.25)

    def test_with_and_unwrapped_work_without_gymnasium_too(self):
        # Without gymnasium (Debian 12) `with cb.Env(...)` was a TypeError and env.unwrapped
        # an AttributeError: gymnasium.Env's, which Env claims to work the same without.
        with cb.Env(QUICK, row="orca") as env:
            self.assertIs(env.unwrapped, env)
            env.reset(seed=0)
        with self.assertRaisesRegex(ValueError, "was closed"):  # `with` closed it
            env.reset(seed=0)
        with cb.VectorEnv(QUICK, row="orca", num_envs=2) as venv:
            venv.reset(seed=0)
        with self.assertRaisesRegex(ValueError, "was closed"):
            venv.reset(seed=0)

    def test_other_sensors_features_come_under_their_name(self):
        env = cb.Env(QUICK, row="orca",
                     set=["rows[orca].sensors=[person, {type: lidar2d, beams: 45}, route]"])
        self.assertIsNone(self.env.observation_space.get("route"))
        for seed in range(3):
            obs, _ = env.reset(seed=seed)
            self.assertTrue(env.observation_space.contains(obs))
            route = obs["route"]
            self.assertEqual(route.shape, (3,))
            r = obs["robot"]
            straight = math.hypot(r[4] - r[0], r[5] - r[1])
            self.assertGreaterEqual(route[0], straight - 1e-9)  # around obstacles, never shorter
            self.assertLessEqual(math.hypot(route[1], route[2]), 1.0 + 1e-9)  # lookahead 1 m

    def test_seed_selects_the_suite_episode_and_repeats_exactly(self):
        a, info_a = self.env.reset(seed=7)
        b, info_b = self.env.reset(seed=7)
        self.assertEqual(info_a, info_b)
        for k in a:
            np.testing.assert_array_equal(a[k], b[k])
        c, info_c = self.env.reset(options={"episode": 8})
        self.assertEqual(info_c["episode_index"], 8)
        d, info_d = self.env.reset()  # the next episode
        self.assertEqual(info_d["episode_index"], 9)
        self.assertFalse(np.array_equal(a["robot"], c["robot"]))

    def test_standing_still_times_out_as_truncated_not_terminated(self):
        self.env.reset(seed=1)
        steps = 0
        while True:
            _, _, terminated, truncated, info = self.env.step([0.0, 0.0])
            steps += 1
            if terminated or truncated:
                break
        if info["status"] == "timeout":
            self.assertTrue(truncated)
            self.assertFalse(terminated)
            self.assertEqual(steps, 100)  # 25 s at 0.25 s
        else:  # a human walked into the robot: a collision ends it first
            self.assertEqual(info["status"], "collision_human")
            self.assertTrue(terminated)
            self.assertFalse(truncated)
        with self.assertRaises(ValueError):
            self.env.step([0.0, 0.0])  # after the end

    def test_bad_actions_and_rows_are_clear_errors(self):
        self.env.reset(seed=0)
        with self.assertRaises(ValueError):
            self.env.step([float("nan"), 0.0])
        with self.assertRaises(ValueError):
            self.env.step([1.0])
        with self.assertRaises(KeyError):
            cb.Env(QUICK, row="no_such_row")
        with self.assertRaises(IndexError):
            cb.Env(QUICK, row=9)
        with self.assertRaises(ValueError):
            cb.Env(QUICK, row=1, set=["humans.count=-1"])
        self.assertEqual(cb.Env(QUICK, row=np.int64(2))._env.label, "orca")  # numpy ints too
        for not_a_row in (1.0, None, True):  # pybind's "Unable to cast" said nothing of rows
            with self.assertRaisesRegex(TypeError, "row must be a row's label or its 1-based"):
                cb.Env(QUICK, row=not_a_row)
        with self.assertRaisesRegex(ValueError, "result\\(\\) before reset\\(\\)"):
            cb.Env(QUICK).result()  # the constructor's probe episode is not the user's

    def test_a_row_with_two_person_sensors_is_refused(self):
        # Their people filled the humans array twice (past its rows in VectorEnv).
        with self.assertRaisesRegex(ValueError, "a second 'person' sensor.*keep one"):
            cb.Env(QUICK, set=["robot.sensors=[person, {type: person, max_range: 3}]"])

    def test_discrete_actions_are_crowdnavs_holonomic_set(self):
        env = cb.Env(QUICK, row="orca", discrete=True)
        self.assertEqual(len(env.actions), 81)
        self.assertEqual(env.action_space.n, 81)
        np.testing.assert_allclose(np.linalg.norm(env.actions, axis=1).max(), 1.0)
        env.reset(seed=0)
        env.step(80)

    def test_sampled_discrete_actions_reach_every_index(self):
        # Without gymnasium, VectorEnv(discrete=True).action_space.sample() never gave the last
        # action (80: uniform reals cast down), a bool Box sampled all True, and the
        # discrete space printed as <crowdsim_bench._DiscreteSpace object at 0x...>.
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=4, discrete=True)
        venv.action_space.seed(0)
        seen = np.concatenate([venv.action_space.sample() for _ in range(2000)])
        self.assertEqual((seen.min(), seen.max()), (0, 80))
        self.assertTrue(venv.action_space.contains(venv.action_space.sample()))
        mask = cb.Box(0, 1, (1000,), dtype=np.bool_, seed=0).sample()
        self.assertTrue(mask.any() and not mask.all())
        self.assertEqual(repr(cb.Env(QUICK, row="orca", discrete=True).action_space),
                         "Discrete(81)")


class UnicycleRobot(unittest.TestCase):
    """A row with `kinematics: unicycle` (docs/kinematics.md): commands, not velocities."""
    UNICYCLE = ["robot.kinematics=unicycle"]

    def test_spaces_hold_every_command_the_env_accepts(self):
        env = cb.Env(QUICK, row="orca", set=self.UNICYCLE)
        self.assertEqual(env.kinematics, "unicycle")
        np.testing.assert_allclose(env.action_space.low, [-1.0, -math.pi])
        np.testing.assert_allclose(env.action_space.high, [1.0, math.pi])
        discrete = cb.Env(QUICK, row="orca", set=self.UNICYCLE, discrete=True)
        self.assertEqual(len(discrete.actions), 81)
        # CrowdNav's set: stop, then 16 turns in [-45, 45] degrees a step x 5 speeds.
        np.testing.assert_allclose(discrete.actions[0], [0.0, 0.0])
        np.testing.assert_allclose(discrete.actions[1:, 1].min() * 0.25, -math.pi / 4)
        np.testing.assert_allclose(discrete.actions[1:, 1].max() * 0.25, math.pi / 4)
        for action in discrete.actions:
            self.assertTrue(env.action_space.contains(action), action)
        env.action_space.seed(3)
        env.reset(seed=0)
        for _ in range(20):
            env.step(env.action_space.sample())
            if env.result()["status"] != "running":
                break

    def test_a_command_turns_the_robot_and_its_frame(self):
        env = cb.Env(QUICK, row="orca", set=self.UNICYCLE)
        obs, _ = env.reset(seed=0)
        heading = obs["robot"][8]
        obs, *_ = env.step([0.0, 1.0])  # turn on the spot at 1 rad/s for 0.25 s
        self.assertAlmostEqual(obs["robot"][8], math.remainder(heading + 0.25, 2 * math.pi))
        np.testing.assert_allclose(obs["robot"][2:4], [0.0, 0.0])  # it did not move
        with self.assertRaisesRegex(ValueError, "command \\(linear m/s, angular rad/s\\)"):
            env.step([float("nan"), 0.0])

    def test_vector_env_takes_commands_too(self):
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=2, set=self.UNICYCLE)
        self.assertEqual(venv.single_action_space.shape, (2,))
        np.testing.assert_allclose(venv.single_action_space.high, [1.0, math.pi])
        venv.reset(seed=0)
        venv.step(np.array([[0.5, 0.0], [0.0, 1.0]]))


class SameEpisodesAsTheCli(unittest.TestCase):
    def test_python_stepped_linear_equals_the_cli_linear_row(self):
        committed = committed_episodes("linear")
        env = cb.Env(QUICK, row="linear")
        for episode in range(8):
            obs, _ = env.reset(seed=episode)
            while True:
                obs, _, terminated, truncated, info = env.step(straight_to_goal(obs))
                if terminated or truncated:
                    break
            cli = committed[episode]
            self.assertEqual(info["status"], cli["status"], f"episode {episode}")
            self.assertEqual(info["steps"], int(cli["steps"]), f"episode {episode}")
            self.assertEqual(f"{info['time']:.2f}", cli["time"])
            self.assertAlmostEqual(info["path_length"], float(cli["path_length"]), places=6)
            self.assertAlmostEqual(info["min_human_distance"], float(cli["min_human_distance"]),
                                   places=6)
            self.assertAlmostEqual(info["max_speed"], float(cli["max_speed"]), places=6)


class Evaluate(unittest.TestCase):
    def test_a_python_policy_gets_the_clis_outputs_and_numbers(self):
        with tempfile.TemporaryDirectory() as out:
            rows = cb.evaluate(straight_to_goal, QUICK, row="linear", label="py_linear", out=out,
                               episodes=6)
            self.assertEqual(len(rows), 1)
            self.assertEqual(rows[0]["label"], "py_linear")
            self.assertEqual(rows[0]["episodes"], 6)
            for f in ("table.md", "table.csv", "episodes.csv", "manifest.json"):
                self.assertTrue(os.path.isfile(os.path.join(out, f)), f)
            committed = committed_episodes("linear")
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                mine = list(csv.DictReader(f))
            self.assertEqual(len(mine), 6)
            for e in mine:
                cli = committed[int(e["episode"])]
                for key in ("status", "time", "steps", "path_length", "min_human_distance"):
                    self.assertEqual(e[key], cli[key], f"episode {e['episode']} {key}")

    def test_the_clis_report_of_an_evaluate_folder_names_the_python_policy(self):
        # `crowdsim-bench report` of evaluate()'s folder said "The suite file changed since this
        # run" (the recorded hash is the suite's with the Python row) and "row not in the suite
        # file any more" under each outcome; neither was so.
        cli = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(
            cb.__file__)))), "bin", "crowdsim-bench")
        self.assertTrue(os.path.isfile(cli), cli)
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "mine")
            cb.evaluate(straight_to_goal, QUICK, row="linear", label="mine", out=out, episodes=6)
            page = os.path.join(tmp, "report.html")
            done = subprocess.run([cli, "report", out, "--out", page], capture_output=True,
                                  text=True, check=False)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertNotIn("suite file changed", done.stderr)
            with open(page, encoding="utf-8") as f:
                html = f.read()
            self.assertNotIn("suite file changed", html)
            self.assertNotIn("row not in the suite file any more", html)
            self.assertIn("a Python policy (crowdsim_bench.evaluate), which the report cannot "
                          "replay", html)

    def test_a_raising_policy_ends_its_episodes_as_policy_errors(self):
        def broken(obs):
            raise RuntimeError("my bug")

        with tempfile.TemporaryDirectory() as out:
            with self.assertWarnsRegex(RuntimeWarning, "2 of 2 episodes .* policy_error"):
                rows = cb.evaluate(broken, QUICK, row=1, out=out, episodes=2)
            self.assertEqual(rows[0]["policy_error"], 1.0)
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                errors = [e["error"] for e in csv.DictReader(f)]
            self.assertTrue(all("my bug" in e for e in errors), errors)

    def test_the_warning_gives_the_first_episodes_message(self):
        # It only said that the messages were in episodes.csv: the user had to open it.
        def broken(obs):
            raise RuntimeError("my bug")

        with tempfile.TemporaryDirectory() as out:
            with self.assertWarnsRegex(RuntimeWarning, "episode 0: the robot's policy failed: "
                                                       "python policy raised RuntimeError: my bug"):
                cb.evaluate(broken, QUICK, row=1, out=out, episodes=2)

    def test_a_policy_returning_none_is_told_to_return_its_velocity(self):
        # None read as one NaN: "got 1 numbers" hid the missing `return`.
        def no_return(obs):
            straight_to_goal(obs)

        with tempfile.TemporaryDirectory() as out:
            with self.assertWarns(RuntimeWarning):
                cb.evaluate(no_return, QUICK, row="linear", out=out, episodes=1)
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                error = next(csv.DictReader(f))["error"]
            self.assertIn("2 numbers (got None: does the policy `return` its velocity?)", error)
        with tempfile.TemporaryDirectory() as out:
            with self.assertWarns(RuntimeWarning):
                cb.evaluate(lambda obs: 0.5, QUICK, row="linear", out=out, episodes=1)
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                error = next(csv.DictReader(f))["error"]
            self.assertIn("2 numbers (got 1 number)", error)

    def test_a_training_file_is_named_as_one(self):
        # It gave an unknown-key error for each of the training file's own keys.
        train = "suites/train/cadrl_crowdnav.yaml"
        for call in (lambda: cb.Env(train), lambda: cb.run_suite(train),
                     lambda: cb.evaluate(straight_to_goal, train)):
            with self.assertRaisesRegex(ValueError, "is a training file .*crowdsim-bench train"):
                call()

    def test_evaluate_never_replaces_another_configurations_results(self):
        # evaluate() plays every episode again (fresh=True): it wiped a CLI run's folder.
        with tempfile.TemporaryDirectory() as out:
            cb.run_suite(QUICK, out=out, episodes=2)
            with open(os.path.join(out, "episodes.csv")) as f:
                before = f.read()
            with self.assertRaisesRegex(ValueError, "holds results of another configuration"):
                cb.evaluate(straight_to_goal, QUICK, row="linear", out=out, episodes=2)
            with open(os.path.join(out, "episodes.csv")) as f:
                self.assertEqual(f.read(), before)
            self.assertTrue(os.path.isfile(os.path.join(out, "table.md")))
        with tempfile.TemporaryDirectory() as out:  # its own earlier results: replaced
            cb.evaluate(straight_to_goal, QUICK, row="linear", out=out, episodes=3)
            rows = cb.evaluate(straight_to_goal, QUICK, row="linear", out=out, episodes=2)
            self.assertEqual(rows[0]["episodes"], 2)

    def test_velocity_as_any_array_of_two_numbers(self):
        with tempfile.TemporaryDirectory() as out:
            rows = cb.evaluate(lambda obs: straight_to_goal(obs).reshape(1, 2), QUICK,
                               row="linear", out=out, episodes=2)
            self.assertEqual(rows[0]["policy_error"], 0.0)
        with tempfile.TemporaryDirectory() as out:
            with self.assertWarns(RuntimeWarning):
                cb.evaluate(lambda obs: [1.0, 2.0, 3.0], QUICK, row="linear", out=out,
                            episodes=1)
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                error = next(csv.DictReader(f))["error"]
            self.assertIn("2 numbers (got 3 numbers)", error)

    def test_ctrl_c_in_the_policy_stops_the_evaluation_and_reaches_the_caller(self):
        calls = []

        def interrupted(obs):
            calls.append(obs["time"])
            if len(calls) == 40:
                raise KeyboardInterrupt
            return straight_to_goal(obs)

        with tempfile.TemporaryDirectory() as out:
            with self.assertRaises(KeyboardInterrupt):
                cb.evaluate(interrupted, QUICK, row="linear", out=out, episodes=20)
            self.assertEqual(len(calls), 40)  # nothing called after it
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                lines = list(csv.DictReader(f))
            self.assertTrue(0 < len(lines) < 20, len(lines))  # the finished ones, kept
            self.assertFalse(any(e["status"] == "policy_error" for e in lines))
            self.assertFalse(os.path.exists(os.path.join(out, "table.md")))

    def test_ctrl_c_stops_run_suite_between_episodes(self):
        # No Python code runs during run_suite: Ctrl-C waited for the whole suite.
        import _thread
        import threading
        import time
        timer = threading.Timer(0.3, _thread.interrupt_main)
        with tempfile.TemporaryDirectory() as out:
            start = time.monotonic()
            timer.start()
            with self.assertRaises(KeyboardInterrupt):
                cb.run_suite(QUICK, out=out, episodes=20000)  # far longer than 0.3 s
            self.assertLess(time.monotonic() - start, 20.0)
            with open(os.path.join(out, "episodes.csv"), newline="") as f:
                kept = sum(1 for _ in csv.DictReader(f))
            self.assertLess(kept, 40000)
            rows = cb.run_suite(QUICK, out=out, episodes=3)  # resumes
            self.assertTrue(all(r["episodes"] == 3 for r in rows))

    def test_two_threads_evaluate_each_their_own_policy(self):
        # One shared "next policy" gave both threads the same one (or a freed one).
        import threading
        seen = {"a": set(), "b": set()}

        def policy_of(name):
            def policy(obs):
                seen[name].add(threading.current_thread().name)
                return straight_to_goal(obs) * (1.0 if name == "a" else 0.0)
            return policy

        with tempfile.TemporaryDirectory() as root:
            results = {}

            def run(name):
                results[name] = cb.evaluate(policy_of(name), QUICK, row="linear", label=name,
                                            out=os.path.join(root, name), episodes=6)

            threads = [threading.Thread(target=run, args=(n,), name=n) for n in ("a", "b")]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            self.assertEqual(seen, {"a": {"a"}, "b": {"b"}})
            self.assertGreater(results["a"][0]["success"], 0.0)  # b stands still: never
            self.assertEqual(results["b"][0]["success"], 0.0)

    def test_run_suite_returns_the_table(self):
        with tempfile.TemporaryDirectory() as out:
            rows = cb.run_suite(QUICK, out=out, episodes=3)
            self.assertEqual([r["label"] for r in rows], ["linear", "orca"])
            self.assertTrue(all(r["episodes"] == 3 for r in rows))
            self.assertTrue(all(0.0 <= r["success"] <= 1.0 for r in rows))

    def test_a_label_that_cannot_name_the_row_or_its_folder_is_refused(self):
        # label="a/b" wrote runs/quick.a/b/, "../x" wrote runs/x/, "" a row without a label.
        with tempfile.TemporaryDirectory() as root:
            suite, here = os.path.abspath(QUICK), os.getcwd()
            os.chdir(root)
            try:
                for bad in ("a/b", "../escape", "a b"):
                    with self.assertRaisesRegex(ValueError, "default output folder", msg=bad):
                        cb.evaluate(straight_to_goal, suite, label=bad, episodes=1)
                for bad in ("", "  ", "two\nlines"):
                    with self.assertRaisesRegex(ValueError, "blank or contain control",
                                                msg=repr(bad)):
                        cb.evaluate(straight_to_goal, suite, label=bad, out="given", episodes=1)
                with self.assertRaisesRegex(TypeError, "label must be a str"):
                    cb.evaluate(straight_to_goal, suite, label=5, out="given", episodes=1)
                self.assertEqual(os.listdir(root), [])  # nothing ran
                rows = cb.evaluate(straight_to_goal, suite, label="a b", out="given", episodes=1)
                self.assertEqual(rows[0]["label"], "a b")  # any label, in a folder given
            finally:
                os.chdir(here)

    def test_out_takes_a_pathlib_path_and_none_for_the_default(self):
        # suite= took a pathlib.Path but out= did not: pybind11's "incompatible function
        # arguments" listing of the core's signature, for a Path or None.
        with tempfile.TemporaryDirectory() as root:
            out = pathlib.Path(root) / "mine"
            rows = cb.evaluate(straight_to_goal, pathlib.Path(QUICK), out=out, episodes=1)
            self.assertEqual(rows[0]["episodes"], 1)
            self.assertTrue((out / "episodes.csv").is_file())
            cb.run_suite(pathlib.Path(QUICK), out=pathlib.Path(root) / "suite", episodes=1)
            self.assertTrue((pathlib.Path(root) / "suite" / "table.md").is_file())
            suite, here = os.path.abspath(QUICK), os.getcwd()
            os.chdir(root)
            try:
                cb.evaluate(straight_to_goal, suite, out=None, episodes=1)
            finally:
                os.chdir(here)
            self.assertTrue(os.path.isfile(os.path.join(root, "runs", "quick.python",
                                                        "episodes.csv")))
            with self.assertRaisesRegex(TypeError, "out must be a folder path"):
                cb.run_suite(QUICK, out=5, episodes=1)


def batched_straight_to_goal(obs, time_step=0.25):
    return np.stack([straight_to_goal({"robot": r}, time_step) for r in obs["robot"]])


class VectorEnvContract(unittest.TestCase):
    N = 3

    def run_batches(self, threads, steps=120):
        venv = cb.VectorEnv(QUICK, row="linear", num_envs=self.N, threads=threads)
        obs, info = venv.reset(seed=10)
        log = [(obs, info)]
        for _ in range(steps):
            out = venv.step(batched_straight_to_goal(obs))
            obs = out[0]
            log.append(out)
        return venv, log

    def test_spaces_and_shapes(self):
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=4)
        obs, info = venv.reset(seed=0)
        self.assertTrue(venv.observation_space.contains(obs))
        self.assertTrue(venv.single_observation_space.contains({k: v[0] for k, v in obs.items()}))
        self.assertEqual(obs["lidar"].shape, (4, 45))
        self.assertEqual(list(info["episode_index"]), [0, 1, 2, 3])
        obs, reward, terminated, truncated, info = venv.step(np.zeros((4, 2)))
        self.assertEqual(reward.shape, (4,))
        self.assertEqual(terminated.dtype, np.bool_)
        self.assertEqual(truncated.dtype, np.bool_)
        np.testing.assert_allclose(obs["time"], 0.25)
        with self.assertRaises(ValueError):
            venv.step(np.zeros((3, 2)))
        discrete = cb.VectorEnv(QUICK, row="orca", num_envs=2, discrete=True)
        discrete.reset()
        discrete.step(np.array([0, 80]))

    def test_other_sensors_features_are_batched_under_their_name(self):
        route = ["rows[orca].sensors=[person, {type: lidar2d, beams: 45}, route]"]
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=3, set=route)
        obs, _ = venv.reset(seed=5)
        self.assertEqual(obs["route"].shape, (3, 3))
        self.assertTrue(venv.observation_space.contains(obs))
        env = cb.Env(QUICK, row="orca", set=route)
        for i in range(3):
            single, _ = env.reset(seed=5 + i)
            np.testing.assert_array_equal(obs["route"][i], single["route"])
        obs, *_ = venv.step(np.zeros((3, 2)))
        single, *_ = env.step(np.zeros(2))  # episode 7, as sub-environment 2
        np.testing.assert_array_equal(obs["route"][2], single["route"])

    def test_each_sub_environment_plays_the_envs_episodes_with_next_step_autoreset(self):
        _, log = self.run_batches(threads=1)
        env = cb.Env(QUICK, row="linear")
        for i in range(self.N):
            episode = 10 + i
            obs, _ = env.reset(seed=episode)
            np.testing.assert_array_equal(log[0][0]["robot"][i], obs["robot"])
            ended = False
            for t, (bobs, reward, terminated, truncated, info) in enumerate(log[1:], start=1):
                if ended:  # the step after the end: the next episode of this sub-environment
                    self.assertEqual(reward[i], 0.0)
                    self.assertEqual(info["episode_index"][i], episode + self.N)
                    self.assertEqual(bobs["time"][i], 0.0)
                    obs, _ = cb.Env(QUICK, row="linear").reset(seed=episode + self.N)
                    np.testing.assert_array_equal(bobs["robot"][i], obs["robot"])
                    break
                obs, r, term, trunc, step_info = env.step(straight_to_goal(obs))
                for key in obs:
                    np.testing.assert_array_equal(bobs[key][i], obs[key], f"env {i} step {t} {key}")
                self.assertEqual(reward[i], r)
                self.assertEqual((terminated[i], truncated[i]), (term, trunc))
                self.assertEqual(cb.STATUS_NAMES[info["status"][i]], step_info["status"])
                ended = term or trunc
            self.assertTrue(ended, f"env {i}: episode {episode} did not end in the steps run")

    def test_counts_must_be_whole_numbers_of_at_least_one(self):
        # num_envs=2.5 made 2 environments and threads=0 or -3 one thread, without a word.
        for kwargs in ({"num_envs": 2.5}, {"num_envs": 0}, {"num_envs": True},
                       {"num_envs": "2"}, {"num_envs": 2, "threads": 0},
                       {"num_envs": 2, "threads": -3}, {"num_envs": 2, "threads": 1.5}):
            with self.assertRaisesRegex(ValueError, "must be a whole number >= 1",
                                        msg=repr(kwargs)):
                cb.VectorEnv(QUICK, row="orca", **kwargs)
        self.assertEqual(cb.VectorEnv(QUICK, row="orca", num_envs=np.int64(2)).num_envs, 2)

    def test_threads_do_not_change_the_batches(self):
        _, one = self.run_batches(threads=1)
        venv, two = self.run_batches(threads=2)
        self.assertEqual(venv.threads, 2)
        for a, b in zip(one[1:], two[1:]):
            for key in a[0]:
                np.testing.assert_array_equal(a[0][key], b[0][key])
            for k in range(1, 4):
                np.testing.assert_array_equal(a[k], b[k])
            np.testing.assert_array_equal(a[4]["episode_index"], b[4]["episode_index"])


ROUTE = ["rows[orca].sensors=[person, {type: lidar2d, beams: 45}, route]"]
# The observation and action configurations the package has: (Env kwargs, what they are).
CONFIGURATIONS = [
    ({}, "person + lidar, continuous"),
    ({"discrete": True}, "person + lidar, discrete"),
    ({"render_mode": "rgb_array"}, "rgb_array"),
    ({"set": ROUTE}, "person + lidar + route"),
    ({"set": "robot.sensors=[{type: lidar2d, beams: 9, fov_deg: 360, max_range: 3}]"},
     "lidar alone"),
    ({"set": "robot.sensors=[person]"}, "person alone"),
]


def sampled_episodes(env, episodes):
    """(obs, info) of every reset and step of `episodes` episodes with sampled actions."""
    env.action_space.seed(0)
    for k in range(episodes):
        obs, info = env.reset(seed=k)
        yield obs, info
        while True:
            obs, _, terminated, truncated, info = env.step(env.action_space.sample())
            yield obs, info
            if terminated or truncated:
                break


def outside(space, obs):
    """The keys of a dict observation its Dict space does not contain (for the messages)."""
    return [k for k in obs if not space[k].contains(obs[k])]


class VectorEnvSize(unittest.TestCase):
    """A VectorEnv's size is bounded, and making a large one stops on Ctrl-C."""

    def test_more_than_the_bound_is_refused_before_anything_is_made(self):
        with self.assertRaisesRegex(ValueError, "num_envs must be at most 4096, got 100000"):
            cb.VectorEnv(QUICK, row="orca", num_envs=100_000)

    def test_making_a_large_one_stops_on_an_interrupt(self):
        # SIGALRM's handler raises as Ctrl-C's does; 4,000 environments take over a minute.
        def interrupt(signum, frame):
            raise KeyboardInterrupt
        old = signal.signal(signal.SIGALRM, interrupt)
        signal.setitimer(signal.ITIMER_REAL, 0.5)
        start = time.monotonic()
        try:
            with self.assertRaises(KeyboardInterrupt):
                cb.VectorEnv(QUICK, row="orca", num_envs=4000)
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
        self.assertLess(time.monotonic() - start, 10)


class SpacesAndInfosAsGymnasiumWantsThem(unittest.TestCase):
    """What Gymnasium's check_env and wrappers rely on, checked with or without gymnasium
    (test_gymnasium.py runs Gymnasium's own tools when it is installed): bounded observation
    spaces that hold every observation, info keys clear of the names Gymnasium writes itself,
    and reset(seed=) seeding np_random."""

    def test_observation_bounds_are_the_rows_own(self):
        # Every Box was (-inf, inf): lidar ranges, time and the route's waypoint have bounds.
        space = cb.Env(QUICK, row="orca").observation_space
        np.testing.assert_array_equal(space["lidar"].low, np.zeros(45))
        np.testing.assert_array_equal(space["lidar"].high, np.full(45, 5.0))  # max_range: 5
        self.assertEqual((float(space["time"].low), float(space["time"].high)), (0.0, 25.0))
        self.assertEqual(space["humans_mask"].dtype, np.bool_)
        self.assertEqual((space["humans_mask"].low.min(), space["humans_mask"].high.max()),
                         (False, True))
        self.assertEqual((space["robot"].low[8], space["robot"].high[8]), (-math.pi, math.pi))
        self.assertEqual(space["robot"].low[6], 0.0)  # radius
        self.assertTrue(np.all(space["humans"].low[:, 4] == 0.0))  # radii
        route = cb.Env(QUICK, row="orca", set=ROUTE).observation_space["route"]
        self.assertEqual(route.low[0], 0.0)  # path distance
        np.testing.assert_allclose(route.high[1:], 1.0, rtol=1e-8)  # lookahead 1 m
        np.testing.assert_allclose(route.low[1:], -1.0, rtol=1e-8)
        # The row's own sensor parameters, set= included.
        lidar = cb.Env(QUICK, row="orca", set=CONFIGURATIONS[4][0]["set"]).observation_space
        self.assertEqual(lidar["lidar"].shape, (9,))
        np.testing.assert_array_equal(lidar["lidar"].high, np.full(9, 3.0))
        near = cb.Env(QUICK, row="orca", set=[
            "rows[orca].sensors=[person, {type: lidar2d, beams: 45}, "
            "{type: route, lookahead: 2.5}]"]).observation_space["route"]
        np.testing.assert_allclose(near.high[1:], 2.5, rtol=1e-8)
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=3)
        for key, single in venv.single_observation_space.items():
            np.testing.assert_array_equal(single.high, space[key].high, key)
            np.testing.assert_array_equal(venv.observation_space[key].low[2], single.low, key)
            np.testing.assert_array_equal(venv.observation_space[key].high[2], single.high, key)

    def test_the_time_bound_is_the_timeout_steps_time(self):
        # 0.3 s does not divide 25 s: the 84th step (25.2 s) times the episode out.
        env = cb.Env(QUICK, row="orca", set="sim.time_step=0.3")
        self.assertAlmostEqual(float(env.observation_space["time"].high), 25.2, places=12)
        for seed in range(10):  # standing still until a timeout (a human may walk into it)
            env.reset(seed=seed)
            while True:
                obs, _, terminated, truncated, info = env.step([0.0, 0.0])
                self.assertTrue(env.observation_space["time"].contains(obs["time"]))
                if terminated or truncated:
                    break
            if truncated:
                self.assertEqual(float(obs["time"]), float(env.observation_space["time"].high))
                break
        self.assertTrue(truncated, "no episode of 10 timed out")

    def test_every_observation_is_in_the_space(self):
        for kwargs, what in CONFIGURATIONS:
            env = cb.Env(QUICK, row="orca", **kwargs)
            for n, (obs, _) in enumerate(sampled_episodes(env, 12)):
                self.assertEqual(set(obs), set(env.observation_space.keys()), what)
                self.assertTrue(env.observation_space.contains(obs),
                                f"{what}, observation {n}: {outside(env.observation_space, obs)}")
        for discrete in (False, True):
            venv = cb.VectorEnv(QUICK, row="orca", num_envs=4, set=ROUTE, discrete=discrete)
            venv.action_space.seed(1)
            obs, _ = venv.reset(seed=0)
            for step in range(150):  # random velocities: episodes of ~17 steps, autoresets
                self.assertTrue(venv.observation_space.contains(obs),
                                f"step {step}: {outside(venv.observation_space, obs)}")
                for i in range(4):
                    self.assertTrue(venv.single_observation_space.contains(
                        {k: v[i] for k, v in obs.items()}))
                self.assertTrue(venv.action_space.contains(venv.action_space.sample()))
                obs, *_ = venv.step(venv.action_space.sample())

    def test_info_keys_avoid_the_names_gymnasium_writes(self):
        # reset()'s info had `episode`, which RecordEpisodeStatistics writes at an episode's
        # end (it asserted), as did the last step's info and VectorEnv's every info.
        self.assertEqual(cb.RESERVED_INFO_KEYS, {"episode", "_episode", "final_obs",
                                                 "_final_obs", "final_info", "_final_info"})
        env = cb.Env(QUICK, row="orca")
        ends = 0
        for obs, info in sampled_episodes(env, 5):
            self.assertFalse(cb.RESERVED_INFO_KEYS & set(info), sorted(info))
            ends += "steps" in info  # the metrics of the episode's end
            if "steps" in info or obs["time"] == 0.0:
                self.assertIn("episode_index", info)
        self.assertEqual(ends, 5)
        _, info = env.reset(seed=4)
        self.assertEqual(info["episode_index"], 4)
        self.assertEqual(env.result()["episode"], 4)  # result() keeps episodes.csv's name
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=3)
        infos = [venv.reset(seed=6)[1]] + [venv.step(np.zeros((3, 2)))[4] for _ in range(3)]
        for info in infos:
            self.assertFalse(cb.RESERVED_INFO_KEYS & set(info), sorted(info))
            for key in [k for k in info if not k.startswith("_")]:
                np.testing.assert_array_equal(info["_" + key], np.ones(3, bool), key)
        np.testing.assert_array_equal(infos[0]["episode_index"], [6, 7, 8])
        self.assertEqual(set(infos[1]), {"status", "_status", "episode_index", "_episode_index"})

    def test_a_reset_mask_is_refused(self):
        # Gymnasium's reset(options={"reset_mask": ...}) resets some sub-environments only: it
        # started them all again, without a word.
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=2)
        venv.reset(seed=0)
        with self.assertRaisesRegex(ValueError, "reset_mask.*not supported"):
            venv.reset(options={"reset_mask": np.array([True, False])})

    def test_reset_seed_seeds_np_random(self):
        # check_env: "Expects the random number generator to have been generated given a seed
        # was passed to reset".
        for env in (cb.Env(QUICK, row="orca"), cb.VectorEnv(QUICK, row="orca", num_envs=2)):
            env.reset(seed=123)
            first = env.np_random.integers(1 << 30, size=4)
            env.reset()
            env.reset(seed=np.int64(123))  # a numpy seed too (an episode index, as before)
            np.testing.assert_array_equal(env.np_random.integers(1 << 30, size=4), first)
            env.reset(seed=456)
            self.assertFalse(np.array_equal(env.np_random.integers(1 << 30, size=4), first))

    def test_without_gymnasium_the_package_works_the_same(self):
        # Debian 12 has no gymnasium: the stand-in spaces, seeding and info keys, no ids.
        code = """if True:
            import sys, json
            sys.modules["gymnasium"] = None
            import numpy as np
            import crowdsim_bench as cb
            env = cb.Env("suites/quick.yaml", row="orca")
            obs, info = env.reset(seed=5)
            a = env.np_random.integers(1000)
            env.reset(seed=5)
            venv = cb.VectorEnv("suites/quick.yaml", row="orca", num_envs=2, discrete=True)
            vobs, vinfo = venv.reset(seed=5)
            _, _, _, _, step_info = venv.step(np.array([0, 80]))
            print(json.dumps({
                "box": type(env.observation_space["lidar"]).__name__,
                "lidar_high": float(env.observation_space["lidar"].high.max()),
                "time_high": float(env.observation_space["time"].high),
                "contains": bool(env.observation_space.contains(obs)
                                 and venv.observation_space.contains(vobs)),
                "info": sorted(info), "vinfo": sorted(vinfo), "step_info": sorted(step_info),
                "seeded": bool(a == env.np_random.integers(1000)),
                "ids": sorted(cb.ENV_IDS)[:1],
                "autoreset": venv.metadata["autoreset_mode"],
                "unwrapped": venv.unwrapped is venv and env.unwrapped is env}))
        """
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              env=dict(os.environ), check=False)
        self.assertEqual(done.returncode, 0, done.stderr)
        import json
        got = json.loads(done.stdout)
        self.assertEqual(got, {
            "box": "Box", "lidar_high": 5.0, "time_high": 25.0, "contains": True,
            "info": ["episode_index", "layout"],
            "vinfo": ["_episode_index", "episode_index"],
            "step_info": ["_episode_index", "_status", "episode_index", "status"],
            "seeded": True, "ids": ["crowdsim_bench/CrowdNav-v0"], "autoreset": "next_step",
            "unwrapped": True})


class UserMistakes(unittest.TestCase):
    """What a user gets wrong first: each a clear Python error, never a crash or a silent
    stand-in."""

    def test_another_interpreter_is_told_which_one_the_package_needs(self):
        # Stands in for an interpreter without the build's numpy (pyenv, conda): the import
        # error names this interpreter and the one the package is built for.
        code = "import sys; sys.modules['numpy'] = None; import crowdsim_bench"
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              env=dict(os.environ), check=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("crowdsim_bench cannot be imported by " + sys.executable, done.stderr)
        self.assertIn("/usr/bin/python3", done.stderr)

    def test_missing_numpy_is_named_with_its_package(self):
        # The .deb only recommends python3-numpy: without it, the error blamed the interpreter
        # and told to run `PYTHONPATH=build/python /usr/bin/python3`, which is what the user of
        # the installed package had done.
        code = "import sys; sys.modules['numpy'] = None; import crowdsim_bench"
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                              env=dict(os.environ), check=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("crowdsim_bench needs numpy, which " + sys.executable + " cannot import: "
                      "install it (Debian: apt install python3-numpy)", done.stderr)
        # The folder to put on PYTHONPATH is the one this package was imported from.
        package_parent = os.path.dirname(os.path.dirname(os.path.abspath(cb.__file__)))
        self.assertIn("PYTHONPATH=" + package_parent + " ", done.stderr)
        self.assertNotIn("PYTHONPATH=build/python", done.stderr)

    def test_stepping_before_reset_is_an_error(self):
        with self.assertRaisesRegex(ValueError, "before reset"):
            cb.Env(QUICK, row="orca").step([0.5, 0.0])
        # render() said to pass render_mode="rgb_array", which the caller had; positions()
        # gave the constructor's probe episode as an empty (0, 1, 2) array.
        with self.assertRaisesRegex(ValueError, r"render\(\) before reset"):
            cb.Env(QUICK, row="orca", render_mode="rgb_array").render()
        with self.assertRaisesRegex(ValueError, r"positions\(\) before reset"):
            cb.Env(QUICK, row="orca", record=True).positions()
        for n in (1, 2, 3):  # the sub-environments past the first were never started
            with self.assertRaisesRegex(ValueError, "before reset"):
                cb.VectorEnv(QUICK, row="orca", num_envs=n).step(np.zeros((n, 2)))

    def test_close_releases_the_row_and_a_closed_env_says_so(self):
        # close() kept the suite row: 256 closed but referenced Envs (a list of them, as in a
        # sweep) made the 257th fail with "close those you no longer use", which it had done.
        kept = []
        for _ in range(300):  # CrowdNav's open world: quicker to load than the rect layouts
            env = cb.Env(QUICK, row="orca", set="world={source: crowdnav}")
            env.close()
            kept.append(env)
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=2)
        venv.close()
        for use in (lambda: kept[0].reset(seed=0), lambda: kept[0].episodes,
                    lambda: venv.reset(seed=0), lambda: venv.step(np.zeros((2, 2)))):
            with self.assertRaisesRegex(ValueError, "was closed"):
                use()
        env = cb.Env(QUICK, row="orca")
        env.reset(seed=0)
        env.close()
        with self.assertRaisesRegex(ValueError, "was closed"):
            env.step([0.5, 0.0])
        env.close()  # twice is fine, as in Gymnasium

    def test_discrete_actions_must_be_whole_indices_in_range(self):
        env = cb.Env(QUICK, row="orca", discrete=True)
        env.reset(seed=0)
        for bad in (-1, 81, 2.7, True, "3", [1, 2]):
            with self.assertRaises(ValueError, msg=repr(bad)):
                env.step(bad)
        env.step(np.int32(80))
        env.step(np.array(0))
        env.step(np.array([3]))  # one index in a 1-element array
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=3, discrete=True)
        venv.reset()
        for bad in (np.full(3, -1), np.array([0, 81, 1]), np.zeros(3), np.zeros(2, int),
                    np.zeros((3, 1), int)):
            with self.assertRaises(ValueError, msg=repr(bad)):
                venv.step(bad)
        venv.step([0, 40, 80])

    def test_set_takes_one_string_or_a_list_of_strings(self):
        one = cb.Env(QUICK, row="orca", set="humans.count=3")
        listed = cb.Env(QUICK, row="orca", set=["humans.count=3"])
        self.assertEqual(one.observation_space["humans"].shape, (3, 5))
        self.assertEqual(listed.observation_space["humans"].shape, (3, 5))
        with self.assertRaisesRegex(TypeError, "key.path=value"):
            cb.Env(QUICK, row="orca", set=["humans.count=3", 4])

    def test_a_bad_set_is_named_as_the_python_argument(self):
        # It said "--set humans.cout=3: ...", the CLI's option, to a caller who wrote set=.
        with tempfile.TemporaryDirectory() as out:
            for call in (lambda: cb.run_suite(QUICK, out=out, episodes=1, set="humans.cout=3"),
                         lambda: cb.Env(QUICK, row="orca", set=["humans.cout=3"])):
                with self.assertRaises(ValueError) as caught:
                    call()
                msg = str(caught.exception)
                self.assertIn("set=humans.cout=3: humans.cout: unknown key 'cout'", msg)
                self.assertNotIn("--set", msg)
            self.assertFalse(os.listdir(out))  # nothing ran

    def test_a_refused_out_folder_is_named_as_the_python_argument(self):
        # It said "Choose another with --out." and "or out=to write elsewhere".
        with tempfile.TemporaryDirectory() as root:
            a_file = os.path.join(root, "a_file")
            open(a_file, "w").close()
            cb.run_suite(QUICK, out=os.path.join(root, "run"), episodes=1)
            for call in (lambda: cb.evaluate(straight_to_goal, QUICK, out=a_file, episodes=1),
                         lambda: cb.run_suite(QUICK, out=os.path.join(root, "run"), episodes=1,
                                              set="humans.count=3")):
                with self.assertRaises(ValueError) as caught:
                    call()
                msg = str(caught.exception)
                self.assertIn("out=", msg)
                self.assertNotIn("--out", msg)
                self.assertNotIn("out=to", msg)

    def test_a_suite_with_an_episode_timeout_is_refused_with_the_fix(self):
        # It said "... the run's isolation is off; drop the isolation override or the
        # timeout": evaluate()'s own override, which the caller never gave.
        with tempfile.TemporaryDirectory() as out:
            with self.assertRaises(ValueError) as caught:
                cb.evaluate(straight_to_goal, QUICK, out=out, episodes=1,
                            set="episode_timeout_s=5")
            msg = str(caught.exception)
            self.assertIn("evaluate() cannot apply", msg)
            self.assertIn("set='episode_timeout_s=0'", msg)
            self.assertNotIn("override", msg)
            self.assertFalse(os.listdir(out))  # nothing ran
            rows = cb.evaluate(straight_to_goal, QUICK, out=out, episodes=1,
                               set=["episode_timeout_s=5", "episode_timeout_s=0"])
            self.assertEqual(rows[0]["episodes"], 1)

    def test_counts_out_of_range_are_refused_as_by_the_cli(self):
        with tempfile.TemporaryDirectory() as out:
            for episodes in (0, -5, 2.5, True):
                with self.assertRaisesRegex(ValueError, "episodes must be", msg=repr(episodes)):
                    cb.run_suite(QUICK, out=out, episodes=episodes)
                with self.assertRaisesRegex(ValueError, "episodes must be", msg=repr(episodes)):
                    cb.evaluate(straight_to_goal, QUICK, out=out, episodes=episodes)
            for jobs in (0, -3, 1025):
                with self.assertRaisesRegex(ValueError, "jobs must be", msg=repr(jobs)):
                    cb.run_suite(QUICK, out=out, jobs=jobs, episodes=1)
            self.assertFalse(os.listdir(out))  # nothing ran

    def test_episode_indices_out_of_range_and_positions_without_recording(self):
        env = cb.Env(QUICK, row="orca")
        for bad in (10**12, -1):
            with self.assertRaisesRegex(ValueError, "episode index"):
                env.reset(seed=bad)
        with self.assertRaises(TypeError):
            env.reset(options={"episode": 1.5})
        with self.assertRaisesRegex(ValueError, "episode index"):
            cb.VectorEnv(QUICK, row="orca", num_envs=2).reset(seed=2**31)
        env.reset(seed=0)
        with self.assertRaisesRegex(ValueError, "record=True"):
            env.positions()


class Render(unittest.TestCase):
    def test_rgb_array_shows_the_episode_so_far(self):
        env = cb.Env(QUICK, row="orca", render_mode="rgb_array")
        obs, _ = env.reset(seed=1)
        first = env.render()
        for _ in range(8):
            obs, _, terminated, truncated, _ = env.step(np.zeros(2))
            if terminated or truncated:
                break
        later = env.render()
        self.assertEqual(first.dtype, np.uint8)
        self.assertEqual(first.ndim, 3)
        self.assertEqual(first.shape[2], 3)
        self.assertGreater(len(np.unique(first.reshape(-1, 3), axis=0)), 10)
        self.assertEqual(first.shape, later.shape)
        self.assertFalse(np.array_equal(first, later))  # the robot and the clock moved
        self.assertIsNone(cb.Env(QUICK, row="orca").render())
        with self.assertRaises(ValueError):
            cb.Env(QUICK, row="orca", render_mode="human")


if __name__ == "__main__":
    unittest.main()

"""Gymnasium's own tools on the package (issue 49): check_env on every observation and action
configuration, a chain of Gymnasium wrappers over Env and over VectorEnv, and gymnasium.make /
make_vec for every registered id. Runs when gymnasium (>= 1.0) is importable; without it each
test says it was skipped and how to get gymnasium (test_crowdsim_bench.py checks the same
contract without gymnasium). Run by ctest (python_package) from the source root with the
build's python/ folder on PYTHONPATH."""
import math
import os
import re
import sys
import unittest
import warnings

import numpy as np

try:
    import gymnasium
    import gymnasium.wrappers.vector
    from gymnasium.utils.env_checker import check_env
except ImportError:  # Debian 12 has no python3-gymnasium
    gymnasium = None

import crowdsim_bench as cb

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_crowdsim_bench import CONFIGURATIONS, ROUTE  # noqa: E402  the same configurations

QUICK = "suites/quick.yaml"
NO_GYMNASIUM = (
    "gymnasium is not installed (Debian 12 has no package of it); to run this test: apt install "
    "python3-venv, python3 -m venv --system-site-packages ~/venv-gym, ~/venv-gym/bin/pip install "
    "'gymnasium>=1.0', then run it with ~/venv-gym/bin/python (docs/gymnasium.md)")
# The warnings check_env may give here: positions and velocities have no bounds (a world
# declares no extent), a velocity box of another v_pref than 1 is not [-1, 1], and an Env made
# without gymnasium.make has no spec to remake it in its other render modes.
EXPECTED_WARNINGS = re.compile(
    r"A Box observation space (minimum value is -infinity|maximum value is infinity)"
    r"|we recommend using a symmetric and normalized space"
    r"|Not able to test alternative render modes due to the environment not having a spec")


def checked(env):
    """Runs Gymnasium's check_env on `env`; returns the warnings it gave that are not expected."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_env(env)
    return [str(w.message) for w in caught if not EXPECTED_WARNINGS.search(str(w.message))]


@unittest.skipIf(gymnasium is None, NO_GYMNASIUM)
class CheckEnv(unittest.TestCase):
    def test_check_env_passes_on_every_configuration(self):
        # It failed on every one: reset(seed=) did not seed np_random.
        for kwargs, what in CONFIGURATIONS:
            with self.subTest(what):
                env = cb.Env(QUICK, row="orca", **kwargs)
                self.assertIsInstance(env, gymnasium.Env)
                self.assertEqual(checked(env), [], what)
                env.close()

    def test_only_positions_and_velocities_are_unbounded(self):
        # Every Box was (-inf, inf), lidar ranges and time included: check_env warned for each.
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            gymnasium.utils.env_checker.check_space_limit(
                cb.Env(QUICK, row="orca", set=ROUTE).observation_space["lidar"], "observation")
            for key in ("time", "humans_mask"):
                gymnasium.utils.env_checker.check_space_limit(
                    cb.Env(QUICK, row="orca").observation_space[key], "observation")
        self.assertEqual([str(w.message) for w in caught], [])


@unittest.skipIf(gymnasium is None, NO_GYMNASIUM)
class Wrappers(unittest.TestCase):
    def test_a_wrapper_chain_runs_episodes(self):
        # RecordEpisodeStatistics asserted at the first episode's end: the info already had
        # `episode`.
        env = cb.Env(QUICK, row="orca")
        env = gymnasium.wrappers.RecordEpisodeStatistics(env)
        env = gymnasium.wrappers.FlattenObservation(env)
        env = gymnasium.wrappers.NormalizeObservation(env)
        env = gymnasium.wrappers.ClipAction(env)
        self.assertEqual(env.observation_space.shape, (9 + 1 + 25 + 5 + 45,))
        env.action_space.seed(0)
        for k in range(6):
            obs, info = env.reset(seed=k)
            self.assertEqual(obs.shape, (85,))
            self.assertEqual(info["episode_index"], k)
            steps, total = 0, 0.0
            while True:
                obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
                steps, total = steps + 1, total + reward
                self.assertTrue(np.all(np.isfinite(obs)))
                if terminated or truncated:
                    break
            self.assertEqual(info["episode"]["l"], steps)
            self.assertAlmostEqual(info["episode"]["r"], total, places=9)
            self.assertEqual((info["steps"], info["episode_index"]), (steps, k))
        self.assertEqual(len(env.get_wrapper_attr("return_queue")), 6)

    def test_a_vector_wrapper_chain_runs_episodes(self):
        # crowdsim_bench.VectorEnv was no gymnasium.vector.VectorEnv: every vector wrapper
        # refused it.
        n = 4
        venv = cb.VectorEnv(QUICK, row="orca", num_envs=n, threads=2)
        self.assertIsInstance(venv, gymnasium.vector.VectorEnv)
        modes = getattr(gymnasium.vector, "AutoresetMode", None)  # gymnasium >= 1.1
        self.assertIs(venv.metadata["autoreset_mode"],
                      modes.NEXT_STEP if modes is not None else "next_step")
        self.assertEqual(venv.single_action_space, cb.Env(QUICK, row="orca").action_space)
        wrappers = gymnasium.wrappers.vector
        stats = envs = wrappers.RecordEpisodeStatistics(venv)
        envs = wrappers.FlattenObservation(envs)
        envs = wrappers.NormalizeObservation(envs)
        envs = wrappers.ClipAction(envs)
        self.assertEqual(envs.observation_space.shape, (n, 85))
        self.assertEqual(envs.single_observation_space.shape, (85,))
        envs.action_space.seed(0)
        obs, info = envs.reset(seed=0)
        self.assertEqual(obs.shape, (n, 85))
        returns, lengths, ended, recorded = np.zeros(n), np.zeros(n, int), np.zeros(n, bool), 0
        for _ in range(200):
            obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
            self.assertTrue(np.all(np.isfinite(obs)))
            # Next-step autoreset: the step after an end starts the next episode, reward 0.
            returns = np.where(ended, 0.0, returns + reward)
            lengths = np.where(ended, 0, lengths + 1)
            ended = terminated | truncated
            if ended.any():
                np.testing.assert_array_equal(info["_episode"], ended)
                np.testing.assert_array_equal(info["episode"]["l"][ended], lengths[ended])
                np.testing.assert_allclose(info["episode"]["r"][ended], returns[ended])
                recorded += int(ended.sum())
        self.assertGreaterEqual(recorded, 2 * n)
        self.assertEqual(len(stats.return_queue), min(recorded, 100))
        listed = wrappers.DictInfoToList(cb.VectorEnv(QUICK, row="orca", num_envs=2))
        _, infos = listed.reset(seed=3)
        self.assertEqual([i["episode_index"] for i in infos], [3, 4])
        envs.close()


@unittest.skipIf(gymnasium is None, NO_GYMNASIUM)
class RegisteredIds(unittest.TestCase):
    def test_make_and_check_env_work_for_every_registered_id(self):
        self.assertIn("crowdsim_bench/Table1-v0", cb.ENV_IDS)
        self.assertIn("crowdsim_bench/FloorPlanHard-v0", cb.ENV_IDS)
        for env_id, (suite, row) in cb.ENV_IDS.items():
            with self.subTest(env_id):
                env = gymnasium.make(env_id)
                self.assertEqual(env.spec.id, env_id)
                self.assertEqual(env.unwrapped.spec.kwargs["suite"],
                                 f"{cb.data_root()}/{suite}")
                self.assertEqual(env.unwrapped._env.label, row)
                obs, info = env.reset(seed=0)
                self.assertEqual(info["episode_index"], 0)
                self.assertTrue(env.observation_space.contains(obs))
                obs, *_ = env.step(env.action_space.sample())
                self.assertTrue(env.observation_space.contains(obs))
                # With a spec, check_env also remakes the env in each render mode (rgb_array)
                # and closes one twice.
                self.assertEqual(checked(env.unwrapped), [])
                env.close()

    def test_a_made_env_renders_frame_lists(self):
        frames = gymnasium.make("crowdsim_bench/Table1-v0", render_mode="rgb_array_list")
        frames.reset(seed=1)
        frames.step(frames.action_space.sample())
        self.assertEqual(len(frames.render()), 2)  # the reset's frame and the step's

    def test_ids_name_the_test_conditions_of_the_papers_tables(self):
        # Table 1: the 1-obstacle test layouts; Table 2 (floor plans): the Gibson test trips.
        for env_id, suite, row in (
                ("crowdsim_bench/Table1-v0", "suites/table1.yaml", 1),
                ("crowdsim_bench/FloorPlanHard-v0", "suites/table2.yaml",
                 "hard_sarl_pp_lidar_person")):
            made = gymnasium.make(env_id).unwrapped
            paper = cb.Env(suite, row=row)
            self.assertEqual(made.episodes, paper.episodes)
            for k in (0, 7, 499):
                a, info_a = made.reset(seed=k)
                b, info_b = paper.reset(seed=k)
                self.assertEqual(info_a, info_b, f"{env_id} episode {k}")
                for key in b:
                    np.testing.assert_array_equal(a[key], b[key], f"{env_id} {k} {key}")

    def test_make_vec_gives_the_cpp_vector_env(self):
        envs = gymnasium.make_vec("crowdsim_bench/Quick-v0", num_envs=3)
        self.assertIsInstance(envs, cb.VectorEnv)
        obs, info = envs.reset(seed=2)
        self.assertEqual(list(info["episode_index"]), [2, 3, 4])
        envs.step(envs.action_space.sample())
        # Gymnasium's own batching of the Env works too.
        sync = gymnasium.make_vec("crowdsim_bench/Quick-v0", num_envs=2,
                                  vectorization_mode="sync")
        sync.reset(seed=0)
        for _ in range(30):
            obs, *_ = sync.step(sync.action_space.sample())
            self.assertTrue(sync.observation_space.contains(obs))
        self.assertTrue(math.isclose(float(sync.single_observation_space["time"].high), 25.0))


if __name__ == "__main__":
    unittest.main()

// crowdsim_bench._core: the C++ side of the Python package. Env steps one suite row's episodes
// with the velocities a Python program gives; evaluate() runs a suite row with a Python callable
// as the robot and writes the CLI's outputs; run_suite() runs a suite file. The Python side
// (crowdsim_bench/__init__.py) adds the Gymnasium API on top.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/data_root.h"
#include "crowdsim/version.h"
#include "observation_arrays.h"
#include "python_policy.h"
#include "python_row.h"
#include "render_frame.h"
#include "row_episodes.h"
#include "vector_env.h"

namespace py = pybind11;

namespace crowdsim::python {
namespace {

py::dict RowDict(const TableRow& r) {
  const RowMetrics& m = r.metrics;
  py::dict d;
  d["label"] = r.Label();
  for (const auto& [k, v] : r.Info()) d[py::str(k)] = v;
  d["episodes"] = m.episodes;
  d["success"] = m.success_rate;
  d["collision"] = m.collision_rate;
  d["collision_human"] = m.collision_human_rate;
  d["collision_obstacle"] = m.collision_obstacle_rate;
  d["timeout"] = m.timeout_rate;
  d["policy_error"] = m.policy_error_rate;
  d["policy_crash"] = m.policy_crash_rate;
  d["policy_timeout"] = m.policy_timeout_rate;
  d["nav_time"] = m.nav_time;
  d["danger"] = m.danger_frequency;
  d["path_length"] = m.path_length;
  d["min_human_distance"] = m.min_human_distance;
  d["discounted_return"] = m.discounted_return;
  return d;
}

py::list Rows(const RunSummary& s) {
  py::list rows;
  for (const TableRow& r : s.rows) rows.append(RowDict(r));
  return rows;
}

/// A column of the episode's outcome as a Python value (the status by its name); the
/// columns of a line's identity (row, episode, seed, layout) are not the outcome's.
template <typename T>
void AddOutcomeValue(py::dict&, const char*, const EpisodeOutcome&, T EpisodeLine::*) {}
/// Social metrics are a suite run's (`columns:`), not computed for a stepped Env.
void AddOutcomeValue(py::dict&, const char*, const EpisodeOutcome&, double SocialMetrics::*) {}
template <typename T>
void AddOutcomeValue(py::dict& d, const char* name, const EpisodeOutcome& r,
                     T EpisodeOutcome::*member) {
  if constexpr (std::is_same_v<T, EpisodeStatus>) {
    d[name] = EpisodeStatusName(r.*member);
  } else {
    d[name] = r.*member;
  }
}

/// One suite row stepped from Python.
class Env {
 public:
  Env(const std::string& suite_path, const py::object& row, const std::vector<std::string>& set)
      : row_(std::make_unique<PythonRow>(suite_path, row, set)),
        episodes_(row_->suite, row_->row, row_->registry) {}

  py::dict Reset(int episode, bool record) {
    try {
      return ObservationDict(episodes_.Reset(episode, record), humans());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(e.what());
    }
  }

  py::tuple Step(double vx, double vy) {
    if (!episodes_.started()) throw py::value_error("step() before reset()");
    if (episodes_.episode().done())
      throw py::value_error("step() after the episode ended: call reset()");
    const StepInfo info = episodes_.Step(Vec2(vx, vy));
    const EpisodeResult& r = episodes_.episode().result();
    py::dict obs = ObservationDict(episodes_.observation(), humans());
    return py::make_tuple(obs, info.reward, EpisodeStatusName(r.status), r.error);
  }

  /// The outcome's columns of episodes.csv (kEpisodeColumns), plus the episode and layout.
  py::dict Result() const {
    const EpisodeResult& r = Current().result();
    py::dict d;
    for (const EpisodeColumn& c : kEpisodeColumns) {
      std::visit([&](auto member) { AddOutcomeValue(d, c.name, r, member); }, c.field);
    }
    d["episode"] = episodes_.episode_index();
    d["layout"] = episodes_.scenario().layout;
    return d;
  }

  /// Robot and human positions of the recorded frames: (frames, 1 + humans, 2).
  py::array_t<double> Positions() const {
    const auto& tr = Current().result().trajectory;
    const py::ssize_t agents = tr.empty() ? 1 : 1 + static_cast<py::ssize_t>(tr[0].humans.size());
    py::array_t<double> out({static_cast<py::ssize_t>(tr.size()), agents, py::ssize_t{2}});
    auto a = out.mutable_unchecked<3>();
    for (size_t f = 0; f < tr.size(); ++f) {
      a(f, 0, 0) = tr[f].robot.position.x();
      a(f, 0, 1) = tr[f].robot.position.y();
      for (size_t h = 0; h < tr[f].humans.size(); ++h) {
        a(f, h + 1, 0) = tr[f].humans[h].position.x();
        a(f, h + 1, 1) = tr[f].humans[h].position.y();
      }
    }
    return out;
  }

  /// The episode so far as the CLI's animation frame draws it: (height, width, 3) uint8.
  py::array_t<std::uint8_t> Render(double scale) const {
    const Episode& episode = Current();
    if (episode.result().trajectory.empty())
      throw py::value_error(
          "render() needs a recorded episode: Env(..., render_mode=\"rgb_array\")");
    const std::string title = row_->suite.name + " · " + row_->row.label + " · episode " +
                              std::to_string(episodes_.episode_index());
    const render::RgbImage image =
        RenderEpisodeFrame(episodes_.scenario(), episode.result(), title, scale);
    py::array_t<std::uint8_t> out(
        {py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{3}});
    std::copy(image.pixels.begin(), image.pixels.end(), out.mutable_data());
    return out;
  }

  int episodes() const { return row_->suite.episodes; }
  double time_step() const { return row_->suite.sim.time_step; }
  double time_limit() const { return row_->suite.sim.time_limit; }
  double v_pref() const { return row_->suite.sim.robot_v_pref; }
  std::string kinematics() const { return KinematicsModelName(row_->row.kinematics.model); }
  double angular_speed_max() const { return row_->row.kinematics.angular_speed_max; }
  int humans() const { return row_->row.humans.count; }
  std::string label() const { return row_->row.label; }
  std::vector<std::string> sensors() const { return SensorNames(row_->row); }

  /// The row's sensors in their order as (plugin name, {parameter: value}), the schema's
  /// defaults included: the Python side bounds its observation spaces by them (lidar2d's
  /// max_range, route's lookahead).
  py::list sensor_params() const {
    py::list out;
    for (const PluginUse& s : row_->row.sensors) {
      py::dict params;
      for (const auto& [name, value] : s.params.values())
        params[py::str(name)] = std::visit([](const auto& v) { return py::cast(v); }, value);
      out.append(py::make_tuple(s.loaded->descriptor->name, params));
    }
    return out;
  }

 private:
  const Episode& Current() const {
    if (!episodes_.started()) throw py::value_error("no episode yet: call reset()");
    return episodes_.episode();
  }

  std::unique_ptr<PythonRow> row_;
  RowEpisodes episodes_;
};

// For the step-overhead benchmark (tests/bench/python): `episodes` episodes of a row stepped in
// C++ with one fixed velocity, as Env does it but without Python: (steps, seconds).
py::tuple TimeFixedVelocitySteps(const std::string& suite_path, const py::object& row,
                                 const std::vector<std::string>& set, int episodes, double vx,
                                 double vy) {
  PythonRow python_row(suite_path, row, set);
  RowEpisodes env(python_row.suite, python_row.row, python_row.registry);
  long steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < episodes; ++k) {
    env.Reset(k, false);
    while (!env.episode().done()) {
      env.Step(Vec2(vx, vy));
      env.observation();
      ++steps;
    }
  }
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - t0;
  return py::make_tuple(steps, wall.count());
}

// RunSuite with the GIL released (a Python policy's Decide takes it back for each decision);
// Ctrl-C stops it between episodes and is raised again here, with the episodes that finished
// kept; its other errors become ValueError.
RunSummary RunWithoutGil(const Suite& suite, PluginRegistry& registry, RunOptions options,
                         PythonStop& stop) {
  options.stop_requested = [&stop] { return stop.Requested(); };
  std::string error;
  RunSummary summary;
  {
    py::gil_scoped_release release;
    try {
      summary = RunSuite(suite, registry, options);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  stop.RaiseIfKept();
  if (!error.empty()) throw py::value_error(InPythonTerms(error));
  return summary;
}

// evaluate() replays the policy's episodes each time (a Python callable has no hash to tell a
// changed one): it may replace only its own earlier results, never another configuration's
// (it wiped a CLI run's folder without a word).
void RefuseOtherResults(const Suite& suite, const std::filesystem::path& out) {
  const std::filesystem::path manifest = out / "manifest.json";
  std::error_code ec;
  if (!std::filesystem::exists(manifest, ec) && !std::filesystem::exists(out / "episodes.csv", ec))
    return;
  const std::string held = ReadManifestField(manifest, "config_hash");
  if (held == suite.ConfigHash()) return;
  const std::string held_suite = ReadManifestField(manifest, "suite");
  throw py::value_error(
      "'" + out.string() + "' holds results of another configuration (" +
      (held.empty() ? std::string("no readable manifest.json")
                    : "suite '" + held_suite + "', config hash " + held) +
      "; this evaluation's is " + suite.ConfigHash() +
      "): evaluate() replaces only its own earlier results of the same row, label and suite "
      "settings. Pass another out=, or remove the folder first");
}

// A policy that raises ends its episode, not the run: say so once, with the first episode's
// message (as the CLI does: without it a user had to open episodes.csv to see what was wrong)
// and where the others are.
void WarnOfPolicyErrors(const RunSummary& summary) {
  for (const PolicyErrorNote& note : summary.policy_errors) {
    const std::string message =
        std::to_string(note.errors) + " of " + std::to_string(note.episodes) +
        " episodes of row '" + note.row +
        "' ended as policy_error (the policy raised or returned a bad velocity); " + note.First() +
        "\nthe messages are in the error column of " + (summary.out_dir / "episodes.csv").string();
    // Level 2: the warning points at the user's call of crowdsim_bench.evaluate, not at it.
    if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 2) != 0) throw py::error_already_set();
  }
}

py::list Evaluate(py::object policy, const std::string& suite_path, const py::object& row,
                  const std::string& label, const std::string& out, int episodes, bool fresh,
                  const std::vector<std::string>& set, bool progress) {
  if (!PyCallable_Check(policy.ptr()))
    throw py::type_error("policy must be callable: policy(obs) -> (vx, vy)");
  PluginRegistry registry;
  Suite suite = LoadSuiteOrThrow(suite_path, registry, set);
  const RowSpec& original = suite.rows[RowIndex(suite, row)];
  PythonStop stop;
  const PythonPolicyBinding binding(SensorNames(original), original.humans.count, policy, &stop);
  const RowSpec row_spec = WithPythonRobot(original, label, binding.plugin());
  suite.rows = {row_spec};
  suite.summaries.clear();
  suite.canonical += "\nrobot: python policy '" + label + "'";
  RunOptions options;
  // Its own folder by default, beside the CLI's runs/<suite name>/ (never in it).
  options.out_dir = out.empty() ? std::filesystem::path(DefaultRunDir(suite).string() + "." + label)
                                : std::filesystem::path(out);
  options.jobs = 1;                         // one Python interpreter: episodes one after another
  options.isolation = IsolationMode::kOff;  // the policy lives in this interpreter: no fork
  if (suite.episode_timeout_s > 0) {
    // The runner's refusal named an "isolation override" the caller never gave.
    throw py::value_error(
        "suite '" + suite.name + "' (" + suite_path + ") sets episode_timeout_s " +
        py::repr(py::float_(suite.episode_timeout_s)).cast<std::string>() +
        ", which evaluate() cannot apply: the Python policy runs in this process, and an "
        "episode cannot be stopped midway without a worker process of its own. Evaluate "
        "without it: set='episode_timeout_s=0'");
  }
  options.episodes = episodes;
  options.fresh = fresh;
  options.progress = progress;
  RefuseOtherResults(suite, options.out_dir);
  const RunSummary summary = RunWithoutGil(suite, registry, options, stop);
  WarnOfPolicyErrors(summary);
  return Rows(summary);
}

py::list RunSuiteFile(const std::string& suite_path, const std::string& out, int jobs, int episodes,
                      bool fresh, const std::vector<std::string>& set, bool progress) {
  PluginRegistry registry;
  const Suite suite = LoadSuiteOrThrow(suite_path, registry, set);
  RunOptions options;
  options.out_dir = out.empty() ? DefaultRunDir(suite) : std::filesystem::path(out);
  options.jobs = jobs;
  options.episodes = episodes;
  options.fresh = fresh;
  options.progress = progress;
  PythonStop stop;
  const RunSummary summary = RunWithoutGil(suite, registry, options, stop);
  return Rows(summary);
}

}  // namespace
}  // namespace crowdsim::python

PYBIND11_MODULE(_core, m) {
  using namespace crowdsim::python;
  m.doc() = "crowdsim-bench's C++ core (use the crowdsim_bench package)";
  m.attr("MAX_JOBS") = crowdsim::kMaxJobs;
  m.attr("MAX_EPISODES") = crowdsim::kMaxEpisodes;
  m.attr("__version__") =
      std::string(crowdsim::Version()) + " (commit " + crowdsim::GitCommit() + ")";
  // Where the CLI finds its data (the Python side registers Gymnasium ids by its suites).
  m.def("data_root", [] { return crowdsim::DataRoot().string(); });
  py::class_<Env>(m, "Env")
      .def(py::init<const std::string&, const py::object&, const std::vector<std::string>&>(),
           py::arg("suite"), py::arg("row"), py::arg("set") = std::vector<std::string>{})
      .def("reset", &Env::Reset, py::arg("episode"), py::arg("record") = false)
      .def("step", &Env::Step, py::arg("vx"), py::arg("vy"))
      .def("result", &Env::Result)
      .def("positions", &Env::Positions)
      .def("render", &Env::Render, py::arg("scale") = 1.0)
      .def_property_readonly("episodes", &Env::episodes)
      .def_property_readonly("time_step", &Env::time_step)
      .def_property_readonly("time_limit", &Env::time_limit)
      .def_property_readonly("v_pref", &Env::v_pref)
      .def_property_readonly("kinematics", &Env::kinematics)
      .def_property_readonly("angular_speed_max", &Env::angular_speed_max)
      .def_property_readonly("humans", &Env::humans)
      .def_property_readonly("label", &Env::label)
      .def_property_readonly("sensors", &Env::sensors)
      .def_property_readonly("sensor_params", &Env::sensor_params);
  py::class_<VectorEnv>(m, "VectorEnv")
      .def(py::init([](const std::string& suite, const py::object& row, int num_envs,
                       const std::vector<std::string>& set, int threads) {
             return std::make_unique<VectorEnv>(std::make_unique<PythonRow>(suite, row, set),
                                                num_envs, threads);
           }),
           py::arg("suite"), py::arg("row"), py::arg("num_envs"),
           py::arg("set") = std::vector<std::string>{}, py::arg("threads") = 1)
      .def("reset", &VectorEnv::Reset, py::arg("first"))
      .def("step", &VectorEnv::Step, py::arg("actions"))
      .def_property_readonly("num_envs", &VectorEnv::num_envs)
      .def_property_readonly("threads", &VectorEnv::threads)
      .def_property_readonly("humans", &VectorEnv::humans)
      .def_property_readonly("beams", &VectorEnv::beams);
  py::list status_names;
  for (int s = 0; s <= static_cast<int>(crowdsim::EpisodeStatus::kPolicyTimeout); ++s)
    status_names.append(crowdsim::EpisodeStatusName(static_cast<crowdsim::EpisodeStatus>(s)));
  m.attr("STATUS_NAMES") = status_names;
  m.def("_time_fixed_velocity_steps", &TimeFixedVelocitySteps, py::arg("suite"), py::arg("row"),
        py::arg("set"), py::arg("episodes"), py::arg("vx"), py::arg("vy"));
  m.def("evaluate", &Evaluate, py::arg("policy"), py::arg("suite"), py::arg("row"),
        py::arg("label"), py::arg("out"), py::arg("episodes"), py::arg("fresh"), py::arg("set"),
        py::arg("progress"));
  m.def("run_suite", &RunSuiteFile, py::arg("suite"), py::arg("out"), py::arg("jobs"),
        py::arg("episodes"), py::arg("fresh"), py::arg("set"), py::arg("progress"));
}

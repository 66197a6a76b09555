// crowdsim_bench._core: the C++ side of the Python package. Env steps one suite row's episodes
// with the velocities a Python program gives; evaluate() runs a suite row with a Python callable
// as the robot and writes the CLI's outputs; run_suite() runs a suite file. The Python side
// (crowdsim_bench/__init__.py) adds the Gymnasium API on top.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/episode.h"
#include "crowdsim/plugin_registry.h"
#include "crowdsim/row_instance.h"
#include "crowdsim/runner.h"
#include "crowdsim/suite.h"
#include "crowdsim/version.h"
#include "python_policy.h"

namespace py = pybind11;

namespace crowdsim::python {
namespace {

Suite Load(const std::string& path, PluginRegistry& registry, const std::vector<std::string>& set) {
  SuiteLoadResult r = LoadSuite(path, registry, set);
  if (!r.suite) {
    std::string msg;
    for (const auto& e : r.errors) msg += (msg.empty() ? "" : "\n") + e.Format();
    throw py::value_error(msg);
  }
  return std::move(*r.suite);
}

size_t RowIndex(const Suite& suite, const py::object& row) {
  if (py::isinstance<py::int_>(row)) {
    const long k = row.cast<long>();  // 1-based, as in the tables and `render --row`
    if (k < 1 || k > static_cast<long>(suite.rows.size()))
      throw py::index_error("row " + std::to_string(k) + " does not exist: the suite has rows 1.." +
                            std::to_string(suite.rows.size()));
    return static_cast<size_t>(k - 1);
  }
  const std::string label = row.cast<std::string>();
  std::string labels;
  for (size_t i = 0; i < suite.rows.size(); ++i) {
    if (suite.rows[i].label == label) return i;
    labels += (labels.empty() ? "" : ", ") + suite.rows[i].label;
  }
  throw py::key_error("no row '" + label + "' in the suite (rows: " + labels + ")");
}

std::vector<std::string> SensorNames(const RowSpec& row) {
  std::vector<std::string> names;
  for (const PluginUse& s : row.sensors) names.push_back(s.loaded->descriptor->name);
  return names;
}

// The row with the Python policy in place of its robot policy; the marker in the canonical text
// keeps its stored results apart from the original row's.
RowSpec WithPythonRobot(const RowSpec& row, const std::string& label) {
  RowSpec out = row;
  out.policy = PluginUse{"python", &PythonPolicyPlugin(), Params{}};
  out.label = label;
  out.reference.reset();
  for (auto& [column, value] : out.info)
    if (column == "model") value = label;  // the row's model column names the Python policy
  out.canonical += "\nrobot: python policy '" + label + "'";
  return out;
}

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

/// One suite row stepped from Python.
class Env {
 public:
  Env(const std::string& suite_path, const py::object& row, const std::vector<std::string>& set)
      : suite_(Load(suite_path, registry_, set)) {
    const RowSpec& original = suite_.rows[RowIndex(suite_, row)];
    row_ = WithPythonRobot(original, original.label);
    world_ = registry_.MakeWorld(*row_.world.loaded, row_.world.params);
    SetNextPythonPolicy(SensorNames(row_), row_.humans.count, nullptr);
    instance_ = std::make_unique<RowInstance>(row_, registry_);
    policy_ = dynamic_cast<PythonPolicy*>(&instance_->robot());
  }

  py::dict Reset(int episode, bool record) {
    if (episode < 0) throw py::value_error("episode must be >= 0");
    episode_.reset();
    scenario_ = world_->Make(MakeEpisodeRequest(suite_, row_, *world_, episode));
    try {
      CheckScenario(scenario_, suite_.sim);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("episode ") + std::to_string(episode) + ": " + e.what());
    }
    episode_ = std::make_unique<Episode>(scenario_, suite_.sim,
                                         instance_->Agents(scenario_.humans.size()), record);
    episode_index_ = episode;
    return ObservationDict(episode_->ObserveRobot(), row_.humans.count);
  }

  py::tuple Step(double vx, double vy) {
    if (!episode_) throw py::value_error("step() before reset()");
    if (episode_->done()) throw py::value_error("step() after the episode ended: call reset()");
    policy_->SetNextVelocity(Vec2(vx, vy));
    const StepInfo info = episode_->Step();
    const EpisodeResult& r = episode_->result();
    py::dict obs = ObservationDict(episode_->ObserveRobot(), row_.humans.count);
    return py::make_tuple(obs, info.reward, EpisodeStatusName(r.status), r.error);
  }

  py::dict Result() const {
    if (!episode_) throw py::value_error("no episode yet: call reset()");
    const EpisodeResult& r = episode_->result();
    py::dict d;
    d["status"] = EpisodeStatusName(r.status);
    d["time"] = r.time;
    d["steps"] = r.steps;
    d["path_length"] = r.path_length;
    d["min_human_distance"] = r.min_human_distance;
    d["discounted_return"] = r.discounted_return;
    d["danger_steps"] = r.danger_steps;
    d["episode"] = episode_index_;
    d["layout"] = scenario_.layout;
    return d;
  }

  /// Robot and human positions of the recorded frames: (frames, 1 + humans, 2).
  py::array_t<double> Positions() const {
    if (!episode_) throw py::value_error("no episode yet: call reset()");
    const auto& tr = episode_->result().trajectory;
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

  int episodes() const { return suite_.episodes; }
  double time_step() const { return suite_.sim.time_step; }
  double time_limit() const { return suite_.sim.time_limit; }
  double v_pref() const { return suite_.sim.robot_v_pref; }
  int humans() const { return row_.humans.count; }
  std::string label() const { return row_.label; }
  std::vector<std::string> sensors() const { return SensorNames(row_); }

 private:
  PluginRegistry registry_;
  Suite suite_;
  RowSpec row_;
  std::shared_ptr<WorldSource> world_;
  std::unique_ptr<RowInstance> instance_;
  PythonPolicy* policy_ = nullptr;
  Scenario scenario_;
  std::unique_ptr<Episode> episode_;
  int episode_index_ = -1;
};

// RunSuite with the GIL released (a Python policy's Decide takes it back for each decision);
// its errors become ValueError.
RunSummary RunWithoutGil(const Suite& suite, PluginRegistry& registry, const RunOptions& options) {
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
  if (!error.empty()) throw py::value_error(error);
  return summary;
}

py::list Evaluate(py::object policy, const std::string& suite_path, const py::object& row,
                  const std::string& label, const std::string& out, int episodes, bool fresh,
                  const std::vector<std::string>& set, bool progress) {
  if (!PyCallable_Check(policy.ptr())) throw py::type_error("policy must be callable: policy(obs) -> (vx, vy)");
  PluginRegistry registry;
  Suite suite = Load(suite_path, registry, set);
  const RowSpec row_spec = WithPythonRobot(suite.rows[RowIndex(suite, row)], label);
  suite.rows = {row_spec};
  suite.summaries.clear();
  suite.canonical += "\nrobot: python policy '" + label + "'";
  RunOptions options;
  options.out_dir = out.empty() ? DefaultRunDir(suite) : std::filesystem::path(out);
  options.jobs = 1;  // one Python interpreter: episodes one after another
  options.episodes = episodes;
  options.fresh = fresh;
  options.progress = progress;
  SetNextPythonPolicy(SensorNames(row_spec), row_spec.humans.count, policy.ptr());
  const RunSummary summary = RunWithoutGil(suite, registry, options);
  SetNextPythonPolicy({}, 0, nullptr);
  return Rows(summary);
}

py::list RunSuiteFile(const std::string& suite_path, const std::string& out, int jobs, int episodes,
                      bool fresh, const std::vector<std::string>& set, bool progress) {
  PluginRegistry registry;
  const Suite suite = Load(suite_path, registry, set);
  RunOptions options;
  options.out_dir = out.empty() ? DefaultRunDir(suite) : std::filesystem::path(out);
  options.jobs = jobs;
  options.episodes = episodes;
  options.fresh = fresh;
  options.progress = progress;
  const RunSummary summary = RunWithoutGil(suite, registry, options);
  return Rows(summary);
}

}  // namespace
}  // namespace crowdsim::python

PYBIND11_MODULE(_core, m) {
  using namespace crowdsim::python;
  m.doc() = "crowdsim-bench's C++ core (use the crowdsim_bench package)";
  m.attr("__version__") = std::string(crowdsim::Version()) + " (commit " + crowdsim::GitCommit() + ")";
  py::class_<Env>(m, "Env")
      .def(py::init<const std::string&, const py::object&, const std::vector<std::string>&>(),
           py::arg("suite"), py::arg("row"), py::arg("set") = std::vector<std::string>{})
      .def("reset", &Env::Reset, py::arg("episode"), py::arg("record") = false)
      .def("step", &Env::Step, py::arg("vx"), py::arg("vy"))
      .def("result", &Env::Result)
      .def("positions", &Env::Positions)
      .def_property_readonly("episodes", &Env::episodes)
      .def_property_readonly("time_step", &Env::time_step)
      .def_property_readonly("time_limit", &Env::time_limit)
      .def_property_readonly("v_pref", &Env::v_pref)
      .def_property_readonly("humans", &Env::humans)
      .def_property_readonly("label", &Env::label)
      .def_property_readonly("sensors", &Env::sensors);
  m.def("evaluate", &Evaluate, py::arg("policy"), py::arg("suite"), py::arg("row"),
        py::arg("label"), py::arg("out"), py::arg("episodes"), py::arg("fresh"), py::arg("set"),
        py::arg("progress"));
  m.def("run_suite", &RunSuiteFile, py::arg("suite"), py::arg("out"), py::arg("jobs"),
        py::arg("episodes"), py::arg("fresh"), py::arg("set"), py::arg("progress"));
}

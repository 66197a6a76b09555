#include "python_row.h"

#include <utility>

#include "crowdsim/bench/spec_file_kind.h"

namespace py = pybind11;

namespace crowdsim::python {

std::string InPythonTerms(std::string message) {
  for (const auto& [cli, python] : {std::pair<std::string, std::string>{"--fresh", "fresh=True"},
                                    {"--out", "out="},  // "choose another --out"
                                    {"--episodes ", "episodes="},
                                    {"no --set", "no set="},  // a run's overrides (manifest)
                                    {"--set ", "set="}}) {
    for (auto at = message.find(cli); at != std::string::npos; at = message.find(cli, at)) {
      message.replace(at, cli.size(), python);
      at += python.size();
    }
  }
  return message;
}

Suite LoadSuiteOrThrow(const std::string& path, PluginRegistry& registry,
                       const std::vector<std::string>& set) {
  SuiteLoadResult r = LoadSuite(path, registry, set);
  if (!r.suite) {
    // A training file read as a suite gives an unknown key for each of its own top-level keys
    // (policy, params, sensors, training) and a missing rows list: say what it is instead, as
    // `crowdsim-bench run` does.
    if (KindOfSpecFile(path) == SpecFileKind::kTraining) {
      throw py::value_error(
          path + " is a training file (train it with `crowdsim-bench train " + path +
          "`); Env, VectorEnv, evaluate() and run_suite() take a suite, whose rows: list the "
          "policies (e.g. suites/quick.yaml)");
    }
    std::string msg;
    for (const auto& e : r.errors) {
      if (!msg.empty()) msg += '\n';
      msg += e.Format();  // appended: GCC 12 warned (-Wrestrict, falsely) on "\n" + text
    }
    throw py::value_error(InPythonTerms(msg));
  }
  return std::move(*r.suite);
}

size_t RowIndex(const Suite& suite, const py::object& row) {
  // An int or any integer with __index__ (numpy's), not a bool; or a label.
  const bool is_bool =
      PyBool_Check(row.ptr()) || py::isinstance(row, py::module_::import("numpy").attr("bool_"));
  if (!is_bool && !py::isinstance<py::str>(row) && PyIndex_Check(row.ptr())) {
    const py::int_ index = py::reinterpret_steal<py::int_>(PyNumber_Index(row.ptr()));
    const bool fits =
        index.ptr() != nullptr && index < py::int_(1L << 30) && index > py::int_(-(1L << 30));
    if (!fits) PyErr_Clear();
    const long k = fits ? index.cast<long>() : 0;  // 1-based, as in the tables and `render --row`
    if (k < 1 || k > static_cast<long>(suite.rows.size()))
      throw py::index_error("row " + py::repr(row).cast<std::string>() +
                            " does not exist: the suite has rows 1.." +
                            std::to_string(suite.rows.size()));
    return static_cast<size_t>(k - 1);
  }
  if (!py::isinstance<py::str>(row)) {
    throw py::type_error("row must be a row's label or its 1-based index, got " +
                         py::repr(row).cast<std::string>() + " (" +
                         py::str(py::type::of(row).attr("__name__")).cast<std::string>() + ")");
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

RowSpec WithPythonRobot(const RowSpec& row, const std::string& label,
                        const LoadedPlugin& python_policy) {
  RowSpec out = row;
  out.policy = PluginUse{"python", &python_policy, Params{}};
  out.label = label;
  out.reference.reset();
  for (auto& [column, value] : out.info)
    if (column == "model") value = label;  // the row's model column names the Python policy
  out.canonical += "\nrobot: python policy '" + label + "'";
  return out;
}

PythonRow::PythonRow(const std::string& suite_path, const py::object& row_choice,
                     const std::vector<std::string>& set)
    : suite(LoadSuiteOrThrow(suite_path, registry, set)) {
  const RowSpec& original = suite.rows[RowIndex(suite, row_choice)];
  binding = std::make_unique<PythonPolicyBinding>(SensorNames(original), original.humans.count,
                                                  py::object(), nullptr);
  row = WithPythonRobot(original, original.label, binding->plugin());
}

}  // namespace crowdsim::python

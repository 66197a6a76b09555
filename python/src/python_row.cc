#include "python_row.h"

#include "python_policy.h"

namespace py = pybind11;

namespace crowdsim::python {

Suite LoadSuiteOrThrow(const std::string& path, PluginRegistry& registry,
                       const std::vector<std::string>& set) {
  SuiteLoadResult r = LoadSuite(path, registry, set);
  if (!r.suite) {
    std::string msg;
    for (const auto& e : r.errors) {
      if (!msg.empty()) msg += '\n';
      msg += e.Format();  // appended: GCC 12 warned (-Wrestrict, falsely) on "\n" + text
    }
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

PythonRow::PythonRow(const std::string& suite_path, const py::object& row_choice,
                     const std::vector<std::string>& set)
    : suite(LoadSuiteOrThrow(suite_path, registry, set)) {
  const RowSpec& original = suite.rows[RowIndex(suite, row_choice)];
  row = WithPythonRobot(original, original.label);
  SetNextPythonPolicy(SensorNames(row), row.humans.count, nullptr);
}

}  // namespace crowdsim::python

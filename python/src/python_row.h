// A suite row as the Python package uses it: the suite read with its own plugin registry and
// one row picked by 1-based index or label, with the Python policy as its robot.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "python_policy.h"

namespace crowdsim::python {

/// A message of the core in the package's words: the CLI's options are keyword arguments here
/// (--set X: set=X, no --set: no set=, --out DIR: out=DIR, --episodes N: episodes=N, --fresh:
/// fresh=True).
std::string InPythonTerms(std::string message);

/// Reads a suite file (with --set style overrides); its errors become ValueError, in the
/// package's words (an override's error names set=, not --set).
Suite LoadSuiteOrThrow(const std::string& path, PluginRegistry& registry,
                       const std::vector<std::string>& set);

/// The index of a row given as a 1-based int or a label (IndexError / KeyError otherwise).
size_t RowIndex(const Suite& suite, const pybind11::object& row);

/// Plugin names of the row's sensors.
std::vector<std::string> SensorNames(const RowSpec& row);

/// The row with the Python policy (`python_policy`, a binding's plugin) in place of its robot
/// policy; the marker in the canonical text keeps its stored results apart from the original
/// row's.
RowSpec WithPythonRobot(const RowSpec& row, const std::string& label,
                        const LoadedPlugin& python_policy);

/// A suite, its registry and one of its rows with the Python robot in Env mode (not movable:
/// the row's plugins live in the registry, and RowEpisodes keep references to the suite and
/// row; the binding outlives the policies made from it, which live in RowEpisodes).
struct PythonRow {
  PythonRow(const std::string& suite_path, const pybind11::object& row,
            const std::vector<std::string>& set);
  PythonRow(const PythonRow&) = delete;
  PythonRow& operator=(const PythonRow&) = delete;

  PluginRegistry registry;
  Suite suite;
  std::unique_ptr<PythonPolicyBinding> binding;
  RowSpec row;
};

}  // namespace crowdsim::python

#include "crowdsim/bench/input_files.h"

#include <system_error>

#include "crowdsim/bench/row_instance.h"
#include "spec/config_text.h"

namespace crowdsim {
namespace fs = std::filesystem;

void AddPluginInputFiles(const PluginUse& use, const std::string& owner,
                         std::vector<NamedInput>* inputs) {
  // The files the config hash covers: those parameters name and the plugin's data files.
  for (const suite_internal::InputFile& file : suite_internal::InputFiles(use)) {
    inputs->push_back(
        {file.path, owner + "'s " + (file.param.empty() ? "data file " + file.name : file.param)});
  }
}

void AddRowInputFiles(const RowSpec& row, const std::string& row_name,
                      std::vector<NamedInput>* inputs) {
  for (const auto& [role, use] : RowPlugins(row))
    AddPluginInputFiles(*use, row_name + " " + role, inputs);
}

std::vector<NamedInput> SuiteInputFiles(const Suite& suite) {
  std::vector<NamedInput> inputs = {{suite.file, "the suite file"}};
  for (const RowSpec& row : suite.rows) AddRowInputFiles(row, "row '" + row.label + "'", &inputs);
  return inputs;
}

std::string OutputOverAnInput(const std::vector<fs::path>& outputs,
                              const std::vector<NamedInput>& inputs) {
  for (const fs::path& out : outputs) {
    for (const NamedInput& in : inputs) {
      std::error_code ec;
      if (fs::equivalent(out, in.path, ec)) {
        return "--out would write " + out.string() + ", which is " + in.what +
               " this command reads: choose another --out";
      }
    }
  }
  return "";
}

}  // namespace crowdsim

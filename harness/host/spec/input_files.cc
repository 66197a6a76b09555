#include "crowdsim/bench/input_files.h"

#include <system_error>
#include <variant>

#include "crowdsim/bench/row_instance.h"

namespace crowdsim {
namespace fs = std::filesystem;

void AddPluginInputFiles(const PluginUse& use, const std::string& owner,
                         std::vector<InputFile>* inputs) {
  for (const auto& [name, value] : use.params.values()) {
    const auto* text = std::get_if<std::string>(&value);
    if (text == nullptr || text->empty()) continue;
    std::error_code ec;
    const fs::path path = use.params.ResolvePath(*text);
    if (fs::is_regular_file(path, ec)) inputs->push_back({path, owner + "'s " + name});
  }
}

void AddRowInputFiles(const RowSpec& row, const std::string& row_name,
                      std::vector<InputFile>* inputs) {
  for (const auto& [role, use] : RowPlugins(row))
    AddPluginInputFiles(*use, row_name + " " + role, inputs);
}

std::vector<InputFile> SuiteInputFiles(const Suite& suite) {
  std::vector<InputFile> inputs = {{suite.file, "the suite file"}};
  for (const RowSpec& row : suite.rows) AddRowInputFiles(row, "row '" + row.label + "'", &inputs);
  return inputs;
}

std::string OutputOverAnInput(const std::vector<fs::path>& outputs,
                              const std::vector<InputFile>& inputs) {
  for (const fs::path& out : outputs) {
    for (const InputFile& in : inputs) {
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

#include "spec/yaml_file.h"

#include <system_error>

#include "crowdsim/bench/results.h"
#include "yaml_document.h"

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

YAML::Node LoadYamlFile(const fs::path& file, const std::string& what,
                        std::vector<SuiteError>* errors) {
  // A run's output folder: commands that replay a run take the suite its manifest names.
  std::error_code ec;
  if (fs::is_directory(file, ec) && fs::exists(file / "manifest.json", ec)) {
    if (const std::string ran = ReadManifestField(file / "manifest.json", "suite_file");
        !ran.empty()) {
      errors->push_back({file.string(), 0, 0, "",
                         "is the output folder of a run; give the " + what +
                             " it ran, which its manifest.json names: " + ran});
      return YAML::Node(YAML::NodeType::Null);
    }
  }
  std::vector<yaml::Problem> problems;
  YAML::Node root = yaml::LoadDocument(file, what, &problems);
  for (const yaml::Problem& p : problems)
    errors->push_back({p.file, p.line, p.column, "", p.message});
  return root;
}

}  // namespace crowdsim::suite_internal

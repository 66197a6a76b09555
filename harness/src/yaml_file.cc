#include "yaml_file.h"

#include <map>
#include <system_error>

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

namespace {

void FindDuplicateKeys(const YAML::Node& n, const std::string& file, std::vector<SuiteError>* errors) {
  if (n.IsMap()) {
    std::map<std::string, YAML::Mark> seen;
    for (const auto& kv : n) {
      if (kv.first.IsScalar()) {
        const auto [first, inserted] = seen.emplace(kv.first.Scalar(), kv.first.Mark());
        if (!inserted) {
          const YAML::Mark at = kv.first.Mark();
          errors->push_back({file, at.line + 1, at.column + 1, "",
                             "key '" + kv.first.Scalar() + "' is given twice in this map (first at line " +
                                 std::to_string(first->second.line + 1) +
                                 "); only one value would count: remove or rename one"});
        }
      }
      FindDuplicateKeys(kv.second, file, errors);
    }
  } else if (n.IsSequence()) {
    for (const auto& item : n) FindDuplicateKeys(item, file, errors);
  }
}

}  // namespace

YAML::Node LoadYamlFile(const fs::path& file, const std::string& what, std::vector<SuiteError>* errors) {
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    errors->push_back({file.string(), 0, 0, "", what + " does not exist"});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (fs::is_directory(file, ec)) {
    errors->push_back({file.string(), 0, 0, "", "is a folder; give the " + what + " (a .yaml file) in it"});
    return YAML::Node(YAML::NodeType::Null);
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    errors->push_back({file.string(), 0, 0, "", "cannot read the " + what + " (permissions?)"});
    return YAML::Node(YAML::NodeType::Null);
  } catch (const YAML::Exception& e) {
    errors->push_back({file.string(), e.mark.line + 1, e.mark.column + 1, "", "not valid YAML: " + e.msg});
    return YAML::Node(YAML::NodeType::Null);
  }
  const std::size_t before = errors->size();
  FindDuplicateKeys(root, file.string(), errors);
  return errors->size() == before ? root : YAML::Node(YAML::NodeType::Null);
}

}  // namespace crowdsim::suite_internal

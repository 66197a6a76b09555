#include "validate_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "atomic_file.h"
#include "crowdsim/bench/csv.h"
#include "crowdsim/cli/args.h"
#include "crowdsim/data_root.h"
#include "known_scenes.h"
#include "validation_table.h"

namespace crowdsim::crowds {

using cli::Args;
using cli::UsageError;

int ValidateCrowds(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--models", "--out"}, {});
  std::vector<std::filesystem::path> files(a.positional.begin(), a.positional.end());
  if (files.empty()) {
    for (const KnownScene& s : KnownScenes())
      files.push_back(DataRoot() / "worlds" / "crowds" / (std::string(s.scene) + ".tracks"));
  }
  std::vector<std::string> models(std::begin(kValidatedModels), std::end(kValidatedModels));
  if (const auto list = a.Get("--models")) {
    models = SplitCsvLine(*list);
    std::erase(models, std::string());
  }
  if (models.empty()) throw UsageError("crowds validate: --models names no model");
  std::string valid;
  for (const char* m : kValidatedModels) valid += std::string(valid.empty() ? "" : ", ") + m;
  for (const std::string& m : models) {
    if (std::find(std::begin(kValidatedModels), std::end(kValidatedModels), m) ==
        std::end(kValidatedModels))
      throw UsageError("crowds validate: unknown human model '" + m + "' (the models: " + valid +
                       ")");
  }
  for (const auto& f : files) {
    if (!std::filesystem::is_regular_file(f))
      throw UsageError("crowds validate: track file " + f.string() +
                       " does not exist; import one with `crowdsim-bench crowds import`");
  }
  const std::filesystem::path out = a.Get("--out").value_or("runs/crowds_validation");
  cli::CreateFolderOf("--out", (out / "table.csv").string());

  // Every plugin and track file read before the first person walks.
  PluginRegistry registry;
  const ValidationSettings settings;
  std::vector<std::unique_ptr<SceneValidation>> scenes;
  for (const auto& f : files)
    scenes.push_back(std::make_unique<SceneValidation>(registry, f, settings));
  std::vector<std::shared_ptr<Policy>> policies;
  for (const std::string& m : models) {
    const LoadedPlugin& p = registry.Load(m, PluginKind::kPolicy);
    policies.push_back(registry.MakePolicy(p, Params::Defaults(p.schema)));
  }
  std::vector<ValidationRow> rows;
  for (const auto& scene : scenes) {
    for (std::size_t m = 0; m < models.size(); ++m) {
      rows.push_back(Summarise(scene->scene(), models[m], scene->Run(*policies[m])));
      std::fprintf(stderr, "validated %s with %s: %d people\n", scene->scene().c_str(),
                   models[m].c_str(), rows.back().people);
    }
  }
  common::WriteFileAtomically(out / "table.csv", ValidationCsv(rows));
  const std::string markdown = ValidationMarkdown(rows);
  common::WriteFileAtomically(out / "table.md", markdown);
  std::printf("%s", markdown.c_str());
  return 0;
}

}  // namespace crowdsim::crowds

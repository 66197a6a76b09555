// report: one self-contained HTML page of a results folder (table, charts, episode figures) or
// of a training folder (learning curve, validations, outcomes and replay memory by block).
#include <iostream>

#include "commands.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/cli/args.h"
#include "crowdsim/render/figure_output.h"
#include "crowdsim/render/learning_curve.h"
#include "crowdsim/render/report.h"
#include "crowdsim/render/results_folder.h"
#include "crowdsim/render/training_report.h"

namespace crowdsim::cli {

int ReportCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--suite"}, {});
  if (a.positional.size() != 1)
    throw UsageError("report needs exactly one results folder (the --out of `run` or `train`)");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("report needs --out FILE.html");
  const std::filesystem::path dir = a.positional[0];
  const bool training =
      render::IsTrainingFolder(dir) && !std::filesystem::exists(dir / "manifest.json");
  const bool figure = out->ends_with(".svg") || out->ends_with(".png") || out->ends_with(".pdf");
  if (training && figure) {
    // A training folder's learning curve alone, as a figure.
    const std::string name =
        dir.filename().empty() ? dir.parent_path().filename().string() : dir.filename().string();
    CreateFolderOf("--out", *out);
    render::WriteFigure(
        render::LearningCurveDrawing(render::ReadTrainingEpisodes(dir),
                                     render::ReadTextFileIfExists(dir / "training_log.csv"), name),
        *out);
    std::cerr << "wrote " << *out << "\n";
    return 0;
  }
  if (!out->ends_with(".html") && !out->ends_with(".htm")) {
    throw UsageError(
        "report writes HTML (or, for a training folder, its learning curve as .svg, .png "
        "or .pdf): --out must end in .html, got '" +
        *out + "'");
  }
  render::ReportOptions options;
  if (auto s = a.Get("--suite")) options.suite_file = *s;
  std::vector<std::string> warnings;
  options.warnings = &warnings;
  PluginRegistry registry;
  try {
    const std::string html =
        training ? render::BuildTrainingReport(dir) : render::BuildReport(dir, registry, options);
    CreateFolderOf("--out", *out);  // once the report is built: a refused folder leaves nothing
    WriteFileAtomically(*out, html);
  } catch (const render::ReportError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
  std::cerr << "wrote " << *out << "\n";
  return 0;
}

}  // namespace crowdsim::cli

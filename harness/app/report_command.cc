// report: one self-contained HTML page of a results folder (table, charts, episode figures).
#include <iostream>

#include "cli_args.h"
#include "commands.h"
#include "crowdsim/plugin_registry.h"
#include "crowdsim/render/report.h"
#include "crowdsim/results.h"

namespace crowdsim::cli {

int ReportCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--suite"}, {});
  if (a.positional.size() != 1)
    throw UsageError("report needs exactly one results folder (the --out of `run`)");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("report needs --out FILE.html");
  if (!out->ends_with(".html") && !out->ends_with(".htm")) {
    throw UsageError("report writes HTML: --out must end in .html, got '" + *out + "'");
  }
  render::ReportOptions options;
  if (auto s = a.Get("--suite")) options.suite_file = *s;
  PluginRegistry registry;
  try {
    WriteFileAtomically(*out, render::BuildReport(a.positional[0], registry, options));
  } catch (const render::ReportError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  std::cerr << "wrote " << *out << "\n";
  return 0;
}

}  // namespace crowdsim::cli

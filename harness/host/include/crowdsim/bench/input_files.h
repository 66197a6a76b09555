// The files a run, a training or a figure reads, so no output is ever written over one of them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim {

/// A file read, and what it is in words: "the suite file", "row 'a' policy's weights".
struct NamedInput {
  std::filesystem::path path;
  std::string what;
};

/// The suite file and, for each row, every file its plugins read (those the config hash covers).
std::vector<NamedInput> SuiteInputFiles(const Suite& suite);

/// Appends the files `use` reads (named by a parameter, or the plugin's data files) as "OWNER's
/// PARAM" or "OWNER's data file NAME".
void AddPluginInputFiles(const PluginUse& use, const std::string& owner,
                         std::vector<NamedInput>* inputs);

/// AddPluginInputFiles for each plugin of `row`: "ROW_NAME policy's weights".
void AddRowInputFiles(const RowSpec& row, const std::string& row_name,
                      std::vector<NamedInput>* inputs);

/// "" when no output is an input; else "--out would write PATH, which is WHAT this command reads:
/// choose another --out".
std::string OutputOverAnInput(const std::vector<std::filesystem::path>& outputs,
                              const std::vector<NamedInput>& inputs);

}  // namespace crowdsim

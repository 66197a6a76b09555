// The files a run, a training or a figure reads, so no output is ever written over one of them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim {

/// A file read, and what it is in words: "the suite file", "row 'a' policy's weights".
struct InputFile {
  std::filesystem::path path;
  std::string what;
};

/// The suite file and, for each row, every plugin parameter naming an existing file.
std::vector<InputFile> SuiteInputFiles(const Suite& suite);

/// Appends every parameter of `use` that names an existing file, as "OWNER's NAME".
void AddPluginInputFiles(const PluginUse& use, const std::string& owner,
                         std::vector<InputFile>* inputs);

/// AddPluginInputFiles for each plugin of `row`: "ROW_NAME policy's weights".
void AddRowInputFiles(const RowSpec& row, const std::string& row_name,
                      std::vector<InputFile>* inputs);

/// "" when no output is an input; else "--out would write PATH, which is WHAT this command reads:
/// choose another --out".
std::string OutputOverAnInput(const std::vector<std::filesystem::path>& outputs,
                              const std::vector<InputFile>& inputs);

}  // namespace crowdsim

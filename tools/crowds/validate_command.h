// `crowdsim-bench crowds validate`: the human models against the recorded people of the six
// scenes (docs/crowds.md), a table per scene and model.
#pragma once

#include <string>
#include <vector>

namespace crowdsim::crowds {

/// The models validated unless --models names others; replay is the recorded people themselves.
inline constexpr const char* kValidatedModels[] = {"orca", "social_force", "hsfm", "linear",
                                                   "replay"};

/// Runs `crowds validate` (`args` after the word "validate"): every check (models, track files)
/// before anything is run; writes OUT/table.csv and OUT/table.md and prints the Markdown.
int ValidateCrowds(const std::vector<std::string>& args);

}  // namespace crowdsim::crowds

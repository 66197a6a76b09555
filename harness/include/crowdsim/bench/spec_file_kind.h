// What a YAML file of this project is, before it is read as one: a suite or a training file.
// `run`, `train`, `validate` and the Python package say which a wrong one is, instead of an
// unknown-key error for each of its top-level keys.
#pragma once

#include <filesystem>

namespace crowdsim {

enum class SpecFileKind { kUnknown, kSuite, kTraining };

/// By the file's first top-level `training:`/`policy:` (a training file) or `rows:` (a suite)
/// key; kUnknown when it has neither or cannot be read.
SpecFileKind KindOfSpecFile(const std::filesystem::path& file);

}  // namespace crowdsim

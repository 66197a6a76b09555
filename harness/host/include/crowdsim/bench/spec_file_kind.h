// What a YAML file of this project is, before it is read as one: a suite, a training file or a
// world (or world set) file. `run`, `train`, `validate` and the Python package say which a
// wrong one is, instead of an unknown-key error for each of its top-level keys.
#pragma once

#include <filesystem>

namespace crowdsim {

enum class SpecFileKind { kUnknown, kSuite, kTraining, kWorld, kWorldSet };

/// By the file's first top-level `training:`/`policy:` (a training file), `rows:` (a suite) or
/// `format: crowdsim-world/1` / `format: crowdsim-world-set/1` (world_file.h) key; kUnknown
/// when it has none or cannot be read.
SpecFileKind KindOfSpecFile(const std::filesystem::path& file);

}  // namespace crowdsim

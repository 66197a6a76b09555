// Which kind of project YAML a file is, so commands name a wrong kind instead of unknown keys.
#pragma once

#include <filesystem>

namespace crowdsim {

enum class SpecFileKind { kUnknown, kSuite, kTraining, kWorld, kWorldSet };

/// By the first top-level `training:`/`policy:`, `rows:` or world `format:` key; kUnknown when none
/// or unreadable.
SpecFileKind KindOfSpecFile(const std::filesystem::path& file);

}  // namespace crowdsim

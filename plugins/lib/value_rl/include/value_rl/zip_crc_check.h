// The integrity check of a zip archive (a libtorch .pt file is one): every entry's bytes
// against the CRC-32 and size its central directory records. libtorch's reader does not check
// them, so a flipped byte in a weights file would otherwise load as other weights.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace crowdsim::value_rl {

/// What is wrong with a damaged archive.
struct ZipDamage {
  std::string entry;    ///< the entry's name; empty when the archive's structure is damaged
  std::string problem;  ///< e.g. "CRC-32 is 0x1a2b3c4d, the archive records 0x5e6f7a8b"
};

/// Checks every entry of the zip archive `file` (stored or deflated, zip64 included): its local
/// header, its bytes inside the file, their size and CRC-32. Returns the first damage found, or
/// nullopt when every entry is intact or when `file` is no zip archive at all (it neither starts
/// with a local header nor has an end record: the caller's reader says what it is instead).
/// Throws std::runtime_error naming the file and the OS reason when it cannot be read.
std::optional<ZipDamage> FindZipDamage(const std::filesystem::path& file);

}  // namespace crowdsim::value_rl

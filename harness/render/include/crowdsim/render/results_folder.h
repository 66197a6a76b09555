// Reading a `crowdsim-bench run` output folder for the report: table.csv and text files (the
// manifest's fields through crowdsim/bench/results.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace crowdsim::render {

/// A CSV file: its header and rows of fields (quoted fields unquoted).
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// Index of column `name`. Throws std::runtime_error naming the file's columns when absent.
  size_t Column(const std::string& name) const;
};

/// Reads a CSV file. Throws std::runtime_error when it cannot be read or is empty.
CsvTable ReadCsv(const std::filesystem::path& path);

/// Whole file as a string. Throws std::runtime_error naming the path.
std::string ReadTextFile(const std::filesystem::path& path);
/// Whole file as a string, or "" when there is no such file (a log not written yet).
std::string ReadTextFileIfExists(const std::filesystem::path& path);

/// A training folder's training_episodes.csv, or, as a committed model folder keeps it,
/// training_episodes.csv.gz decompressed; "" when neither exists. Throws std::runtime_error
/// for a damaged .gz.
std::string ReadTrainingEpisodes(const std::filesystem::path& folder);

}  // namespace crowdsim::render

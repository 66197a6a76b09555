// Reading a `crowdsim-bench run` output folder for the report: manifest fields and table.csv.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace crowdsim::render {

/// The string value of a top-level key of a JSON object text (manifest.json), or nullopt.
std::optional<std::string> JsonStringField(const std::string& json, const std::string& key);

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

}  // namespace crowdsim::render

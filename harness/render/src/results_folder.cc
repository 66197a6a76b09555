#include "crowdsim/render/results_folder.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "crowdsim/bench/csv.h"

namespace crowdsim::render {

size_t CsvTable::Column(const std::string& name) const {
  for (size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  std::string cols;
  for (const auto& h : header) cols += (cols.empty() ? "" : ", ") + h;
  throw std::runtime_error("column '" + name + "' is missing (columns: " + cols + ")");
}

CsvTable ReadCsv(const std::filesystem::path& path) {
  std::istringstream in(ReadTextFile(path));
  CsvTable t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r") continue;
    if (t.header.empty()) {
      t.header = SplitCsvLine(line);
    } else {
      t.rows.push_back(SplitCsvLine(line));
    }
  }
  if (t.header.empty()) throw std::runtime_error(path.string() + " is empty");
  return t;
}

std::string ReadTextFileIfExists(const std::filesystem::path& path) {
  return std::filesystem::exists(path) ? ReadTextFile(path) : std::string();
}

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace crowdsim::render

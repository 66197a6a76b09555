#include "crowdsim/render/results_folder.h"

#include <zlib.h>

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

std::string ReadTrainingEpisodes(const std::filesystem::path& folder) {
  const auto plain = folder / "training_episodes.csv";
  if (std::filesystem::exists(plain)) return ReadTextFile(plain);
  const auto packed = folder / "training_episodes.csv.gz";
  if (!std::filesystem::exists(packed)) return "";
  gzFile in = gzopen(packed.c_str(), "rb");
  if (in == nullptr) throw std::runtime_error("cannot read " + packed.string());
  std::string text;
  char buffer[1 << 16];
  int n = 0;
  while ((n = gzread(in, buffer, sizeof(buffer))) > 0) text.append(buffer, static_cast<size_t>(n));
  int error = Z_OK;
  const std::string what = gzerror(in, &error);  // a copy: gzclose frees zlib's text
  gzclose(in);
  if (n < 0 || (error != Z_OK && error != Z_STREAM_END)) {
    throw std::runtime_error(packed.string() + " is damaged: " + what);
  }
  return text;
}

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace crowdsim::render

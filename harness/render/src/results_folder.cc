#include "crowdsim/render/results_folder.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "crowdsim/csv.h"

namespace crowdsim::render {

std::optional<std::string> JsonStringField(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\"";
  size_t pos = json.find(quoted);
  if (pos == std::string::npos) return std::nullopt;
  pos = json.find_first_not_of(" \t\r\n", pos + quoted.size());
  if (pos == std::string::npos || json[pos] != ':') return std::nullopt;
  pos = json.find_first_not_of(" \t\r\n", pos + 1);
  if (pos == std::string::npos || json[pos] != '"') return std::nullopt;
  std::string out;
  for (size_t i = pos + 1; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '"') return out;
    if (c != '\\' || i + 1 >= json.size()) {
      out += c;
      continue;
    }
    const char e = json[++i];
    switch (e) {
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'u': {
        // Our manifests escape only control characters this way.
        if (i + 4 >= json.size()) return std::nullopt;
        const unsigned v = static_cast<unsigned>(std::stoul(json.substr(i + 1, 4), nullptr, 16));
        if (v < 0x80) out += static_cast<char>(v);
        i += 4;
        break;
      }
      default:
        out += e;
    }
  }
  return std::nullopt;
}

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

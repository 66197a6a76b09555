#include "yaml_document.h"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <system_error>

#include "crowdsim/data_root.h"

namespace crowdsim::yaml {
namespace fs = std::filesystem;

namespace {

// Most values a document may hold, aliases expanded (ten times our largest world set): nested
// aliases can stand for billions.
constexpr std::size_t kMaxNodes = 1'000'000;

// Largest file read (over 100 times our largest world set): yaml-cpp needs ~70 bytes per byte read.
constexpr std::uintmax_t kMaxFileBytes = 16u << 20;

// Whether the file names an anchor (&name) that aliases (*name) may repeat.
bool HasAnchors(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  char before = '\n';
  for (char c; in.get(c); before = c) {
    if (c == '&' && (before == ' ' || before == '\n' || before == '\t' || before == '[' ||
                     before == '{' || before == ',' || before == ':' || before == '-')) {
      return true;
    }
  }
  return false;
}

// One walk before any reader: refuses duplicate keys, self-containing aliases and expansions past
// kMaxNodes. `open`: the current path.
struct Walk {
  Walk(const std::string& file, std::vector<Problem>* errors) : file(file), errors(errors) {}

  const std::string& file;
  std::vector<Problem>* errors;
  std::vector<YAML::Node> open;
  std::size_t visited = 0;
  bool stopped = false;

  void Error(const YAML::Node& at, const std::string& message) {
    const YAML::Mark m = at.Mark();
    errors->push_back({file, m.line + 1, m.column + 1, message});
  }

  void Visit(const YAML::Node& n) {
    if (stopped) return;
    if (++visited > kMaxNodes) {
      Error(n, "the document holds more than " + std::to_string(kMaxNodes) + " values" +
                   (HasAnchors(file) ? " once its aliases (*name) are expanded; write fewer "
                                       "aliases of aliases"
                                     : ", ten times the largest committed world set; split it "
                                       "into several files"));
      stopped = true;
      return;
    }
    if (!n.IsMap() && !n.IsSequence()) return;
    for (const YAML::Node& outer : open) {
      if (outer.is(n)) {
        Error(n,
              "this map or list contains an alias (*name) of itself, so it never ends; "
              "remove the alias");
        stopped = true;
        return;
      }
    }
    open.push_back(n);
    if (n.IsMap()) {
      std::map<std::string, YAML::Mark> seen;
      for (const auto& kv : n) {
        if (kv.first.IsScalar()) {
          const auto [first, inserted] = seen.emplace(kv.first.Scalar(), kv.first.Mark());
          if (!inserted) {
            Error(kv.first, "key '" + kv.first.Scalar() +
                                "' is given twice in this map (first at line " +
                                std::to_string(first->second.line + 1) +
                                "); only one value would count: remove or rename one");
          }
        }
        Visit(kv.first);
        Visit(kv.second);
      }
    } else {
      for (const auto& item : n) Visit(item);
    }
    open.pop_back();
  }
};

// The refused file's lines up to the error's (0-based `last`), BOM removed (yaml-cpp gives it no
// column).
std::vector<std::string> LinesUpTo(const fs::path& file, int last) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; static_cast<int>(lines.size()) <= last && std::getline(in, line);) {
    if (lines.empty() && line.starts_with("\xef\xbb\xbf")) line.erase(0, 3);
    lines.push_back(std::move(line));
  }
  return lines;
}

// yaml-cpp names a tab only at a top-level key: name one in the indentation of the error's line or
// the line before.
std::string TabHint(const std::vector<std::string>& lines, int zero_based_line) {
  for (int n = std::max(0, zero_based_line - 1); n < static_cast<int>(lines.size()); ++n) {
    const std::string& line = lines[static_cast<std::size_t>(n)];
    const std::size_t indent_end = line.find_first_not_of(" \t");
    if (line.substr(0, indent_end).find('\t') != std::string::npos) {
      return " (line " + std::to_string(n + 1) +
             " is indented with a tab: YAML indents with spaces only)";
    }
  }
  return "";
}

// UTF-16 and UTF-32 text: a byte order mark, or a NUL in the first two bytes of `start`.
bool WideText(const std::string& start) {
  return start.starts_with("\xff\xfe") || start.starts_with("\xfe\xff") ||
         start.substr(0, 2).find('\0') != std::string::npos;
}

// yaml-cpp reports an unclosed '{' or '[' late: name the innermost one opened before the error
// (outside quotes and comments).
std::string UnclosedBracketHint(const fs::path& file, const std::vector<std::string>& lines,
                                const std::string& message, const YAML::Mark& at) {
  const bool map = message.find("end of map flow not found") != std::string::npos;
  if (!map && message.find("end of sequence flow not found") == std::string::npos) return "";
  struct Open {
    char bracket;
    int line, column;  // 1-based
  };
  std::vector<Open> open;
  // Columns are UTF-8 bytes, as yaml-cpp counts; in UTF-16 or UTF-32 bytes are not characters, so
  // no hint.
  std::ifstream in(file, std::ios::binary);
  char head[2] = {};
  in.read(head, sizeof(head));
  if (WideText(std::string(head, static_cast<std::size_t>(in.gcount())))) return "";
  char quote = 0;
  for (int n = 0; n < static_cast<int>(lines.size()) && n <= at.line; ++n) {
    const std::string& line = lines[static_cast<std::size_t>(n)];
    const std::size_t end =
        n == at.line ? std::min<std::size_t>(line.size(), at.column) : line.size();
    for (std::size_t i = 0; i < end; ++i) {
      const char c = line[i];
      const char before = i == 0 ? ' ' : line[i - 1];
      if (quote != 0) {
        // An escaped character in "...", or a quote written twice in '...' ('it''s').
        if ((c == '\\' && quote == '"') ||
            (c == '\'' && quote == '\'' && i + 1 < end && line[i + 1] == '\''))
          ++i;
        else if (c == quote)
          quote = 0;
        continue;
      }
      if (c == '#' && (before == ' ' || before == '\t' || i == 0)) break;
      // A quote opens a string only where a value starts, not inside a plain scalar.
      const std::size_t last = i == 0 ? std::string::npos : line.find_last_not_of(" \t", i - 1);
      const bool starts_value =
          last == std::string::npos || std::string(",[{:-?").find(line[last]) != std::string::npos;
      if ((c == '"' || c == '\'') && starts_value) {
        quote = c;
      } else if (c == '{' || c == '[') {
        open.push_back({c, n + 1, static_cast<int>(i) + 1});
      } else if ((c == '}' || c == ']') && !open.empty()) {
        open.pop_back();
      }
    }
  }
  const char wanted = map ? '{' : '[';
  for (auto it = open.rbegin(); it != open.rend(); ++it) {
    if (it->bracket != wanted) continue;
    return std::string(" (the '") + wanted + "' at line " + std::to_string(it->line) + ", column " +
           std::to_string(it->column) + " is not closed: end it with '" + (map ? '}' : ']') + "')";
  }
  return "";
}

// yaml-cpp reports a missing ':' or an over-indented key a line or two late: name the likely line.
std::string MissingColonHint(const std::vector<std::string>& lines, const std::string& message,
                             int error_line) {
  const bool illegal_value = message.find("illegal map value") != std::string::npos;
  if (!illegal_value && message.find("end of map not found") == std::string::npos) return "";
  const auto content = [](const std::string& text) {
    // The text before a comment, without its indentation and trailing blanks ("" when none).
    std::string s = text.substr(0, text.find(" #"));
    if (s.starts_with("#")) s.clear();
    const std::size_t first = s.find_first_not_of(" \t");
    const std::size_t last = s.find_last_not_of(" \t\r");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
  };
  const auto indent = [](const std::string& text) { return text.find_first_not_of(' '); };
  std::string before, at;
  int before_line = -1;
  for (int n = 0; n < static_cast<int>(lines.size()) && n <= error_line; ++n) {
    const std::string& line = lines[static_cast<std::size_t>(n)];
    if (n == error_line) {
      at = line;
    } else if (!content(line).empty()) {
      before = line;
      before_line = n;
    }
  }
  // The suspect: the line before the error's for an illegal value, else the error's own.
  const std::string suspect = content(illegal_value ? before : at);
  const int suspect_line = illegal_value ? before_line : error_line;
  if (suspect.empty() || suspect.starts_with("-") || suspect.find_first_of("\"'{[") == 0) {
    return "";
  }
  const std::string named = " (line " + std::to_string(suspect_line + 1) + ", '" + suspect + "', ";
  const std::size_t colon = suspect.find(':');
  if (colon == std::string::npos) return named + "has no ':' after its key: write 'key: value')";
  if (illegal_value && colon + 1 < suspect.size() && indent(at) != std::string::npos &&
      indent(at) > indent(before)) {
    return named + "already has its value, and line " + std::to_string(error_line + 1) +
           " is indented deeper: indent its key as the keys beside it)";
  }
  return "";
}

// What a non-text file is (e.g. a PNG given as a suite), for the message; "" for text.
std::string BinaryKind(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[4096];
  in.read(head, sizeof(head));
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  if (start.starts_with("\x89PNG")) return "a PNG image";
  if (!WideText(start) && start.find('\0') != std::string::npos) return "binary data";
  return "";
}

}  // namespace

std::string Problem::Format() const {
  std::string out = file;  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on sums
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
    out += ':';
    out += std::to_string(column);
  }
  out += ": ";
  out += message;
  return out;
}

YAML::Node LoadDocument(const fs::path& file, const std::string& what,
                        std::vector<Problem>* errors) {
  std::error_code ec;
  // Standard input and pipes are refused: a spec is read more than once, and a pipe gives its text
  // to the first read only.
  const std::string from_a_pipe =
      "; a " + what + " is read more than once: write it to a file and give that file";
  if (file == "-") {
    errors->push_back({file.string(), 0, 0, "standard input cannot be read" + from_a_pipe});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (!fs::exists(file, ec)) {
    // A relative path the data folder holds (e.g. `suites/quick.yaml` outside a source tree):
    // suggest it.
    const fs::path shipped = DataRoot() / file;
    const bool suggest = file.is_relative() && fs::is_regular_file(shipped, ec);
    errors->push_back(
        {file.string(), 0, 0,
         what + " does not exist" +
             (suggest ? "; did you mean " + shipped.string() + " (the data folder's)?" : "")});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (fs::is_directory(file, ec)) {
    errors->push_back(
        {file.string(), 0, 0, "is a folder; give the " + what + " (a .yaml file) in it"});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (!fs::is_regular_file(file, ec)) {
    errors->push_back(
        {file.string(), 0, 0, "is not a regular file (a pipe or a device)" + from_a_pipe});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (const std::string binary = BinaryKind(file); !binary.empty()) {
    errors->push_back({file.string(), 0, 0, "is " + binary + ", not a " + what + " (YAML text)"});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (const std::uintmax_t bytes = fs::file_size(file, ec); !ec && bytes > kMaxFileBytes) {
    errors->push_back({file.string(), 0, 0,
                       "is " + std::to_string(bytes >> 20) + " MB; a " + what + " may be at most " +
                           std::to_string(kMaxFileBytes >> 20) +
                           " MB (over 100 times the largest shipped one): split it into several "
                           "files"});
    return YAML::Node(YAML::NodeType::Null);
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::DeepRecursion& e) {
    errors->push_back({file.string(), e.mark.line + 1, e.mark.column + 1,
                       "maps and lists are nested more than " + std::to_string(e.depth()) +
                           " levels deep here; no " + what +
                           " needs more than a few: close the brackets or flatten it"});
    return YAML::Node(YAML::NodeType::Null);
  } catch (const YAML::BadFile&) {
    errors->push_back({file.string(), 0, 0, "cannot read the " + what + " (permissions?)"});
    return YAML::Node(YAML::NodeType::Null);
  } catch (const YAML::Exception& e) {
    const std::vector<std::string> lines = LinesUpTo(file, e.mark.line);
    // A tab said outright; else the line that most likely holds the mistake.
    std::string hint = e.msg.find("tab") == std::string::npos ? TabHint(lines, e.mark.line) : "";
    if (hint.empty()) hint = MissingColonHint(lines, e.msg, e.mark.line);
    errors->push_back(
        {file.string(), e.mark.line + 1, e.mark.column + 1,
         "not valid YAML: " + e.msg + UnclosedBracketHint(file, lines, e.msg, e.mark) + hint});
    return YAML::Node(YAML::NodeType::Null);
  }
  const std::size_t before = errors->size();
  const std::string name = file.string();
  Walk(name, errors).Visit(root);
  return errors->size() == before ? root : YAML::Node(YAML::NodeType::Null);
}

}  // namespace crowdsim::yaml

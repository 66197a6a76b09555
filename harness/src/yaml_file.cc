#include "yaml_file.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <system_error>

#include "crowdsim/bench/results.h"

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

namespace {

// The most values a document may hold with its aliases expanded: ten times our largest world
// set; more is a document whose aliases nest aliases (a few lines can stand for billions).
constexpr std::size_t kMaxNodes = 1'000'000;

// One walk over the document before any reader sees it: duplicate keys, and the two shapes of
// alias (`*name`) that no reader could walk: a map or list that contains itself, and an
// expansion beyond kMaxNodes. `open` holds the maps and lists being walked (the current path).
struct Walk {
  Walk(const std::string& file, std::vector<SuiteError>* errors) : file(file), errors(errors) {}

  const std::string& file;
  std::vector<SuiteError>* errors;
  std::vector<YAML::Node> open;
  std::size_t visited = 0;
  bool stopped = false;

  void Error(const YAML::Node& at, const std::string& message) {
    const YAML::Mark m = at.Mark();
    errors->push_back({file, m.line + 1, m.column + 1, "", message});
  }

  void Visit(const YAML::Node& n) {
    if (stopped) return;
    if (++visited > kMaxNodes) {
      Error(n, "the document holds more than " + std::to_string(kMaxNodes) +
                   " values once its aliases (*name) are expanded; write fewer aliases of aliases");
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

// yaml-cpp names a tab in an indentation "illegal tab" only at a top-level key; elsewhere it
// reports what the tab broke ("illegal map value", "illegal block entry"). A tab in the
// indentation of the error's line or the one before it is said outright.
std::string TabHint(const fs::path& file, int zero_based_line) {
  std::ifstream in(file);
  std::string line;
  for (int n = 0; std::getline(in, line) && n <= zero_based_line; ++n) {
    if (n < zero_based_line - 1) continue;
    const std::size_t indent_end = line.find_first_not_of(" \t");
    if (line.substr(0, indent_end).find('\t') != std::string::npos) {
      return " (line " + std::to_string(n + 1) +
             " is indented with a tab: YAML indents with spaces only)";
    }
  }
  return "";
}

// yaml-cpp says "end of map flow not found" (or "sequence flow") where it gave up, often the
// line after the one whose '{' (or '[') lacks its closing bracket. The innermost such bracket
// opened before the error (outside quotes and comments) is said, with its line and column.
std::string UnclosedBracketHint(const fs::path& file, const std::string& message,
                                const YAML::Mark& at) {
  const bool map = message.find("end of map flow not found") != std::string::npos;
  if (!map && message.find("end of sequence flow not found") == std::string::npos) return "";
  struct Open {
    char bracket;
    int line, column;  // 1-based
  };
  std::vector<Open> open;
  std::ifstream in(file);
  std::string line;
  char quote = 0;
  for (int n = 0; std::getline(in, line) && n <= at.line; ++n) {
    const std::size_t end =
        n == at.line ? std::min<std::size_t>(line.size(), at.column) : line.size();
    for (std::size_t i = 0; i < end; ++i) {
      const char c = line[i];
      const char before = i == 0 ? ' ' : line[i - 1];
      if (quote != 0) {
        if (c == '\\' && quote == '"')
          ++i;
        else if (c == quote)
          quote = 0;
        continue;
      }
      if (c == '#' && (before == ' ' || before == '\t' || i == 0)) break;
      const bool starts_value = i == 0 || std::string(" \t,[{:-").find(before) != std::string::npos;
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

// What a file that is no text is (a PNG floor plan given as the suite): its bytes read as YAML
// gave "unknown escape character" and printed a stray byte. "" for a text file.
std::string BinaryKind(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[4096];
  in.read(head, sizeof(head));
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  if (start.starts_with("\x89PNG")) return "a PNG image";
  // UTF-16 and UTF-32 text holds NUL bytes: YAML tells it by a byte order mark, or by a NUL
  // among its first two bytes.
  const bool wide = start.starts_with("\xff\xfe") || start.starts_with("\xfe\xff") ||
                    start.substr(0, 2).find('\0') != std::string::npos;
  if (!wide && start.find('\0') != std::string::npos) return "binary data";
  return "";
}

}  // namespace

YAML::Node LoadYamlFile(const fs::path& file, const std::string& what,
                        std::vector<SuiteError>* errors) {
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    errors->push_back({file.string(), 0, 0, "", what + " does not exist"});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (fs::is_directory(file, ec)) {
    // The output folder of a run (commands that replay a run take the suite it ran).
    const std::string ran = fs::exists(file / "manifest.json", ec)
                                ? ReadManifestField(file / "manifest.json", "suite_file")
                                : std::string();
    errors->push_back({file.string(), 0, 0, "",
                       ran.empty() ? "is a folder; give the " + what + " (a .yaml file) in it"
                                   : "is the output folder of a run; give the " + what +
                                         " it ran, which its manifest.json names: " + ran});
    return YAML::Node(YAML::NodeType::Null);
  }
  if (const std::string binary = BinaryKind(file); !binary.empty()) {
    errors->push_back(
        {file.string(), 0, 0, "", "is " + binary + ", not a " + what + " (YAML text)"});
    return YAML::Node(YAML::NodeType::Null);
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    errors->push_back({file.string(), 0, 0, "", "cannot read the " + what + " (permissions?)"});
    return YAML::Node(YAML::NodeType::Null);
  } catch (const YAML::Exception& e) {
    errors->push_back(
        {file.string(), e.mark.line + 1, e.mark.column + 1, "",
         "not valid YAML: " + e.msg + UnclosedBracketHint(file, e.msg, e.mark) +
             (e.msg.find("tab") == std::string::npos ? TabHint(file, e.mark.line) : "")});
    return YAML::Node(YAML::NodeType::Null);
  }
  const std::size_t before = errors->size();
  const std::string name = file.string();
  Walk(name, errors).Visit(root);
  return errors->size() == before ? root : YAML::Node(YAML::NodeType::Null);
}

}  // namespace crowdsim::suite_internal

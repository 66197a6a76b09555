#include "spec/yaml_edit.h"

#include <algorithm>
#include <cctype>
#include <optional>

namespace crowdsim::suite_internal {

namespace {

/// Whether the key path `inner` is `outer` or lies under it ("humans.count" in "humans").
bool PathContains(const std::string& outer, const std::string& inner) {
  return inner == outer || inner.starts_with(outer + ".") || inner.starts_with(outer + "[");
}

/// One step of a key path: a map key, then list selections ([2], [orca]).
struct Segment {
  std::string key;
  std::vector<std::string> selectors;
};

std::optional<std::vector<Segment>> ParsePath(const std::string& path, std::string* why) {
  std::vector<Segment> segments;
  std::size_t i = 0;
  while (i <= path.size()) {
    Segment s;
    while (i < path.size() && path[i] != '.' && path[i] != '[') s.key += path[i++];
    if (s.key.empty()) {
      *why = "an empty key in '" + path +
             "' (keys are joined by '.', list items chosen by [N] or [name])";
      return std::nullopt;
    }
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) {
        *why = "an unclosed or empty [...] in '" + path + "'";
        return std::nullopt;
      }
      s.selectors.push_back(path.substr(i + 1, close - i - 1));
      i = close + 1;
    }
    segments.push_back(std::move(s));
    if (i == path.size()) break;
    if (path[i] != '.') {
      *why = "'" + path.substr(i) + "' in '" + path + "': after [...] comes '.' or the end";
      return std::nullopt;
    }
    ++i;
  }
  return segments;
}

/// An item's name for [name]: its label, else policy or type, else its text.
std::string ItemName(const YAML::Node& item) {
  if (item.IsScalar()) return item.Scalar();
  if (item.IsMap()) {
    for (const char* key : {"label", "policy", "type"}) {
      const YAML::Node v = item[key];
      if (v.IsDefined() && v.IsScalar()) return v.Scalar();
    }
  }
  return "";
}

bool IsIndex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c));
  });
}

/// `map` with `key` set to `value`, as a new map sharing the other children. Never in place:
/// yaml-cpp nodes are shared references, and sweep rows share unchanged parts.
YAML::Node WithKey(const YAML::Node& map, const std::string& key, const YAML::Node& value) {
  YAML::Node copy(YAML::NodeType::Map);
  bool replaced = false;
  if (map.IsMap()) {
    for (const auto& kv : map) {
      if (kv.first.IsScalar() && kv.first.Scalar() == key) {
        copy.force_insert(kv.first, value);
        replaced = true;
      } else {
        copy.force_insert(kv.first, kv.second);
      }
    }
  }
  if (!replaced) copy.force_insert(key, value);
  return copy;
}

/// `list` with item `index` replaced by `value`, as a new list.
YAML::Node WithItem(const YAML::Node& list, std::size_t index, const YAML::Node& value) {
  YAML::Node copy(YAML::NodeType::Sequence);
  for (std::size_t j = 0; j < list.size(); ++j) copy.push_back(j == index ? value : list[j]);
  return copy;
}

/// The key path as readers write it (rows[1].humans.count), or "" for a [name] selector.
std::string ReaderPath(const std::vector<Segment>& segments) {
  std::string out;
  for (const Segment& s : segments) {
    out += (out.empty() ? "" : ".") + s.key;
    for (const std::string& sel : s.selectors) {
      if (!IsIndex(sel)) return "";
      out += "[" + sel + "]";
    }
  }
  return out;
}

/// `node` with segments[i..] (from selector k) set to `value`, copying containers along the path;
/// `problem`: "" or what went wrong.
YAML::Node SetFrom(const YAML::Node& node, const std::vector<Segment>& segments, std::size_t i,
                   std::size_t k, const YAML::Node& value, std::string* resolved,
                   std::string* problem) {
  const Segment& s = segments[i];
  if (k == 0) {
    // Enter the map key of segment i.
    const std::string at = resolved->empty() ? std::string("the top level") : "'" + *resolved + "'";
    if (!node.IsMap() && !node.IsNull() && node.IsDefined()) {
      *problem = at + " is not a map, so it has no key '" + s.key + "'";
      return node;
    }
    *resolved += (resolved->empty() ? "" : ".") + s.key;
    const YAML::Node child = node.IsMap() ? node[s.key] : YAML::Node();
    if (s.selectors.empty()) {
      if (i + 1 == segments.size()) return WithKey(node, s.key, value);
      const YAML::Node inner = child.IsDefined() ? child : YAML::Node(YAML::NodeType::Map);
      return WithKey(node, s.key, SetFrom(inner, segments, i + 1, 0, value, resolved, problem));
    }
    if (!child.IsDefined()) {
      *problem = "there is no list '" + *resolved + "'";
      return node;
    }
    return WithKey(node, s.key, SetFrom(child, segments, i, 1, value, resolved, problem));
  }
  // Selector k-1 of segment i picks an item of the list `node`.
  if (!node.IsSequence()) {
    *problem = "'" + *resolved + "' is not a list";
    return node;
  }
  const std::string& sel = s.selectors[k - 1];
  std::optional<std::size_t> found;
  std::vector<std::string> names;
  for (std::size_t j = 0; j < node.size(); ++j) {
    names.push_back(ItemName(node[j]));
    // An index too long for a number is no item (std::stoul would throw).
    if (!found && (IsIndex(sel) ? sel.size() <= 9 && std::stoul(sel) == j : names.back() == sel))
      found = j;
  }
  if (!found) {
    std::string valid;
    for (std::size_t j = 0; j < names.size(); ++j) {
      valid += (j ? ", " : "") + std::to_string(j) + (names[j].empty() ? "" : " " + names[j]);
    }
    *problem = "'" + *resolved + "' has no item [" + sel + "] (items: " + valid + ")";
    // A sweep label (crowd/humans.count=2) exists only after sweeping: hint it for rows with a
    // sweep.
    const std::string swept = sel.substr(0, sel.find('/'));
    const auto row = std::find(names.begin(), names.end(), swept);
    if (swept.size() < sel.size() && row != names.end()) {
      const YAML::Node item = node[static_cast<std::size_t>(row - names.begin())];
      if (item.IsMap() && item["sweep"]) {
        *problem += "; the rows of a sweep are set through the row that has it: " + *resolved +
                    "[" + swept + "]";
      }
    }
    return node;
  }
  *resolved += "[" + std::to_string(*found) + "]";
  const bool last_selector = k == s.selectors.size();
  if (last_selector && i + 1 == segments.size()) return WithItem(node, *found, value);
  YAML::Node item = node[*found];
  if (last_selector && item.IsScalar()) {
    // An item given by name alone (sensor `person`) takes keys in its map form {type: person}.
    YAML::Node as_map(YAML::NodeType::Map);
    as_map.force_insert("type", item);
    item.reset(as_map);  // rebinds this handle; `=` would overwrite the shared node itself
  }
  const YAML::Node changed = last_selector
                                 ? SetFrom(item, segments, i + 1, 0, value, resolved, problem)
                                 : SetFrom(item, segments, i, k + 1, value, resolved, problem);
  return WithItem(node, *found, changed);
}

/// Sets the value at `segments` in `root` (rebinding it to the edited copy); returns "" or what
/// went wrong. `resolved_out`: the path by index.
std::string SetPath(YAML::Node& root, const std::vector<Segment>& segments, const YAML::Node& value,
                    std::string* resolved_out = nullptr) {
  std::string resolved, problem;
  YAML::Node edited = SetFrom(root, segments, 0, 0, value, &resolved, &problem);
  if (problem.empty()) root.reset(edited);
  if (resolved_out != nullptr) *resolved_out = problem.empty() ? resolved : "";
  return problem;
}

/// Where an override's value begins: the first '=' outside a [...] selector, else the first '=';
/// npos when none.
std::size_t ValueSign(const std::string& text) {
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '[') ++depth;
    if (text[i] == ']' && depth > 0) --depth;
    if (text[i] == '=' && depth == 0) return i;
  }
  return text.find('=');
}

}  // namespace

void ApplyOverrides(YAML::Node& root, const std::vector<std::string>& overrides,
                    std::vector<SuiteError>* errors, std::vector<std::string>* resolved) {
  if (resolved != nullptr) resolved->assign(overrides.size(), "");
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    const std::string& text = overrides[i];
    auto fail = [&](const std::string& message) {
      errors->push_back({"--set " + text, 0, 0, "", message});
    };
    const std::size_t eq = ValueSign(text);
    if (eq == std::string::npos || eq == 0) {
      fail("give key.path=value, e.g. humans.count=10 or rows[orca].params.safety_space=0.1");
      continue;
    }
    std::string why;
    const auto segments = ParsePath(text.substr(0, eq), &why);
    if (!segments) {
      fail(why);
      continue;
    }
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      fail("the value is not valid YAML: " + e.msg);
      continue;
    }
    if (!value.IsDefined() || value.IsNull()) {
      fail("no value after '=' (to drop a key, edit the file)");
      continue;
    }
    const std::string problem =
        SetPath(root, *segments, value, resolved != nullptr ? &(*resolved)[i] : nullptr);
    if (!problem.empty()) fail(problem);
  }
}

void LocateOverrideErrors(const std::vector<std::string>& overrides,
                          std::vector<SuiteError>* errors, const std::vector<std::string>& resolved,
                          const std::vector<std::vector<std::size_t>>& row_map) {
  auto place = [](SuiteError& e, const std::string& text) {
    e.file = "--set " + text;
    e.line = 0;
    e.column = 0;
  };
  std::vector<bool> placed(errors->size(), false);
  // First by each override's resolved path: errors at or under it, and placeless ones about keys it
  // created.
  for (std::size_t i = 0; i < overrides.size() && i < resolved.size(); ++i) {
    if (resolved[i].empty()) continue;
    std::vector<std::string> paths = {resolved[i]};
    if (resolved[i].starts_with("rows[") && !row_map.empty()) {
      const std::size_t close = resolved[i].find(']');
      const std::size_t row = std::stoul(resolved[i].substr(5, close - 5));
      if (row < row_map.size() && !row_map[row].empty()) {  // empty: its sweep failed
        paths.clear();
        for (std::size_t now : row_map[row]) {
          paths.push_back("rows[" + std::to_string(now) + resolved[i].substr(close));
        }
      }
    }
    for (std::size_t k = 0; k < errors->size(); ++k) {
      SuiteError& e = (*errors)[k];
      if (e.line > 1 || e.key_path.empty()) continue;
      for (const std::string& path : paths) {
        if (PathContains(path, e.key_path) || (e.line == 0 && PathContains(e.key_path, path))) {
          place(e, overrides[i]);
          placed[k] = true;
          break;
        }
      }
    }
  }
  // Then by the keys as written: errors under the override's path, or ending in its last key.
  for (const std::string& text : overrides) {
    const std::size_t eq = ValueSign(text);
    if (eq == std::string::npos) continue;
    std::string why;
    const auto segments = ParsePath(text.substr(0, eq), &why);
    if (!segments) continue;
    const std::string exact = ReaderPath(*segments);
    const std::string& tail = segments->back().key;
    for (std::size_t k = 0; k < errors->size(); ++k) {
      SuiteError& e = (*errors)[k];
      if (placed[k] || e.line > 1) continue;
      const bool under = (!exact.empty() && PathContains(exact, e.key_path)) ||
                         (segments->back().selectors.empty() &&
                          (e.key_path == tail || e.key_path.ends_with("." + tail)));
      if (under) place(e, text);
    }
  }
}

namespace {

std::string ValueText(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << v;
  return out.c_str();
}

}  // namespace

void ExpandSweeps(YAML::Node& root, const std::string& file, std::vector<SuiteError>* errors,
                  std::vector<SweptRow>* swept, std::vector<std::vector<std::size_t>>* row_map) {
  YAML::Node rows = root["rows"];
  if (!rows.IsDefined() || !rows.IsSequence()) return;
  auto error = [&](const YAML::Node& at, const std::string& path, const std::string& message) {
    const YAML::Mark m = at.Mark();
    errors->push_back(
        {file, m.line >= 0 ? m.line + 1 : 0, m.line >= 0 ? m.column + 1 : 0, path, message});
  };
  YAML::Node expanded(YAML::NodeType::Sequence);
  bool any = false;
  if (row_map != nullptr) row_map->assign(rows.size(), {});
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const YAML::Node row = rows[r];
    const YAML::Node sweep = row.IsMap() ? row["sweep"] : YAML::Node(YAML::NodeType::Undefined);
    if (!sweep.IsDefined()) {
      if (row_map != nullptr) (*row_map)[r].push_back(expanded.size());
      expanded.push_back(row);
      continue;
    }
    any = true;
    const std::string path = "rows[" + std::to_string(r) + "].sweep";
    if (!sweep.IsMap() || sweep.size() == 0) {
      error(sweep, path, "must map row keys to lists of values, e.g. {humans.count: [5, 10, 20]}");
      continue;
    }
    struct Axis {
      std::string key;
      std::vector<Segment> segments;
      YAML::Node values;
      YAML::Mark mark;
    };
    std::vector<Axis> axes;
    std::size_t combinations = 1;
    bool ok = true;
    for (const auto& kv : sweep) {
      Axis axis{kv.first.Scalar(), {}, kv.second, kv.first.Mark()};
      std::string why;
      auto segments = ParsePath(axis.key, &why);
      if (!segments) {
        error(kv.first, path, why);
        ok = false;
        continue;
      }
      if (axis.key == "sweep" || axis.key == "label" || segments->front().key == "sweep") {
        error(kv.first, path + "." + axis.key, "cannot be swept");
        ok = false;
        continue;
      }
      if (!kv.second.IsSequence() || kv.second.size() == 0) {
        error(kv.second, path + "." + axis.key,
              "must be a non-empty list of values, e.g. [5, 10, 20]");
        ok = false;
        continue;
      }
      axis.segments = std::move(*segments);
      combinations *= kv.second.size();
      axes.push_back(std::move(axis));
    }
    // A nested axis (humans and humans.count) would be overwritten while labels name its values.
    for (std::size_t a = 0; ok && a < axes.size(); ++a) {
      for (std::size_t b = 0; b < axes.size(); ++b) {
        if (a == b || !PathContains(axes[a].key, axes[b].key)) continue;
        const YAML::Mark m = axes[b].mark;
        errors->push_back({file, m.line >= 0 ? m.line + 1 : 0, m.line >= 0 ? m.column + 1 : 0,
                           path + "." + axes[b].key,
                           "lies inside the swept key '" + axes[a].key +
                               "', which replaces it in every row: sweep one of the two"});
        ok = false;
        break;
      }
    }
    constexpr std::size_t kMaxRows = 10000;
    if (ok && combinations > kMaxRows) {
      error(sweep, path,
            std::to_string(combinations) + " combinations; at most " + std::to_string(kMaxRows));
      ok = false;
    }
    if (!ok) continue;
    const YAML::Node label_node = row["label"].IsDefined() ? row["label"] : row["policy"];
    const std::string base =
        label_node.IsDefined() && label_node.IsScalar() ? label_node.Scalar() : "row";
    for (std::size_t c = 0; c < combinations; ++c) {
      YAML::Node copy = WithKey(row, "sweep", YAML::Node());
      copy.remove("sweep");
      std::string label = base;
      std::size_t rest = c;
      std::vector<std::size_t> pick(axes.size());
      for (std::size_t a = axes.size(); a-- > 0;) {
        pick[a] = rest % axes[a].values.size();
        rest /= axes[a].values.size();
      }
      YAML::Node info = copy["info"].IsDefined() ? copy["info"] : YAML::Node(YAML::NodeType::Map);
      for (std::size_t a = 0; a < axes.size(); ++a) {
        const Axis& axis = axes[a];
        const YAML::Node value = axis.values[pick[a]];
        // A row inherits the suite's world and the robot's sensors: give it its own first.
        const std::string& head = axis.segments.front().key;
        if (head == "world" && !copy["world"].IsDefined() && root["world"].IsDefined()) {
          copy.reset(WithKey(copy, "world", root["world"]));
        }
        if (head == "sensors" && !copy["sensors"].IsDefined() && root["robot"].IsDefined() &&
            root["robot"]["sensors"].IsDefined()) {
          copy.reset(WithKey(copy, "sensors", root["robot"]["sensors"]));
        }
        if (head == "kinematics" && !copy["kinematics"].IsDefined() && root["robot"].IsDefined() &&
            root["robot"]["kinematics"].IsDefined()) {
          copy.reset(WithKey(copy, "kinematics", root["robot"]["kinematics"]));
        }
        const std::string problem = SetPath(copy, axis.segments, value);
        if (!problem.empty()) {
          error(value, path + "." + axis.key, problem);
          ok = false;
          break;
        }
        label += "/" + axis.key + "=" + ValueText(value);
        info.reset(WithKey(info, axis.key, YAML::Node(ValueText(value))));
      }
      copy.reset(WithKey(copy, "info", info));
      if (!ok) break;
      copy.reset(WithKey(copy, "label", YAML::Node(label)));
      if (swept != nullptr) {
        SweptRow made{expanded.size(), r, {}};
        for (const Axis& axis : axes) {
          made.keys.push_back({axis.key, axis.mark.line >= 0 ? axis.mark.line + 1 : 0,
                               axis.mark.line >= 0 ? axis.mark.column + 1 : 0});
        }
        swept->push_back(std::move(made));
      }
      if (row_map != nullptr) (*row_map)[r].push_back(expanded.size());
      expanded.push_back(copy);
    }
  }
  if (any) root.reset(WithKey(root, "rows", expanded));
}

void LocateSweepErrors(const std::vector<SweptRow>& swept, const std::string& file,
                       std::vector<SuiteError>* errors) {
  for (SuiteError& e : *errors) {
    const bool from_set = e.file.starts_with("--set ");  // its place is the option: kept
    for (const SweptRow& row : swept) {
      const std::string prefix = "rows[" + std::to_string(row.row) + "].";
      if (!e.key_path.starts_with(prefix)) continue;
      const std::string rest = e.key_path.substr(prefix.size());
      const std::string source = "rows[" + std::to_string(row.source_row) + "]";
      e.key_path = source + "." + rest;  // the row as the file writes it
      bool placed = false;
      for (const SweptRow::Key& key : row.keys) {
        // The swept key, a key under it, or a map the sweep made on its way.
        if (!PathContains(key.path, rest) && !key.path.starts_with(rest + ".")) continue;
        e.key_path = source + ".sweep." + key.path;
        if (e.line == 0 && !from_set) {  // a key the sweep made: the sweep entry's place
          e.file = file;
          e.line = key.line;
          e.column = key.column;
        }
        placed = true;
        break;
      }
      if (!placed && e.line == 0 && !from_set && !row.keys.empty()) {
        // A key the sweep wrote beside the swept ones (the row's label): at its sweep.
        e.file = file;
        e.line = row.keys.front().line;
        e.column = row.keys.front().column;
      }
      break;
    }
  }
}

void RefuseOverridesOfSweptKeys(const std::vector<std::string>& overrides,
                                const std::vector<std::string>& resolved,
                                const std::vector<SweptRow>& swept, const std::string& file,
                                std::vector<SuiteError>* errors) {
  for (std::size_t i = 0; i < overrides.size() && i < resolved.size(); ++i) {
    const std::string& set = resolved[i];  // rows[N].key.path, N a row of the file
    if (!set.starts_with("rows[")) continue;
    const std::size_t close = set.find(']');
    if (close == std::string::npos || close + 1 >= set.size() || set[close + 1] != '.') continue;
    const std::size_t row = std::stoul(set.substr(5, close - 5));
    const std::string key = set.substr(close + 2);
    for (const SweptRow& made : swept) {
      if (made.source_row != row) continue;
      for (const SweptRow::Key& axis : made.keys) {
        if (!PathContains(axis.path, key) && !PathContains(key, axis.path)) continue;
        errors->push_back({"--set " + overrides[i], 0, 0, "",
                           "rows[" + std::to_string(row) + "] sweeps '" + axis.path + "' (" + file +
                               ":" + std::to_string(axis.line) + ":" + std::to_string(axis.column) +
                               "), which replaces this value in every row it makes: change "
                               "the sweep's values instead"});
        break;
      }
      break;  // every row of one sweep has the same keys
    }
  }
}

}  // namespace crowdsim::suite_internal

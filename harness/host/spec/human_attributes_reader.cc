#include "spec/human_attributes_reader.h"

#include "crowdsim/params.h"

namespace crowdsim::suite_internal {

namespace {

/// `key: v` or `key: [lo, hi]` with every value in (0, max].
void ReadRange(Reader& r, const YAML::Node& n, const std::string& path, double max,
               const char* unit, std::optional<AttributeRange>* out) {
  if (n.IsSequence()) {
    if (n.size() != 2) {
      r.Error(n, path, std::string("a range is a list of two values [lo, hi] (") + unit + ")");
      return;
    }
    const auto lo = r.Number(n[0], Reader::Index(path, 0), 0.0, max, /*lo_open=*/true);
    const auto hi = r.Number(n[1], Reader::Index(path, 1), 0.0, max, /*lo_open=*/true);
    if (!lo || !hi) return;
    if (*lo > *hi) {
      r.Error(n, path, "lo is larger than hi");
      return;
    }
    *out = AttributeRange{*lo, *hi};
    return;
  }
  if (auto v = r.Number(n, path, 0.0, max, /*lo_open=*/true)) *out = AttributeRange{*v, *v};
}

/// `groups: {share: s, size: n | [min, max]}`.
void ReadGroups(Reader& r, const YAML::Node& n, const std::string& path, int count,
                std::optional<GroupsSpec>* out) {
  if (!r.IsMap(n, path, "share and size")) return;
  r.CheckKeys(n, path, {"share", "size"});
  GroupsSpec g;
  if (!Present(n["share"])) {
    r.Error(n, Reader::Child(path, "share"),
            "missing key 'share' (the share of the people who walk in groups, in [0, 1])");
    return;
  }
  const auto share = r.Number(n["share"], Reader::Child(path, "share"), 0.0, 1.0);
  if (!share) return;
  g.share = *share;
  const YAML::Node size = n["size"];
  const std::string size_path = Reader::Child(path, "size");
  if (Present(size)) {
    const bool range = size.IsSequence();
    if (range && size.size() != 2) {
      r.Error(size, size_path, "a range is a list of two sizes [min, max]");
      return;
    }
    const auto lo = r.Integer(range ? size[0] : size, size_path, 2, 10000);
    const auto hi = range ? r.Integer(size[1], size_path, 2, 10000) : lo;
    if (!lo || !hi) return;
    if (*lo > *hi) {
      r.Error(size, size_path, "min is larger than max");
      return;
    }
    g.size_min = static_cast<int>(*lo);
    g.size_max = static_cast<int>(*hi);
  }
  if (g.share > 0.0 && g.size_min > count) {
    r.Error(Present(size) ? size : n, size_path,
            "a group of " + std::to_string(g.size_min) + " is larger than the crowd of " +
                std::to_string(count) + " (humans.count): lower the size or raise the count");
    return;
  }
  *out = g;
}

}  // namespace

void ReadHumanAttributes(Reader& r,
                         const std::function<std::pair<YAML::Node, std::string>(const char*)>& pick,
                         HumansSpec* out) {
  if (auto [n, p] = pick("radius"); Present(n)) ReadRange(r, n, p, 10.0, "m", &out->radius);
  if (auto [n, p] = pick("v_pref"); Present(n)) ReadRange(r, n, p, 100.0, "m/s", &out->v_pref);
  if (auto [n, p] = pick("distracted"); Present(n)) {
    if (auto v = r.Number(n, p, 0.0, 1.0)) out->distracted = *v;
  }
  if (auto [n, p] = pick("groups"); Present(n)) ReadGroups(r, n, p, out->count_max, &out->groups);
}

void CanonicalHumanAttributes(const HumansSpec& humans, std::ostream& os) {
  auto range = [&](const char* key, const std::optional<AttributeRange>& a) {
    if (a) os << key << "=" << FormatParamValue(a->lo) << ":" << FormatParamValue(a->hi) << ",";
  };
  range("radius", humans.radius);
  range("v_pref", humans.v_pref);
  if (humans.distracted > 0.0) os << "distracted=" << FormatParamValue(humans.distracted) << ",";
  if (const auto& g = humans.groups) {
    os << "groups=" << FormatParamValue(g->share) << ":" << g->size_min << ":" << g->size_max
       << ",";
  }
}

}  // namespace crowdsim::suite_internal

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

}  // namespace

void ReadHumanAttributes(Reader& r,
                         const std::function<std::pair<YAML::Node, std::string>(const char*)>& pick,
                         HumansSpec* out) {
  if (auto [n, p] = pick("radius"); Present(n)) ReadRange(r, n, p, 10.0, "m", &out->radius);
  if (auto [n, p] = pick("v_pref"); Present(n)) ReadRange(r, n, p, 100.0, "m/s", &out->v_pref);
  if (auto [n, p] = pick("distracted"); Present(n)) {
    if (auto v = r.Number(n, p, 0.0, 1.0)) out->distracted = *v;
  }
}

void CanonicalHumanAttributes(const HumansSpec& humans, std::ostream& os) {
  auto range = [&](const char* key, const std::optional<AttributeRange>& a) {
    if (a) os << key << "=" << FormatParamValue(a->lo) << ":" << FormatParamValue(a->hi) << ",";
  };
  range("radius", humans.radius);
  range("v_pref", humans.v_pref);
  if (humans.distracted > 0.0) os << "distracted=" << FormatParamValue(humans.distracted) << ",";
}

}  // namespace crowdsim::suite_internal

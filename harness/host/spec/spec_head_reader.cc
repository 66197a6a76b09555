#include "spec/spec_head_reader.h"

#include <limits>
#include <variant>

namespace crowdsim::suite_internal {

SpecHead ReadSpecHead(Reader& r, const YAML::Node& root, const std::string& folder) {
  SpecHead head;
  head.name = r.Name(root, folder);
  if (Present(root["description"])) {
    // A list or map is not a description: an error, not "".
    if (auto text = r.String(root["description"], "description")) head.description = *text;
  }
  if (root["seed"]) {
    if (auto v = r.Integer(root["seed"], "seed", 0, std::numeric_limits<std::int64_t>::max())) {
      head.seed = static_cast<std::uint64_t>(*v);
    }
  }
  if (root["sim"]) ReadSim(r, root["sim"], &head.sim);
  return head;
}

void ReadSim(Reader& r, const YAML::Node& n, SimConfig* sim) {
  if (!r.IsMap(n, "sim", "simulation settings")) return;
  std::vector<std::string> keys;
  for (const SimField& f : kSimFields) keys.push_back(f.key);
  r.CheckKeys(n, "sim", keys);
  for (const SimField& f : kSimFields) {
    if (!n[f.key]) continue;
    const std::string path = Reader::Child("sim", f.key);
    if (const auto* number = std::get_if<double SimConfig::*>(&f.member)) {
      if (auto v = r.Number(n[f.key], path, f.lo, f.hi, f.lo_open)) sim->** number = *v;
    } else if (auto b = r.Bool(n[f.key], path)) {
      sim->*std::get<bool SimConfig::*>(f.member) = *b;
    }
  }
  // A step count beyond any real episode is a typo (e.g. time_step: 1e-300).
  constexpr double kMaxSteps = 1e6;
  if (sim->time_limit / sim->time_step > kMaxSteps) {
    r.Error(n["time_step"] ? n["time_step"] : n, "sim.time_step",
            "time_limit / time_step = " + std::to_string(sim->time_limit / sim->time_step) +
                " steps per episode, more than 1,000,000; raise time_step or lower time_limit");
  }
}

}  // namespace crowdsim::suite_internal

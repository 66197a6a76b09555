// What a run resumes: stored episodes of this configuration and scope. Other lines are refused or
// moved to episodes.dropped.csv, never silently lost.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

using EpisodeKey = std::pair<std::string, int>;  // (row label, episode index)
using EpisodeLines = std::map<EpisodeKey, EpisodeLine>;

/// Where a run writes, its shard ("" or "K/N") and episodes per row (slices depend on it).
struct ResumeTarget {
  std::filesystem::path out_dir;
  std::string shard;
  int episodes = 0;
};

/// The stored episodes this run keeps (`worlds` give seeds). Set-aside lines are always reported,
/// resumed ones with `note`. Throws RunRefused for a configuration with no unchanged row, another
/// suite (by name), or, for a shard, a folder of another shard, run or count.
EpisodeLines StoredEpisodes(const Suite& suite,
                            const std::vector<std::shared_ptr<WorldSource>>& worlds,
                            const ResumeTarget& target, bool note);

}  // namespace crowdsim

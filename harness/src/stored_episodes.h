// What a run resumes from its output folder: the finished episodes stored in episodes.csv that
// belong to this configuration and this run's scope, with every other stored line either
// refused (a folder of another shard), set aside (rows removed from or changed in the suite:
// moved to episodes.dropped.csv, never silently lost) or skipped as foreign (a line whose seed
// is not the one this suite gives its episode).
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

/// Where a run writes and which shard it is ("" for a whole run, else "K/N").
struct ResumeTarget {
  std::filesystem::path out_dir;
  std::string shard;
};

/// The stored episodes of `target.out_dir` this run keeps. `worlds` are the rows' world
/// sources (their identities give the episodes' seeds). With `note`, what is resumed, set
/// aside or skipped is said on stderr. Throws RunError when the folder holds another
/// configuration with no row unchanged, or another shard (or a whole run) while this run is a
/// shard: resuming there would drop the episodes outside this shard.
EpisodeLines StoredEpisodes(const Suite& suite,
                            const std::vector<std::shared_ptr<WorldSource>>& worlds,
                            const ResumeTarget& target, bool note);

}  // namespace crowdsim

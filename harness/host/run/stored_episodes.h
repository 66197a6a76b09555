// What a run resumes from its output folder: the finished episodes stored in episodes.csv that
// belong to this configuration and this run's scope, with every other stored line either
// refused (a folder of another shard), or set aside: moved to episodes.dropped.csv, never
// silently lost (rows removed from or changed in the suite, foreign lines whose seed is not the
// one this suite gives the episode, damaged lines as read).
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

/// Where a run writes, which shard it is ("" for a whole run, else "K/N") and of how many
/// episodes per row (which episodes a shard holds depends on it).
struct ResumeTarget {
  std::filesystem::path out_dir;
  std::string shard;
  int episodes = 0;
};

/// The stored episodes of `target.out_dir` this run keeps. `worlds` are the rows' world
/// sources (their identities give the episodes' seeds). Lines set aside (damaged ones too, as
/// read) are always said on stderr; with `note`, what is resumed as well. Throws RunRefused when
/// the folder holds another configuration with no row unchanged or of another suite (by its
/// name: a suite renamed with an unchanged configuration resumes), or another shard (or a whole
/// run, or the same shard of another episode count) while this run is a shard: resuming there
/// would drop the episodes outside this shard.
EpisodeLines StoredEpisodes(const Suite& suite,
                            const std::vector<std::shared_ptr<WorldSource>>& worlds,
                            const ResumeTarget& target, bool note);

}  // namespace crowdsim

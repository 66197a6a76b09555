// "Did you mean": the valid name nearest a mistyped one, for the errors that list the valid
// names (a suite's or training file's keys, a plugin's parameters, the plugins of a kind).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace crowdsim {

/// The one name of `valid` within a few edits of `given` (a letter missing, extra, wrong, or two
/// swapped; case ignored): one edit, or a quarter of the longer name's length when that is more
/// (two for `episode` and `episodes`, too few for `rl_episodes`). Nothing when `given` has
/// fewer than three letters, when no name is that near, or when two are equally near.
std::optional<std::string> ClosestName(const std::string& given,
                                       const std::vector<std::string>& valid);

/// "; did you mean 'NAME'?" for ClosestName's answer, or "" without one: the tail of an
/// "unknown ..." message.
std::string DidYouMean(const std::string& given, const std::vector<std::string>& valid);

}  // namespace crowdsim

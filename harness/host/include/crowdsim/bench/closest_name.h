// "Did you mean": the valid name nearest a mistyped one, for errors listing valid names.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace crowdsim {

/// The one name of `valid` within max(1, a quarter of the longer name) edits of `given`, case
/// ignored; none under three letters or on a tie.
std::optional<std::string> ClosestName(const std::string& given,
                                       const std::vector<std::string>& valid);

/// "; did you mean 'NAME'?" for ClosestName's answer, else "": an "unknown ..." message's tail.
std::string DidYouMean(const std::string& given, const std::vector<std::string>& valid);

}  // namespace crowdsim

// Checks a plugin's Schema() on load: wrong-typed defaults would throw an anonymous
// std::bad_variant_access later; out-of-range ones no suite could give.
#pragma once

#include <string>
#include <vector>

#include "crowdsim/params.h"

namespace crowdsim {

/// The problems of `schema`, one phrase each ("parameter 'n': default 0.5 is a number, but the
/// parameter is declared int").
std::vector<std::string> SchemaProblems(const ParamSchema& schema);

}  // namespace crowdsim

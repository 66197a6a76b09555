// The check of a plugin's declared parameters (its Schema()), made when the plugin is loaded.
// A default of another type than its parameter's fails only when the constructor reads it (as
// std::bad_variant_access, naming neither the plugin nor the parameter), and a default outside
// the parameter's range or choices is a value no suite could give.
#pragma once

#include <string>
#include <vector>

#include "crowdsim/params.h"

namespace crowdsim {

/// What is wrong with `schema`, one phrase per problem naming the parameter, its default and
/// what the schema declares for it ("parameter 'n': default 0.5 is a number, but the parameter
/// is declared int"); empty when the host can use it.
std::vector<std::string> SchemaProblems(const ParamSchema& schema);

}  // namespace crowdsim

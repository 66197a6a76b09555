// Makes the OMPL planner named by the `planner` parameter, with every random generator it
// owns seeded from the plan's seed and exact (linear) nearest neighbours.
#pragma once

#include <ompl/base/Planner.h>

#include <cstdint>
#include <string>

namespace crowdsim::ompl_planner {

/// The planner `name` (one of Planners()) for `si`; its own RNG, where it has one, gets
/// `seed`. Throws std::invalid_argument listing the valid names for an unknown one.
::ompl::base::PlannerPtr MakePlanner(const std::string& name,
                                     const ::ompl::base::SpaceInformationPtr& si,
                                     std::uint32_t seed);

}  // namespace crowdsim::ompl_planner

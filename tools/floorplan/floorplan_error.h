// The one exception of the floor-plan importer.
#pragma once

#include <stdexcept>

namespace crowdsim::floorplan {

/// Bad input or an impossible import; what() names the file, the problem and the fix.
class FloorplanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace crowdsim::floorplan

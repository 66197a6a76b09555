// The one exception of the floor-plan importer.
#pragma once

#include <stdexcept>

namespace crowdsim::floorplan {

/// Bad input or an impossible import; what() names the file, the problem and the fix.
class FloorplanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An import that a missing command-line option stops (a plain image without --resolution):
/// `floorplan import` reports it as a usage error, exit 2, as its help says of usage errors.
class FloorplanOptionError : public FloorplanError {
 public:
  using FloorplanError::FloorplanError;
};

}  // namespace crowdsim::floorplan

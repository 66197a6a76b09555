#include "crowdsim/version.h"

namespace crowdsim {

const char* Version() { return CROWDSIM_VERSION; }

}  // namespace crowdsim

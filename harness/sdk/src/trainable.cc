// Key function of Trainable: one vtable and type info in the SDK, so a plugin's dynamic_cast works.
#include "crowdsim/trainable.h"

namespace crowdsim {

Trainable::~Trainable() = default;

}  // namespace crowdsim

// Key function of Trainable: its vtable and type info live once, in the core library, so a
// dynamic_cast from a plugin's Policy finds the same type.
#include "crowdsim/trainable.h"

namespace crowdsim {

Trainable::~Trainable() = default;

}  // namespace crowdsim

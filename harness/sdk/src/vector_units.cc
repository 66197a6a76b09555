#include "crowdsim/vector_units.h"

#include <cstdlib>
#include <string_view>

namespace crowdsim {

bool HaveAvx2() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool have = [] {
    __builtin_cpu_init();  // may run before the library's own constructors
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return have;
#else
  return false;
#endif
}

bool SimdDisabled() {
  const char* simd = std::getenv("CROWDSIM_SIMD");
  return simd != nullptr && std::string_view(simd) == "off";
}

bool UseAvx2() { return HaveAvx2() && !SimdDisabled(); }

}  // namespace crowdsim

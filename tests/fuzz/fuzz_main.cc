// libFuzzer's entry for one target of fuzz_targets.h, chosen at build time by
// CROWDSIM_FUZZ_TARGET (tests/fuzz/CMakeLists.txt builds one executable per target). A broken
// contract aborts with the reason, so libFuzzer saves the input as a crash.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const crowdsim::fuzz::FuzzTarget* target = [] {
    const auto* t = crowdsim::fuzz::FindFuzzTarget(CROWDSIM_FUZZ_TARGET);
    if (!t) {
      std::fprintf(stderr, "no fuzz target named '%s' in tests/fuzz/fuzz_targets.cc\n",
                   CROWDSIM_FUZZ_TARGET);
      std::abort();
    }
    return t;
  }();
  const std::string problem =
      target->run(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "%s broke its contract: %s\n", target->name, problem.c_str());
    std::abort();
  }
  return 0;
}

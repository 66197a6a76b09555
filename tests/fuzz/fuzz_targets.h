// The readers of user-written files, as fuzz targets: each takes any bytes, feeds them to one
// reader exactly as the CLI would (a file on disk, the default plugin search path) and says
// whether the reader kept its contract: a result or clean, located errors, never a crash, an
// abort or an exception other than the one it documents.
//
// One table serves both users: the libFuzzer executables (fuzz_main.cc, clang build with
// -DCROWDSIM_FUZZ=ON, scripts/fuzz.sh) and the corpus replay test of every build
// (corpus_replay_test.cc), which feeds each committed input under tests/fuzz/corpus/<name>/
// to the same function once.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace crowdsim::fuzz {

struct FuzzTarget {
  const char* name;  ///< also the corpus folder tests/fuzz/corpus/<name>/
  const char* what;  ///< one line for listings
  /// Reads `input`; returns "" when the reader kept its contract, else what went wrong.
  /// Exceptions the reader does not document propagate (a finding, not a clean error).
  std::string (*run)(std::string_view input);
};

/// Every fuzz target.
const std::vector<FuzzTarget>& FuzzTargets();

/// The target named `name`, or nullptr.
const FuzzTarget* FindFuzzTarget(std::string_view name);

}  // namespace crowdsim::fuzz

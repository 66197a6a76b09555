// Internal: edits of a spec document before reading: `--set key.path=value` and `sweep:` expansion.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

/// Applies `key.path=value` assignments in order: keys joined by '.', [N] (0-based) or [name]
/// enters a list (`rows[orca].params.safety_space=0.1`); the value is YAML. Missing maps are
/// created, missing items are errors. `resolved` (optional): each path by index, "" on failure.
void ApplyOverrides(YAML::Node& root, const std::vector<std::string>& overrides,
                    std::vector<SuiteError>* errors, std::vector<std::string>* resolved = nullptr);

/// Points reader errors about a --set value at that option (errors at or under its path, or about
/// keys it created). `row_map` (ExpandSweeps'): file rows to expanded ones.
void LocateOverrideErrors(const std::vector<std::string>& overrides,
                          std::vector<SuiteError>* errors,
                          const std::vector<std::string>& resolved = {},
                          const std::vector<std::vector<std::size_t>>& row_map = {});

/// A sweep row: its expanded index, its source row, and the swept keys with file places.
struct SweptRow {
  std::size_t row = 0;
  std::size_t source_row = 0;
  struct Key {
    std::string path;  ///< row-relative, as written: "world.obstacles"
    int line = 0, column = 0;
  };
  std::vector<Key> keys;
};

/// Replaces each row having `sweep:` (key paths to value lists, e.g. `{humans.count: [5, 10]}`) by
/// one row per combination, first key slowest, labelled `label/key=value/...`, one info column per
/// key; inherited sections copied first. `row_map` (optional): file row to indices.
void ExpandSweeps(YAML::Node& root, const std::string& file, std::vector<SuiteError>* errors,
                  std::vector<SweptRow>* swept = nullptr,
                  std::vector<std::vector<std::size_t>>* row_map = nullptr);

/// Points placeless errors in expanded rows at the `sweep:` entry that set the key: reported once,
/// where fixable.
void LocateSweepErrors(const std::vector<SweptRow>& swept, const std::string& file,
                       std::vector<SuiteError>* errors);

/// Refuses a --set into a key the row's sweep also sets (or around or within one): the sweep would
/// replace it. `resolved`, `swept`: from ApplyOverrides, ExpandSweeps.
void RefuseOverridesOfSweptKeys(const std::vector<std::string>& overrides,
                                const std::vector<std::string>& resolved,
                                const std::vector<SweptRow>& swept, const std::string& file,
                                std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal

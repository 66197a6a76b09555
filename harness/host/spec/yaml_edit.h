// Internal to the core: edits of a suite or training document before it is read, so that one
// file serves many experiments: `--set key.path=value` from the command line, and a row's
// `sweep:` block expanded into one row per combination of values.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

/// Applies `key.path=value` assignments in order. A path is keys joined by '.', where a list is
/// entered with [N] (0-based) or [name] (the item whose label, or else policy, type or own
/// text, is name): `humans.count=10`, `rows[orca].params.safety_space=0.1`,
/// `robot.sensors[lidar2d].beams=90`. The value is YAML (`10`, `[person, lidar2d]`, `{a: 1}`).
/// Missing maps on the way are created; a list item that does not exist is an error. Each
/// problem becomes an error whose file is "--set EXPR".
/// `resolved` (optional) receives, per override, the path it set with list items by index
/// (rows[12].params.x), "" where it failed: LocateOverrideErrors uses them.
void ApplyOverrides(YAML::Node& root, const std::vector<std::string>& overrides,
                    std::vector<SuiteError>* errors, std::vector<std::string>* resolved = nullptr);

/// Points the reader's errors about a value set with --set at that option (they would name
/// line 1 of the file): an error whose key path is an override's, or lies under it.
/// With `resolved` (ApplyOverrides'), also an error without a place in the file about a key
/// an override made on its way (rows[orca].param.x=1: 'param' unknown).
/// `row_map` (ExpandSweeps') gives the rows' indices after sweeps expanded them.
void LocateOverrideErrors(const std::vector<std::string>& overrides,
                          std::vector<SuiteError>* errors,
                          const std::vector<std::string>& resolved = {},
                          const std::vector<std::vector<std::size_t>>& row_map = {});

/// A row that a sweep made: its index after expansion, the row of the file it came from, and
/// the swept keys with their place in the file.
struct SweptRow {
  std::size_t row = 0;
  std::size_t source_row = 0;
  struct Key {
    std::string path;  ///< row-relative, as written: "world.obstacles"
    int line = 0, column = 0;
  };
  std::vector<Key> keys;
};

/// Replaces every row with a `sweep:` map of row-relative key paths to value lists, e.g.
/// `sweep: {humans.count: [5, 10, 20], world.obstacles: [1, 3]}`, by one row per combination
/// (the first key varies slowest), labelled `label/key=value/...` and with one info column per
/// swept key. A row that inherits `world`, `humans` or the robot's sensors gets its own copy
/// before the swept key is set. `file` locates errors.
/// `row_map` (optional) receives, per row of the file, its index or indices after expansion.
void ExpandSweeps(YAML::Node& root, const std::string& file, std::vector<SuiteError>* errors,
                  std::vector<SweptRow>* swept = nullptr,
                  std::vector<std::vector<std::size_t>>* row_map = nullptr);

/// Points the reader's errors about a swept key at the `sweep:` entry that set it: an error
/// without a location under an expanded row (`rows[5].world.obstacle`, a key the sweep made)
/// becomes the file location of that entry (`rows[4].sweep.world.obstacle`), so that it is
/// reported once, where it can be fixed.
void LocateSweepErrors(const std::vector<SweptRow>& swept, const std::string& file,
                       std::vector<SuiteError>* errors);

/// A --set into a row's key that the row's sweep sets too (or into a map holding one, or a key
/// inside one) would be replaced in every row the sweep makes, though the manifest lists it
/// among the overrides: an error naming the option and the sweep entry. `resolved` is
/// ApplyOverrides', `swept` ExpandSweeps'.
void RefuseOverridesOfSweptKeys(const std::vector<std::string>& overrides,
                                const std::vector<std::string>& resolved,
                                const std::vector<SweptRow>& swept, const std::string& file,
                                std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal

// A test fixture that loads suite texts from a temporary folder: the suite, or its first error.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::testing {

class SuiteFileTest : public ::testing::Test {
 protected:
  SuiteLoadResult Load(const std::string& yaml) {
    return LoadSuite(dir_.Write("suite.yaml", yaml), registry_);
  }
  /// The loaded suite; a test failure listing the errors when it does not load.
  Suite Loaded(const std::string& yaml) {
    SuiteLoadResult r = Load(yaml);
    std::string errors;
    for (const auto& e : r.errors) errors += e.Format() + "\n";
    EXPECT_TRUE(r.suite) << errors;
    return r.suite ? *r.suite : Suite{};
  }
  /// The first error as the CLI prints it; "" when the suite loads.
  std::string FirstError(const std::string& yaml) {
    SuiteLoadResult r = Load(yaml);
    return r.errors.empty() ? "" : r.errors.front().Format();
  }

  TempDir dir_;
  PluginRegistry registry_{{PluginDir()}};
};

}  // namespace crowdsim::testing

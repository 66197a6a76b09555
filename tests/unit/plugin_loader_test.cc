// Plugin loading: the good path and each kind of broken plugin gives a clear error.
#include <gtest/gtest.h>

#include <fstream>

#include "crowdsim/bench/plugin_registry.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::FixturePluginDir;
using testing::PluginDir;

std::string LoadError(PluginRegistry& reg, const std::string& name, PluginKind kind) {
  try {
    reg.Load(name, kind);
  } catch (const PluginError& e) {
    return e.what();
  }
  return "";
}

TEST(PluginLoader, LoadsLinearByNameAndChecksKind) {
  PluginRegistry reg({PluginDir()});
  const LoadedPlugin& p = reg.Load("linear", PluginKind::kPolicy);
  EXPECT_STREQ(p.descriptor->name, "linear");
  EXPECT_EQ(p.descriptor->abi_version, kPluginAbiVersion);
  ASSERT_EQ(p.schema.size(), 2u);
  auto policy = reg.MakePolicy(p, Params::Defaults(p.schema));
  ASSERT_NE(policy, nullptr);
  const std::string err = LoadError(reg, "linear", PluginKind::kSensor);
  EXPECT_NE(err.find("is a policy plugin, but a sensor plugin is needed"), std::string::npos)
      << err;
}

TEST(PluginLoader, LoadsByExplicitPathOnce) {
  PluginRegistry reg(std::vector<std::filesystem::path>{});
  const auto path = (PluginDir() / "crowdsim_linear.so").string();
  const LoadedPlugin& a = reg.Load(path, PluginKind::kPolicy);
  const LoadedPlugin& b = reg.Load(path, PluginKind::kPolicy);
  EXPECT_EQ(&a, &b);
}

TEST(PluginLoader, PolicyKeepsLibraryLoadedAfterRegistryDies) {
  std::shared_ptr<Policy> policy;
  {
    PluginRegistry reg({PluginDir()});
    const auto& p = reg.Load("linear", PluginKind::kPolicy);
    policy = reg.MakePolicy(p, Params::Defaults(p.schema));
  }
  Observation obs;
  obs.self.position = Vec2(0, 0);
  obs.self.goal = Vec2(3, 4);
  const Action a = policy->Decide(obs);  // code of the plugin still mapped
  EXPECT_NEAR(a.velocity.norm(), 1.0, 1e-12);
}

TEST(PluginLoader, UnknownNameListsWhereItLooked) {
  PluginRegistry reg({PluginDir()});
  const std::string err = LoadError(reg, "orcaa", PluginKind::kPolicy);
  EXPECT_NE(err.find("no plugin named 'orcaa'"), std::string::npos) << err;
  EXPECT_NE(err.find("crowdsim_orcaa.so"), std::string::npos) << err;
  EXPECT_NE(err.find("CROWDSIM_PLUGIN_PATH"), std::string::npos) << err;
}

TEST(PluginLoader, MissingFile) {
  PluginRegistry reg(std::vector<std::filesystem::path>{});
  const std::string err = LoadError(reg, "/nonexistent/crowdsim_x.so", PluginKind::kPolicy);
  EXPECT_NE(err.find("does not exist"), std::string::npos) << err;
}

TEST(PluginLoader, NotASharedLibrary) {
  PluginRegistry reg({FixturePluginDir()});
  const std::string err = LoadError(reg, "not_a_library", PluginKind::kPolicy);
  EXPECT_NE(err.find("cannot load plugin file"), std::string::npos) << err;
  EXPECT_NE(err.find("crowdsim_not_a_library.so"), std::string::npos) << err;
}

// boost.dll ended the loader's message with an unrelated errno text ("Bad file descriptor").
TEST(PluginLoader, ALibraryTheLoaderRefusesIsNamedInTheLoadersWords) {
  PluginRegistry reg({FixturePluginDir()});
  const std::string err = LoadError(reg, "undefined_symbol", PluginKind::kPolicy);
  EXPECT_NE(err.find("crowdsim_undefined_symbol.so: undefined symbol: "
                     "crowdsim_fixture_missing_symbol. It is not a loadable"),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("Bad file descriptor"), std::string::npos) << err;
  EXPECT_EQ(err.find("boost::dll"), std::string::npos) << err;
}

TEST(PluginLoader, SharedLibraryWithoutAlias) {
  PluginRegistry reg({FixturePluginDir()});
  const std::string err = LoadError(reg, "no_alias", PluginKind::kPolicy);
  EXPECT_NE(err.find("not a crowdsim-bench plugin"), std::string::npos) << err;
  EXPECT_NE(err.find("CROWDSIM_EXPORT_PLUGIN"), std::string::npos) << err;
}

TEST(PluginLoader, WrongAbiVersionIsRefusedFirst) {
  PluginRegistry reg({FixturePluginDir()});
  const std::string err = LoadError(reg, "wrong_abi", PluginKind::kPolicy);
  EXPECT_NE(err.find("ABI version " + std::to_string(kPluginAbiVersion + 998)), std::string::npos)
      << err;
  EXPECT_NE(err.find("expects version " + std::to_string(kPluginAbiVersion)), std::string::npos)
      << err;
  EXPECT_NE(err.find("Rebuild"), std::string::npos) << err;
}

TEST(PluginLoader, FactoryThrows) {
  PluginRegistry reg({FixturePluginDir()});
  const LoadedPlugin& p = reg.Load("throwing_factory", PluginKind::kPolicy);
  try {
    reg.MakePolicy(p, Params::Defaults(p.schema));
    FAIL() << "expected PluginError";
  } catch (const PluginError& e) {
    const std::string err = e.what();
    EXPECT_NE(err.find("failed to create its policy"), std::string::npos) << err;
    EXPECT_NE(err.find("model file missing (fixture)"), std::string::npos) << err;
  }
}

TEST(PluginLoader, SchemaWithAWrongDefaultIsRefusedNamingEachParameter) {
  PluginRegistry reg({FixturePluginDir()});
  const std::string err = LoadError(reg, "bad_schema", PluginKind::kPolicy);
  EXPECT_NE(err.find("crowdsim_bad_schema.so"), std::string::npos) << err;
  EXPECT_NE(err.find("parameter 'count': default 2.5 is a double, but ParamType::kInt takes a "
                     "std::int64_t"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("parameter 'gain': default 20 is outside its range [0, 10]"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("parameter 'gain' is declared twice"), std::string::npos) << err;
  EXPECT_NE(err.find("Fix the plugin's Schema()"), std::string::npos) << err;
}

TEST(PluginLoader, EveryBuiltInPluginsSchemaIsSound) {
  PluginRegistry reg({PluginDir()});
  const auto found = reg.Discover();
  EXPECT_TRUE(found.problems.empty()) << found.problems.front();
  EXPECT_GE(found.plugins.size(), 5u);
}

TEST(PluginLoader, FileNameAndDescriptorNameMustAgree) {
  // A copy of the linear plugin under another plugin name: found by that name, called 'linear'.
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "renamed_plugin";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(PluginDir() / "crowdsim_linear.so", dir / "crowdsim_mine.so",
                             std::filesystem::copy_options::overwrite_existing);
  for (const std::string& asked : {std::string("mine"), (dir / "crowdsim_mine.so").string()}) {
    PluginRegistry reg({dir});
    const std::string err = LoadError(reg, asked, PluginKind::kPolicy);
    EXPECT_NE(err.find("is named 'mine' but its descriptor calls it 'linear'"), std::string::npos)
        << err;
    EXPECT_NE(err.find("Rename the file to crowdsim_linear.so"), std::string::npos) << err;
  }
  // Another file name (not crowdsim_<name>.so), given as a path: no name to agree with.
  std::filesystem::copy_file(PluginDir() / "crowdsim_linear.so", dir / "my_policy.so",
                             std::filesystem::copy_options::overwrite_existing);
  PluginRegistry reg(std::vector<std::filesystem::path>{});
  EXPECT_STREQ(reg.Load((dir / "my_policy.so").string(), PluginKind::kPolicy).descriptor->name,
               "linear");
  std::filesystem::remove_all(dir);
}

TEST(PluginLoader, DiscoverReportsBrokenFilesWithoutStopping) {
  PluginRegistry reg({PluginDir(), FixturePluginDir()});
  auto found = reg.Discover();
  bool has_linear = false;
  for (const auto* p : found.plugins) has_linear |= std::string(p->descriptor->name) == "linear";
  EXPECT_TRUE(has_linear);
  EXPECT_GE(found.problems.size(), 4u);  // not_a_library, no_alias, wrong_abi, undefined_symbol
}

// A plugin file cut short (an interrupted copy: its first 1-12 kB) is an error naming it, for
// loading and for the discovery list-plugins runs, never a SIGBUS of the whole process.
TEST(PluginLoader, APluginFileCutShortIsAnErrorNotACrash) {
  const auto dir = std::filesystem::temp_directory_path() / "crowdsim_cut_plugins";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ifstream whole(PluginDir() / "crowdsim_orca.so", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(whole)),
                          std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 12000u);
  for (const std::size_t kb : {1, 4, 12}) {
    const auto cut = dir / ("crowdsim_cut" + std::to_string(kb) + ".so");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, kb * 1024);
    PluginRegistry reg(std::vector<std::filesystem::path>{});
    const std::string err = LoadError(reg, cut.string(), PluginKind::kPolicy);
    EXPECT_NE(err.find("cannot load plugin file '" + cut.string() + "': it is cut short"),
              std::string::npos)
        << err;
  }
  PluginRegistry reg({dir, PluginDir()});
  const auto found = reg.Discover();
  EXPECT_EQ(found.problems.size(), 3u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace crowdsim

// Command-line parsing shared by the crowdsim-bench subcommands (harness/app/) and the tools
// they register (tools/): positional arguments, --options, and the usage error main reports.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace crowdsim::cli {

/// A usage problem; main prints it with the subcommand's usage.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `--help` among a command's options (not as an option's value): main prints the usage.
class HelpRequested : public std::exception {
 public:
  const char* what() const noexcept override { return "--help"; }
};

/// Positional arguments and --options of one subcommand.
struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  ///< "--out" -> "DIR"; flags map to ""
  std::map<std::string, std::vector<std::string>>
      repeated;  ///< every value of each option, in order

  /// Parses `args`; `with_value` names the options that take a value, `flags` those that do not.
  static Args Parse(const std::vector<std::string>& args,
                    const std::vector<std::string>& with_value,
                    const std::vector<std::string>& flags);
  bool Has(const std::string& name) const { return options.count(name) != 0; }
  /// The value of an option given at most once (UsageError when it was given more often).
  std::optional<std::string> Get(const std::string& name) const;
  /// Every value of a repeatable option (e.g. --set), in order; empty when absent.
  std::vector<std::string> All(const std::string& name) const;
  /// Integer option within [lo, hi], or `fallback` when absent.
  std::int64_t GetInt(const std::string& name, std::int64_t fallback, std::int64_t lo,
                      std::int64_t hi) const;
  /// Number option (any decimal notation), or `fallback` when absent.
  double GetNumber(const std::string& name, double fallback) const;
};

/// Where a warning about a spec file comes from: "FILE", or "FILE with --set A --set B" when
/// the values it names may be the options' (a warning blamed the file for a --set value).
std::string SpecSource(const std::string& file, const std::vector<std::string>& sets);

/// Creates the folder an output file goes in (as `run --out` creates its folder); throws
/// UsageError naming the option, the folder and the reason when it cannot.
void CreateFolderOf(const std::string& option, const std::string& file);

}  // namespace crowdsim::cli
